package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;

/**
 * The pendant's LCD as plain text: {@link #HEIGHT} rows of {@link #WIDTH} characters. Row 0 is
 * the status line, row 1 the active alarm, row 2 the screen title, then {@link #BODY_ROWS} body
 * rows, the prompt line, and the function-key labels on the last row. The cursor line starts
 * with {@code >} and the field under the cursor is shown in braces: {@code {200}}.
 *
 * <p>An alarm or a prompt longer than a row is never cut: it wraps at spaces onto up to
 * {@link #MAX_WRAP} rows ({@code alarmRows}, {@code promptRows}), taken from the body (the body
 * window keeps the cursor line in view).
 */
public record Lcd(List<String> rows, int alarmRows, int promptRows) {
  public static final int WIDTH = 64;
  public static final int BODY_ROWS = 11;
  public static final int HEIGHT = BODY_ROWS + 5;
  /** The most rows an alarm or a prompt wraps onto (the rest of the body stays for the screen). */
  public static final int MAX_WRAP = 4;

  public Lcd {
    rows = List.copyOf(rows);
    if (rows.size() != HEIGHT) {
      throw new IllegalArgumentException("an LCD has " + HEIGHT + " rows, got " + rows.size());
    }
    if (alarmRows < 1 || promptRows < 1 || alarmRows > MAX_WRAP || promptRows > MAX_WRAP) {
      throw new IllegalArgumentException("alarm and prompt take 1.." + MAX_WRAP + " rows, got " + alarmRows + ", " + promptRows);
    }
  }

  /** An LCD whose alarm and prompt take one row each. */
  public Lcd(List<String> rows) {
    this(rows, 1, 1);
  }

  /**
   * Builds the LCD, padding every row to {@link #WIDTH}; an alarm or prompt too long for a row
   * wraps onto the rows below (the alarm) or above (the prompt) it.
   */
  static Lcd of(String status, String alarm, String title, List<String> body, String prompt, List<String> fkeys) {
    List<String> alarmLines = wrapped(alarm);
    List<String> promptLines = wrapped(prompt);
    int bodyRows = BODY_ROWS - (alarmLines.size() - 1) - (promptLines.size() - 1);
    List<String> out = new ArrayList<>(HEIGHT);
    out.add(fit(status));
    alarmLines.forEach(r -> out.add(fit(r)));
    out.add(fit(title));
    int first = 0;
    for (int i = 0; i < body.size(); i++) {
      if (body.get(i).startsWith(">")) {
        first = Math.max(0, i - bodyRows + 1);
        break;
      }
    }
    for (int i = first; i < first + bodyRows; i++) {
      out.add(fit(i < body.size() ? body.get(i) : ""));
    }
    promptLines.forEach(r -> out.add(fit(r)));
    out.add(fit(fkeyRow(fkeys)));
    return new Lcd(out, alarmLines.size(), promptLines.size());
  }

  /** One row, or the text wrapped onto at most {@link #MAX_WRAP} rows (the last one cut only beyond that). */
  private static List<String> wrapped(String text) {
    String one = text.replace('\n', ' ');
    if (one.length() <= WIDTH) {
      return List.of(one);
    }
    List<String> w = wrap(one, WIDTH);
    return w.size() <= MAX_WRAP ? w : w.subList(0, MAX_WRAP);
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

  /** The alarm line (blank without an active alarm); a wrapped alarm's rows joined by a space. */
  public String alarmLine() {
    return joined(1, alarmRows);
  }

  /** Whether row {@code i} shows (part of) the active alarm. */
  public boolean isAlarmRow(int i) {
    return i >= 1 && i <= alarmRows;
  }

  /** The screen title. */
  public String title() {
    return rows.get(1 + alarmRows);
  }

  /** The prompt line (messages and entry); a wrapped prompt's rows joined by a space. */
  public String promptLine() {
    return joined(HEIGHT - 1 - promptRows, promptRows);
  }

  private String joined(int from, int count) {
    if (count == 1) {
      return rows.get(from);
    }
    StringBuilder sb = new StringBuilder();
    for (int i = from; i < from + count; i++) {
      sb.append(i > from ? " " : "").append(rows.get(i).stripTrailing());
    }
    return sb.toString();
  }

  /** The function-key labels. */
  public String functionKeys() {
    return rows.get(HEIGHT - 1);
  }

  /** The body rows. */
  public List<String> body() {
    return rows.subList(2 + alarmRows, HEIGHT - 1 - promptRows);
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
    for (int r = 2 + alarmRows; r < HEIGHT - 1 - promptRows; r++) {
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
