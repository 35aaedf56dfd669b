package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The UR-type closed form promises any arm of the family (UrTypeIk's class comment: J2, J3, J4
 * parallel, J1 merely not parallel to them, the J5 and J6 axes meeting in one point), not only
 * the right angles of a real UR. Here an arm built from DH rows with oblique twists (J1 at 75° to
 * J2, J5 at 69° to J4, J6 at 63° to J5) and a lateral shoulder offset must get the closed form,
 * and every pose made by FK must come back: the joints that made it among the solutions, each
 * solution reaching the pose by FK, eight distinct flag triples for a pose with eight branches,
 * solve by each CONFIG returning that branch, and the nearest solution being the truth. A UR5
 * whose J6 axis misses J5's by 1 mm is not of the family and gets the numeric solver.
 */
class UrTypeGeneralLayoutTest {

  /** A 6R arm from DH rows (d, a, alpha per joint) and joint limits of ±lim. */
  static RobotModel dhArm(String id, double[] d, double[] a, double[] alpha, double lim) {
    List<JointSpec> joints = new ArrayList<>();
    List<LinkSpec> links = new ArrayList<>();
    links.add(new LinkSpec("base", List.of()));
    for (int i = 0; i < 6; i++) {
      Transform origin = i == 0 ? Transform.IDENTITY
          : Transform.translation(0, 0, d[i - 1]).compose(Transform.translation(a[i - 1], 0, 0))
              .compose(Transform.rotation(1, 0, 0, alpha[i - 1]));
      joints.add(new JointSpec("J" + (i + 1), origin, Vec3.Z, -lim, lim, Math.PI));
      links.add(new LinkSpec("link" + (i + 1), List.of()));
    }
    return RobotModel.fromChain(id, id, joints, Transform.translation(0, 0, d[5]), Transform.IDENTITY, links, false);
  }

  static RobotModel oblique() {
    return dhArm("ur-oblique", new double[] {120, 60, -25, 110, 95, 80}, new double[] {30, -425, -392, 0, 0, 0},
        new double[] {1.3, 0, 0, 1.2, -1.1, 0}, 2 * Math.PI);
  }

  @Test
  void anObliqueArmOfTheFamilyGetsTheClosedFormAndEveryPoseComesBack() {
    RobotModel m = oblique();
    assertThat(IkSolver.kindFor(m)).isEqualTo(UrTypeIk.KIND);
    assertThat(m.wristKind()).isEqualTo("parallel");
    UrTypeIk ik = new UrTypeIk(m);
    int eightBranches = 0;
    for (double[] q : IkSolverContractTest.samples(m, 91, 12)) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      String what = "pose of " + Arrays.toString(q);
      List<double[]> base = ik.baseSolutions(X);
      assertThat(base.size()).as(what).isBetween(1, UrTypeIk.BASE_SOLUTIONS);
      assertThat(base.stream().anyMatch(s -> OffsetWristCompletenessTest.wrappedDiff(s, q) < 1e-6)).as("%s: its joints", what).isTrue();
      Set<String> flags = new HashSet<>();
      for (double[] s : base) {
        Transform Y = ForwardKinematics.flangePoseInBase(m, s);
        assertThat(Y.distanceTo(X)).as("%s: solution %s", what, Arrays.toString(s)).isLessThan(1e-6);
        assertThat(Y.rotationAngleTo(X)).isLessThan(1e-9);
        Config c = ik.configOf(s);
        flags.add(c.toString().substring(0, 5));
        // Solving by that CONFIG near the solution gives it back.
        IkResult r = ik.solve(X, c, s);
        assertThat(r).as("%s: solve %s", what, c).isInstanceOf(IkResult.Solved.class);
        assertThat(OffsetWristCompletenessTest.wrappedDiff(((IkResult.Solved) r).q(), s)).as("%s: solve %s", what, c).isLessThan(1e-6);
        assertThat(ik.configOf(((IkResult.Solved) r).q()).sameBranch(c)).isTrue();
      }
      assertThat(flags).as("%s: one flag triple per branch", what).hasSize(base.size());
      if (base.size() == UrTypeIk.BASE_SOLUTIONS) {
        eightBranches++;
      }
      IkResult near = ik.solveNearest(X, q);
      assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), q)).as("%s: nearest", what).isLessThan(1e-6);
      IkResult.Solved ns = (IkResult.Solved) near;
      assertThat(ns.positionErrorMm()).isCloseTo(ForwardKinematics.flangePoseInBase(m, ns.q()).distanceTo(X),
          org.assertj.core.api.Assertions.within(1e-9));
    }
    assertThat(eightBranches).as("poses with all eight branches").isGreaterThan(0);
  }

  @Test
  void aFullTurnOfJ1J4OrJ6ChangesOnlyItsTurnNumber() {
    // CONFIG (docs/kinematics.md): the F/N, U/D, T/B flags belong to the branch, the turn numbers
    // to J1, J4 and J6 alone: a full turn of one of them changes its turn number by one and nothing else.
    RobotModel m = oblique();
    UrTypeIk ik = new UrTypeIk(m);
    for (double[] q : IkSolverContractTest.samples(m, 92, 10)) {
      Config c = ik.configOf(q);
      for (int j : new int[] {0, 3, 5}) {
        double[] t = q.clone();
        t[j] += 2 * Math.PI;
        Config ct = ik.configOf(t);
        assertThat(ct.sameBranch(c)).as("J%d turned a full turn", j + 1).isTrue();
        assertThat(new int[] {ct.turn1(), ct.turn4(), ct.turn6()})
            .containsExactly(c.turn1() + (j == 0 ? 1 : 0), c.turn4() + (j == 3 ? 1 : 0), c.turn6() + (j == 5 ? 1 : 0));
      }
    }
  }

  @Test
  void aWristWhoseAxesMissEachOtherIsNotOfTheFamily() {
    // UR5 with d6's joint frame pushed 1 mm sideways: J5 and J6 no longer meet (the loose
    // tolerance is 0.05 mm), so neither closed form applies.
    RobotModel ur5 = IkSolverContractTest.ur5(Math.PI);
    List<JointSpec> js = new ArrayList<>(ur5.joints());
    JointSpec j6 = js.get(5);
    js.set(5, new JointSpec(j6.name(), Transform.translation(1, 0, 0).compose(j6.X_PJ()), j6.axis(), j6.lowerRad(),
        j6.upperRad(), j6.maxSpeedRadPerSec()));
    RobotModel off = RobotModel.fromChain("ur5-off", "UR5 off", js, ur5.X_6F(), ur5.X_WB(), ur5.links(), false);
    assertThat(UrTypeIk.applies(off)).isFalse();
    assertThat(IkSolver.kindFor(off)).isEqualTo(NumericSolver.KIND);
    org.assertj.core.api.Assertions.assertThatThrownBy(() -> new UrTypeIk(off))
        .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("ur5-off: not a three-parallel-axes arm");
  }
}
