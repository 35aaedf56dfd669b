package org.robotrun.pendant;

import java.util.Optional;
import org.robotrun.math.PoseLimits;
import org.robotrun.pendant.ExprText.BadText;

/**
 * Numbers typed into a pendant entry, checked at entry the way the .LS reader and the scenario
 * loader check them when a file is read: whatever the pendant accepts is saved and read back
 * without an error. A refusal is one prompt-line message naming the field and the range; the
 * caller keeps the old value.
 */
final class NumberEntry {
  private NumberEntry() {}

  /** Longest typed text a message repeats: a message must fit the 64-column prompt line. */
  private static final int SHOWN_CHARS = 9;

  /** The typed text as a finite number, or empty when it is not one. */
  static Optional<Double> parse(String text) {
    java.util.OptionalDouble v = org.robotrun.math.DecimalText.parse(text.trim());
    return v.isPresent() ? Optional.of(v.getAsDouble()) : Optional.empty();
  }

  /**
   * The typed value for {@code field} within {@code lo..hi} (inclusive).
   *
   * @param unit shown after the range ({@code "mm"}, {@code "deg"}, or empty)
   * @throws BadText "field text: out of range, enter lo to hi unit" (or "not a number")
   */
  static double within(String field, String text, double lo, double hi, String unit) throws BadText {
    Optional<Double> v = parse(text);
    if (v.isPresent() && v.get() >= lo && v.get() <= hi) {
      return v.get();
    }
    String range = ExprText.plain(lo) + " to " + ExprText.plain(hi) + (unit.isEmpty() ? "" : " " + unit);
    throw refusal(field, text, v.isPresent() ? "out of range" : "not a number", range);
  }

  /** A Cartesian coordinate X, Y or Z in mm, within {@link PoseLimits#MAX_COORDINATE_MM}. */
  static double coordinateMm(String field, String text) throws BadText {
    return within(field, text, -PoseLimits.MAX_COORDINATE_MM, PoseLimits.MAX_COORDINATE_MM, "mm");
  }

  /** An angle W, P, R or J1..J6 in degrees, within {@link PoseLimits#MAX_ANGLE_DEG}. */
  static double angleDeg(String field, String text) throws BadText {
    return within(field, text, -PoseLimits.MAX_ANGLE_DEG, PoseLimits.MAX_ANGLE_DEG, "deg");
  }

  /** Any finite number (a register value). */
  static double finite(String field, String text) throws BadText {
    Optional<Double> v = parse(text);
    if (v.isEmpty()) {
      throw refusal(field, text, "not a number", "digits, '.' and '-'");
    }
    return v.get();
  }

  /** A number above 0 (a speed, a pulse width), as the .LS reader takes them. */
  static double positive(String field, String text) throws BadText {
    Optional<Double> v = parse(text);
    if (v.isEmpty() || !(v.get() > 0)) {
      throw refusal(field, text, v.isEmpty() ? "not a number" : "out of range", "a number above 0");
    }
    return v.get();
  }

  /** A whole number within {@code lo..hi}. */
  static int wholeWithin(String field, String text, int lo, int hi) throws BadText {
    String t = text.trim();
    if (!t.matches("[+-]?\\d+")) {
      throw refusal(field, text, "not a whole number", lo + " to " + hi);
    }
    try {
      int v = Integer.parseInt(t);
      if (v >= lo && v <= hi) {
        return v;
      }
    } catch (NumberFormatException e) {
      // more digits than an int holds: out of range as well
    }
    throw refusal(field, text, "out of range", lo + " to " + hi);
  }

  /**
   * "field text: problem, enter range": one prompt line naming the field and what it takes; the
   * typed text is repeated when short (a long one would push the range off the line).
   */
  static BadText refusal(String field, String text, String problem, String range) {
    String t = text.trim();
    String shown = t.isEmpty() || t.length() > SHOWN_CHARS ? "" : " " + t;
    return new BadText(field + shown + ": " + problem + ", enter " + range, true);
  }
}
