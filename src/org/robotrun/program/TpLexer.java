package org.robotrun.program;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.program.TpToken.Kind;

/**
 * Splits one line of a .LS file into tokens. It works a line at a time because the format is
 * line-oriented: a bad line never disturbs the next one, which is what lets the parser report
 * every bad line in one pass.
 *
 * <p>Three places hold free text rather than tokens, and the lexer knows them: the comment of
 * an indexed item after {@code :} inside brackets ({@code LBL[99:NO GRIP]}), the text of {@code
 * MESSAGE[...]}, and (at the start of a statement) a {@code !} remark or a {@code //}
 * commented-out line. Everything else is words, numbers, strings and punctuation; a character
 * TP does not use becomes a {@link Kind#BAD_CHAR} token for the parser to report.
 */
public final class TpLexer {
  private TpLexer() {}

  /**
   * Keywords of German controller listings and their English form: a German listing reads as
   * the same program as its English one. The table holds the words seen in German .LS files
   * (WARTE, AUFRUF, SPRUNG, MARKE, KONFIG ...); an unedited file is written back as read, and an
   * edited line is written in English, which every controller reads.
   */
  private static final java.util.Map<String, String> GERMAN = java.util.Map.ofEntries(
      java.util.Map.entry("WARTE", "WAIT"),
      java.util.Map.entry("AUFRUF", "CALL"),
      java.util.Map.entry("SPRUNG", "JMP"),
      java.util.Map.entry("MARKE", "LBL"),
      java.util.Map.entry("WENN", "IF"),
      java.util.Map.entry("DANN", "THEN"),
      java.util.Map.entry("SONST", "ELSE"),
      java.util.Map.entry("ENDE", "END"),
      java.util.Map.entry("ABBRUCH", "ABORT"),
      java.util.Map.entry("FEIN", "FINE"),
      java.util.Map.entry("KONFIG", "CONFIG"),
      java.util.Map.entry("MELDUNG", "MESSAGE"),
      java.util.Map.entry("AUSWAHL", "SELECT"),
      java.util.Map.entry("UND", "AND"),
      java.util.Map.entry("ODER", "OR"),
      java.util.Map.entry("EIN", "ON"),
      java.util.Map.entry("AUS", "OFF"),
      java.util.Map.entry("SEK", "sec"),
      // Seen in real German R-30iA/R-30iB listings (public backups, see docs/tp-language.md):
      java.util.Map.entry("LABEL", "LBL"),
      java.util.Map.entry("AN", "ON"),
      java.util.Map.entry("IST", "SELECT"),
      java.util.Map.entry("STOPP", "STOP"),
      java.util.Map.entry("TRAGLST", "PAYLOAD"),
      java.util.Map.entry("WKZ_NUM", "UTOOL_NUM"),
      java.util.Map.entry("BENUTZER_NUM", "UFRAME_NUM"),
      java.util.Map.entry("BALM", "UALM"),
      java.util.Map.entry("ZEIT", "TIME"),
      java.util.Map.entry("WEG", "DISTANCE"),
      java.util.Map.entry("VOR", "BEFORE"),
      java.util.Map.entry("NACH", "AFTER"),
      java.util.Map.entry("IRQ", "SKIP"),
      java.util.Map.entry("BEDINGUNG", "CONDITION"),
      java.util.Map.entry("INTERRUPT", "Skip"));

  /**
   * German names of register and I/O kinds, used only right before '[' (so the arc motion
   * {@code A P[1] ...} stays a motion): {@code E[]} input, {@code A[]} output, {@code gE[]}/{@code gA[]}
   * group I/O, {@code i[]} data register, as real German listings write them.
   */
  private static final java.util.Map<String, String> GERMAN_KINDS = java.util.Map.of(
      "E", "DI", "A", "DO", "GE", "GI", "GA", "GO", "I", "R");

  /** The English keyword for a German one, else {@code word} itself (never after CALL: that is a name). */
  static String english(String word, List<TpToken> before) {
    String en = GERMAN.get(word.toUpperCase(java.util.Locale.ROOT));
    if (en == null || (!before.isEmpty() && (before.get(before.size() - 1).isWord("CALL")
        || before.get(before.size() - 1).isWord("RUN")))) {
      return word;
    }
    return en;
  }

  /** Shared one-character token texts, so punctuation does not allocate a string per token. */
  private static final String[] ONE_CHAR = new String[128];

  static {
    for (char c = 0; c < ONE_CHAR.length; c++) {
      ONE_CHAR[c] = String.valueOf(c).intern();
    }
  }

