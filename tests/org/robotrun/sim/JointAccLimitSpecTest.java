package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * docs/motion.md: "ACCn scales the acceleration (ACC50 accelerates half as hard; at most ACC150,
 * and joint moves never above the joint limit)". A J move at ACC150 therefore takes exactly as long
 * as at ACC100 (each joint still needs 0.25 s to its data-sheet speed), while an L move at ACC150
 * ramps in 0.2 / 1.5 s. Durations are computed with {@link MotionTimingSpecTest}'s trapezoids from
 * the data sheet; a measured time is within two 4 ms ticks of them.
 */
class JointAccLimitSpecTest {
  @Test
  void acc150NeverTakesAJointPastItsAccelerationLimit() {
    double[] home = MotionTimingSpecTest.HOME;
    double[] j1j4 = MotionTimingSpecTest.J1J4;
    List<Double> t = MotionTimingSpecTest.durations(100, "J P[1:HOME] 100% FINE", "J P[7:J1J4] 100% FINE ACC150",
        "J P[1:HOME] 100% FINE ACC100", "L P[2:A] 500mm/sec FINE", "L P[3:B] 500mm/sec FINE ACC150");
    double atLimit = MotionTimingSpecTest.jointMoveSec(home, j1j4, 100, 100);
    assertThat(MotionTimingSpecTest.jointMoveSec(home, j1j4, 100, 150)).isCloseTo(atLimit, offset(1e-12));
    assertThat(t.get(1)).isCloseTo(atLimit, offset(MotionTimingSpecTest.TICKS_2));
    assertThat(t.get(2)).isCloseTo(atLimit, offset(MotionTimingSpecTest.TICKS_2));
    // an L move does use ACC150: 270 mm at 500 mm/s, reached in 0.2 / 1.5 s
    double ab = MotionTimingSpecTest.A.distanceTo(MotionTimingSpecTest.B);
    assertThat(t.get(4)).isCloseTo(MotionTimingSpecTest.trapezoid(ab, 500, 500 * 1.5 / 0.2),
        offset(MotionTimingSpecTest.TICKS_2));
  }
}
