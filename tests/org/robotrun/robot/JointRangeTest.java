package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;

/** The joint-limit helper the three closed-form solvers share. */
class JointRangeTest {
  private final RobotModel robot = RobotDefinitions.defaultRobot();
  private final JointRange range = new JointRange(robot);
  private final double lo = robot.joint(0).lowerRad();
  private final double hi = robot.joint(0).upperRad();

  @Test
  void roundOffOutsideALimitCountsAsInsideAndIsClampedOntoIt() {
    assertThat(range.ok(hi + 0.5e-9, 0)).isTrue();
    assertThat(range.ok(hi + 2e-9, 0)).isFalse();
    assertThat(range.ok(Double.NaN, 0)).isFalse();
    assertThat(range.clamp(hi + 0.5e-9, 0)).isEqualTo(hi);
    assertThat(range.clamp(lo - 0.5e-9, 0)).isEqualTo(lo);
    assertThat(range.clamp(Double.NaN, 0)).isNaN();
    double[] q = {hi + 1, lo - 1, 0, 0, 0, 0};
    assertThat(range.firstOutside(q)).isEqualTo(0);
    range.clampAll(q);
    assertThat(q[0]).isEqualTo(hi);
    assertThat(q[1]).isEqualTo(robot.joint(1).lowerRad());
    assertThat(range.firstOutside(q)).isEqualTo(-1);
  }

  @Test
  void theNearestTurnIsInsideTheLimitsAndClampedInEveryBranch() {
    double twoPi = 2 * Math.PI;
    // the turn nearest the reference
    assertThat(range.nearestTurn(0.1 + twoPi, 0, 0)).isCloseTo(0.1, org.assertj.core.data.Offset.offset(1e-12));
    // the nearest turn is outside, the next one down lies 1e-10 beyond the upper limit: clamped onto it
    double justOver = hi + 1e-10;
    assertThat(range.nearestTurn(justOver + twoPi, justOver + twoPi, 0)).isEqualTo(hi);
    // the same below the lower limit
    double justUnder = lo - 1e-10;
    assertThat(range.nearestTurn(justUnder - twoPi, justUnder - twoPi, 0)).isEqualTo(lo);
    // no turn inside: NaN
    double narrowLo = robot.joint(1).lowerRad(), narrowHi = robot.joint(1).upperRad();
    assertThat(narrowHi - narrowLo).isLessThan(twoPi - 0.1);
    assertThat(range.nearestTurn(narrowHi + 0.05, narrowHi + 0.05, 1)).isNaN();
  }

  @Test
  void intoLimitsTakesTheOtherTurnOrLeavesAValueWithNone() {
    double narrowHi = robot.joint(1).upperRad();
    assertThat(range.intoLimits(narrowHi + 1e-10, 1)).isEqualTo(narrowHi);
    assertThat(range.intoLimits(narrowHi + 0.05, 1)).isEqualTo(narrowHi + 0.05);
    // J1 (±170°): -175° is outside, its other turn +185° too; +175° likewise
    assertThat(range.intoLimits(Math.toRadians(-175), 0)).isEqualTo(Math.toRadians(-175));
    assertThat(JointRange.distance(new double[] {1, 2, 0, 0, 0, 0}, new double[] {0, 0, 0, 0, 0, 3})).isEqualTo(14);
  }
}
