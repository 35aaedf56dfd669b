package org.robotrun.program;

/**
 * A token of a TP statement or position block, with its place in the file.
 *
 * @param kind what it is
 * @param text the characters as written (for {@link TpToken.Kind#ITEM_COMMENT}, {@link
 *     TpToken.Kind#RAW} and {@link TpToken.Kind#STRING}: the content without delimiters)
 * @param line 1-based line number
 * @param column 1-based column of its first character
 */
public record TpToken(Kind kind, String text, int line, int column) {

  /** Token kinds. Words (J, CNT50, MOD, mm) are all {@link #WORD}; the parser gives them meaning. */
  public enum Kind {
    WORD,
    NUMBER,
    /** A quoted string, '...' or "...". */
    STRING,
    /** The comment of an indexed item: {@code COUNT} in {@code R[1:COUNT]}. */
    ITEM_COMMENT,
    /** Free text: a {@code !} remark, a {@code //} line, the text of {@code MESSAGE[...]}. */
    RAW,
    LBRACKET,
    RBRACKET,
    LPAREN,
    RPAREN,
    LBRACE,
    RBRACE,
    COMMA,
    COLON,
    SEMICOLON,
    EQ,
    NE,
    LT,
    LE,
    GT,
    GE,
    PLUS,
    MINUS,
    STAR,
    SLASH,
    PERCENT,
    BANG,
    /** A character no TP statement uses; the parser reports it. */
    BAD_CHAR,
    /** End of the line. */
    EOL
  }

  public boolean is(Kind k) {
    return kind == k;
  }

  /** True for a word spelled {@code word}, ignoring case (FANUC files are upper case; people type lower). */
  public boolean isWord(String word) {
    return kind == Kind.WORD && text.equalsIgnoreCase(word);
  }

  /** How to name this token in "expected X, found Y" messages. */
  public String describe() {
    return switch (kind) {
      case EOL -> "end of line";
      case STRING -> "'" + clip(text) + "'";
      case ITEM_COMMENT -> "comment ':" + clip(text) + "'";
      case RAW -> "text";
      case BAD_CHAR -> "character " + printable(text);
      default -> "'" + clip(text) + "'";
    };
  }

  /** Messages quote at most 40 characters of a token, however long the line. */
  public static String clip(String s) {
    return s.length() <= 40 ? s : s.substring(0, 40) + "...";
  }

  private static String printable(String s) {
    int c = s.isEmpty() ? 0 : s.codePointAt(0);
    return c >= 0x20 && c < 0x7f ? "'" + s + "'" : String.format(java.util.Locale.ROOT, "U+%04X", c);
  }
}
