package org.robotrun.math;

import java.util.OptionalDouble;
import java.util.regex.Pattern;

/**
 * The one number grammar for text a person or a file gives RobotRun outside JSON and the TP
 * language (key scripts, ASCII STL, CSV files, command-line joint lists): a plain decimal with
 * an optional exponent, {@code 12}, {@code -0.5}, {@code .5}, {@code 1e3}. Not what
 * {@link Double#parseDouble} also takes ({@code NaN}, {@code Infinity}, hexadecimal
 * {@code 0x1p3}, Java's {@code 5d}/{@code 5f} suffixes, surrounding blanks), and never a
 * value that overflows to infinity.
 */
public final class DecimalText {
  private DecimalText() {}

  private static final Pattern DECIMAL = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d{1,4})?");

  /** Whether {@code text} is a decimal in this grammar (its value may still overflow). */
  public static boolean isDecimal(String text) {
    return text.length() <= 400 && DECIMAL.matcher(text).matches();
  }

  /** The value of {@code text}, or empty when it is not a decimal or overflows to infinity. */
  public static OptionalDouble parse(String text) {
    if (!isDecimal(text)) {
      return OptionalDouble.empty();
    }
    double v = Double.parseDouble(text);
    return Double.isFinite(v) ? OptionalDouble.of(v) : OptionalDouble.empty();
  }

  // ---- writing: the one set of number formatters for files, reports and messages ----------------

  /**
   * A number as a message or a report states it: an integral value (below 1e15) without
   * decimals ({@code 400}), any other as Java's shortest round-trip text ({@code 0.5}).
   */
  public static String plain(double v) {
    return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
  }

  /**
   * A number as RobotRun writes it into a file: at most 15 significant digits (so 9.999999999999998
   * after a trip through a matrix is written 10), no exponent, no trailing zeros, "0" for anything
   * under 1e-12.
   */
  public static String tidy(double v) {
    if (Math.abs(v) < 1e-12) {
      return "0";
    }
    java.math.BigDecimal d = new java.math.BigDecimal(v)
        .round(new java.math.MathContext(15, java.math.RoundingMode.HALF_EVEN)).stripTrailingZeros();
    return d.signum() == 0 ? "0" : d.scale() <= 0 ? d.toBigInteger().toString() : d.toPlainString();
  }

  /** As {@link #tidy} for a value that must read back as a real: an integral one keeps ".0" ({@code 3.0}). */
  public static String tidyReal(double v) {
    String t = tidy(v);
    return t.contains(".") ? t : t + ".0";
  }
}
