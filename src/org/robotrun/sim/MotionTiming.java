package org.robotrun.sim;

/**
 * How long one motion took, for cycle-time analysis.
 *
 * @param program program of the motion line ("" for MOVE_TO)
 * @param line its line number (0 for MOVE_TO)
 * @param startSec simulated time the motion started (for a blended motion: when its blend began)
 * @param endSec simulated time it reached its end point
 */
public record MotionTiming(String program, int line, double startSec, double endSec) {
  /** Duration (s). */
  public double durationSec() {
    return endSec - startSec;
  }
}
