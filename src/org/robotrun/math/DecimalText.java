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
}
