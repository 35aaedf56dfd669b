package org.robotrun.math;

import static org.assertj.core.api.Assertions.assertThat;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.DoubleRange;
import net.jqwik.api.constraints.Scale;
import org.junit.jupiter.api.Test;

class XyzwprTest {

  @Property(seed = "42")
  void rotationRoundTripsThroughXyzwpr(
      @ForAll @DoubleRange(min = -180, max = 180) @Scale(6) double wDeg,
      @ForAll @DoubleRange(min = -90, max = 90) @Scale(6) double pDeg,
      @ForAll @DoubleRange(min = -180, max = 180) @Scale(6) double rDeg) {
    // Method: matrix -> WPR -> matrix gives the same rotation (tolerance 1e-9 rad), gimbal included.
    Transform t = Xyzwpr.ofDegrees(1, 2, 3, wDeg, pDeg, rDeg).toTransform();
    Transform back = Xyzwpr.fromTransform(t).toTransform();
    assertThat(t.rotationAngleTo(back)).isLessThan(1e-9);
  }

  @Test
  void gimbalPoseKeepsItsRotation() {
    for (double pDeg : new double[] {90, -90, 89.9999999, -89.9999999}) {
      Transform t = Xyzwpr.ofDegrees(0, 0, 0, 30, pDeg, 40).toTransform();
      Xyzwpr back = Xyzwpr.fromTransform(t);
      assertThat(t.rotationAngleTo(back.toTransform())).as("P=%s", pDeg).isLessThan(1e-9);
    }
  }

  @Test
  void rIsAboutZAndAppliedLast() {
    // R = 90 deg alone turns the tool's x axis onto world +Y.
    Transform t = Xyzwpr.ofDegrees(0, 0, 0, 0, 0, 90).toTransform();
    assertThat(t.axis(0).y()).isEqualTo(1.0, org.assertj.core.api.Assertions.within(1e-15));
  }
}
