package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import org.junit.jupiter.api.Test;
import org.robotrun.DataSheet;
import org.robotrun.math.Transform;

/**
 * Jog speeds bounded on both sides, from docs/motion.md ("Jog"): at 100 % override JOINT moves a
 * joint at 25 % of its data-sheet maximum, WORLD/TOOL/USER translate at 250 mm/s and turn at
 * 60 °/s, the override scales all of them, and each axis ramps up and down in 0.1 s. A key held
 * for a time T and then released therefore covers exactly speed·T (the ramp up loses speed·0.05 s,
 * the ramp down gives it back); the tolerance is two ticks of travel.
 */
class JogSpeedSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final double RAMP = 0.1; // docs/motion.md: each axis ramps up and down in 0.1 s
  static final double[] MAX_DEG_S = DataSheet.maxSpeedsDegPerSec();

  static double[] start() {
    return new double[] {0.3, 0.2, -0.1, 0.4, Math.toRadians(-70), 0.2};
  }

  /** Holds key (axis, +1) for {@code heldTicks}, releases it and ticks until idle; returns the joints. */
  static double[] jog(int axis, JogFrame frame, double override, int heldTicks, double[] q) {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    keys.keyDown(axis, +1, JogState.Press.HELD);
    for (int i = 0; i < heldTicks; i++) {
      assertThat(jog.tick(q, keys, frame, override, MotionRunnerTest.TOOL, Transform.IDENTITY, DT))
          .isInstanceOf(JogResult.Moving.class);
    }
    keys.keyUp(axis, +1);
    int more = 0;
    while (!(jog.tick(q, keys, frame, override, MotionRunnerTest.TOOL, Transform.IDENTITY, DT) instanceof JogResult.Idle)) {
      assertThat(++more).as("ramp down ticks").isLessThanOrEqualTo((int) Math.ceil(RAMP / DT) + 2);
    }
    return q;
  }

  @Test
  void worldTranslationIs250MmPerSecondTimesTheOverride() {
    for (double override : new double[] {1.0, 0.5, 0.1}) {
      double[] q = start();
      Transform before = MotionRunnerTest.tcp(q);
      jog(0, JogFrame.WORLD, override, 200, q); // 0.8 s held
      double v = 250 * override;
      double moved = MotionRunnerTest.tcp(q).x() - before.x();
      assertThat(moved).as("override %.1f", override).isCloseTo(v * 200 * DT, offset(2 * v * DT));
    }
  }

  @Test
  void worldRotationIs60DegreesPerSecondTimesTheOverride() {
    for (double override : new double[] {1.0, 0.3}) {
      double[] q = start();
      Transform before = MotionRunnerTest.tcp(q);
      jog(5, JogFrame.WORLD, override, 150, q); // about WORLD z through the TCP, 0.6 s
      double w = 60 * override;
      double turned = Math.toDegrees(MotionRunnerTest.tcp(q).rotationAngleTo(before));
      assertThat(turned).as("override %.1f", override).isCloseTo(w * 150 * DT, offset(2 * w * DT));
      assertThat(MotionRunnerTest.tcp(q).distanceTo(before)).isLessThan(0.01);
    }
  }

  @Test
  void jointJogIsAQuarterOfTheDataSheetSpeedTimesTheOverride() {
    // J1 (450 °/s on the data sheet) and J6 (1000 °/s): 112.5 °/s and 250 °/s at 100 %.
    for (int j : new int[] {0, 5}) {
      for (double override : new double[] {1.0, 0.4}) {
        double[] q = start();
        double before = q[j];
        jog(j, JogFrame.JOINT, override, 100, q); // 0.4 s held
        double w = 0.25 * MAX_DEG_S[j] * override;
        assertThat(Math.toDegrees(q[j] - before)).as("J%d at %.1f", j + 1, override)
            .isCloseTo(w * 100 * DT, offset(2 * w * DT));
      }
    }
  }

  @Test
  void theRampTakesATenthOfASecond() {
    // After 0.05 s of a held key the speed is half the jog speed (linear ramp over 0.1 s), after 0.1 s all of it.
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    double[] q = start();
    keys.keyDown(0, +1, JogState.Press.HELD);
    double[] speeds = new double[40];
    for (int i = 0; i < speeds.length; i++) {
      double x0 = MotionRunnerTest.tcp(q).x();
      jog.tick(q, keys, JogFrame.WORLD, 1, MotionRunnerTest.TOOL, Transform.IDENTITY, DT);
      speeds[i] = (MotionRunnerTest.tcp(q).x() - x0) / DT;
    }
    double perTick = 250 * DT / RAMP; // 10 mm/s per tick
    assertThat(speeds[(int) Math.round(0.05 / DT) - 1]).isCloseTo(125, offset(1.5 * perTick));
    assertThat(speeds[(int) Math.round(0.1 / DT) + 1]).isCloseTo(250, offset(0.01));
    assertThat(speeds[39]).isCloseTo(250, offset(0.01));
  }
}
