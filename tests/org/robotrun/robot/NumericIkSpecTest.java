package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * The numeric solver against its documented settings (NumericIk.Settings.defaults: converged below
 * 1e-6 mm and 1e-9 rad; 2000 iterations in all; from a random start a median of about 15
 * iterations): each answer's error is measured here by forward kinematics of the joints it returns,
 * and must be within the tolerance whatever iteration count led there; starts half a turn away
 * about each base axis; the reported errors are the measured ones; a looser tolerance is honoured
 * and a tiny iteration cap is never exceeded; the oblique arm of KinematicChainOracleTest (no
 * closed form) solves too.
 */
class NumericIkSpecTest {
  static final RobotModel LRMATE = RobotDefinitions.defaultRobot();

  static void exact(RobotModel m, IkResult r, Transform X, double tolMm, double tolRad, String what) {
    assertThat(r).as(what).isInstanceOf(IkResult.Solved.class);
    IkResult.Solved s = (IkResult.Solved) r;
    Transform Y = ForwardKinematics.flangePoseInBase(m, s.q());
    assertThat(Y.distanceTo(X)).as("%s position", what).isLessThan(tolMm);
    assertThat(Y.rotationAngleTo(X)).as("%s orientation", what).isLessThan(tolRad);
    // The reported errors are the real ones.
    assertThat(s.positionErrorMm()).as("%s reported mm", what).isCloseTo(Y.distanceTo(X), within(1e-9));
    assertThat(s.orientationErrorRad()).as("%s reported rad", what).isCloseTo(Y.rotationAngleTo(X), within(2e-9));
    assertThat(m.firstJointOutsideLimits(s.q())).as("%s in limits", what).isEqualTo(-1);
  }

  @Test
  void solutionsFromRandomStartsMeetTheToleranceInFewIterations() {
    NumericIk ik = new NumericIk(LRMATE);
    Random rnd = new Random(41);
    int[] iterations = new int[60];
    for (int k = 0; k < iterations.length; k++) {
      double[] q = random(LRMATE, rnd);
      double[] start = random(LRMATE, rnd);
      Transform X = ForwardKinematics.flangePoseInBase(LRMATE, q);
      IkResult r = ik.solve(X, start);
      exact(LRMATE, r, X, 1e-6, 1e-9, "target " + k);
      iterations[k] = ((IkResult.Solved) r).iterations();
      assertThat(iterations[k]).isBetween(1, 2000);
    }
    Arrays.sort(iterations);
    // Documented: a median of about 15 from a random start.
    assertThat(iterations[iterations.length / 2]).isLessThanOrEqualTo(25);
  }

  @Test
  void aStartHalfATurnAwayAboutEachBaseAxisStillConverges() {
    // J6 turned by 180° from the target's joints: the orientation error is a half turn about J6's
    // axis, which lies along base −z (J5 = −90°, J1 = 0), base y (J1 = 90°... wrist down, turned)
    // or base x (q = 0: the flange looks along +x).
    double[][] targets = {
      {0, 0, 0, 0, Math.toRadians(-90), 0},
      {Math.toRadians(90), 0, 0, 0, Math.toRadians(-90), 0.3},
      {0, 0.1, -0.1, 0, 0, 0.2},
      {0.4, 0.2, 0.1, 0.3, -0.7, -0.5},
    };
    NumericIk ik = new NumericIk(LRMATE);
    for (double[] q : targets) {
      Transform X = ForwardKinematics.flangePoseInBase(LRMATE, q);
      double[] start = q.clone();
      start[5] += Math.PI;
      IkResult r = ik.solve(X, start);
      exact(LRMATE, r, X, 1e-6, 1e-9, "half turn from " + Arrays.toString(q));
      // Near start (a millidegree off each joint): a handful of Newton steps.
      double[] near = q.clone();
      for (int i = 0; i < 6; i++) {
        near[i] += 1e-5;
      }
      IkResult n = ik.solve(X, near);
      exact(LRMATE, n, X, 1e-6, 1e-9, "near " + Arrays.toString(q));
      assertThat(((IkResult.Solved) n).iterations()).isLessThanOrEqualTo(6);
      // Already there: solved at once.
      IkResult there = ik.solve(X, q);
      exact(LRMATE, there, X, 1e-6, 1e-9, "at " + Arrays.toString(q));
      assertThat(((IkResult.Solved) there).iterations()).isLessThanOrEqualTo(2);
    }
  }

