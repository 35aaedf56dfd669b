package org.robotrun.motion;

/**
 * The speed of a motion as the program states it, converted to SI-like internal units (mm,
 * rad, s) once, at the boundary. Which kinds fit which motion type is the program's rule; the
 * planner accepts any kind for any type and reads it sensibly (a {@link JointPercent} on a
 * linear move is a fraction of the linear speed limit).
 */
public sealed interface Speed {

  /** {@code n%}: fraction (0..1] of each joint's maximum speed. */
  record JointPercent(double fraction) implements Speed {
    public JointPercent {
      check(fraction > 0 && fraction <= 1, "joint speed must be more than 0% and at most 100%", fraction * 100);
    }
  }

  /** {@code n sec} / {@code n msec}: the motion's duration at 100% override (s). */
  record Duration(double seconds) implements Speed {
    public Duration {
      check(seconds > 0 && Double.isFinite(seconds), "motion time must be positive", seconds);
    }
  }

  /** {@code mm/sec}, {@code cm/min}, {@code inch/min}: TCP path speed (mm/s). */
  record Linear(double mmPerSec) implements Speed {
    public Linear {
      check(mmPerSec > 0 && Double.isFinite(mmPerSec), "path speed must be positive", mmPerSec);
    }
  }

  /** {@code deg/sec}: TCP orientation speed (rad/s), for rotation-dominated moves. */
  record Angular(double radPerSec) implements Speed {
    public Angular {
      check(radPerSec > 0 && Double.isFinite(radPerSec), "orientation speed must be positive", radPerSec);
    }
  }

  /** From {@code n%}. */
  static Speed percent(double pct) {
    return new JointPercent(pct / 100);
  }

  /** From {@code n mm/sec}. */
  static Speed mmPerSec(double v) {
    return new Linear(v);
  }

  /** From {@code n cm/min}: 1 cm/min = 10 mm / 60 s. */
  static Speed cmPerMin(double v) {
    return new Linear(v * 10 / 60);
  }

  /** From {@code n inch/min}: 1 inch = 25.4 mm. */
  static Speed inchPerMin(double v) {
    return new Linear(v * 25.4 / 60);
  }

  /** From {@code n deg/sec}. */
  static Speed degPerSec(double v) {
    return new Angular(Math.toRadians(v));
  }

  /** From {@code n sec}. */
  static Speed seconds(double s) {
    return new Duration(s);
  }

  /** From {@code n msec}. */
  static Speed milliseconds(double ms) {
    return new Duration(ms / 1000);
  }

  private static void check(boolean ok, String what, double value) {
    if (!ok) {
      throw new IllegalArgumentException(what + ", got " + value);
    }
  }
}
