package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * The CRX layout as OffsetWristIk's class comment defines it, one condition at a time: J2 meets
 * the J1 axis and is perpendicular to it; J3 parallel to J2; the J4 axis meets J3's at the elbow,
 * in the plane through J2's origin perpendicular to J2; J5 meets J4, J6 meets J5 at a distance
 * y1 &gt; 0. The CRX-10iA with one of these broken by a few millimetres or degrees is not of the
 * layout (the search would solve another arm): the solver refuses it naming the model, and the
 * arm gets another solver. The same arm with other link lengths still is, and solves.
 */
class OffsetWristLayoutTest {
  static final RobotModel CRX = RobotDefinitions.load("crx10ia");

  /** CRX-10iA with joint i's frame moved by {@code change} (in its parent link, before its own frame). */
  static RobotModel changed(int i, Transform change) {
    List<JointSpec> js = new ArrayList<>(CRX.joints());
    JointSpec j = js.get(i);
    js.set(i, new JointSpec(j.name(), change.compose(j.X_PJ()), j.axis(), j.lowerRad(), j.upperRad(), j.maxSpeedRadPerSec()));
    return RobotModel.fromChain("crx-changed", "CRX changed", js, CRX.X_6F(), CRX.X_WB(), CRX.links(), CRX.coupledJ3());
  }

  static void notTheLayout(RobotModel m, String what) {
    assertThat(OffsetWristIk.applies(m)).as(what).isFalse();
    assertThat(IkSolver.kindFor(m)).as(what).isNotEqualTo(OffsetWristIk.KIND);
    assertThat(m.wristKind()).as(what).isNotEqualTo("offset");
    assertThatThrownBy(() -> new OffsetWristIk(m)).as(what).isInstanceOf(IllegalArgumentException.class)
        .hasMessage("crx-changed: not the CRX layout (see OffsetWristIk), the offset-wrist solver does not apply");
  }

  @Test
  void breakingOneConditionOfTheLayoutLeavesTheOffsetWristSolverOut() {
    assertThat(OffsetWristIk.applies(CRX)).isTrue();
    // The elbow 20 mm off the plane through J2's origin (J3 moved along the J2 axis, y).
    notTheLayout(changed(2, Transform.translation(0, 20, 0)), "elbow off the arm plane");
    // J2 tilted 2 degrees from perpendicular to J1.
    notTheLayout(changed(1, Transform.rotation(1, 0, 0, Math.toRadians(2))), "J2 not perpendicular to J1");
    // J2 20 mm beside the J1 axis (along x: the axes no longer meet).
    notTheLayout(changed(1, Transform.translation(20, 0, 0)), "J2 does not meet J1");
    // J3 tilted 2 degrees about x: no longer parallel to J2.
    notTheLayout(changed(2, Transform.rotation(1, 0, 0, Math.toRadians(2))), "J3 not parallel to J2");
    // J4's axis 30 mm above J3's: they no longer meet at an elbow.
    notTheLayout(changed(3, Transform.translation(0, 0, 30)), "J4 misses J3");
    // J5 30 mm above J4's axis: J5 misses J4.
    notTheLayout(changed(4, Transform.translation(0, 0, 30)), "J5 misses J4");
    // J5 tilted: not perpendicular to J4.
    notTheLayout(changed(4, Transform.rotation(0, 0, 1, Math.toRadians(3))), "J5 not perpendicular to J4");
    // J6 tilted: not perpendicular to J5.
    notTheLayout(changed(5, Transform.rotation(1, 0, 0, Math.toRadians(3))), "J6 not perpendicular to J5");
    // J6 30 mm above J5's axis: they no longer meet.
    notTheLayout(changed(5, Transform.translation(0, 0, 30)), "J6 misses J5");
  }

  @Test
  void aSphericalWristIsTheClosedFormsNotTheSearchs() {
    // J6 moved back onto J5's origin (y1 = 0): the wrist is spherical and the arm is OPW.
    RobotModel m = changed(5, Transform.translation(0, 150, 0));
    assertThat(m.opw()).isPresent();
    assertThat(OffsetWristIk.applies(m)).isFalse();
    assertThat(IkSolver.kindFor(m)).isEqualTo(ClosedFormIk.KIND);
    assertThat(OffsetWristIk.layout(m)).isEmpty();
  }

  @Test
  void otherLinkLengthsAndAnotherWristOffsetAreStillTheLayoutAndSolve() {
    // Upper arm 400 mm instead of 540, forearm 600 instead of 540, y1 100 instead of 150.
    RobotModel m = changed(2, Transform.translation(0, 0, -140));
    List<JointSpec> js = new ArrayList<>(m.joints());
    js.set(4, new JointSpec("J5", Transform.translation(60, 0, 0).compose(js.get(4).X_PJ()), js.get(4).axis(),
        js.get(4).lowerRad(), js.get(4).upperRad(), js.get(4).maxSpeedRadPerSec()));
    js.set(5, new JointSpec("J6", Transform.translation(0, 50, 0).compose(js.get(5).X_PJ()), js.get(5).axis(),
        js.get(5).lowerRad(), js.get(5).upperRad(), js.get(5).maxSpeedRadPerSec()));
    RobotModel other = RobotModel.fromChain("crx-other", "CRX other", js, CRX.X_6F(), CRX.X_WB(), CRX.links(), true);
    assertThat(IkSolver.kindFor(other)).isEqualTo(OffsetWristIk.KIND);
    OffsetWristIk.Layout lay = OffsetWristIk.layout(other).orElseThrow();
    assertThat(lay.l2()).isCloseTo(400, org.assertj.core.api.Assertions.within(1e-9));
    assertThat(lay.l3()).isCloseTo(600, org.assertj.core.api.Assertions.within(1e-9));
    assertThat(lay.y1()).isCloseTo(100, org.assertj.core.api.Assertions.within(1e-9));
    IkSolver ik = IkSolver.forModel(other);
    for (double[] q : IkSolverContractTest.samples(other, 430, 5)) {
      Transform X = ForwardKinematics.flangePoseInBase(other, q);
      IkResult r = ik.solve(X, ik.configOf(q), q);
      IkSolverContractTest.reaches(other, ((IkResult.Solved) r).q(), X, "other CRX");
      assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) ik.solveNearest(X, q)).q(), q)).isLessThan(1e-6);
    }
  }
}
