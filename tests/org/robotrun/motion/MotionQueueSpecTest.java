package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.data.Offset.offset;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

/**
 * The motion queue's timing rules from docs/motion.md, with the times computed here: a
 * {@code sec} move takes its time even when the arm need not move, HOLD brings the path to rest
 * within the 0.25 s ramp and SHIFT+FWD (resume) finishes the move, and a CNTn move's blend point
 * lies n % of its deceleration time before its end. Joint speeds: the LR Mate 200iD's data
 * sheet (J1 450 °/s), reached in 0.25 s (MotionLimits.JOINT_ACCEL_TIME_SEC).
 */
class MotionQueueSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final double[] HOME = MotionRunnerTest.HOME;
  static final double J1_SPEED = Math.toRadians(450);
  static final double ACCEL_SEC = 0.25;

  /** Records when each move starts and ends (simulated seconds). */
  static final class Times implements MotionListener {
    final List<String> events = new ArrayList<>();
    double started = Double.NaN;
    double finished = Double.NaN;

    @Override
    public void moveStarted(long tag, double t) {
      events.add("start " + tag);
      started = t;
    }

    @Override
    public void moveFinished(long tag, double t) {
      events.add("end " + tag);
      finished = t;
    }

    @Override
    public void moveFailed(long tag, MotionFault f) {
      events.add("fail " + tag + ": " + f.message());
    }
  }

  static double[] j1At(double deg) {
    double[] q = HOME.clone();
    q[0] = Math.toRadians(deg);
    return q;
  }

  /** A move's duration from its start and end events: ticks are 4 ms, so within one tick. */
  static double duration(MotionRunner r, MoveRequest m, double override) {
    Times t = new Times();
    MotionRunner runner = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, r.joints(), t);
    runner.setOverride(override);
    runner.enqueue(m);
    for (int i = 0; i < 100_000 && !runner.idle(); i++) {
      runner.tick(DT);
      for (int j = 0; j < 6; j++) {
        assertThat(runner.joints()[j]).isEqualTo(r.joints()[j]);
      }
    }
    assertThat(t.events).containsExactly("start " + m.tag(), "end " + m.tag());
    return t.finished - t.started;
  }

  @Test
  void aSecMoveToWhereTheArmIsTakesItsTimeAndTwiceThatAtHalfOverride() {
    MotionRunner at = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, HOME, new Times());
    MoveRequest j = new MoveRequest.Joint(HOME, Speed.seconds(0.5), Termination.fine(), 1, 1);
    assertThat(duration(at, j, 1)).isCloseTo(0.5, offset(DT + 1e-9));
    assertThat(duration(at, j, 0.5)).isCloseTo(1.0, offset(DT + 1e-9));
    MoveRequest l = new MoveRequest.Linear(MotionRunnerTest.tcp(HOME), MotionRunnerTest.TOOL, Speed.milliseconds(800),
        Termination.fine(), 1, 2);
    assertThat(duration(at, l, 1)).isCloseTo(0.8, offset(DT + 1e-9));
  }

  /**
   * J1 over 300° at 100 %: 450 °/s reached in 0.25 s, so the move lasts 300/450 + 0.25 s. With
   * CNT50 the blend point is half the 0.25 s deceleration before the end.
   */
  @Test
  void theBlendPointOfACnt50MoveIsHalfItsDecelerationBeforeItsEnd() {
    Times t = new Times();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, j1At(-150), t);
    r.enqueue(new MoveRequest.Joint(j1At(150), Speed.percent(100), Termination.cnt(50), 1, 4));
    double total = Math.toRadians(300) / J1_SPEED + ACCEL_SEC;
    double blendAt = total - 0.5 * ACCEL_SEC;
    assertThat(r.passedBlendPoint(4)).isFalse(); // queued, not running
    assertThat(r.contains(4)).isTrue();
    double firstPassed = Double.NaN;
    for (int i = 0; i < 10_000 && !r.idle(); i++) {
      r.tick(DT);
      if (Double.isNaN(firstPassed) && r.passedBlendPoint(4)) {
        firstPassed = r.timeSec();
      }
      assertThat(r.passedBlendPoint(99)).isFalse();
    }
    assertThat(firstPassed).isCloseTo(blendAt, offset(DT + 1e-9));
    assertThat(t.finished).isCloseTo(total, offset(DT + 1e-9));
    assertThat(r.joints()[0]).isCloseTo(Math.toRadians(150), offset(1e-12));
  }

  /**
   * HOLD during a move: the path decelerates over the 0.25 s ramp (the arm still moves at first),
   * is at rest after it and stays there; resume finishes the move on its target.
   */
  @Test
  void holdBringsTheArmToRestWithinTheRampAndResumeFinishesTheMove() {
    Times t = new Times();
    double[] target = j1At(150);
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, j1At(-150), t);
    assertThat(r.atRest()).isTrue();
    r.enqueue(new MoveRequest.Joint(target, Speed.percent(100), Termination.fine(), 1, 5));
    for (int i = 0; i < 75; i++) { // 0.3 s: cruising
      r.tick(DT);
      assertThat(r.atRest()).isFalse();
    }
    r.hold();
    assertThat(r.held()).isTrue();
    int rampTicks = (int) Math.ceil(ACCEL_SEC / DT);
    double[] prev = r.joints();
    for (int i = 0; i < rampTicks - 1; i++) {
      r.tick(DT);
      assertThat(r.atRest()).as("tick %d of the ramp", i).isFalse();
      assertThat(r.joints()[0]).isGreaterThan(prev[0]);
      prev = r.joints();
    }
    r.tick(DT);
    r.tick(DT);
    assertThat(r.atRest()).isTrue();
    double[] stopped = r.joints();
    for (int i = 0; i < 100; i++) {
      r.tick(DT);
    }
    assertThat(r.joints()).isEqualTo(stopped);
    assertThat(r.atRest()).isTrue();
    assertThat(t.events).containsExactly("start 5");
    r.resume();
    assertThat(r.held()).isFalse();
    r.tick(DT);
    r.tick(DT);
    assertThat(r.atRest()).isFalse();
    for (int i = 0; i < 10_000 && !r.idle(); i++) {
      r.tick(DT);
    }
    assertThat(t.events).containsExactly("start 5", "end 5");
    assertThat(r.joints()[0]).isCloseTo(target[0], offset(1e-12));
    assertThat(r.atRest()).isTrue();
  }

  /** HOLD, releasing the deadman or an alarm turns every key off, latched ones too (docs/motion.md). */
  @Test
  void stoppingTheKeysUnlatchesThem() {
    JogState keys = new JogState();
    keys.keyDown(0, +1, JogState.Press.LATCHED);
    keys.keyDown(4, -1, JogState.Press.HELD);
    assertThat(keys.latched(0)).isTrue();
    assertThat(keys.latched(4)).isFalse();
    keys.stopAll();
    for (int i = 0; i < 6; i++) {
      assertThat(keys.direction(i)).isZero();
      assertThat(keys.latched(i)).isFalse();
    }
    assertThat(keys.anyOn()).isFalse();
    // A held key going down after that is held, not latched: its key-up stops it.
    keys.keyDown(0, +1, JogState.Press.HELD);
    assertThat(keys.anyOn()).isTrue();
    keys.keyUp(0, +1);
    assertThat(keys.anyOn()).isFalse();
  }

  /** There are six jog axes (0..5) and two keys for each (+1, −1); anything else is refused by name. */
  @Test
  void aKeyOutsideTheSixPairsIsRefused() {
    JogState keys = new JogState();
    assertThatThrownBy(() -> keys.keyDown(0, 2, JogState.Press.HELD)).isInstanceOf(IllegalArgumentException.class)
        .hasMessageContaining("axis 0..5 and sign ±1");
    assertThatThrownBy(() -> keys.keyDown(6, 1, JogState.Press.LATCHED)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> keys.keyUp(0, 0)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> keys.keyUp(-1, 1)).isInstanceOf(IllegalArgumentException.class);
    assertThat(keys.anyOn()).isFalse();
  }

  @Test
  void motionRunnerRefusesJointsSetWhileMovingAndABadOverride() {
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, HOME, new Times());
    r.enqueue(new MoveRequest.Joint(j1At(20), Speed.percent(10), Termination.fine(), 1, 1));
    assertThatThrownBy(() -> r.setJoints(HOME)).isInstanceOf(IllegalStateException.class);
    assertThatThrownBy(() -> r.setOverride(0)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> r.setOverride(1.01)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> r.setCartesianSpeedCap(0, Transform.IDENTITY)).isInstanceOf(IllegalArgumentException.class);
  }
}
