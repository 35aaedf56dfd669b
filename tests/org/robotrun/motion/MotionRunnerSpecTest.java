package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The motion runner against docs/motion.md (issue 31): HOLD and resume ramp the rate over 0.25 s
 * (a stop from full speed costs half the ramp, the restart the other half), an override change
 * never jumps, the time left of a move is its trapezoid's remaining time over the override,
 * ABORT drops every move where the arm stands, and the units and bounds a program's speed,
 * termination and ACC are checked against. Expected values come from the data-sheet speed of J1
 * and the documented ramps, never from a run.
 */
class MotionRunnerSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final double RAMP = MotionLimits.JOINT_ACCEL_TIME_SEC;
  /** The arm's home with J1 at -160°, so J1 can turn 320° in one move (0.71 s of cruise). */
  static final double[] HOME = start();

  static double[] start() {
    double[] q = MotionRunnerTest.HOME.clone();
    q[0] = Math.toRadians(-160);
    return q;
  }

  /** A J1-only move of {@code deg} at {@code pct}%: the other joints stay, so J1 sets the pace. */
  static MoveRequest.Joint j1Move(double deg, double pct, long tag) {
    double[] q = HOME.clone();
    q[0] += Math.toRadians(deg);
    return new MoveRequest.Joint(q, Speed.percent(pct), Termination.fine(), 1, tag);
  }

  /** The trapezoid of a J1 move at 100%: cruise at the data-sheet speed, 0.25 s ramps. */
  static double trapezoidSec(double deg) {
    double v = MotionRunnerTest.LIMITS.jointSpeed(0);
    return Math.toRadians(deg) / v + RAMP;
  }

  static int ticksToIdle(MotionRunner r) {
    int n = 0;
    while (!r.idle() && n < 100_000) {
      r.tick(DT);
      n++;
    }
    return n;
  }

  // Method: J1 turns 320° at 100% (a trapezoid with 0.25 s ramps, the data-sheet speed v). HOLD
  // in the cruise: the rate falls to 0 in 0.25 s, so J1 coasts v·0.125 s before it stands
  // (docs/motion.md: HOLD decelerates along the path). Held for 0.5 s it does not move. After
  // resume the move ends on its target, having lost the hold time plus 0.25 s (half a ramp to
  // stop, half to restart) against the plain trapezoid. Tolerance: two ticks.
  @Test
  void holdStopsWithinTheRampAndResumeFinishesLateByTheHoldPlusOneRamp() {
    double v = MotionRunnerTest.LIMITS.jointSpeed(0);
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, HOME, rec);
    r.enqueue(j1Move(320, 100, 7));
    int ticks = 0;
    for (; ticks < Math.round(0.4 / DT); ticks++) {
      r.tick(DT);
    }
    double atHold = r.joints()[0];
    r.hold();
    assertThat(r.held()).isTrue();
    int stopTicks = 0;
    double prev = atHold;
    while (true) {
      r.tick(DT);
      ticks++;
      stopTicks++;
      double now = r.joints()[0];
      if (now == prev) {
        break;
      }
      prev = now;
      assertThat(stopTicks).isLessThan(1000);
    }
    assertThat(stopTicks * DT).isCloseTo(RAMP, within(2 * DT));
    assertThat(prev - atHold).isCloseTo(v * RAMP / 2, within(2 * v * DT));
    assertThat(r.atRest()).isTrue();
    assertThat(r.idle()).isFalse();
    int heldTicks = (int) Math.round(0.5 / DT);
    for (int i = 0; i < heldTicks; i++) {
      r.tick(DT);
    }
    ticks += heldTicks;
    assertThat(r.joints()[0]).isEqualTo(prev);
    assertThat(r.timeLeftSec(7)).isGreaterThan(0);
    r.resume();
    assertThat(r.held()).isFalse();
    ticks += ticksToIdle(r);
    assertThat(r.joints()[0]).isCloseTo(HOME[0] + Math.toRadians(320), within(1e-12));
    // Lost: half a ramp stopping, half a ramp restarting, and every tick spent standing.
    double expected = trapezoidSec(320) + RAMP + (1 + heldTicks) * DT;
    assertThat(ticks * DT).isCloseTo(expected, within(3 * DT));
    assertThat(rec.events).containsExactly("start 7", "end 7");
  }

  // Method: the same move at 100%; in the cruise the override drops to 50%: J1's speed falls to
  // v/2 without a step larger than the ramp allows per tick (v·dt/0.25), is there within 0.25 s,
  // and the time left doubles (time left = remaining path time / override).
  @Test
  void anOverrideChangeRampsTheSpeedAndScalesTheTimeLeft() {
    double v = MotionRunnerTest.LIMITS.jointSpeed(0);
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, HOME, new MotionRunnerTest.Recorder());
    r.enqueue(j1Move(320, 100, 3));
    for (int i = 0; i < Math.round(0.4 / DT); i++) {
      r.tick(DT);
    }
    double pathLeft = r.timeLeftSec(3);
    assertThat(pathLeft).isCloseTo(trapezoidSec(320) - 0.4, within(2 * DT));
    r.setOverride(0.5);
    assertThat(r.override()).isEqualTo(0.5);
    assertThat(r.timeLeftSec(3)).isCloseTo(2 * pathLeft, within(1e-9));
    double prevQ = r.joints()[0];
    double prevV = v;
    for (int i = 0; i < Math.round(RAMP / DT); i++) {
      r.tick(DT);
      double q = r.joints()[0];
      double vel = (q - prevQ) / DT;
      assertThat(Math.abs(vel - prevV)).isLessThanOrEqualTo(v * DT / RAMP * (1 + 1e-6));
      assertThat(vel).isGreaterThanOrEqualTo(v / 2 * (1 - 1e-9));
      prevQ = q;
      prevV = vel;
    }
    assertThat(prevV).isCloseTo(v / 2, within(v * 1e-9));
    r.tick(DT);
    assertThat((r.joints()[0] - prevQ) / DT).isCloseTo(v / 2, within(v * 1e-9));
  }

  // Method: a J1 move of 320° at 50% from rest (the runner starts at the set override at once):
  // its time left right after the first tick is its 100% trapezoid less one tick, over 0.5; a
  // queued second move has no time left yet (infinite), is contained, is not past its blend point.
  @Test
  void timeLeftIsTheTrapezoidOverTheOverrideAndQueuedMovesHaveNone() {
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, HOME, new MotionRunnerTest.Recorder());
    r.setOverride(0.5);
    r.enqueue(j1Move(320, 100, 1));
    r.tick(DT);
    r.enqueue(j1Move(300, 100, 2));
    assertThat(r.acceptsMove()).isFalse();
    // After one tick at rate 0.5 the path has advanced half a tick.
    assertThat(r.timeLeftSec(1)).isCloseTo((trapezoidSec(320) - DT / 2) / 0.5, within(1e-9));
    assertThat(r.timeLeftSec(2)).isInfinite();
    assertThat(r.timeLeftSec(99)).isInfinite();
    assertThat(r.contains(1)).isTrue();
    assertThat(r.contains(2)).isTrue();
    assertThat(r.contains(3)).isFalse();
    assertThat(r.passedBlendPoint(1)).isFalse();
    assertThat(r.passedBlendPoint(2)).isFalse();
    assertThat(r.activeTags()).containsExactly(1L);
    assertThatThrownBy(() -> r.enqueue(j1Move(5, 100, 4))).isInstanceOf(IllegalStateException.class);
    assertThatThrownBy(() -> r.setJoints(HOME)).isInstanceOf(IllegalStateException.class);
    int ticks = 1 + ticksToIdle(r);
    // The second move goes from HOME to HOME + 300° (20° back): a triangle, since J1 needs
    // v·0.25 s = 112.5° to reach full speed: 2·sqrt(d·0.25 / v). Both at 50%: twice as long.
    double d2 = Math.toRadians(20);
    double second = 2 * Math.sqrt(d2 * RAMP / MotionRunnerTest.LIMITS.jointSpeed(0));
    assertThat(ticks * DT).isCloseTo(2 * (trapezoidSec(320) + second), within(4 * DT));
    assertThat(r.joints()[0]).isCloseTo(HOME[0] + Math.toRadians(300), within(1e-12));
    assertThat(r.contains(1)).isFalse();
    assertThat(r.timeSec()).isCloseTo(ticks * DT, within(1e-9));
  }

  // Method: ABORT (stopNow) mid-move with a second move queued: nothing runs or waits any more,
  // the arm stays where it was, further ticks do not move it, no move reports an end, and the
  // runner takes a new move from there at full rate.
  @Test
  void stopNowDropsEveryMoveWhereTheArmStands() {
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, HOME, rec);
    r.enqueue(j1Move(90, 100, 1));
    r.tick(DT);
    r.enqueue(j1Move(10, 100, 2));
    for (int i = 0; i < 50; i++) {
      r.tick(DT);
    }
    r.hold();
    double[] q = r.joints();
    r.stopNow();
    assertThat(r.idle()).isTrue();
    assertThat(r.atRest()).isTrue();
    assertThat(r.held()).isFalse();
    assertThat(r.activeTags()).isEmpty();
    for (int i = 0; i < 20; i++) {
      r.tick(DT);
    }
    assertThat(r.joints()).containsExactly(q);
    assertThat(rec.events).containsExactly("start 1");
    double[] target = q.clone();
    target[0] += Math.toRadians(10);
    r.enqueue(new MoveRequest.Joint(target, Speed.percent(100), Termination.fine(), 1, 3));
    ticksToIdle(r);
    assertThat(r.joints()[0]).isCloseTo(target[0], within(1e-12));
    assertThat(rec.events).containsExactly("start 1", "start 3", "end 3");
    r.setJoints(HOME);
    assertThat(r.joints()).containsExactly(HOME);
  }

  // Method: the program's units converted as TP-LANGUAGE.md and docs/motion.md define them,
  // and every bound: speeds positive and finite, n% in (0, 100], CNT 0..100, ACC 1..150,
  // override in (0, 1], a speed cap above 0.
  @Test
  void unitsAndBoundsOfSpeedTerminationAccAndOverride() {
    assertThat(((Speed.Linear) Speed.cmPerMin(600)).mmPerSec()).isCloseTo(100, within(1e-12));
    assertThat(((Speed.Linear) Speed.inchPerMin(60)).mmPerSec()).isCloseTo(25.4, within(1e-12));
    assertThat(((Speed.Linear) Speed.mmPerSec(250)).mmPerSec()).isEqualTo(250);
    assertThat(((Speed.Angular) Speed.degPerSec(90)).radPerSec()).isCloseTo(Math.PI / 2, within(1e-15));
    assertThat(((Speed.Duration) Speed.milliseconds(250)).seconds()).isCloseTo(0.25, within(1e-15));
    assertThat(((Speed.Duration) Speed.seconds(2)).seconds()).isEqualTo(2);
    assertThat(((Speed.JointPercent) Speed.percent(100)).fraction()).isEqualTo(1);
    assertThat(((Speed.JointPercent) Speed.percent(1)).fraction()).isCloseTo(0.01, within(1e-15));
    for (Runnable bad : List.<Runnable>of(
        () -> Speed.percent(0), () -> Speed.percent(100.5), () -> Speed.percent(-5),
        () -> Speed.mmPerSec(0), () -> Speed.mmPerSec(Double.POSITIVE_INFINITY), () -> Speed.mmPerSec(Double.NaN),
        () -> Speed.degPerSec(0), () -> Speed.degPerSec(Double.POSITIVE_INFINITY),
        () -> Speed.seconds(0), () -> Speed.milliseconds(-1), () -> Speed.seconds(Double.POSITIVE_INFINITY),
        () -> Termination.cnt(-1), () -> Termination.cnt(101),
        () -> new MoveRequest.Joint(HOME, Speed.percent(50), Termination.fine(), 0, 1),
        () -> new MoveRequest.Joint(HOME, Speed.percent(50), Termination.fine(), 1.51, 1),
        () -> new MoveRequest.Joint(new double[5], Speed.percent(50), Termination.fine(), 1, 1))) {
      assertThatThrownBy(bad::run).isInstanceOf(IllegalArgumentException.class);
    }
    assertThat(((Termination.Cnt) Termination.cnt(0)).value()).isZero();
    assertThat(((Termination.Cnt) Termination.cnt(100)).value()).isEqualTo(100);
    assertThat(new MoveRequest.Joint(HOME, Speed.percent(50), Termination.fine(), 1.5, 1).accFraction()).isEqualTo(1.5);
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, HOME, new MotionRunnerTest.Recorder());
    assertThatThrownBy(() -> r.setOverride(0)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> r.setOverride(1.01)).isInstanceOf(IllegalArgumentException.class);
    r.setOverride(1);
    r.setOverride(0.01);
    assertThat(r.override()).isEqualTo(0.01);
    assertThatThrownBy(() -> r.setCartesianSpeedCap(0, org.robotrun.math.Transform.IDENTITY)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> r.setCartesianSpeedCap(Double.NaN, org.robotrun.math.Transform.IDENTITY)).isInstanceOf(IllegalArgumentException.class);
    r.setCartesianSpeedCap(250, org.robotrun.math.Transform.IDENTITY);
    assertThat(r.cartesianSpeedCap()).isEqualTo(250);
    // The joint limits are the data sheet's speeds, each reached in 0.25 s.
    for (int j = 0; j < 6; j++) {
      assertThat(MotionRunnerTest.LIMITS.jointSpeed(j)).isEqualTo(MotionRunnerTest.MODEL.joint(j).maxSpeedRadPerSec());
      assertThat(MotionRunnerTest.LIMITS.jointAccel(j)).isCloseTo(MotionRunnerTest.LIMITS.jointSpeed(j) / RAMP, within(1e-9));
    }
  }
}
