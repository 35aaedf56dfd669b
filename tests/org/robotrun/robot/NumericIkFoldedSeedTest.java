package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * A target that only the folded seeds reach (docs/kinematics.md, numeric restarts: 16 seeds with
 * J2 in the top 3 % of its range, J3 in the bottom 3 %, J1 near a limit): on the LR Mate, J1 at
 * +170°, J2 at +120.7°, J3 at its −70° limit, the wrist nearly in line (J5 = −0.001 rad) and J6
 * 2π − 0.05 rad. It was found by a sweep like NumericIkCoverageTest's corners (which this class
 * keeps running under mutation testing, where that sweep is left out); the closed form lists the
 * pose, so the numeric solver must reach it from home and from the far side of every range.
 */
class NumericIkFoldedSeedTest {
  static final RobotModel ROBOT = RobotDefinitions.defaultRobot();

  @Test
  void aFoldedCornerWithJ1AtItsLimitIsSolvedFromHomeAndFromFarAway() {
    double[] q = {2.9660597283903605, 2.106314706095663, -1.2217304763960306, -1.7640897797272361, -0.001, 6.233185307179586};
    Transform X = ForwardKinematics.flangePoseInBase(ROBOT, q);
    assertThat(new ClosedFormIk(ROBOT).allSolutions(X)).isNotEmpty();
    assertThat(ROBOT.firstJointOutsideLimits(q)).isEqualTo(-1);
    double[] lo = ROBOT.lowerLimits();
    double[] hi = ROBOT.upperLimits();
    double[] far = new double[6];
    for (int i = 0; i < 6; i++) {
      double mid = 0.5 * (lo[i] + hi[i]);
      far[i] = q[i] > mid ? lo[i] + 0.25 * (hi[i] - lo[i]) : hi[i] - 0.25 * (hi[i] - lo[i]);
    }
    NumericIk ik = new NumericIk(ROBOT);
    for (double[] start : new double[][] {new double[6], far}) {
      NumericIkSpecTest.exact(ROBOT, ik.solve(X, start), X, 1e-6, 1e-9, "from " + Arrays.toString(start));
    }
  }
}
