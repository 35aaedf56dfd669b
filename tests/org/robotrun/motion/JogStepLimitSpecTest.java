package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

/**
 * Incremental (VFINE/FINE) jog steps at the edges docs/motion.md names: a step refused out of
 * reach leaves the joints as they were; a step that ends exactly on a joint's limit is taken (the
 * limits are inclusive: a JOINT jog comes to rest exactly there), one past it is refused. And the
 * ACC bound of a motion (ACC 1..150 on the R-30iB) is named with the value given.
 */
class JogStepLimitSpecTest {
  static final Transform TOOL = MotionRunnerTest.TOOL;

  @Test
  void aStepOutOfReachIsRefusedAndTheJointsStay() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    double[] q = MotionLimitSpecTest.deg(0, 10, -10, 0, -70, 0);
    double[] before = q.clone();
    // 2 m along WORLD X: beyond the LR Mate's 717 mm reach.
    JogResult r = jog.step(q, JogFrame.WORLD, 0, +1, 2000, 0, TOOL, Transform.IDENTITY);
    assertThat(r).isInstanceOf(JogResult.Stopped.class);
    assertThat(((JogResult.Stopped) r).message()).isEqualTo("step out of reach");
    assertThat(q).isEqualTo(before);
  }

  @Test
  void aJointStepEndingExactlyOnTheLimitIsTakenAndTheNextIsRefused() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    double upper = MotionRunnerTest.MODEL.joint(0).upperRad();
    double lower = MotionRunnerTest.MODEL.joint(0).lowerRad();
    double step = 0.25; // a power of two: (limit - step) + step is the limit exactly
    double[] q = MotionLimitSpecTest.deg(0, 0, 0, 0, -60, 0);
    q[0] = upper - step;
    assertThat(q[0] + step).isEqualTo(upper);
    assertThat(jog.step(q, JogFrame.JOINT, 0, +1, 0, step, TOOL, Transform.IDENTITY)).isInstanceOf(JogResult.Moving.class);
    assertThat(q[0]).isEqualTo(upper);
    JogResult past = jog.step(q, JogFrame.JOINT, 0, +1, 0, step, TOOL, Transform.IDENTITY);
    assertThat(((JogResult.Stopped) past).message()).isEqualTo("J1 at its limit");
    assertThat(q[0]).isEqualTo(upper);

    q[0] = lower + step;
    assertThat(q[0] - step).isEqualTo(lower);
    assertThat(jog.step(q, JogFrame.JOINT, 0, -1, 0, step, TOOL, Transform.IDENTITY)).isInstanceOf(JogResult.Moving.class);
    assertThat(q[0]).isEqualTo(lower);
    assertThat(jog.step(q, JogFrame.JOINT, 0, -1, 0, step, TOOL, Transform.IDENTITY)).isInstanceOf(JogResult.Stopped.class);
  }

  @Test
  void anAccOutsideOneTo150IsRefusedNamingTheValueGiven() {
    assertThatThrownBy(() -> new MoveRequest.Joint(MotionRunnerTest.HOME, Speed.percent(50), Termination.fine(), 2, 1))
        .isInstanceOf(IllegalArgumentException.class).hasMessage("ACC must be 1..150, got 200.0");
    assertThatThrownBy(() -> new MoveRequest.Joint(MotionRunnerTest.HOME, Speed.percent(50), Termination.fine(), 0, 1))
        .isInstanceOf(IllegalArgumentException.class).hasMessage("ACC must be 1..150, got 0.0");
  }
}
