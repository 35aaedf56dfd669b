package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.math.Transform;

/**
 * An arm bolted on at a slant is the same arm: its CONFIG flags are defined in the arm's own
 * frames (the wrist point against the J1 axis, the elbow against the upper arm, the sign of J5:
 * docs/kinematics.md), so they cannot depend on where the base sits. Each solver family (the OPW
 * closed form on the LR Mate, the offset-wrist search on the CRX-10iA, the UR-type closed form on a
 * UR5 from its published DH) is built a second time with J1's frame moved by a rigid transform M
 * (turned 0.7 rad about the oblique axis (1, 2, −2)/3 and shifted), so that no joint axis lies
 * along a base axis. Expected here: FK of the mounted arm is M · FK (composed in the test); the
 * same solver family applies; every joint vector has the same CONFIG; the pose M · X has exactly
 * the solutions of X, with the same labels; solving by CONFIG and the nearest solution are the
 * same joints.
 */
class MountedArmInvarianceTest {
  static final Transform MOUNT = Transform.translation(120, -80, 45)
      .compose(Transform.rotation(1.0 / 3, 2.0 / 3, -2.0 / 3, 0.7));

  static Stream<String> arms() {
    return IkSolverContractTest.arms();
  }

  /** The model with J1's frame moved by {@code mount} (the base turned and shifted under the arm). */
  static RobotModel mounted(RobotModel m, Transform mount) {
    List<JointSpec> js = new ArrayList<>(m.joints());
    JointSpec j1 = js.get(0);
    js.set(0, new JointSpec(j1.name(), mount.compose(j1.X_PJ()), j1.axis(), j1.lowerRad(), j1.upperRad(),
        j1.maxSpeedRadPerSec()));
    return RobotModel.fromChain(m.id() + "-mounted", m.displayName(), js, m.X_6F(), m.X_WB(), m.links(), m.coupledJ3());
  }

  @ParameterizedTest
  @MethodSource("arms")
  void aSlantedMountChangesNeitherTheSolutionsNorTheirConfig(String id) {
    RobotModel m = IkSolverContractTest.arm(id);
    RobotModel mm = mounted(m, MOUNT);
    IkSolver plain = IkSolver.forModel(m);
    IkSolver slanted = IkSolver.forModel(mm);
    assertThat(slanted.kind()).as(id).isEqualTo(plain.kind());
    assertThat(mm.wristKind()).isEqualTo(m.wristKind());
    for (double[] q : IkSolverContractTest.samples(m, 410 + id.length(), 4)) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      Transform Y = MOUNT.compose(X);
      assertThat(ForwardKinematics.flangePoseInBase(mm, q).distanceTo(Y)).as("%s FK", id).isLessThan(1e-9);
      assertThat(slanted.configOf(q)).as("%s CONFIG of %s", id, java.util.Arrays.toString(q)).isEqualTo(plain.configOf(q));
      List<IkSolver.Solution> a = plain.allSolutions(X);
      List<IkSolver.Solution> b = slanted.allSolutions(Y);
      assertThat(b).as("%s solution count", id).hasSameSizeAs(a);
      for (IkSolver.Solution s : a) {
        assertThat(b.stream().anyMatch(o -> IkSolverContractTest.maxDiff(o.q(), s.q()) < 1e-6 && o.config().equals(s.config())))
            .as("%s: solution %s (%s) also on the slanted mount", id, java.util.Arrays.toString(s.q()), s.config()).isTrue();
      }
      for (IkSolver.Solution s : b) {
        IkSolverContractTest.reaches(mm, s.q(), Y, id + " slanted");
        assertThat(slanted.configOf(s.q())).isEqualTo(s.config());
      }
      Config c = plain.configOf(q);
      IkResult byConfig = slanted.solve(Y, c, new double[6]);
      assertThat(byConfig).as("%s solve %s", id, c).isInstanceOf(IkResult.Solved.class);
      assertThat(slanted.configOf(((IkResult.Solved) byConfig).q())).isEqualTo(c);
      IkSolverContractTest.reaches(mm, ((IkResult.Solved) byConfig).q(), Y, id + " by CONFIG");
      IkResult near = slanted.solveNearest(Y, q);
      assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), q)).as("%s nearest", id).isLessThan(1e-6);
      // The reported errors are the ones measured by FK.
      IkResult.Solved ns = (IkResult.Solved) near;
      Transform got = ForwardKinematics.flangePoseInBase(mm, ns.q());
      assertThat(ns.positionErrorMm()).isLessThan(1e-6).isCloseTo(got.distanceTo(Y), org.assertj.core.api.Assertions.within(1e-9));
      assertThat(ns.orientationErrorRad()).isLessThan(1e-9);
    }
  }

  @ParameterizedTest
  @MethodSource("arms")
  void everyFlagOfEveryBranchSurvivesTheMount(String id) {
    // All eight flag triples where the arm has them: the eight branches of one pose each keep their label.
    RobotModel m = IkSolverContractTest.arm(id);
    RobotModel mm = mounted(m, MOUNT);
    IkSolver plain = IkSolver.forModel(m);
    IkSolver slanted = IkSolver.forModel(mm);
    java.util.Set<String> seen = new java.util.HashSet<>();
    for (double[] q0 : IkSolverContractTest.samples(m, 420 + id.length(), 6)) {
      for (IkSolver.Solution s : plain.allSolutions(ForwardKinematics.flangePoseInBase(m, q0))) {
        assertThat(slanted.configOf(s.q())).as("%s %s", id, s.config()).isEqualTo(s.config());
        seen.add(s.config().toString().substring(0, 5));
      }
    }
    assertThat(seen).as("%s: flag triples met", id).hasSizeGreaterThanOrEqualTo(4);
  }
}
