package org.robotrun.motion;

/**
 * Why a motion or a jog stopped.
 *
 * @param kind machine-readable cause
 * @param message one line for the pendant's alarm screen
 */
public record MotionFault(Kind kind, String message) {

  /** The cause. */
  public enum Kind {
    /** A joint would pass its limit. */
    JOINT_LIMIT,
    /** The target or a point of the path is out of the arm's reach. */
    OUT_OF_REACH,
    /** The path runs through (or too close to) a singularity. */
    SINGULARITY,
    /** The move's geometry makes no sense (three points of a circle on one line, ...). */
    BAD_PATH
  }
}
