package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

/**
 * docs/motion.md: a Cartesian move that has to crawl below 5 % of its speed for 0.5 s stops with
 * MOTN-023; docs/alarms.md: MOTN-023 is the wrist singularity "J5 near 0: J4 and J6 in line". The
 * crawl is made as in {@link MotionStallSpecTest} (J1's speed limit set to 0.1 % of what the line
 * needs), here with the wrist bent only 5°: the alarm names the wrist and J5, not a generic
 * singularity, and not MOTN-018 (the line is well within reach).
 */
class WristStallSpecTest {
  static final double V = 400;

  @Test
  void aCrawlWithJ5NearZeroStopsWithTheWristSingularityNamingJ5() {
    double[] q0 = {0, 0.3, -0.2, 0, Math.toRadians(-5), 0};
    Transform start = MotionRunnerTest.tcp(q0);
    double x = Math.hypot(start.x(), start.y());
    double[] v = MotionRunnerTest.LIMITS.jointMaxSpeedRadPerSec();
    double[] a = MotionRunnerTest.LIMITS.jointMaxAccelRadPerSec2();
    v[0] = 0.001 * V / x;
    a[0] = v[0] / MotionLimits.JOINT_ACCEL_TIME_SEC;
    MotionLimits limits = new MotionLimits(v, a, MotionRunnerTest.LIMITS.linearMaxSpeedMmPerSec(),
        MotionRunnerTest.LIMITS.rotationMaxSpeedRadPerSec(), MotionRunnerTest.LIMITS.rotationMaxAccelRadPerSec2());
    Transform end = start.withTranslation(start.x(), start.y() + 100, start.z());
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, limits, q0, rec);
    r.enqueue(new MoveRequest.Linear(end, MotionRunnerTest.TOOL, Speed.mmPerSec(V), Termination.fine(), 1, 8));
    MotionRunnerTest.run(r, 20_000);
    assertThat(rec.events).containsExactly("start 8", "fail 8");
    assertThat(rec.fault.kind()).isEqualTo(MotionFault.Kind.SINGULARITY);
    assertThat(rec.fault.message()).startsWith("wrist singularity: J4 and J6 line up (J5 = -5.0 deg)");
    assertThat(r.timeSec()).isGreaterThan(0.5);
  }
}