  /**
   * Tokens of {@code text}, ending with an {@link Kind#EOL} token.
   *
   * @param text the characters to split (no line break)
   * @param line the 1-based line number, stamped on every token
   * @param firstColumn the 1-based column of {@code text}'s first character in the file line
   * @param statement true for a /MN statement body, where a leading {@code !} or {@code //}
   *     makes the rest of the line free text
   */
  public static List<TpToken> tokenize(String text, int line, int firstColumn, boolean statement) {
    List<TpToken> out = new ArrayList<>(24);
    int n = text.length();
    int i = 0;
    int bracketDepth = 0;
    while (i < n) {
      char c = text.charAt(i);
      int col = firstColumn + i;
      if (c == ' ' || c == '\t') {
        i++;
        continue;
      }
      if (statement && out.isEmpty()) {
        if (c == '!') {
          out.add(new TpToken(Kind.BANG, "!", line, col));
          out.add(new TpToken(Kind.RAW, text.substring(i + 1), line, col + 1));
          i = n;
          continue;
        }
        if (c == '-' && i + 1 < n && text.charAt(i + 1) == '-') {
          // "--eg:text": a remark line (some controller versions write them)
          out.add(new TpToken(Kind.MINUS, "--", line, col));
          out.add(new TpToken(Kind.RAW, text.substring(i + 2), line, col + 2));
          i = n;
          continue;
        }
        if (c == '/' && i + 1 < n && text.charAt(i + 1) == '/') {
          out.add(new TpToken(Kind.SLASH, "//", line, col));
          out.add(new TpToken(Kind.RAW, text.substring(i + 2), line, col + 2));
          i = n;
          continue;
        }
      }
      if (c == '@' && i + 1 < n && (text.charAt(i + 1) == 'P' || text.charAt(i + 1) == 'p')) {
        // "J @P[3] 100% FINE": the controller marks the point the robot stands at; not part of the statement
        i++;
        continue;
      }
      if (isWordStart(c)) {
        int j = i + 1;
        if (c == '$') {
          // A system variable's path is one word: $MCR.$GENOVERRIDE, $MNUTOOLNUM[1],
          // $MIX_BG[2].$STATUS, $SYSTEM_TIME[1].RUN_TOT, and a KAREL variable $[PROG]NAME.
          j = systemVariableEnd(text, i);
        }
        while (j < n && isWordPart(text.charAt(j))) {
          j++;
        }
        String word = text.substring(i, j);
        if (j < n && text.charAt(j) == '[' && c != '$') {
          String kind = GERMAN_KINDS.get(word.toUpperCase(java.util.Locale.ROOT));
          if (kind != null) {
            word = kind;
          }
        } else if (j < n && text.charAt(j) == '.' && word.equalsIgnoreCase("FREIG")) {
          // "FREIG. PREG": the German UNLOCK PREG
          word = "UNLOCK";
          j++;
        }
        out.add(new TpToken(Kind.WORD, english(word, out), line, col));
        i = j;
        continue;
      }
      if (isDigit(c) || (c == '.' && i + 1 < n && isDigit(text.charAt(i + 1)))) {
        int j = i;
        while (j < n && isDigit(text.charAt(j))) {
          j++;
        }
        if (j < n && text.charAt(j) == '.') {
          j++;
          while (j < n && isDigit(text.charAt(j))) {
            j++;
          }
        }
        out.add(new TpToken(Kind.NUMBER, text.substring(i, j), line, col));
        i = j;
        continue;
      }
      switch (c) {
        case '\'', '"' -> {
          int end = text.indexOf(c, i + 1);
          if (end < 0) {
            // Unclosed: the parser sees a string running to the end and a BAD_CHAR for the quote.
            out.add(new TpToken(Kind.BAD_CHAR, String.valueOf(c), line, col));
            i++;
          } else {
            out.add(new TpToken(Kind.STRING, text.substring(i + 1, end), line, col));
            i = end + 1;
          }
        }
        case '[' -> {
          if (i + 2 < n && text.charAt(i + 2) == ']' && (text.charAt(i + 1) == '&' || text.charAt(i + 1) == '+')) {
            // "E[1] [&] !E[2] [+] M[3]": the German listing's AND / OR in a condition
            out.add(new TpToken(Kind.WORD, text.charAt(i + 1) == '&' ? "AND" : "OR", line, col));
            i += 3;
            continue;
          }
          boolean message = !out.isEmpty() && out.get(out.size() - 1).isWord("MESSAGE");
          out.add(new TpToken(Kind.LBRACKET, ONE_CHAR['['], line, col));
          i++;
          if (message) {
            // The text runs to the last ']': a controller lists MESSAGE[R[1] > 5 mm] as typed.
            int end = text.lastIndexOf(']');
            end = end < i ? -1 : end;
            int stop = end < 0 ? n : end;
            out.add(new TpToken(Kind.RAW, text.substring(i, stop), line, firstColumn + i));
            i = stop;
          } else {
            bracketDepth++;
          }
        }
        case ']' -> {
          bracketDepth = Math.max(0, bracketDepth - 1);
          out.add(new TpToken(Kind.RBRACKET, ONE_CHAR[']'], line, col));
          i++;
        }
        case ':' -> {
          out.add(new TpToken(Kind.COLON, ONE_CHAR[':'], line, col));
          i++;
          boolean group = out.size() >= 3 && isGroupWord(out.get(out.size() - 2)) && out.get(out.size() - 3).is(Kind.LBRACKET);
          if (bracketDepth > 0 && !group) {
            // ("PR[GP1:5,3:Z]": after a group the index follows, not a comment)
            int stop = commentEnd(text, i);
            out.add(new TpToken(Kind.ITEM_COMMENT, text.substring(i, stop), line, firstColumn + i));
            i = stop;
          }
        }
        case '<' -> {
          if (i + 1 < n && text.charAt(i + 1) == '>') {
            out.add(new TpToken(Kind.NE, "<>", line, col));
            i += 2;
          } else if (i + 1 < n && text.charAt(i + 1) == '=') {
            out.add(new TpToken(Kind.LE, "<=", line, col));
            i += 2;
          } else {
            out.add(new TpToken(Kind.LT, "<", line, col));
            i++;
          }
        }
        case '>' -> {
          if (i + 1 < n && text.charAt(i + 1) == '=') {
            out.add(new TpToken(Kind.GE, ">=", line, col));
            i += 2;
          } else {
            out.add(new TpToken(Kind.GT, ">", line, col));
            i++;
          }
        }
        default -> {
          Kind k = single(c);
          out.add(new TpToken(k, c < ONE_CHAR.length ? ONE_CHAR[c] : String.valueOf(c), line, col));
          i++;
        }
      }
    }
    out.add(new TpToken(Kind.EOL, "", line, firstColumn + n));
    return out;
  }

