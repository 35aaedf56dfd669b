package org.robotrun.program;

/**
 * FANUC configuration of a Cartesian position, written {@code 'N U T, 0, 0, 0'}: wrist
 * {@code F}lip / {@code N}o flip, elbow {@code U}p / {@code D}own, arm {@code T}op (front) /
 * {@code B}ottom (back), and the three turn numbers in the order written (whole turns, -1, 0,
 * 1...; which joints they count is the robot's business, not the program's).
 */
public record Config(boolean flip, boolean up, boolean top, int turn1, int turn2, int turn3) {

  /** {@code 'N U T, 0, 0, 0'}. */
  public static final Config DEFAULT = new Config(false, true, true, 0, 0, 0);
}
