package org.robotrun.robot;

/**
 * A frame could not be taught from the recorded points: the message says which point to
 * re-teach and why, e.g. "re-teach the X direction point: it is 0.2 mm from the orient origin
 * point (at least 1.0 mm needed)".
 */
public final class FrameTeachingException extends IllegalArgumentException {
  private final String point;

  public FrameTeachingException(String point, String why) {
    super("re-teach the " + point + ": " + why);
    this.point = point;
  }

  /** The point to re-teach, e.g. "approach point 2" or "Y direction point". */
  public String point() {
    return point;
  }
}