  /** {@code GP1} .. {@code GP9}, any case: a motion group before ':' in {@code PR[GP1:5]}. */
  private static boolean isGroupWord(TpToken t) {
    String w = t.text();
    return t.is(Kind.WORD) && w.length() == 3 && (w.charAt(0) == 'G' || w.charAt(0) == 'g')
        && (w.charAt(1) == 'P' || w.charAt(1) == 'p') && w.charAt(2) >= '1' && w.charAt(2) <= '9';
  }

  /** The end of the system variable path starting with the {@code $} at {@code from}. */
  private static int systemVariableEnd(String text, int from) {
    int n = text.length();
    int j = from + 1;
    if (j < n && text.charAt(j) == '[') {
      int close = text.indexOf(']', j);
      if (close > j + 1 && isWordRun(text, j + 1, close)) {
        j = close + 1;
      }
    }
    while (true) {
      while (j < n && isWordPart(text.charAt(j))) {
        j++;
      }
      if (j < n && text.charAt(j) == '[') {
        int k = j + 1;
        while (k < n && isDigit(text.charAt(k))) {
          k++;
        }
        if (k > j + 1 && k < n && text.charAt(k) == ']') {
          j = k + 1;
          continue;
        }
        return j;
      }
      if (j + 1 < n && text.charAt(j) == '.' && (text.charAt(j + 1) == '$' || isWordStart(text.charAt(j + 1)))) {
        j += 2;
        continue;
      }
      return j;
    }
  }

  private static boolean isWordRun(String text, int from, int to) {
    for (int k = from; k < to; k++) {
      if (!isWordPart(text.charAt(k))) {
        return false;
      }
    }
    return true;
  }

  /**
   * Where an item comment starting at {@code from} ends: at the {@code ]} that closes its item.
   * Brackets inside it pair up ({@code R[103:Z-PR[38]]}, a comment a controller keeps as typed).
   */
  private static int commentEnd(String text, int from) {
    int depth = 0;
    for (int k = from; k < text.length(); k++) {
      char c = text.charAt(k);
      if (c == '[') {
        depth++;
      } else if (c == ']') {
        if (depth == 0) {
          return k;
        }
        depth--;
      }
    }
    int first = text.indexOf(']', from);
    return first < 0 ? text.length() : first;
  }

  private static Kind single(char c) {
    return switch (c) {
      case ']' -> Kind.RBRACKET;
      case '(' -> Kind.LPAREN;
      case ')' -> Kind.RPAREN;
      case '{' -> Kind.LBRACE;
      case '}' -> Kind.RBRACE;
      case ',' -> Kind.COMMA;
      case ';' -> Kind.SEMICOLON;
      case '=' -> Kind.EQ;
      case '+' -> Kind.PLUS;
      case '-' -> Kind.MINUS;
      case '*' -> Kind.STAR;
      case '/' -> Kind.SLASH;
      case '%' -> Kind.PERCENT;
      case '!' -> Kind.BANG;
      default -> Kind.BAD_CHAR;
    };
  }

  private static boolean isDigit(char c) {
    return c >= '0' && c <= '9';
  }

  private static boolean isWordStart(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == '$';
  }

  private static boolean isWordPart(char c) {
    return isWordStart(c) || isDigit(c);
  }
}
