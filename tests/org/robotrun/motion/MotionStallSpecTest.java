package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

/**
 * docs/motion.md: a Cartesian move that "has to crawl below 5% of its speed for 0.5 s" stops with
 * MOTN-023 (singularity). The crawl is made here without a singularity: the arm's J1 speed limit
 * is set to a fraction of what the line needs. From HOME the TCP sits x = |p| in front of J1 on
 * WORLD x; a line along WORLD y at v mm/s needs J1 at v·x/(x² + y²), at most v/x at the start, so
 * a J1 limit of k·v/x lets the path run at k of its speed at best.
 */
class MotionStallSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final double V = 400;

  record Outcome(MotionRunnerTest.Recorder rec, List<double[]> trace, double endSec, Transform start, Transform end) {}

  static Outcome lineWithJ1At(double fractionOfNeed) {
    double[] home = MotionRunnerTest.HOME;
    Transform start = MotionRunnerTest.tcp(home);
    double x = Math.hypot(start.x(), start.y());
    double[] v = MotionRunnerTest.LIMITS.jointMaxSpeedRadPerSec();
    double[] a = MotionRunnerTest.LIMITS.jointMaxAccelRadPerSec2();
    v[0] = fractionOfNeed * V / x;
    a[0] = v[0] / MotionLimits.JOINT_ACCEL_TIME_SEC;
    MotionLimits limits = new MotionLimits(v, a, MotionRunnerTest.LIMITS.linearMaxSpeedMmPerSec(),
        MotionRunnerTest.LIMITS.rotationMaxSpeedRadPerSec(), MotionRunnerTest.LIMITS.rotationMaxAccelRadPerSec2());
    Transform end = start.withTranslation(start.x(), start.y() + 100, start.z());
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, limits, home, rec);
    r.enqueue(new MoveRequest.Linear(end, MotionRunnerTest.TOOL, Speed.mmPerSec(V), Termination.fine(), 1, 7));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);
    for (int k = 1; k < trace.size(); k++) {
      double j1 = Math.abs(trace.get(k)[0] - trace.get(k - 1)[0]) / DT;
      assertThat(j1).as("J1 speed at tick %d", k).isLessThanOrEqualTo(v[0] * (1 + 1e-9));
    }
    return new Outcome(rec, trace, r.timeSec(), start, end);
  }

  @Test
  void crawlingBelowFivePercentForHalfASecondStopsWithASingularityAlarm() {
    Outcome o = lineWithJ1At(0.001);
    assertThat(o.rec().fault).isNotNull();
    assertThat(o.rec().fault.kind()).isEqualTo(MotionFault.Kind.SINGULARITY);
    // J5 = −90°: not the wrist; the message names the speed.
    assertThat(o.rec().fault.message()).contains("joints would exceed their speed");
    assertThat(o.rec().events).containsExactly("start 7", "fail 7");
    // The crawl starts once the 0.2 s speed ramp asks for more than 20× the allowed 0.1%: at path
    // time τ the ramp asks V·τ/0.2, so below 5% from τ = 0.004 s; crawling, τ grows as
    // dτ/dt = 0.0002/τ, so τ = 0.004 s at t = 0.04 s. Given up 0.5 s later, within a few ticks.
    assertThat(o.endSec()).isGreaterThan(0.5).isLessThan(0.54 + 5 * DT);
    // It crawled along the line, at most at 0.1% of 400 mm/s, and stayed on it.
    Transform last = MotionRunnerTest.tcp(o.trace().get(o.trace().size() - 1));
    double moved = last.translationVector().distanceTo(o.start().translationVector());
    assertThat(moved).isGreaterThan(0).isLessThan(0.001 * V * o.endSec() * 1.01);
    assertThat(last.x()).isCloseTo(o.start().x(), within(0.01));
    assertThat(last.z()).isCloseTo(o.start().z(), within(0.01));
  }

  @Test
  void slowedToFifteenPercentStillArrives() {
    Outcome o = lineWithJ1At(0.15);
    assertThat(o.rec().fault).isNull();
    assertThat(o.rec().events).containsExactly("start 7", "end 7");
    Transform last = MotionRunnerTest.tcp(o.trace().get(o.trace().size() - 1));
    assertThat(last.distanceTo(o.end())).isLessThan(0.01);
    // 100 mm at no more than 15% of 400 mm/s (the need falls only 5% over the line) takes at
    // least 100 / (0.15 · 400 / cos²(atan(100/x))) s; planned it would take about 0.45 s.
    double x = Math.hypot(o.start().x(), o.start().y());
    double fastest = 100 / (0.15 * V * (x * x + 100 * 100) / (x * x));
    assertThat(o.endSec()).isGreaterThan(fastest);
  }
}
