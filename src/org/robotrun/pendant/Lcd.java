package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;

/**
 * The pendant's LCD as plain text: {@link #HEIGHT} rows of {@link #WIDTH} characters. Row 0 is
 * the status line, row 1 the active alarm, row 2 the screen title, then {@link #BODY_ROWS} body
 * rows, the prompt line, and the function-key labels on the last row. The cursor line starts
 * with {@code >} and the field under the cursor is shown in braces: {@code {200}}.
 */
public record Lcd(List<String> rows) {
  public static final int WIDTH = 64;
  public static final int BODY_ROWS = 11;
  public static final int HEIGHT = BODY_ROWS + 5;

  public Lcd {
    rows = List.copyOf(rows);
    if (rows.size() != HEIGHT) {
      throw new IllegalArgumentException("an LCD has " + HEIGHT + " rows, got " + rows.size());
    }
  }

  /** Builds the LCD, padding or cutting every row to {@link #WIDTH}. */
  static Lcd of(String status, String alarm, String title, List<String> body, String prompt, List<String> fkeys) {
    List<String> out = new ArrayList<>(HEIGHT);
    out.add(fit(status));
    out.add(fit(alarm));
    out.add(fit(title));
    for (int i = 0; i < BODY_ROWS; i++) {
      out.add(fit(i < body.size() ? body.get(i) : ""));
    }
    out.add(fit(prompt));
    out.add(fit(fkeyRow(fkeys)));
    return new Lcd(out);
  }

  private static String fkeyRow(List<String> labels) {
    StringBuilder sb = new StringBuilder();
    int cell = WIDTH / 5;
    for (int i = 0; i < 5; i++) {
      String l = i < labels.size() ? labels.get(i) : "";
      String c = center(l, cell - 1);
      sb.append(c).append(i < 4 ? "|" : "");
    }
    return sb.toString();
  }

  private static String center(String s, int width) {
    if (s.length() >= width) {
      return s.substring(0, width);
    }
    int left = (width - s.length()) / 2;
    return " ".repeat(left) + s + " ".repeat(width - s.length() - left);
  }

  /** A rounded negative zero ("-0.000"): a controller shows it without the sign. */
  private static final java.util.regex.Pattern PADDED_NEGATIVE_ZERO =
      java.util.regex.Pattern.compile("(?<=  )-(0\\.0+)(?![\\d])");
  private static final java.util.regex.Pattern NEGATIVE_ZERO = java.util.regex.Pattern.compile("(?<![\\d.])-(0\\.0+)(?![\\d])");

  /** Pads or cuts to exactly {@link #WIDTH} characters; "-0.0" shows as "0.0". */
  static String fit(String s) {
    // in a padded column the sign's place becomes a blank so columns stay aligned
    String one = PADDED_NEGATIVE_ZERO.matcher(s.replace('\n', ' ')).replaceAll(" $1");
    one = NEGATIVE_ZERO.matcher(one).replaceAll("$1");
    return one.length() >= WIDTH ? one.substring(0, WIDTH) : one + " ".repeat(WIDTH - one.length());
  }

  /** {@code text} broken at spaces into rows of at most {@code width} characters (a long word is cut). */
  static List<String> wrap(String text, int width) {
    List<String> out = new ArrayList<>();
    StringBuilder line = new StringBuilder();
    for (String word : text.split(" ")) {
      while (word.length() > width) {
        if (line.length() > 0) {
          out.add(line.toString());
          line.setLength(0);
        }
        out.add(word.substring(0, width));
        word = word.substring(width);
      }
      if (line.length() > 0 && line.length() + 1 + word.length() > width) {
        out.add(line.toString());
        line.setLength(0);
      }
      line.append(line.length() > 0 ? " " : "").append(word);
    }
    if (line.length() > 0) {
      out.add(line.toString());
    }
    return out;
  }

  /** Row {@code i} (0-based). */
  public String row(int i) {
    return rows.get(i);
  }

  /** The status line. */
  public String statusLine() {
    return rows.get(0);
  }

  /** The alarm line (blank without an active alarm). */
  public String alarmLine() {
    return rows.get(1);
  }

  /** The prompt line (messages and entry). */
  public String promptLine() {
    return rows.get(HEIGHT - 2);
  }

  /** The function-key labels. */
  public String functionKeys() {
    return rows.get(HEIGHT - 1);
  }

  /** The body rows. */
  public List<String> body() {
    return rows.subList(3, 3 + BODY_ROWS);
  }

  /** The row the cursor is on (the body row starting with {@code >}), if any. */
  public java.util.Optional<String> cursorRow() {
    return body().stream().filter(r -> r.startsWith(">")).findFirst();
  }

  /**
   * Where the field under the cursor is drawn, for a UI that shows it in inverse video: the LCD
   * row and the columns of the braces around it ({@code openCol} holds '{', {@code closeCol} '}').
   */
  public record FieldSpan(int row, int openCol, int closeCol) {}

  /** The braced field on the cursor row, if the cursor sits on one. */
  public java.util.Optional<FieldSpan> cursorField() {
    for (int r = 3; r < 3 + BODY_ROWS; r++) {
      String row = rows.get(r);
      if (row.startsWith(">")) {
        int open = row.indexOf('{');
        int close = open < 0 ? -1 : row.indexOf('}', open);
        return close < 0 ? java.util.Optional.empty() : java.util.Optional.of(new FieldSpan(r, open, close));
      }
    }
    return java.util.Optional.empty();
  }

  /** The whole screen, framed, one row per line, trailing blanks kept so columns line up. */
  @Override
  public String toString() {
    StringBuilder sb = new StringBuilder();
    String edge = "+" + "-".repeat(WIDTH) + "+\n";
    sb.append(edge);
    for (String r : rows) {
      sb.append('|').append(r).append("|\n");
    }
    sb.append(edge);
    return sb.toString();
  }
}
