package org.robotrun.motion;

/**
 * Which jog keys are on. Six axis pairs (J1..J6 in JOINT; X, Y, Z, rotation about X, Y, Z in the
 * Cartesian frames), each off, + or −.
 *
 * <p>Two ways to press a key, as the pendant offers both:
 * <ul>
 *   <li><b>held</b> (a keyboard key): the axis moves while the key is down and stops on key up;
 *   <li><b>latched</b> (a click on the on-screen key): the first click turns the axis on, a
 *       second click on the same key turns it off, a click on the other key of the pair switches
 *       direction; a key up does nothing.
 * </ul>
 * Keys of different pairs combine (X and Y together move diagonally). {@link #stopAll} (HOLD,
 * deadman released, alarm) turns everything off. Mutable; one per controller.
 */
public final class JogState {
  /** How a key was pressed. */
  public enum Press {
    HELD, LATCHED
  }

  private final int[] direction = new int[6];
  private final boolean[] latched = new boolean[6];

  /**
   * A key goes down.
   *
   * @param axis 0..5
   * @param sign +1 or −1: which key of the pair
   */
  public void keyDown(int axis, int sign, Press press) {
    checkAxis(axis, sign);
    switch (press) {
      case HELD -> {
        direction[axis] = sign;
        latched[axis] = false;
      }
      case LATCHED -> {
        if (latched[axis] && direction[axis] == sign) {
          direction[axis] = 0;
          latched[axis] = false;
        } else {
          direction[axis] = sign;
          latched[axis] = true;
        }
      }
    }
  }

  /** A key comes up: stops a held axis moving that way; latched axes keep going. */
  public void keyUp(int axis, int sign) {
    checkAxis(axis, sign);
    if (!latched[axis] && direction[axis] == sign) {
      direction[axis] = 0;
    }
  }

  /** Everything off. */
  public void stopAll() {
    java.util.Arrays.fill(direction, 0);
    java.util.Arrays.fill(latched, false);
  }

  /** −1, 0 or +1 for axis 0..5. */
  public int direction(int axis) {
    return direction[axis];
  }

  /** Whether axis 0..5 is on by a latched click. */
  public boolean latched(int axis) {
    return latched[axis];
  }

  /** Whether any axis is on. */
  public boolean anyOn() {
    for (int d : direction) {
      if (d != 0) {
        return true;
      }
    }
    return false;
  }

  private static void checkAxis(int axis, int sign) {
    if (axis < 0 || axis > 5 || (sign != 1 && sign != -1)) {
      throw new IllegalArgumentException("jog key: axis 0..5 and sign ±1, got " + axis + ", " + sign);
    }
  }
}
