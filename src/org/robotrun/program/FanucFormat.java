package org.robotrun.program;

import java.math.BigDecimal;
import java.util.Locale;

/**
 * Numbers and padding the way a FANUC controller writes them in .LS files, so files we write
 * look like (and diff cleanly against) files a controller or ROBOGUIDE wrote.
 */
public final class FanucFormat {
  private FanucFormat() {}

  /** Column the {@code =} of a /ATTR line starts at (tab stops of 8). */
  private static final int ATTR_VALUE_COLUMN = 16;

  /**
   * A position-block value: three decimals right-aligned in ten characters, {@code "   350.000"},
   * {@code "   -90.000"}, always, as a controller writes them: a taught value such as
   * -1.2246e-14 mm prints {@code "     0.000"}. Anything that rounds to zero prints unsigned (a
   * controller never shows "-0.000"). A position is therefore saved to 0.001 mm / 0.001 deg.
   */
  public static String positionValue(double v) {
    String s = String.format(Locale.ROOT, "%10.3f", v);
    if (s.strip().equals("-0.000")) {
      return "     0.000";
    }
    return s;
  }

  /**
   * A WAIT time in seconds: two decimals in six characters with the leading zero dropped, as
   * in {@code WAIT    .20(sec)} and {@code WAIT   1.50(sec)}.
   */
  public static String waitSeconds(double seconds) {
    String s = String.format(Locale.ROOT, "%.2f", seconds);
    if (Double.parseDouble(s) != seconds) {
      s = exact(seconds, 2);
    }
    if (s.startsWith("0.")) {
      s = s.substring(1);
    } else if (s.startsWith("-0.")) {
      s = "-" + s.substring(2);
    }
    return pad(s, 6);
  }

  /**
   * A real constant in a statement: the shortest decimal that reads back as the same double,
   * without exponent; integral values keep one decimal ({@code 2.0}) so the reader knows the
   * constant is real. A leading zero is kept ({@code 0.5}): controllers read both forms.
   */
  public static String real(double v) {
    if (v == 0) {
      return 1 / v < 0 ? "-0.0" : "0.0";
    }
    String s = BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
    return s.indexOf('.') < 0 ? s + ".0" : s;
  }

  /**
   * A speed, duration or other plain number: integral values without decimals ({@code 400}),
   * others as {@link #real}.
   */
  public static String plain(double v) {
    if (v == Math.rint(v) && Math.abs(v) < 1e15) {
      return Long.toString((long) v);
    }
    return real(v);
  }

  /** An /ATTR key padded with tabs so its {@code =} lands on column 16, as controllers write it. */
  public static String attrKey(String key) {
    return padWithTabs(key, 0);
  }

  /**
   * {@code text} followed by tabs up to the next tab stop at or after column 16 (counting from
   * {@code startColumn}, 0-based), at least one tab.
   */
  public static String padWithTabs(String text, int startColumn) {
    StringBuilder sb = new StringBuilder(text);
    int col = startColumn + text.length();
    do {
      sb.append('\t');
      col = (col / 8 + 1) * 8;
    } while (col < ATTR_VALUE_COLUMN);
    return sb.toString();
  }

  /** The shortest decimal that reads back as {@code v}, with at least {@code minDecimals} decimals. */
  private static String exact(double v, int minDecimals) {
    BigDecimal d = BigDecimal.valueOf(v);
    if (d.scale() < minDecimals) {
      d = d.setScale(minDecimals);
    }
    return d.toPlainString();
  }

  private static String pad(String s, int width) {
    return s.length() >= width ? s : " ".repeat(width - s.length()) + s;
  }
}
