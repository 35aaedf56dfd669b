package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The small answers around the solvers, each against a value worked out here: the rotation angle
 * between two orientations (a rotation by a known angle about a known axis, down to 1e-9 rad where
 * the documented "accurate near 0" matters), the closed form's quick reachability verdict that the
 * numeric solver uses (reachable, beyond reach, reachable only outside a narrowed J1, the wrist centre
 * on the J1 axis where J1 is free), a solution's printed form (degrees), and the numeric solver
 * behind {@link IkSolver} on an arm with no closed form.
 */
class IkVerdictOracleTest {
  static final RobotModel LRMATE = RobotDefinitions.load("lrmate200id");

  static double[] packed(Transform x) {
    double[] a = new double[12];
    KinematicChain.pack(x, a, 0);
    return a;
  }

  @Test
  void rotationAngleIsTheAngleOfTheRelativeRotationAccurateNearZero() {
    Random rnd = new Random(61);
    for (int k = 0; k < 200; k++) {
      Vec3 a = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalized();
      Vec3 axis = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalized();
      Transform base = Transform.rotation(a.x(), a.y(), a.z(), rnd.nextDouble() * Math.PI);
      // Angles from 1e-9 rad (the precision the solvers report errors at) to a half turn.
      double theta = k < 40 ? Math.pow(10, -9 + 8 * rnd.nextDouble()) : rnd.nextDouble() * Math.PI;
      Transform turned = base.compose(Transform.rotation(axis.x(), axis.y(), axis.z(), theta));
      double got = ClosedFormIk.rotationAngle(packed(base), packed(turned));
      assertThat(got).as("angle %.3e about %s", theta, axis).isCloseTo(theta, within(1e-12 + 1e-9 * theta));
      assertThat(ClosedFormIk.rotationAngle(packed(turned), packed(base))).isCloseTo(theta, within(1e-12 + 1e-9 * theta));
      // The position part plays no role.
      assertThat(ClosedFormIk.rotationAngle(packed(base.withTranslation(100, -200, 300)), packed(turned)))
          .isCloseTo(theta, within(1e-12 + 1e-9 * theta));
    }
    assertThat(ClosedFormIk.rotationAngle(packed(Transform.IDENTITY), packed(Transform.IDENTITY))).isZero();
    assertThat(ClosedFormIk.rotationAngle(packed(Transform.IDENTITY), packed(Transform.rotation(0, 0, 1, Math.PI))))
        .isCloseTo(Math.PI, within(1e-15));
  }

