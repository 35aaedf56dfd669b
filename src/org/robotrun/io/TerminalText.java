package org.robotrun.io;

/**
 * Makes text that may echo file content or names safe to print on a terminal: the one place
 * every command-line message passes through before it is printed.
 *
 * <p>Control characters are escaped so that a file cannot drive the user's terminal (an
 * {@code ESC[2J} in a label would clear it): ESC becomes {@code \e}, carriage return
 * {@code \r}, other C0/C1 controls, DEL, invisible format characters (bidirectional overrides,
 * zero-width marks) and lone surrogates become {@code \}{@code uXXXX}. Line feeds and tabs stay.
 * A run of more than {@link #MAX_WORD} characters without a blank (a 5 000-character name) is
 * shortened in the middle with an ellipsis, and so is a line of more than {@link #MAX_LINE}.
 */
public final class TerminalText {
  /** Longest run of non-blank characters printed whole. */
  public static final int MAX_WORD = 120;
  /** Longest line printed whole. */
  public static final int MAX_LINE = 2000;

  private static final String ELLIPSIS = "…";

  private TerminalText() {}

  /** {@code text} with control characters escaped and overlong names and lines shortened. */
  public static String safe(String text) {
    if (text == null) {
      return "null";
    }
    if (isPlain(text)) {
      return text;
    }
    StringBuilder out = new StringBuilder(Math.min(text.length(), 4 * MAX_LINE) + 16);
    int lineStart = 0;
    while (lineStart <= text.length()) {
      int nl = text.indexOf('\n', lineStart);
      int end = nl < 0 ? text.length() : nl;
      out.append(line(text.substring(lineStart, end)));
      if (nl < 0) {
        break;
      }
      out.append('\n');
      lineStart = nl + 1;
    }
    return out.toString();
  }

  /** Whether {@code text} needs no change (the common case, checked cheaply). */
  private static boolean isPlain(String text) {
    int word = 0;
    int line = 0;
    for (int i = 0; i < text.length(); i++) {
      char c = text.charAt(i);
      if (c == '\n') {
        word = 0;
        line = 0;
        continue;
      }
      if (c < 0x20 && c != '\t' || c >= 0x7F) {
        return false;
      }
      word = c == ' ' || c == '\t' ? 0 : word + 1;
      line++;
      if (word > MAX_WORD || line > MAX_LINE) {
        return false;
      }
    }
    return true;
  }

  private static String line(String raw) {
    String l = raw;
    boolean crlf = l.endsWith("\r");
    if (crlf) {
      l = l.substring(0, l.length() - 1);
    }
    StringBuilder escaped = new StringBuilder(l.length());
    for (String word : l.split("(?<=[ \\t])|(?=[ \\t])", -1)) {
      escaped.append(shorten(escape(word), MAX_WORD));
    }
    String s = shorten(escaped.toString(), MAX_LINE);
    return crlf ? s + "\r" : s;
  }

  private static String shorten(String s, int max) {
    int n = s.codePointCount(0, s.length());
    if (n <= max) {
      return s;
    }
    int head = max * 2 / 3;
    int tail = max - head - 1;
    int headEnd = s.offsetByCodePoints(0, head);
    int tailStart = s.offsetByCodePoints(s.length(), -tail);
    return s.substring(0, headEnd) + ELLIPSIS + s.substring(tailStart);
  }

  private static String escape(String s) {
    StringBuilder out = new StringBuilder(s.length());
    for (int i = 0; i < s.length(); ) {
      int cp = s.codePointAt(i);
      int len = Character.charCount(cp);
      if (cp == 0x1B) {
        out.append("\\e");
      } else if (cp == '\r') {
        out.append("\\r");
      } else if (cp == '\t') {
        out.append('\t');
      } else if (Character.isISOControl(cp) || Character.getType(cp) == Character.FORMAT
          || Character.getType(cp) == Character.SURROGATE || cp == 0x2028 || cp == 0x2029) {
        out.append(String.format(java.util.Locale.ROOT, "\\u%04X", cp));
      } else {
        out.appendCodePoint(cp);
      }
      i += len;
    }
    return out.toString();
  }
}
