package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/** Jogging in JOINT, WORLD and TOOL, and the held/latched key semantics. */
class JoggerTest {
  static final double DT = MotionRunnerTest.DT;
  static final Transform TOOL = MotionRunnerTest.TOOL;

  static double[] start() {
    return new double[] {0.3, 0.2, -0.1, 0.4, Math.toRadians(-70), 0.2};
  }

  @Test
  void worldPlusXMovesTheTcpAlongXOnly() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = start();
    Transform before = MotionRunnerTest.tcp(q);
    keys.keyDown(0, +1, JogState.Press.HELD);
    for (int i = 0; i < 250; i++) {
      assertThat(jog.tick(q, keys, JogFrame.WORLD, 0.5, TOOL, Transform.IDENTITY, DT)).isInstanceOf(JogResult.Moving.class);
    }
    keys.keyUp(0, +1);
    for (int i = 0; i < 50; i++) {
      jog.tick(q, keys, JogFrame.WORLD, 0.5, TOOL, Transform.IDENTITY, DT);
    }
    assertThat(jog.tick(q, keys, JogFrame.WORLD, 0.5, TOOL, Transform.IDENTITY, DT)).isInstanceOf(JogResult.Idle.class);
    Transform after = MotionRunnerTest.tcp(q);
    // About 1 s at 125 mm/s (50% of 250 mm/s): X grew, Y, Z and orientation held (0.01 mm / 0.01 deg).
    assertThat(after.x() - before.x()).isGreaterThan(100);
    assertThat(after.y()).isCloseTo(before.y(), offset(0.01));
    assertThat(after.z()).isCloseTo(before.z(), offset(0.01));
    assertThat(Math.toDegrees(after.rotationAngleTo(before))).isLessThan(0.01);
  }

  @Test
  void toolJogFollowsTheToolAxes() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = start();
    Transform before = MotionRunnerTest.tcp(q);
    keys.keyDown(2, -1, JogState.Press.LATCHED);
    for (int i = 0; i < 200; i++) {
      jog.tick(q, keys, JogFrame.TOOL, 0.3, TOOL, Transform.IDENTITY, DT);
    }
    Transform after = MotionRunnerTest.tcp(q);
    Vec3 moved = after.translationVector().minus(before.translationVector());
    Vec3 toolZ = before.axis(2);
    // Moved backwards along tool z, nothing sideways (mm), orientation kept.
    assertThat(moved.dot(toolZ)).isLessThan(-50);
    assertThat(moved.minus(toolZ.times(moved.dot(toolZ))).norm()).isLessThan(0.01);
    assertThat(Math.toDegrees(after.rotationAngleTo(before))).isLessThan(0.01);
  }

  @Test
  void userJogFollowsTheUserFrameAxes() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = start();
    Transform before = MotionRunnerTest.tcp(q);
    // A user frame turned 30 degrees about WORLD z and moved: its +Y is (−sin 30°, cos 30°, 0).
    Transform X_WU = Transform.rotation(0, 0, 1, Math.toRadians(30)).withTranslation(100, 50, -20);
    keys.keyDown(1, +1, JogState.Press.HELD);
    for (int i = 0; i < 150; i++) {
      jog.tick(q, keys, JogFrame.USER, 0.4, TOOL, X_WU, DT);
    }
    Vec3 moved = MotionRunnerTest.tcp(q).translationVector().minus(before.translationVector());
    Vec3 userY = X_WU.axis(1);
    assertThat(moved.dot(userY)).isGreaterThan(40);
    assertThat(moved.minus(userY.times(moved.dot(userY))).norm()).isLessThan(0.01);
  }

  @Test
  void toolRotationKeepsTheTcpInPlace() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = start();
    Transform before = MotionRunnerTest.tcp(q);
    keys.keyDown(5, +1, JogState.Press.HELD);
    for (int i = 0; i < 100; i++) {
      jog.tick(q, keys, JogFrame.TOOL, 0.5, TOOL, Transform.IDENTITY, DT);
    }
    Transform after = MotionRunnerTest.tcp(q);
    assertThat(after.distanceTo(before)).isLessThan(0.01);
    // Rotated about its own z: the z axis stays put, the angle grew.
    assertThat(after.axis(2).minus(before.axis(2)).norm()).isLessThan(1e-4);
    assertThat(Math.toDegrees(after.rotationAngleTo(before))).isGreaterThan(5);
  }

  @Test
  void jointJogStopsAtTheLimitWithAMessage() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = start();
    double upper = MotionRunnerTest.MODEL.joint(0).upperRad();
    keys.keyDown(0, +1, JogState.Press.HELD);
    JogResult r = new JogResult.Moving();
    double prevV = 0;
    int ticks = 0;
    while (r instanceof JogResult.Moving && ticks++ < 10_000) {
      double before = q[0];
      r = jog.tick(q, keys, JogFrame.JOINT, 1, TOOL, Transform.IDENTITY, DT);
      double v = (q[0] - before) / DT;
      // No jump: speed changes by at most the ramp's step per tick (plus rounding).
      assertThat(Math.abs(v - prevV)).isLessThanOrEqualTo(
          Jogger.JOINT_JOG_FRACTION * MotionRunnerTest.LIMITS.jointSpeed(0) / Jogger.RAMP_SEC * DT * 1.5 + 1e-9);
      prevV = v;
    }
    assertThat(r).isInstanceOf(JogResult.Stopped.class);
    assertThat(((JogResult.Stopped) r).message()).contains("J1").contains("upper limit");
    assertThat(q[0]).isCloseTo(upper, offset(1e-9));
    assertThat(keys.anyOn()).isFalse();
  }

  @Test
  void jointJogOfJ2KeepsTheForearmAttitude() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = start();
    double[] before = org.robotrun.robot.JointConvention.kinematicToPendant(MotionRunnerTest.MODEL, q);
    keys.keyDown(1, +1, JogState.Press.HELD);
    for (int i = 0; i < 100; i++) {
      jog.tick(q, keys, JogFrame.JOINT, 0.5, TOOL, Transform.IDENTITY, DT);
    }
    double[] after = org.robotrun.robot.JointConvention.kinematicToPendant(MotionRunnerTest.MODEL, q);
    // Pendant J2 moved, pendant J3 (the forearm's angle from horizontal) did not.
    assertThat(after[1] - before[1]).isGreaterThan(0.1);
    assertThat(after[2]).isCloseTo(before[2], offset(1e-12));
    for (int j : new int[] {0, 3, 4, 5}) {
      assertThat(after[j]).isEqualTo(before[j]);
    }
  }

  @Test
  void jogOutToTheEdgeOfReachStopsWithAMessageWithoutOutrunningAJoint() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = start();
    keys.keyDown(0, +1, JogState.Press.LATCHED);
    JogResult r = new JogResult.Moving();
    int ticks = 0;
    while (!(r instanceof JogResult.Stopped) && ticks++ < 10_000) {
      double[] before = q.clone();
      r = jog.tick(q, keys, JogFrame.WORLD, 1, TOOL, Transform.IDENTITY, DT);
      for (int j = 0; j < 6; j++) {
        assertThat(Double.isFinite(q[j])).isTrue();
        assertThat(Math.abs(q[j] - before[j]) / DT).isLessThanOrEqualTo(MotionRunnerTest.LIMITS.jointSpeed(j) * (1 + 1e-9));
      }
    }
    assertThat(r).isInstanceOf(JogResult.Stopped.class);
    assertThat(((JogResult.Stopped) r).message()).isNotBlank();
    assertThat(keys.anyOn()).isFalse();
    // It got far out before stopping (the LR Mate reaches about 700 mm).
    assertThat(MotionRunnerTest.tcp(q).x()).isGreaterThan(500);
  }

  @Test
  void latchedKeysToggleSwitchAndCombine() {
    JogState keys = new JogState();
    keys.keyDown(0, +1, JogState.Press.LATCHED);
    keys.keyUp(0, +1);
    assertThat(keys.direction(0)).isEqualTo(1);
    keys.keyDown(0, -1, JogState.Press.LATCHED);
    assertThat(keys.direction(0)).isEqualTo(-1);
    keys.keyDown(1, +1, JogState.Press.LATCHED);
    assertThat(keys.direction(1)).isEqualTo(1);
    assertThat(keys.direction(0)).isEqualTo(-1);
    keys.keyDown(0, -1, JogState.Press.LATCHED);
    assertThat(keys.direction(0)).isZero();
    keys.keyDown(2, +1, JogState.Press.HELD);
    keys.keyUp(2, +1);
    assertThat(keys.direction(2)).isZero();
    keys.stopAll();
    assertThat(keys.anyOn()).isFalse();
  }
}
