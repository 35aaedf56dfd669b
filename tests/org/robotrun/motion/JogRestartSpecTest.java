package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.data.Offset.offset;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.robot.ForwardKinematics;

/**
 * docs/motion.md, Jog: each axis ramps up in 0.1 s, and a jog whose frame or tool changes while a
 * key is on starts again from rest in the new frame, so the TCP never changes direction at speed
 * (the pendant's COORD stops the jog outright, docs/pendant.md; this is the jog's own guard). At
 * 250 mm/s reached in 0.1 s, the first 4 ms tick from rest reaches 10 mm/s and moves 0.04 mm; at
 * speed a tick moves 1 mm.
 */
class JogRestartSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final Transform TOOL = MotionRunnerTest.TOOL;
  static final double FIRST_TICK_MM = 250 * (DT / 0.1) * DT;

  static double tcpStep(double[] before, double[] after, Transform tool) {
    return ForwardKinematics.flangePoseInWorld(MotionRunnerTest.MODEL, before).compose(tool).translationVector()
        .distanceTo(ForwardKinematics.flangePoseInWorld(MotionRunnerTest.MODEL, after).compose(tool).translationVector());
  }

  /** Jogs X held for 0.3 s in WORLD with TOOL, then one tick in {@code frame} with {@code tool}; the TCP step of that tick (mm). */
  static double stepAfterSwitch(JogFrame frame, Transform tool) {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = {0, 0.2, -0.1, 0.3, Math.toRadians(-70), 0.2};
    keys.keyDown(0, +1, JogState.Press.HELD);
    double[] before = q.clone();
    for (int k = 0; k < 75; k++) {
      before = q.clone();
      assertThat(jog.tick(q, keys, JogFrame.WORLD, 1, TOOL, Transform.IDENTITY, DT)).isInstanceOf(JogResult.Moving.class);
    }
    assertThat(tcpStep(before, q, TOOL)).isCloseTo(250 * DT, offset(0.01));
    before = q.clone();
    assertThat(jog.tick(q, keys, frame, 1, tool, Transform.IDENTITY, DT)).isInstanceOf(JogResult.Moving.class);
    return tcpStep(before, q, tool);
  }

  @Test
  void aChangeOfFrameRestartsTheJogFromRest() {
    assertThat(FIRST_TICK_MM).isCloseTo(0.04, offset(1e-12));
    assertThat(stepAfterSwitch(JogFrame.TOOL, TOOL)).isCloseTo(FIRST_TICK_MM, offset(0.002));
    assertThat(stepAfterSwitch(JogFrame.USER, TOOL)).isCloseTo(FIRST_TICK_MM, offset(0.002));
  }

  @Test
  void aChangeOfToolRestartsTheJogFromRest() {
    assertThat(stepAfterSwitch(JogFrame.WORLD, Transform.translation(0, 0, 180))).isCloseTo(FIRST_TICK_MM, offset(0.002));
  }

  @Test
  void theSameFrameAndToolKeepTheSpeed() {
    assertThat(stepAfterSwitch(JogFrame.WORLD, TOOL)).isCloseTo(250 * DT, offset(0.01));
  }

  @Test
  void aCartesianCapMustBePositive() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    assertThatThrownBy(() -> jog.setCartesianSpeedCap(0)).isInstanceOf(IllegalArgumentException.class)
        .hasMessage("speed cap must be > 0 mm/s, got 0.0");
    assertThatThrownBy(() -> jog.setCartesianSpeedCap(Double.NaN)).isInstanceOf(IllegalArgumentException.class);
    jog.setCartesianSpeedCap(250);
  }
}
