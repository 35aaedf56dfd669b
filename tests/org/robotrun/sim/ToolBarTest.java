package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.world.LocalBox;

/**
 * The collision bar of a robot without an end effector (docs/collision.md, {@link CellCollisions}):
 * a 20 mm square bar from 2 mm past the flange to the active TCP, along the flange-to-TCP line,
 * whatever direction the tool points; none for a TCP within 3 mm of the flange.
 */
class ToolBarTest {

  private static void assertBar(Vec3 tcp) {
    LocalBox b = CellCollisions.toolBar(Transform.translation(tcp.x(), tcp.y(), tcp.z())).orElseThrow();
    double length = tcp.norm() - 2;
    Vec3 dir = tcp.times(1 / tcp.norm());
    assertThat(b.hxMm()).isEqualTo(10.0);
    assertThat(b.hyMm()).isEqualTo(10.0);
    assertThat(b.hzMm()).isCloseTo(length / 2, within(1e-9));
    // the bar's own z axis points from the flange to the TCP
    Vec3 z = b.X_LB().axis(2);
    assertThat(z.x()).as("%s", tcp).isCloseTo(dir.x(), within(1e-9));
    assertThat(z.y()).as("%s", tcp).isCloseTo(dir.y(), within(1e-9));
    assertThat(z.z()).as("%s", tcp).isCloseTo(dir.z(), within(1e-9));
    // its ends: 2 mm past the flange, and the TCP
    Vec3 near = b.X_LB().apply(new Vec3(0, 0, -b.hzMm()));
    Vec3 far = b.X_LB().apply(new Vec3(0, 0, b.hzMm()));
    assertThat(near.distanceTo(dir.times(2))).as("%s", tcp).isLessThan(1e-9);
    assertThat(far.distanceTo(tcp)).as("%s", tcp).isLessThan(1e-9);
    // a right-handed, orthonormal frame
    assertThat(b.X_LB().axis(0).cross(b.X_LB().axis(1)).distanceTo(z)).isLessThan(1e-9);
  }

  @Test
  void theBarRunsFromTwoMillimetresPastTheFlangeToTheTcpInEveryDirection() {
    assertBar(new Vec3(0, 0, 100));
    assertBar(new Vec3(0, 0, -100));
    assertBar(new Vec3(100, 0, 0));
    assertBar(new Vec3(0, -250, 0));
    assertBar(new Vec3(30, 40, 120));
    assertBar(new Vec3(-30, 10, -5));
    assertBar(new Vec3(0, 0, 3.5));
  }

  @Test
  void aTcpWithinThreeMillimetresOfTheFlangeHasNoBar() {
    assertThat(CellCollisions.toolBar(Transform.IDENTITY)).isEmpty();
    assertThat(CellCollisions.toolBar(Transform.translation(0, 0, 3))).isEmpty();
    assertThat(CellCollisions.toolBar(Transform.translation(0, 2, 2))).isEmpty();
    assertThat(CellCollisions.toolBar(Transform.translation(0, 0, 3.01))).isPresent();
  }
}
