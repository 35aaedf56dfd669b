package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * The closed form's answers per CONFIG where the geometry decides them (docs/kinematics.md):
 * with the arm stretched forward, only the front (T) side reaches, so asking B is out of reach
 * "only the other arm side reaches it" and every listed solution is T; at the wrist singularity
 * (J5 = 0) F and N are the same posture and both are solved; a CONFIG whose J4 falls outside
 * narrowed limits names the joint, the value it would need and the limits, in degrees.
 */
class ClosedFormBranchTest {
  static final RobotModel LRMATE = RobotDefinitions.load("lrmate200id");

  @Test
  void stretchedForwardOnlyTheFrontSideReaches() {
    // The elbow 0.01 rad short of stretched and J2 leaning 1 rad forward: the wrist centre is
    // within a few mm of the arm's reach from the front shoulder, and 100 mm (2·a1) farther from
    // where the shoulder sits when J1 turns half a turn to reach over the top.
    double[] q = {0.2, 1.0, NumericIkCoverageTest.stretchedElbowJ3() - 0.01, 0.3, -0.6, 0.1};
    Transform X = ForwardKinematics.flangePoseInBase(LRMATE, q);
    ClosedFormIk ik = new ClosedFormIk(LRMATE);
    Config c = ik.configOf(q);
    assertThat(c.top()).isTrue();
    IkResult front = ik.solve(X, c);
    IkSolverContractTest.reaches(LRMATE, ((IkResult.Solved) front).q(), X, "front");
    for (boolean up : new boolean[] {true, false}) {
      for (boolean flip : new boolean[] {true, false}) {
        Config back = new Config(flip, up, false, 0, 0, 0);
        IkResult r = ik.solve(X, back);
        assertThat(r).as("%s", back).isInstanceOf(IkResult.Unreachable.class);
        assertThat(((IkResult.Unreachable) r).reason()).isEqualTo(IkResult.Reason.OUT_OF_REACH);
        assertThat(((IkResult.Unreachable) r).message())
            .isEqualTo("the pose is out of reach in CONFIG '" + back + "' (only the other arm side reaches it)");
      }
    }
    List<IkSolver.Solution> all = ik.allSolutions(X);
    assertThat(all).isNotEmpty().allSatisfy(s -> assertThat(s.config().top()).isTrue());
    // A base solution mask with only the front arm's four bits.
    double[] out = new double[48];
    int valid = ik.solveAllBase(X, out);
    assertThat(valid).isEqualTo(0b1111);
    for (int k = 0; k < 4; k++) {
      Transform Y = ForwardKinematics.flangePoseInBase(LRMATE, java.util.Arrays.copyOfRange(out, 6 * k, 6 * k + 6));
      assertThat(Y.distanceTo(X)).as("base solution %d", k).isLessThan(1e-6);
    }
    // 10 mm farther out no side reaches.
    Transform beyond = X.withTranslation(X.x() * 1.03, X.y() * 1.03, X.z());
    IkResult r = ik.solve(beyond, c);
    assertThat(((IkResult.Unreachable) r).message()).contains("is out of reach: the wrist centre is beyond the arm's reach");
    assertThat(ik.solveAllBase(beyond, out)).isZero();
  }

  @Test
  void atTheWristSingularityFAndNAreTheSamePostureAndBothSolve() {
    ClosedFormIk ik = new ClosedFormIk(LRMATE);
    double[] q = {0.4, 0.3, -0.2, 0.7, 0, -0.5};
    Transform X = ForwardKinematics.flangePoseInBase(LRMATE, q);
    for (boolean flip : new boolean[] {true, false}) {
      Config c = new Config(flip, true, true, 0, 0, 0);
      IkResult r = ik.solve(X, c);
      assertThat(r).as("%s", c).isInstanceOf(IkResult.Solved.class);
      double[] got = ((IkResult.Solved) r).q();
      IkSolverContractTest.reaches(LRMATE, got, X, c.toString());
      assertThat(Math.abs(ClosedFormIk.wrap(got[4]))).as("J5 of %s", c).isLessThan(1e-9);
      // Only J4 + J6 is fixed there (both turn about the same line, J4 and J6 about −x).
      assertThat(ClosedFormIk.wrap(got[3] + got[5] - q[3] - q[5])).isCloseTo(0, org.assertj.core.api.Assertions.within(1e-9));
    }
    // The nearest solution keeps the arm's own J4 and J6.
    IkResult near = ik.solveNearest(X, q);
    assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), q)).isLessThan(1e-9);
  }

  @Test
  void aConfigWhoseJ4IsOutsideNarrowedLimitsNamesTheJointTheValueAndTheLimits() {
    double[] q = {0.3, 0.2, -0.3, 0.4, -0.8, 0.5};
    RobotModel narrow = IkSolverContractTest.narrowed(LRMATE, 3, 0.3, 0.5);
    ClosedFormIk ik = new ClosedFormIk(narrow);
    Transform X = ForwardKinematics.flangePoseInBase(narrow, q);
    Config c = ik.configOf(q);
    // The other wrist of the same arm: J4 half a turn away (0.4 − π), J5 and J6 mirrored.
    Config other = new Config(!c.flip(), c.up(), c.top(), 0, 0, 0);
    IkResult r = ik.solve(X, other);
    assertThat(((IkResult.Unreachable) r).reason()).isEqualTo(IkResult.Reason.JOINT_LIMIT);
    assertThat(((IkResult.Unreachable) r).message()).isEqualTo(String.format(Locale.ROOT,
        "CONFIG '%s' needs J4 = %.1f deg, outside %.1f..%.1f deg", other, Math.toDegrees(0.4 - Math.PI),
        Math.toDegrees(0.3), Math.toDegrees(0.5)));
    IkResult ok = ik.solve(X, c);
    assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) ok).q(), q)).isLessThan(1e-9);
    // Nearest: only the in-limit wrist is a candidate, whatever the start.
    IkResult near = ik.solveNearest(X, new double[] {0.3, 0.2, -0.3, 0.4 - Math.PI, 0.8, 0.5 - Math.PI});
    assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), q)).isLessThan(1e-9);
  }
}