  @Test
  void reachabilityIsEmptyForAReachedPoseAndOutOfReachBeyondIt() {
    ClosedFormIk ik = new ClosedFormIk(LRMATE);
    Random rnd = new Random(62);
    for (int k = 0; k < 20; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = LRMATE.joint(i).lowerRad() + rnd.nextDouble() * (LRMATE.joint(i).upperRad() - LRMATE.joint(i).lowerRad());
      }
      Transform X = ForwardKinematics.flangePoseInBase(LRMATE, q);
      assertThat(ik.reachability(packed(X))).as("reached by %s", java.util.Arrays.toString(q)).isEmpty();
      // 1000 mm farther out along the line from the shoulder: beyond the 717 mm arm (330 + 35 + 335 + 80 mm, loosely).
      Vec3 p = X.translationVector();
      Vec3 out = new Vec3(p.x(), p.y(), 0).normalized().times(1200);
      Optional<IkResult.Unreachable> r = ik.reachability(packed(X.withTranslation(out.x(), out.y(), p.z())));
      assertThat(r).isPresent();
      assertThat(r.get().reason()).isEqualTo(IkResult.Reason.OUT_OF_REACH);
      assertThat(r.get().message()).contains("out of reach");
    }
    // Every joint at a limit: a solution there counts (the verdict errs toward "maybe").
    double[] atLimits = new double[6];
    for (int i = 0; i < 6; i++) {
      atLimits[i] = i % 2 == 0 ? LRMATE.joint(i).upperRad() : LRMATE.joint(i).lowerRad();
    }
    atLimits[4] = Math.toRadians(-60);
    assertThat(ik.reachability(packed(ForwardKinematics.flangePoseInBase(LRMATE, atLimits)))).isEmpty();
  }

  @Test
  void reachableOnlyOutsideANarrowedJ1IsAJointLimitVerdict() {
    // The LR Mate's wrist centre lies in J1's plane (b = 0), so its two J1 values are a half turn
    // apart: with J1 held to [q1 + 1.0, q1 + 1.05] rad neither fits (1 rad and pi - 1 rad away).
    double[] q = {0.3, 0.2, -0.3, 0.4, -0.8, 0.5};
    Transform X = ForwardKinematics.flangePoseInBase(LRMATE, q);
    RobotModel narrow = IkSolverContractTest.narrowed(LRMATE, 0, q[0] + 1.0, q[0] + 1.05);
    Optional<IkResult.Unreachable> r = new ClosedFormIk(narrow).reachability(packed(X));
    assertThat(r).isPresent();
    assertThat(r.get().reason()).isEqualTo(IkResult.Reason.JOINT_LIMIT);
    assertThat(r.get().message()).contains("every solution has a joint outside its limits");
    // J1 narrowed around the truth keeps it reachable; a band 1e-7 rad beside it too (the slack).
    assertThat(new ClosedFormIk(IkSolverContractTest.narrowed(LRMATE, 0, q[0] - 0.01, q[0] + 0.01)).reachability(packed(X)))
        .isEmpty();
    assertThat(new ClosedFormIk(IkSolverContractTest.narrowed(LRMATE, 0, q[0] + 1e-7, q[0] + 0.01)).reachability(packed(X)))
        .isEmpty();
    assertThat(new ClosedFormIk(IkSolverContractTest.narrowed(LRMATE, 0, q[0] + 1e-4, q[0] + 0.01)).reachability(packed(X)))
        .isPresent();
    // And the numeric solver gives the same verdict without iterating through all its seeds.
    IkResult n = new NumericIk(narrow).solve(X, new double[] {q[0] + 1.02, 0, 0, 0, -0.5, 0});
    assertThat(n).isInstanceOf(IkResult.Unreachable.class);
    assertThat(((IkResult.Unreachable) n).reason()).isEqualTo(IkResult.Reason.JOINT_LIMIT);
  }

  @Test
  void aWristCentreOnTheJ1AxisLeavesJ1FreeSoTheVerdictIsMaybe() {
    // A witness: J1 = 1.02 rad and J2 leaned back until the wrist centre (J5's origin) is on the
    // J1 axis (bisection on its distance in front of the axis). Turning J1 then moves nothing but
    // the wrist's orientation, so the verdict must not hang on J1's limits.
    double[] q = {1.02, 0, 0.3, 0.4, -0.9, 0.5};
    double lo = -1.5, hi = 0;
    for (int it = 0; it < 200; it++) {
      q[1] = 0.5 * (lo + hi);
      Vec3 w = ForwardKinematics.linkPosesInBase(LRMATE, q)[5].translationVector();
      if (w.x() * Math.cos(q[0]) + w.y() * Math.sin(q[0]) > 0) {
        hi = q[1];
      } else {
        lo = q[1];
      }
    }
    Transform Xw = ForwardKinematics.flangePoseInBase(LRMATE, q);
    // The same pose with the wrist centre exactly on the axis (position = c4 along the approach axis).
    double c4 = LRMATE.opw().orElseThrow().c4();
    Transform X = Xw.withTranslation(c4 * Xw.r02(), c4 * Xw.r12(), Xw.z());
    assertThat(Xw.distanceTo(X)).as("the witness reaches it").isLessThan(1e-6);
    RobotModel narrow = IkSolverContractTest.narrowed(LRMATE, 0, 1.0, 1.05);
    assertThat(narrow.firstJointOutsideLimits(q)).isEqualTo(-1);
    assertThat(new ClosedFormIk(narrow).reachability(packed(X))).isEmpty();
    // 1 mm off the axis J1 is fixed again (azimuth 0 or a half turn), and the band excludes it.
    Transform off = X.withTranslation(X.x() + 1, X.y(), X.z());
    assertThat(new ClosedFormIk(narrow).reachability(packed(off))).isPresent();
  }

  @Test
  void aJointLimitIsInclusiveAndTheFirstJointOutsideIsNamed() {
    JointSpec j = LRMATE.joint(1);
    assertThat(j.withinLimits(j.lowerRad())).isTrue();
    assertThat(j.withinLimits(j.upperRad())).isTrue();
    assertThat(j.withinLimits(Math.nextDown(j.lowerRad()))).isFalse();
    assertThat(j.withinLimits(Math.nextUp(j.upperRad()))).isFalse();
    assertThat(j.withinLimits(Double.NaN)).isFalse();
    double[] q = new double[6];
    assertThat(LRMATE.firstJointOutsideLimits(q)).isEqualTo(-1);
    q[4] = LRMATE.joint(4).upperRad() + 1e-12;
    q[5] = LRMATE.joint(5).upperRad() + 1;
    assertThat(LRMATE.firstJointOutsideLimits(q)).isEqualTo(4);
  }

  @Test
  void aSolutionPrintsItsJointsInDegrees() {
    IkResult.Solved s = new IkResult.Solved(new double[] {Math.PI / 2, -Math.PI / 4, 0, Math.PI, 0.5, -1}, 1.5e-7, 2.5e-10, 7);
    assertThat(s.toString()).isEqualTo(
        "Solved[q=(90.0000, -45.0000, 0.0000, 180.0000, 28.6479, -57.2958) deg, error 1.50e-07 mm 2.50e-10 rad, 7 iterations]");
  }

  @Test
  void theNumericSolverBehindIkSolverSolvesFromTheGivenJointsAndListsOneSolution() {
    RobotModel m = KinematicChainOracleTest.obliqueArm();
    IkSolver ik = IkSolver.forModel(m);
    assertThat(ik.kind()).isEqualTo(NumericSolver.KIND);
    assertThat(ik.model()).isSameAs(m);
    Random rnd = new Random(63);
    for (int k = 0; k < 5; k++) {
      double[] q = NumericIkSpecTest.random(m, rnd);
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      double[] near = q.clone();
      for (int i = 0; i < 6; i++) {
        near[i] = Math.max(m.joint(i).lowerRad(), Math.min(m.joint(i).upperRad(), near[i] + 0.02));
      }
      // From joints a hundredth of a radian off, the iteration lands on the joints that made the pose.
      for (IkResult r : List.of(ik.solveNearest(X, near), ik.solve(X, ik.configOf(q), near))) {
        NumericIkSpecTest.exact(m, r, X, 1e-6, 1e-9, "oblique " + k);
        assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) r).q(), q)).isLessThan(1e-6);
      }
      List<IkSolver.Solution> all = ik.allSolutions(X);
      assertThat(all).hasSize(1);
      IkSolverContractTest.reaches(m, all.get(0).q(), X, "oblique listed " + k);
      assertThat(all.get(0).config()).isEqualTo(ik.configOf(all.get(0).q()));
    }
    // The oblique arm's CONFIG is the geometric one: F/N is the sign of J5.
    assertThat(ik.configOf(new double[] {0, 0.2, 0.3, 0, 0.4, 0}).flip()).isTrue();
    assertThat(ik.configOf(new double[] {0, 0.2, 0.3, 0, -0.4, 0}).flip()).isFalse();
    assertThat(ik.configOf(new double[] {0, 0.2, 0.3, 0, -0.4, 4.0}).turn6()).isEqualTo(1);
    Transform far = Transform.translation(5000, 4000, 3000);
    assertThat(ik.allSolutions(far)).isEmpty();
    assertThat(ik.solveNearest(far, new double[6])).isInstanceOf(IkResult.Unreachable.class);
  }
}
