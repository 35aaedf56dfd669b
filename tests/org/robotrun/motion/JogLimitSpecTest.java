package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

/**
 * A Cartesian jog meeting a joint limit and passing beside the wrist singularity, as
 * docs/motion.md says: it slows down rather than outrun a joint, and stops itself with a message
 * at a joint limit, never with a jump. Limits and speeds: the LR Mate 200iD's data sheet
 * (J1 ±170°, 450 °/s; J4 550 °/s; resources/robots/lrmate200id.json); the jog speed 250 mm/s.
 */
class JogLimitSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final Transform TOOL = MotionRunnerTest.TOOL;

  static double[] deg(double... d) {
    return MotionLimitSpecTest.deg(d);
  }

  /**
   * J1 at 165°, the TCP behind the arm; a WORLD jog in the direction in which J1 grows (the
   * tangent of the TCP's circle about J1's axis). The jog stops itself with a message naming J1's
   * upper limit before J1 passes 170°, the keys go off, and J1 got within one tick of the limit.
   */
  @Test
  void aWorldJogIntoJ1sLimitStopsAtTheLimitWithAMessage() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = deg(165, 10, -10, 0, -80, 0);
    // The TCP's tangent for growing J1 at 165°: (-sin 165°, cos 165°) in WORLD XY, mostly -Y.
    int axis = 1;
    int sign = -1;
    keys.keyDown(axis, sign, JogState.Press.LATCHED);
    JogResult r = new JogResult.Moving();
    Transform start = MotionRunnerTest.tcp(q);
    int ticks = 0;
    while (r instanceof JogResult.Moving && ticks++ < 5_000) {
      r = jog.tick(q, keys, JogFrame.WORLD, 1, TOOL, Transform.IDENTITY, DT);
      assertThat(Math.toDegrees(q[0])).isLessThanOrEqualTo(170);
    }
    assertThat(r).isInstanceOf(JogResult.Stopped.class);
    Matcher m = Pattern.compile("J1 at its upper limit \\(([0-9.]+) deg\\)").matcher(((JogResult.Stopped) r).message());
    assertThat(m.matches()).as(((JogResult.Stopped) r).message()).isTrue();
    // The value shown is where J1 stopped: at most one tick of a 250 mm/s jog short of 170°
    // (250 mm/s × 4 ms = 1 mm at a radius of more than 300 mm is under 0.2°).
    double shown = Double.parseDouble(m.group(1));
    assertThat(shown).isEqualTo(Math.round(Math.toDegrees(q[0]) * 10) / 10.0);
    assertThat(Math.toDegrees(q[0])).isGreaterThan(169.8);
    assertThat(keys.anyOn()).isFalse();
    // It really jogged along -Y until then (J1 went from 165° to the limit).
    assertThat(start.y() - MotionRunnerTest.tcp(q).y()).isGreaterThan(20);
  }

  /** The same jog the other way from -165°: the lower limit, named as such. */
  @Test
  void aWorldJogIntoJ1sLowerLimitNamesTheLowerLimit() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = deg(-165, 10, -10, 0, -80, 0);
    keys.keyDown(1, +1, JogState.Press.LATCHED);
    JogResult r = new JogResult.Moving();
    int ticks = 0;
    while (r instanceof JogResult.Moving && ticks++ < 5_000) {
      r = jog.tick(q, keys, JogFrame.WORLD, 1, TOOL, Transform.IDENTITY, DT);
      assertThat(Math.toDegrees(q[0])).isGreaterThanOrEqualTo(-170);
    }
    assertThat(((JogResult.Stopped) r).message()).startsWith("J1 at its lower limit (-");
    assertThat(Math.toDegrees(q[0])).isLessThan(-169.8);
  }

  /**
   * A WORLD +Y jog on a line 15 mm beside the point where the wrist is straight (J5 = 0): J4 and
   * J6 have to swing about 180° within a few centimetres, faster than J4's 550 °/s allows at
   * 250 mm/s. The jog slows down for it (never a tick faster than a joint's data-sheet speed, the
   * TCP kept on its line) and comes through without stopping, then speeds up again.
   */
  @Test
  void aJogBesideTheWristSingularitySlowsDownAndComesThrough() {
    double[] qMid = {0, 0.3, 0.2, 0, 0, 0};
    Transform mid = MotionRunnerTest.tcp(qMid);
    Transform from = mid.withTranslation(mid.x(), mid.y() - 40, mid.z() + 15);
    double[] q = {0, 0.3, 0.2, -1.57, 0.1, 1.57};
    assertThat(new PoseTracker(MotionRunnerTest.MODEL).track(q, from, TOOL, 1e-6, 1e-9)).isTrue();
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    keys.keyDown(1, +1, JogState.Press.LATCHED);
    double slowest = Double.MAX_VALUE;
    double fastestLate = 0;
    int ticks = (int) Math.round(0.8 / DT); // 80 mm at full jog speed; the singular point is at 40 mm
    for (int k = 0; k < ticks; k++) {
      double[] before = q.clone();
      JogResult r = jog.tick(q, keys, JogFrame.WORLD, 1, TOOL, Transform.IDENTITY, DT);
      assertThat(r).as("tick %d", k).isInstanceOf(JogResult.Moving.class);
      for (int j = 0; j < 6; j++) {
        assertThat(Math.abs(q[j] - before[j]) / DT).isLessThanOrEqualTo(MotionRunnerTest.LIMITS.jointSpeed(j) * (1 + 1e-9));
      }
      Transform x = MotionRunnerTest.tcp(q);
      // On the jog's line (along WORLD Y) to 0.01 mm, orientation kept.
      assertThat(Math.hypot(x.x() - from.x(), x.z() - from.z())).isLessThan(0.01);
      double v = MotionRunnerTest.tcp(before).translationVector().distanceTo(x.translationVector()) / DT;
      if (k > Jogger.RAMP_SEC / DT + 2) {
        slowest = Math.min(slowest, v);
      }
      if (k > ticks - 10) {
        fastestLate = Math.max(fastestLate, v);
      }
    }
    // It slowed well below 250 mm/s near the singular point, but not below the 5 % floor.
    assertThat(slowest).isLessThan(0.9 * Jogger.LINEAR_JOG_MM_PER_SEC).isGreaterThan(0.05 * Jogger.LINEAR_JOG_MM_PER_SEC);
    // The wrist swung past the straight point: the TCP is now beyond it on the line.
    assertThat(MotionRunnerTest.tcp(q).y()).isGreaterThan(mid.y());
    // Past it, the jog is back near its full speed.
    assertThat(fastestLate).isGreaterThan(0.9 * Jogger.LINEAR_JOG_MM_PER_SEC);
  }

  /**
   * JOINT J2+ with the coupled J3 (docs/motion.md): the J2 keys turn kinematic J3 along, so when
   * kinematic J3 reaches its limit first, the jog stops there with a message naming J3, J3
   * exactly at its limit (braked, not cut), J2 moved by as much as J3.
   */
  @Test
  void aJointJogOfJ2StopsWhenTheCoupledJ3ReachesItsLimit() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    org.robotrun.robot.KinematicChain chain = new PoseTracker(MotionRunnerTest.MODEL).chain();
    JogState keys = new JogState();
    double[] q = deg(0, 0, 0, 0, -60, 0);
    q[2] = chain.upper(2) - Math.toRadians(5);
    double[] q0 = q.clone();
    keys.keyDown(1, +1, JogState.Press.HELD);
    JogResult r = new JogResult.Moving();
    int ticks = 0;
    while (r instanceof JogResult.Moving && ticks++ < 10_000) {
      r = jog.tick(q, keys, JogFrame.JOINT, 1, TOOL, Transform.IDENTITY, DT);
      assertThat(q[2]).isLessThanOrEqualTo(chain.upper(2));
    }
    assertThat(((JogResult.Stopped) r).message()).isEqualTo("J2 stopped: J3 (coupled to J2) at its upper limit");
    assertThat(q[2]).isEqualTo(chain.upper(2));
    assertThat(q[1] - q0[1]).isCloseTo(q[2] - q0[2], org.assertj.core.data.Offset.offset(1e-12));
    assertThat(keys.anyOn()).isFalse();
  }

  /**
   * JOINT J1− at 50 % override to the lower limit: it comes to rest exactly at −170° with a
   * message naming the lower limit, and its speed never changes much faster than the 0.1 s ramp
   * of a 50 % jog allows (the braking included).
   */
  @Test
  void aJointJogAtHalfOverrideBrakesIntoTheLowerLimitWithoutAJump() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = deg(-160, 0, 0, 0, -60, 0);
    double lower = MotionRunnerTest.MODEL.joint(0).lowerRad();
    double full = Jogger.JOINT_JOG_FRACTION * Math.toRadians(450) * 0.5;
    double maxDv = full / Jogger.RAMP_SEC * DT;
    keys.keyDown(0, -1, JogState.Press.HELD);
    JogResult r = new JogResult.Moving();
    double prevV = 0;
    int ticks = 0;
    while (r instanceof JogResult.Moving && ticks++ < 10_000) {
      double before = q[0];
      r = jog.tick(q, keys, JogFrame.JOINT, 0.5, TOOL, Transform.IDENTITY, DT);
      double v = (q[0] - before) / DT;
      assertThat(v).isGreaterThanOrEqualTo(-full * (1 + 1e-9));
      // The ramp's step; the last tick, which lands exactly on the limit, up to twice that.
      assertThat(Math.abs(v - prevV)).isLessThanOrEqualTo(maxDv * 2 + 1e-9);
      prevV = v;
    }
    assertThat(((JogResult.Stopped) r).message()).isEqualTo("J1 at its lower limit (-170.0 deg)");
    assertThat(q[0]).isEqualTo(lower);
  }

  /** WORLD W (axis 3, about X through the TCP) turns at 60 °/s, not at the 250 of a translation. */
  @Test
  void aWorldRotationAboutXTurnsAtSixtyDegreesPerSecond() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = deg(0, 10, -10, 0, -70, 0);
    Transform before = MotionRunnerTest.tcp(q);
    keys.keyDown(3, +1, JogState.Press.HELD);
    for (int i = 0; i < 100; i++) { // 0.4 s held: 0.05 s of ramp-up lost
      jog.tick(q, keys, JogFrame.WORLD, 1, TOOL, Transform.IDENTITY, DT);
    }
    Transform after = MotionRunnerTest.tcp(q);
    double turned = Math.toDegrees(after.rotationAngleTo(before));
    assertThat(turned).isCloseTo(60 * (0.4 - Jogger.RAMP_SEC / 2), org.assertj.core.data.Offset.offset(0.3));
    assertThat(after.translationVector().distanceTo(before.translationVector())).isLessThan(0.01);
  }

  /** After a stop (HOLD, deadman) a key pressed again ramps up from rest: no jump at full speed. */
  @Test
  void aJogStoppedAndStartedAgainRampsUpFromRest() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = deg(0, 0, 0, 0, -60, 0);
    keys.keyDown(0, +1, JogState.Press.HELD);
    for (int i = 0; i < 50; i++) {
      jog.tick(q, keys, JogFrame.JOINT, 1, TOOL, Transform.IDENTITY, DT);
    }
    jog.stop(keys);
    keys.keyDown(0, +1, JogState.Press.HELD);
    double before = q[0];
    jog.tick(q, keys, JogFrame.JOINT, 1, TOOL, Transform.IDENTITY, DT);
    double full = Jogger.JOINT_JOG_FRACTION * Math.toRadians(450);
    // One tick of the ramp: at most full / 0.1 s × 4 ms of speed, for 4 ms.
    assertThat((q[0] - before) / DT).isLessThanOrEqualTo(full / Jogger.RAMP_SEC * DT * (1 + 1e-9));
  }
}
