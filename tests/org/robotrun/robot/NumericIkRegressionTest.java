package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Angles;
import org.robotrun.math.Transform;

/**
 * Issue 18's targets that the numeric solver once missed, each a few solves (so they also run
 * under mutation testing, where the sweeps of {@link NumericIkCoverageTest} are left out): the
 * corner with J2, J3 and J5 at their limits and the flange 37 mm from the J1 axis (found only
 * with J1 seeded toward the wrist point, docs/kinematics.md), the sweep failures found before
 * those seeds, and the wrist folded back over the base (found only from the edge seeds).
 */
class NumericIkRegressionTest {
  private static final RobotModel ROBOT = RobotDefinitions.defaultRobot();
  private final NumericIk numeric = new NumericIk(ROBOT);
  private final ClosedFormIk closed = new ClosedFormIk(ROBOT);

  /** The closed form lists the pose of q (inside the limits); the numeric solver reaches it from the start. */
  private void whatTheClosedFormFindsTheNumericSolverFindsToo(double[] q, int start) {
    Transform X_BF = ForwardKinematics.flangePoseInBase(ROBOT, q);
    assertThat(closed.allSolutions(X_BF)).isNotEmpty();
    double[] q0 = start == 0 ? new double[6] : farStart(q);
    IkResult r = numeric.solve(X_BF, q0);
    assertThat(r).as("target %s from %s", java.util.Arrays.toString(Angles.toDegrees(q)), start)
        .isInstanceOf(IkResult.Solved.class);
    double[] sol = ((IkResult.Solved) r).q();
    Transform reached = ForwardKinematics.flangePoseInBase(ROBOT, sol);
    assertThat(reached.distanceTo(X_BF)).isLessThan(1e-6);
    assertThat(reached.rotationAngleTo(X_BF)).isLessThan(1e-8);
    assertThat(ROBOT.firstJointOutsideLimits(sol)).isEqualTo(-1);
  }

  /** A start on the far side of each joint's range from the target (as NumericIkCoverageTest's). */
  private static double[] farStart(double[] q) {
    double[] lo = ROBOT.lowerLimits();
    double[] hi = ROBOT.upperLimits();
    double[] s = new double[6];
    for (int i = 0; i < 6; i++) {
      double mid = 0.5 * (lo[i] + hi[i]);
      s[i] = q[i] > mid ? lo[i] + 0.25 * (hi[i] - lo[i]) : hi[i] - 0.25 * (hi[i] - lo[i]);
    }
    return s;
  }

  @Test
  void theCornerWithThreeJointsAtTheirLimitsIsSolved() {
    // Issue 18's last open target: J2, J3 and J5 at their limits, the flange 37 mm from the J1
    // axis (its azimuth says nothing about J1), found from home and from a far start.
    double[] q = Angles.toRadians(new double[] {-36.8, 144.94, -69.99994, 148.5, 124.994, 183.8});
    whatTheClosedFormFindsTheNumericSolverFindsToo(q, 0);
    whatTheClosedFormFindsTheNumericSolverFindsToo(q, 1);
    // Found in a sweep like the corners property (seed 5), failing before the wrist-point seeds.
    whatTheClosedFormFindsTheNumericSolverFindsToo(Angles.toRadians(
        new double[] {-20.457721244213467, 145.0, -70.0, -136.5351702747399, 124.99427042204869, 359.42704220486917}), 1);
    whatTheClosedFormFindsTheNumericSolverFindsToo(Angles.toRadians(
        new double[] {-169.99999994270422, 145.0, -69.9999999427042, -94.90939477244062, 5.729577951308232E-6,
            -31.95938682729684}), 0);
    whatTheClosedFormFindsTheNumericSolverFindsToo(Angles.toRadians(
        new double[] {-19.716200312771914, 144.4270422048692, -69.42704220486917, 113.74214719533138, 91.40677199169157,
            -227.99100523391476}), 1);
  }

  @Test
  void theWristFoldedBackOverTheBaseIsSolvedFromHome() {
    // The reproducer of issue 18: J2 near +139 deg, J3 -68 deg, J4 +185 deg, the wrist folded back
    // over the base; tried over J1, J5, J6 on a grid.
    java.util.List<String> failures = new java.util.ArrayList<>();
    for (double j1 : new double[] {-150, -60, 0, 45, 120, 165}) {
      for (double j5 : new double[] {-120, -60, -10, 10, 60, 120}) {
        for (double j6 : new double[] {-300, 0, 170}) {
          double[] q = Angles.toRadians(new double[] {j1, 139, -68, 185, j5, j6});
          Transform X_BF = ForwardKinematics.flangePoseInBase(ROBOT, q);
          if (!(numeric.solve(X_BF, new double[6]) instanceof IkResult.Solved)) {
            failures.add(j1 + "/" + j5 + "/" + j6);
          }
        }
      }
    }
    assertThat(failures).isEmpty();
  }
}
