package org.robotrun.render;

import static org.assertj.core.api.Assertions.assertThat;

import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

class ScreenRectTest {
  private static final int W = 640;
  private static final int H = 400;
  private final OrbitCamera camera = new OrbitCamera();
  private final Matrix4f viewProj = camera.viewProjection(W / (float) H);
  private final MeshBounds cube = new MeshBounds(-50, -50, -50, 50, 50, 50);

  @Test
  void emptyUntilABoxIsAdded() {
    ScreenRect r = new ScreenRect();
    r.reset(W, H);
    assertThat(r.isEmpty()).isTrue();
  }

  @Test
  void aBoxInViewGivesASmallRectangleAroundItsProjectedCentre() {
    ScreenRect r = new ScreenRect();
    r.reset(W, H);
    Matrix4f model = new Matrix4f().translation(200, 0, 0);
    r.addBox(viewProj, model, cube);
    // The projected centre lies inside; the rectangle is far smaller than the viewport.
    Vector4f c = viewProj.transform(new Vector4f(200, 0, 0, 1));
    float cx = (c.x / c.w * 0.5f + 0.5f) * W;
    float cy = (c.y / c.w * 0.5f + 0.5f) * H;
    assertThat(r.isEmpty()).isFalse();
    assertThat(cx).isBetween((float) r.x0(), (float) r.x1());
    assertThat(cy).isBetween((float) r.y0(), (float) r.y1());
    assertThat((r.x1() - r.x0()) * (r.y1() - r.y0())).isLessThan(W * H / 10);
  }

  @Test
  void aBoxReachingBehindTheEyeTakesTheWholeViewport() {
    ScreenRect r = new ScreenRect();
    r.reset(W, H);
    var eye = camera.eye();
    r.addBox(viewProj, new Matrix4f().translation(eye.x, eye.y, eye.z), cube);
    assertThat(r.x0()).isZero();
    assertThat(r.y0()).isZero();
    assertThat(r.x1()).isEqualTo(W);
    assertThat(r.y1()).isEqualTo(H);
  }

  @Test
  void aBoxOffScreenIsClampedToTheViewport() {
    ScreenRect r = new ScreenRect();
    r.reset(W, H);
    // Far to the side of the view direction but in front of the eye.
    r.addBox(viewProj, new Matrix4f().translation(-3000, -6000, 0), cube);
    assertThat(r.x0()).isBetween(0, W);
    assertThat(r.x1()).isBetween(0, W);
    assertThat(r.y0()).isBetween(0, H);
    assertThat(r.y1()).isBetween(0, H);
  }
}
