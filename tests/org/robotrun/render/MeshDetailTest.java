package org.robotrun.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;

class MeshDetailTest {
  /** How far a circle of radius r divided into n segments strays from the true circle (its chords' middle). */
  private static double sag(double r, int n) {
    return r * (1 - Math.cos(Math.PI / n));
  }

  @Test
  void aCylinderGetsTheFewestSegmentsThatStayWithinAQuarterPixel() {
    for (double r = 0.5; r < 400; r *= 1.3) {
      int n = MeshDetail.cylinderSegments(r);
      if (n < MeshFactory.CYLINDER_SEGMENTS) {
        assertThat(sag(r, n)).as("radius %.1f px, %d segments", r, n).isLessThanOrEqualTo(MeshDetail.MAX_ERROR_PX);
      }
      // and no coarser choice would have done
      for (int coarser : MeshDetail.CYLINDER_STEPS) {
        if (coarser < n) {
          assertThat(sag(r, coarser)).isGreaterThan(MeshDetail.MAX_ERROR_PX);
        }
      }
    }
    // 24 px across a radius: a 24-gon strays 0.21 px, a 16-gon 0.46 px
    assertThat(MeshDetail.cylinderSegments(24)).isEqualTo(24);
    // large on screen: the full mesh
    assertThat(MeshDetail.cylinderSegments(1000)).isEqualTo(MeshFactory.CYLINDER_SEGMENTS);
    assertThat(MeshDetail.cylinderSegments(2)).isEqualTo(12);
  }

  @Test
  void aRoundedEdgeGetsTheFewestSegmentsPerQuarterCircle() {
    // a quarter circle in k segments: each spans 90/k degrees
    assertThat(MeshDetail.roundSegments(0.5)).isEqualTo(1);
    assertThat(MeshDetail.roundSegments(3)).isEqualTo(2);
    assertThat(sag(3, 8)).isLessThanOrEqualTo(MeshDetail.MAX_ERROR_PX);
    assertThat(sag(3, 4)).isGreaterThan(MeshDetail.MAX_ERROR_PX);
    assertThat(MeshDetail.roundSegments(100)).isEqualTo(MeshFactory.ROUND_SEGMENTS);
  }

  @Test
  void pixelsPerMillimetreFollowTheCameraAndGrowNearerTheEye() {
    int w = 1000, h = 800;
    float fovY = (float) Math.toRadians(40);
    Matrix4f vp = new Matrix4f().perspective(fovY, (float) w / h, 10f, 20000f)
        .lookAt(0, -2000, 0, 0, 0, 0, 0, 0, 1);
    // at the view's centre, 2000 mm away: h/2 / tan(fov/2) / 2000 pixels per mm
    double expected = h / 2.0 / Math.tan(fovY / 2) / 2000;
    assertThat(MeshDetail.pixelsPerMm(vp, 0, 0, 0, 0, w, h)).isCloseTo(expected, within(expected * 1e-4));
    // twice as far: half
    assertThat(MeshDetail.pixelsPerMm(vp, 0, 2000, 0, 0, w, h)).isCloseTo(expected / 2, within(expected * 1e-4));
    // a sphere of 500 mm around the point reaches 1500 mm from the eye: 2000 / 1500 more
    assertThat(MeshDetail.pixelsPerMm(vp, 0, 0, 0, 500, w, h)).isCloseTo(expected * 2000 / 1500, within(expected * 1e-3));
    // a sphere that reaches the eye: full detail
    assertThat(MeshDetail.pixelsPerMm(vp, 0, 0, 0, 2500, w, h)).isInfinite();
    // behind the eye: full detail
    assertThat(MeshDetail.pixelsPerMm(vp, 0, -3000, 0, 0, w, h)).isInfinite();
  }
}
