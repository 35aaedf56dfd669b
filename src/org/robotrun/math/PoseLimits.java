package org.robotrun.math;

/**
 * The largest position values RobotRun accepts anywhere a person or a file gives one: a .LS
 * position block, a scenario pose, a value typed on the pendant. One bound for every entry
 * point, so whatever the pendant accepts is written to a file and read back without an error.
 *
 * <p>The bounds only keep absurd values out (1e308, a typo with eight extra digits); they are
 * far beyond any reach or joint range, which the controller checks when it moves. NaN and
 * infinities are outside every bound.
 */
public final class PoseLimits {
  private PoseLimits() {}

  /** Largest |x|, |y|, |z| (and object size), in mm: a 100 m cell is far beyond any robot's reach. */
  public static final double MAX_COORDINATE_MM = 100_000;

  /**
   * Largest |w|, |p|, |r| and joint angle, in degrees: a hundred turns, far beyond any joint's
   * range (multi-turn wrists stop near ±900°), while a degree still has about eleven exact
   * decimals.
   */
  public static final double MAX_ANGLE_DEG = 36_000;

  /** Whether {@code mm} is a coordinate within ±{@link #MAX_COORDINATE_MM} (false for NaN). */
  public static boolean coordinateOk(double mm) {
    return Math.abs(mm) <= MAX_COORDINATE_MM;
  }

  /** Whether {@code deg} is an angle within ±{@link #MAX_ANGLE_DEG} (false for NaN). */
  public static boolean angleOk(double deg) {
    return Math.abs(deg) <= MAX_ANGLE_DEG;
  }
}