  @Test
  void aLooserToleranceIsHonouredAndACapIsNeverExceeded() {
    Transform X = ForwardKinematics.flangePoseInBase(LRMATE, new double[] {0.5, 0.3, -0.2, 0.4, -0.9, 0.7});
    double[] start = {0, 0, 0, 0, -0.5, 0};
    NumericIk loose = new NumericIk(LRMATE, new NumericIk.Settings(0.5, 1e-3, 20, 2000, 20_000_000, 300, 0.1, 0.95));
    IkResult r = loose.solve(X, start);
    assertThat(r).isInstanceOf(IkResult.Solved.class);
    IkResult.Solved s = (IkResult.Solved) r;
    Transform Y = ForwardKinematics.flangePoseInBase(LRMATE, s.q());
    assertThat(Y.distanceTo(X)).isLessThan(0.5);
    assertThat(Y.rotationAngleTo(X)).isLessThan(1e-3);
    IkResult tight = new NumericIk(LRMATE).solve(X, start);
    assertThat(((IkResult.Solved) tight).iterations()).isGreaterThanOrEqualTo(s.iterations());
    // Three iterations in all: an answer within them or none.
    NumericIk capped = new NumericIk(LRMATE, new NumericIk.Settings(1e-6, 1e-9, 1, 3, 20_000_000, 300, 0.1, 0.95));
    IkResult c = capped.solve(X, start);
    if (c instanceof IkResult.Solved cs) {
      assertThat(cs.iterations()).isLessThanOrEqualTo(3);
    } else {
      assertThat(((IkResult.Unreachable) c).reason()).isEqualTo(IkResult.Reason.NO_CONVERGENCE);
    }
    assertThatThrownBy(() -> new NumericIk.Settings(0, 1e-9, 20, 2000, 1, 300, 0.1, 0.95)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new NumericIk.Settings(1e-6, 0, 20, 2000, 1, 300, 0.1, 0.95)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new NumericIk.Settings(1e-6, 1e-9, 0, 2000, 1, 300, 0.1, 0.95)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new NumericIk.Settings(1e-6, 1e-9, 20, 0, 1, 300, 0.1, 0.95)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new NumericIk.Settings(1e-6, 1e-9, 20, 2000, 0, 300, 0.1, 0.95)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new NumericIk.Settings(1e-6, 1e-9, 20, 2000, 1, 0, 0.1, 0.95)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new NumericIk.Settings(1e-6, 1e-9, 20, 2000, 1, 300, -0.1, 0.95)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new NumericIk.Settings(1e-6, 1e-9, 20, 2000, 1, 300, 0.1, 0)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new NumericIk.Settings(1e-6, 1e-9, 20, 2000, 1, 300, 0.1, 1.01)).isInstanceOf(IllegalArgumentException.class);
    assertThat(new NumericIk.Settings(1e-6, 1e-9, 20, 2000, 1, 300, 0, 1).stallRatio()).isEqualTo(1);
    assertThatThrownBy(() -> new NumericIk(LRMATE).solve(X, new double[5])).isInstanceOf(IllegalArgumentException.class);
  }

  @Test
  void theObliqueArmSolvesNumerically() {
    RobotModel m = KinematicChainOracleTest.obliqueArm();
    assertThat(IkSolver.kindFor(m)).isEqualTo(NumericSolver.KIND);
    NumericIk ik = new NumericIk(m);
    Random rnd = new Random(42);
    int solved = 0;
    for (int k = 0; k < 20; k++) {
      double[] q = random(m, rnd);
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      double[] start = q.clone();
      for (int i = 0; i < 6; i++) {
        start[i] += 0.3 * (rnd.nextDouble() - 0.5);
        start[i] = Math.max(m.joint(i).lowerRad(), Math.min(m.joint(i).upperRad(), start[i]));
      }
      IkResult r = ik.solve(X, start);
      if (r instanceof IkResult.Solved) {
        exact(m, r, X, 1e-6, 1e-9, "oblique " + k);
        solved++;
      }
    }
    // Every target is reachable (made by FK inside the limits); the seeds find them all.
    assertThat(solved).isEqualTo(20);
    // And packed input is the same as a Transform.
    double[] q = random(m, rnd);
    Transform X = ForwardKinematics.flangePoseInBase(m, q);
    double[] packed = new double[12];
    KinematicChain.pack(X, packed, 0);
    exact(m, ik.solve(packed, q), X, 1e-6, 1e-9, "packed");
  }

  static double[] random(RobotModel m, Random rnd) {
    double[] q = new double[6];
    for (int i = 0; i < 6; i++) {
      double lo = Math.max(m.joint(i).lowerRad(), -Math.PI);
      double hi = Math.min(m.joint(i).upperRad(), Math.PI);
      q[i] = lo + rnd.nextDouble() * (hi - lo);
    }
    return q;
  }
}
