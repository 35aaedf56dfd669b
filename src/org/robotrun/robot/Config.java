package org.robotrun.robot;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A FANUC arm configuration, as a taught position's {@code CONFIG:'N U T, 0, 0, 0'}: which of
 * the up to eight closed-form branches, plus the turn numbers of J1, J4 and J6.
 *
 * <p>How each flag follows from the joint values is defined by the arm's solver
 * ({@link IkSolver#configOf(double[])}: the closed form's formulas on OPW arms, the same
 * definitions from the link geometry on others); the turn numbers follow {@link #turnOf(double)}.
 *
 * @param flip F (true) or N: the sign of J5 (F when J5 &gt; 0)
 * @param up U (true) or D: elbow up or down
 * @param top T (true) or B: wrist centre in front of (T) or behind (B) the J1 axis
 * @param turn1 turn number of J1
 * @param turn4 turn number of J4
 * @param turn6 turn number of J6
 */
public record Config(boolean flip, boolean up, boolean top, int turn1, int turn4, int turn6) {

  private static final Pattern FORM = Pattern.compile(
      "\\s*([FN])\\s*([UD])\\s*([TB])\\s*,\\s*(-?\\d+)\\s*,\\s*(-?\\d+)\\s*,\\s*(-?\\d+)\\s*");

  /**
   * FANUC turn number of a joint angle: 0 for (-180°, 180°], 1 for (180°, 540°], -1 for
   * (-540°, -180°], and so on.
   */
  public static int turnOf(double qRad) {
    return (int) Math.ceil((qRad - Math.PI) / (2 * Math.PI));
  }

  /** Parses the pendant form {@code "N U T, 0, 0, 0"} (spaces optional). */
  public static Config parse(String text) {
    Matcher m = FORM.matcher(text);
    if (!m.matches()) {
      throw new IllegalArgumentException(
          "CONFIG: expected 'F|N U|D T|B, t1, t4, t6' like 'N U T, 0, 0, 0', got '" + text + "'");
    }
    return new Config(
        m.group(1).equals("F"), m.group(2).equals("U"), m.group(3).equals("T"),
        Integer.parseInt(m.group(4)), Integer.parseInt(m.group(5)), Integer.parseInt(m.group(6)));
  }

  /** Same branch, other turn numbers. */
  public Config withTurns(int t1, int t4, int t6) {
    return new Config(flip, up, top, t1, t4, t6);
  }

  /** Whether the F/N, U/D and T/B flags equal the other's (turn numbers ignored). */
  public boolean sameBranch(Config o) {
    return flip == o.flip && up == o.up && top == o.top;
  }

  /** The pendant form, e.g. {@code "N U T, 0, 0, 0"}. */
  @Override
  public String toString() {
    return (flip ? "F" : "N") + " " + (up ? "U" : "D") + " " + (top ? "T" : "B")
        + ", " + turn1 + ", " + turn4 + ", " + turn6;
  }
}
