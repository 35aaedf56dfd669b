package org.robotrun.io;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.robotrun.program.TpLexer;
import org.robotrun.program.TpStatementParser;
import org.robotrun.program.TpSyntaxError;
import org.robotrun.program.TpToken;
import org.robotrun.program.TpTokenCursor;
import org.robotrun.program.Instruction;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Program;
import org.robotrun.program.ProgramSource;

/**
 * Reads FANUC ASCII {@code .LS} programs (TP-LANGUAGE.md): {@code /PROG}, {@code /ATTR},
 * {@code /MN}, {@code /POS}, {@code /END}.
 *
 * <p>Reading never throws on bad content: it returns the program it could read plus a
 * diagnostic for every bad line ({@code file:line: message} naming what was expected). It
 * recovers at line boundaries, so one pass reports them all. Statements FANUC has but RobotRun
 * does not are reported as {@code not supported: NAME}; nothing is dropped silently. Only a
 * file that cannot be read at all (missing, a directory, no permission) is an {@link
 * IOException}.
 *
 * <p>Normalisation, so that read → write → read gives the same model: missing /ATTR entries get
 * the defaults a controller writes, and LINE_COUNT is set to the real number of lines (with a
 * warning when the file said otherwise).
 */
public final class LsReader {
  /** Largest .LS file read (a controller's biggest programs are a few MiB of positions). */
  public static final long MAX_FILE_BYTES = 16L << 20;

  private LsReader() {}

  /** Reads a file; CALL targets are not checked (the program set is unknown). */
  public static LsReadResult read(Path file) throws IOException {
    return read(file.toString(), readBytes(file));
  }

  /**
   * Reads a file as {@link #read(Path)} does, and warns on the /PROG line when the file's name
   * (without {@code .LS}, any case) is not the program's name: a controller loads a program by
   * its /PROG name, so a student who renamed PICK3.LS to PICK.LS still has a program PICK3.
   */
  public static LsReadResult readCheckingFileName(Path file) throws IOException {
    byte[] bytes = readBytes(file);
    LsReadResult r = read(file.toString(), bytes);
    String fileName = file.getFileName().toString();
    boolean ls = fileName.length() > 3 && fileName.regionMatches(true, fileName.length() - 3, ".ls", 0, 3);
    String stem = ls ? fileName.substring(0, fileName.length() - 3) : fileName;
    String program = r.program().name();
    int line = progLine(decode(bytes));
    if (line == 0 || stem.equalsIgnoreCase(program)
        || r.diagnostics().stream().anyMatch(d -> d.isError() && d.line() == line)) {
      // no /PROG, or a bad one (already an error): the name came from the file
      return r;
    }
    List<Diagnostic> all = new ArrayList<>(r.diagnostics());
    all.add(Diagnostic.warning(r.file(), line, "the program is named " + program + " (/PROG) but the file is "
        + fileName + ": a controller loads it as " + program + ", not " + stem.toUpperCase(Locale.ROOT)));
    return new LsReadResult(r.file(), r.program(), all, r.sourceLines());
  }

  /** The file's bytes, within {@link #MAX_FILE_BYTES}; a FIFO, device or folder is refused unopened. */
  private static byte[] readBytes(Path file) throws IOException {
    return BoundedFiles.read(file, MAX_FILE_BYTES, ".LS programs");
  }

  /** The 1-based line of the /PROG header, 0 when there is none. */
  private static int progLine(String text) {
    String[] lines = text.split("\r?\n|\r", -1);
    for (int i = 0; i < lines.length; i++) {
      String t = lines[i].strip();
      if (t.startsWith("\uFEFF")) {
        t = t.substring(1);
      }
      if (t.regionMatches(true, 0, "/PROG", 0, 5)) {
        return i + 1;
      }
    }
    return 0;
  }

  /** Reads a file's bytes (already loaded) as {@link #read(Path)} does; {@code name} names it in messages. */
  public static LsReadResult read(String name, byte[] bytes) {
    int badLine = firstNonUtf8Line(bytes);
    java.nio.charset.Charset cs = badLine == 0 ? StandardCharsets.UTF_8 : StandardCharsets.ISO_8859_1;
    LsReadResult r = new Parse(name, decode(bytes), bytes, cs).run();
    if (badLine == 0) {
      return r;
    }
    List<Diagnostic> all = new ArrayList<>(r.diagnostics());
    all.add(Diagnostic.warning(name, badLine,
        "not UTF-8: read as Latin-1 (ISO-8859-1), as controllers write it; written back in Latin-1"));
    return new LsReadResult(r.file(), r.program(), all, r.sourceLines());
  }

  /** Reads a file and checks CALL targets against {@code knownPrograms} (names, any case). */
  public static LsReadResult read(Path file, Set<String> knownPrograms) throws IOException {
    return read(file).withCallTargetsChecked(knownPrograms);
  }

  /** Parses text; CALL targets are not checked. */
  public static LsReadResult parse(String fileName, String text) {
    return new Parse(fileName, text, text.getBytes(StandardCharsets.UTF_8), StandardCharsets.UTF_8).run();
  }

  /** Parses text and checks CALL targets against {@code knownPrograms}. */
  public static LsReadResult parse(String fileName, String text, Set<String> knownPrograms) {
    return parse(fileName, text).withCallTargetsChecked(knownPrograms);
  }

  /**
   * Bytes to text: UTF-8 when the bytes are valid UTF-8 (ASCII, as controllers write, included),
   * else Latin-1, which maps every byte to one character. So a comment in another 8-bit encoding
   * is never replaced by U+FFFD, and binary garbage reaches the parser (and is reported) instead
   * of failing the read.
   */
  static String decode(byte[] bytes) {
    try {
      return StandardCharsets.UTF_8.newDecoder()
          .onMalformedInput(CodingErrorAction.REPORT)
          .onUnmappableCharacter(CodingErrorAction.REPORT)
          .decode(ByteBuffer.wrap(bytes))
          .toString();
    } catch (CharacterCodingException e) {
      return new String(bytes, StandardCharsets.ISO_8859_1);
    }
  }

  /** The 1-based line of the first byte sequence that is not UTF-8, or 0 when all of it is. */
  static int firstNonUtf8Line(byte[] bytes) {
    try {
      StandardCharsets.UTF_8.newDecoder()
          .onMalformedInput(CodingErrorAction.REPORT)
          .onUnmappableCharacter(CodingErrorAction.REPORT)
          .decode(ByteBuffer.wrap(bytes));
      return 0;
    } catch (CharacterCodingException e) {
      // Find the first bad sequence by decoding line by line (rare path: only for non-UTF-8 files).
      int line = 1;
      int start = 0;
      for (int i = 0; i <= bytes.length; i++) {
        if (i == bytes.length || bytes[i] == '\n') {
          try {
            StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                .decode(ByteBuffer.wrap(bytes, start, i - start));
          } catch (CharacterCodingException bad) {
            return line;
          }
          line++;
          start = i + 1;
        }
      }
      return 1;
    }
  }

  /** One parse: the mutable state of reading one file, used once. */
  private static final class Parse {
    private final String file;
    private final String[] lines;
    private final List<Diagnostic> diags = new ArrayList<>();

    private String name;
    private final Map<String, String> attributes = new LinkedHashMap<>();
    private String comment = "";
    private int declaredLineCount = -1;
    private int lineCountLine;
    private final List<Instruction> instructions = new ArrayList<>();
    private final List<Integer> sourceLines = new ArrayList<>();
    private final Map<String, int[]> unsupportedSeen = new java.util.HashMap<>();
    private final Set<Integer> otherGroupsOnly = new java.util.HashSet<>();
    private Map<Integer, LocalPosition> positions = Map.of();

    private final String text;
    private final byte[] bytes;
    private final java.nio.charset.Charset charset;
    private final List<Integer> statementStart = new ArrayList<>();
    /** Statements whose text was mended (not only renumbered): an edit writes them afresh. */
    private final Set<Integer> mendedText = new java.util.HashSet<>();
    private final List<String> sectionOrder = new ArrayList<>();
    private final Map<String, Integer> sectionIndex = new java.util.HashMap<>();

    Parse(String file, String text, byte[] bytes, java.nio.charset.Charset charset) {
      this.file = file;
      this.text = text;
      this.bytes = bytes;
      this.charset = charset;
      // Some Windows editors put a UTF-8 byte-order mark before '/PROG'; it is not text.
      this.lines = splitLines(text.startsWith("\uFEFF") ? text.substring(1) : text);
      this.name = defaultName(file);
    }

    LsReadResult run() {
      int i = 0;
      int n = lines.length;
      while (i < n && lines[i].isBlank()) {
        i++;
      }
      if (i == n) {
        diags.add(Diagnostic.error(file, 1, "empty file: expected an ASCII .LS program starting with '/PROG  NAME'"));
        return result();
      }
      if (!"/PROG".equals(sectionHeader(lines[i]))) {
        if (looksBinary(lines[i])) {
          diags.add(Diagnostic.error(file, i + 1, "not a text file: expected an ASCII .LS program starting with '/PROG  NAME'"));
          return result();
        }
        diags.add(Diagnostic.error(file, i + 1, "expected '/PROG  NAME' (an ASCII .LS program), found '" + clip(lines[i]) + "'"));
      }
      if ("/PROG".equals(sectionHeader(lines[i]))) {
        // a lone CR ends a line too (splitLines): worth a word, once, in a file that is a program
        for (int c = text.indexOf('\r'); c >= 0; c = text.indexOf('\r', c + 1)) {
          if (c + 1 == text.length() || text.charAt(c + 1) != '\n') {
            mend(rawLines(text.substring(0, c + 1)).size(),
                "a line ending in a lone CR (an old Mac editor's line end): read as a line break");
            break;
          }
        }
      }
      boolean sawProg = false;
      boolean sawAttr = false;
      boolean sawMn = false;
      boolean sawPos = false;
      boolean sawEnd = false;
      while (i < n) {
        String header = sectionHeader(lines[i]);
        if (header == null) {
          i++; // text before any section: already reported above
          continue;
        }
        int start = i + 1;
        int end = start;
        while (end < n && sectionHeader(lines[end]) == null) {
          end++;
        }
        int headerLine = i + 1;
        sectionOrder.add(header);
        sectionIndex.putIfAbsent(header, i);
        switch (header) {
          case "/PROG" -> {
            if (sawProg) {
              diags.add(Diagnostic.error(file, headerLine, "second /PROG: one file holds one program"));
            } else {
              prog(lines[i], headerLine);
              sawProg = true;
            }
            blankOnly(start, end, "/PROG");
          }
          case "/ATTR" -> {
            if (sawAttr) {
              diags.add(Diagnostic.error(file, headerLine, "second /ATTR section"));
            }
            sawAttr = true;
            attr(start, end);
          }
          case "/MN" -> {
            if (sawMn) {
              diags.add(Diagnostic.error(file, headerLine, "second /MN section"));
            }
            sawMn = true;
            mn(start, end);
          }
          case "/POS" -> {
            if (sawPos) {
              diags.add(Diagnostic.error(file, headerLine, "second /POS section"));
            }
            if (!sawMn) {
              diags.add(Diagnostic.error(file, headerLine,
                  "/POS before /MN: expected /PROG, /ATTR, /MN, /POS, /END in that order"));
            }
            sawPos = true;
            List<String> body = new ArrayList<>(end - start);
            for (int k = start; k < end; k++) {
              body.add(lines[k]);
            }
            positions = LsPositionParser.parse(file, body, start + 1, diags, otherGroupsOnly);
          }
          case "/END" -> {
            sawEnd = true;
            for (int k = start; k < end; k++) {
              if (!lines[k].isBlank()) {
                diags.add(Diagnostic.warning(file, k + 1, "text after /END is ignored"));
                break;
              }
            }
          }
          default -> {
            // Controllers write an empty /APPL into most files; only content is worth a word.
            int content = 0;
            for (int k = start; k < end; k++) {
              content += lines[k].isBlank() ? 0 : 1;
            }
            if (content > 0) {
              diags.add(Diagnostic.warning(file, headerLine,
                  "not supported: section " + header + " (its " + content + " lines are kept, not used)"));
            }
          }
        }
        if (sawEnd) {
          break;
        }
        i = end;
      }
      int last = Math.max(1, n);
      if (!sawProg && diags.isEmpty()) {
        diags.add(Diagnostic.error(file, 1, "missing '/PROG  NAME'"));
      }
      if (!sawMn) {
        diags.add(Diagnostic.error(file, last, "missing /MN section (the program body)"));
      }
      if (!sawEnd) {
        diags.add(Diagnostic.error(file, last, "file ends without /END (truncated?)"));
      }
      return result();
    }

    private LsReadResult result() {
      if (declaredLineCount >= 0 && declaredLineCount != instructions.size()) {
        diags.add(Diagnostic.warning(file, lineCountLine,
            "LINE_COUNT = " + declaredLineCount + " but /MN has " + instructions.size() + " lines; using "
                + instructions.size()));
      }
      Map<String, String> attrs = new LinkedHashMap<>(attributes);
      for (Map.Entry<String, String> d : LsAttributes.DEFAULTS.entrySet()) {
        attrs.putIfAbsent(d.getKey(), d.getValue());
      }
      attrs.put(LsAttributes.LINE_COUNT, Integer.toString(instructions.size()));
      Program program = new Program(name, attrs, comment, instructions, positions);
      for (Diagnostic d : LsProgramChecks.check(file, program, sourceLines)) {
        // A point of another motion group only (GP2 and no GP1) is there; it was reported once.
        boolean otherGroup = otherGroupsOnly.stream().anyMatch(n -> d.message().startsWith("P[" + n + "] is used but /POS has no"));
        if (!otherGroup) {
          diags.add(d);
        }
      }
      return new LsReadResult(file, withSource(program), diags, sourceLines);
    }

    /**
     * The program with the text it was read from, when the file has the usual shape (/PROG,
     * /ATTR, optionally /APPL, /MN, /POS, /END in that order, each once); else the program alone,
     * and the writer lays the whole file out afresh.
     */
    private Program withSource(Program program) {
      if (!usualOrder(sectionOrder) || bytes == null) {
        return program;
      }
      List<String> raw = rawLines(text);
      if (raw.size() != lines.length) {
        return program;
      }
      int mn = sectionIndex.get("/MN");
      int tailStart = sectionIndex.getOrDefault("/POS", sectionIndex.get("/END"));
      int firstStatement = statementStart.isEmpty() ? tailStart : statementStart.get(0);
      List<String> header = raw.subList(0, firstStatement);
      // /APPL and any other section between /ATTR and /MN (a controller may list /APPL twice)
      int applStart = mn;
      for (String section : sectionOrder) {
        if (!CORE_SECTIONS.contains(section)) {
          applStart = Math.min(applStart, sectionIndex.get(section));
        }
      }
      List<String> appl = raw.subList(applStart, mn);
      String lineEnd = text.contains("\r\n") ? "\r\n" : text.indexOf('\n') < 0 && text.indexOf('\r') >= 0 ? "\r" : "\n";
      List<List<String>> statements = new ArrayList<>();
      for (int j = 0; j < statementStart.size(); j++) {
        int from = statementStart.get(j);
        int to = j + 1 < statementStart.size() ? statementStart.get(j + 1) : tailStart;
        if (to < from) {
          return program;
        }
        if (to == from || j > 0 && statementStart.get(j - 1) == from || mendedText.contains(j)) {
          // (a mended statement, as `R[1]=[R80]/2`, is written as it was read: R[1]=R[80]/2)
          // a statement and the remark after its ';' share a line: an edit lays both out afresh
          statements.add(List.of());
          continue;
        }
        statements.add(raw.subList(from, to));
      }
      ProgramSource src = new ProgramSource(bytes, charset, lineEnd, program, header, appl, statements,
          raw.subList(tailStart, raw.size()));
      return new Program(program.name(), program.attributes(), program.comment(), program.lines(),
          program.positions(), java.util.Optional.of(src));
    }

    private static final Set<String> CORE_SECTIONS = Set.of("/PROG", "/ATTR", "/MN", "/POS", "/END");

    /**
     * /PROG, optionally /ATTR, any other sections (/APPL, once or more), /MN, optionally /POS,
     * /END: the shape whose text the writer can keep.
     */
    private static boolean usualOrder(List<String> order) {
      int i = 0;
      if (order.isEmpty() || !order.get(i++).equals("/PROG")) {
        return false;
      }
      if (i < order.size() && order.get(i).equals("/ATTR")) {
        i++;
      }
      while (i < order.size() && !CORE_SECTIONS.contains(order.get(i))) {
        i++;
      }
      if (i >= order.size() || !order.get(i++).equals("/MN")) {
        return false;
      }
      if (i < order.size() && order.get(i).equals("/POS")) {
        i++;
      }
      return i == order.size() - 1 && order.get(i).equals("/END");
    }

    /** The text's lines split as {@link #splitLines} splits them, each keeping its line end. */
    private static List<String> rawLines(String text) {
      List<String> out = new ArrayList<>();
      int s = 0;
      for (int i = 0; i < text.length(); i++) {
        char c = text.charAt(i);
        if (c == '\n' || c == '\r' && (i + 1 == text.length() || text.charAt(i + 1) != '\n')) {
          out.add(text.substring(s, i + 1));
          s = i + 1;
        }
      }
      if (s < text.length()) {
        out.add(text.substring(s));
      }
      return out;
    }

    // ---- /PROG --------------------------------------------------------------------------

    private void prog(String text, int line) {
      String[] words = text.substring("/PROG".length()).trim().split("\\s+");
      if (words.length == 0 || words[0].isEmpty()) {
        diags.add(Diagnostic.error(file, line, "expected a program name after /PROG"));
        return;
      }
      if (!Program.isValidName(words[0])) {
        diags.add(Diagnostic.error(file, line, "'" + clip(words[0])
            + "' is not a program name: expected letters, digits and '_', not starting with a digit, at most "
            + Program.MAX_NAME_LENGTH + " characters"));
      } else {
        name = words[0].toUpperCase(Locale.ROOT);
      }
      if (words.length > 1) {
        String sub = words[1];
        attributes.put(Program.SUBTYPE_KEY, sub);
        if (!sub.equalsIgnoreCase("Cond") && !sub.equalsIgnoreCase("Macro") && !sub.equalsIgnoreCase("Makro") // German listing
            && !sub.equalsIgnoreCase("Job") && !sub.equalsIgnoreCase("Process")) {
          diags.add(Diagnostic.warning(file, line,
              "not supported: program sub-type '" + clip(sub) + "' (read as a normal program)"));
        }
      }
    }

    private void blankOnly(int start, int end, String section) {
      for (int k = start; k < end; k++) {
        if (!lines[k].isBlank()) {
          diags.add(Diagnostic.error(file, k + 1, "unexpected text after " + section + ": expected /ATTR or /MN"));
          return;
        }
      }
    }

    // ---- /ATTR --------------------------------------------------------------------------

    private void attr(int start, int end) {
      int k = start;
      while (k < end) {
        if (lines[k].isBlank()) {
          k++;
          continue;
        }
        int first = k;
        StringBuilder entry = new StringBuilder(lines[k].strip());
        // Only a grouped entry ("TCD:  STACK_SIZE = 0,") runs over several lines; a plain entry
        // missing its ';' is reported alone instead of swallowing the entries after it.
        boolean grouped = isGroupedStart(entry.toString());
        while (grouped && !endsWithSemicolon(entry) && k + 1 < end) {
          k++;
          entry.append('\n').append(lines[k].strip());
        }
        k++;
        attrEntry(entry.toString(), first + 1);
      }
    }

    private static boolean isGroupedStart(String text) {
      int colon = text.indexOf(':');
      int eq = text.indexOf('=');
      return colon > 0 && (eq < 0 || colon < eq) && isKey(text.substring(0, colon).strip());
    }

    private static boolean endsWithSemicolon(StringBuilder sb) {
      return sb.length() > 0 && sb.charAt(sb.length() - 1) == ';';
    }

    private void attrEntry(String text, int line) {
      if (!text.endsWith(";") && !text.contains("\n") && text.indexOf('=') > 0
          && isKey(text.substring(0, text.indexOf('=')).strip())) {
        // "VERSION = 0" typed without its ';'
        mend(line, "no ';' at the end of the /ATTR entry: read as if it were there");
        text = text + ";";
      }
      if (!text.endsWith(";")) {
        diags.add(Diagnostic.error(file, line, "/ATTR entry does not end with ';': expected 'KEY = value;'"));
        return;
      }
      String body = text.substring(0, text.length() - 1);
      int colon = body.indexOf(':');
      int eq = body.indexOf('=');
      if (isGroupedStart(body)) {
        // A grouped entry: "TCD:  STACK_SIZE = 0, TASK_PRIORITY = 50, ...".
        String key = body.substring(0, colon).strip().toUpperCase(Locale.ROOT);
        List<String> parts = new ArrayList<>();
        for (String sub : body.substring(colon + 1).split(",")) {
          int e = sub.indexOf('=');
          if (e < 0 || !isKey(sub.substring(0, e).strip())) {
            diags.add(Diagnostic.error(file, line, "/ATTR " + key
                + ": expected 'NAME = value' entries separated by ',', found '" + clip(sub.strip()) + "'"));
            return;
          }
          parts.add(sub.substring(0, e).strip() + " = " + sub.substring(e + 1).strip());
        }
        putAttr(key, String.join(", ", parts), line);
        return;
      }
      if (eq < 0 || !isKey(body.substring(0, eq).strip())) {
        diags.add(Diagnostic.error(file, line, "expected 'KEY = value;' in /ATTR, found '" + clip(text) + "'"));
        return;
      }
      String key = body.substring(0, eq).strip().toUpperCase(Locale.ROOT);
      String value = body.substring(eq + 1).strip();
      switch (key) {
        case LsAttributes.COMMENT, "KOMMENTAR" -> comment = value.length() >= 2 && value.startsWith("\"") && value.endsWith("\"")
            ? value.substring(1, value.length() - 1) : value;
        case LsAttributes.LINE_COUNT, "ZEILEN" -> {
          lineCountLine = line;
          try {
            declaredLineCount = Integer.parseInt(value);
          } catch (NumberFormatException e) {
            diags.add(Diagnostic.warning(file, line, "LINE_COUNT '" + clip(value) + "' is not a number; using the real count"));
          }
          putAttr(key, value, line);
        }
        default -> putAttr(key, value, line);
      }
    }

    private void putAttr(String key, String value, int line) {
      if (attributes.put(key, value) != null) {
        diags.add(Diagnostic.warning(file, line, "/ATTR " + key + " appears twice; the last one counts"));
      }
    }

    private static boolean isKey(String s) {
      if (s.isEmpty()) {
        return false;
      }
      for (int i = 0; i < s.length(); i++) {
        char c = s.charAt(i);
        // German listings write keys such as "EIGN." and "PROG_GRÖßE" (any letter, and '.')
        if (!Character.isLetterOrDigit(c) && c != '_' && c != '.') {
          return false;
        }
      }
      return true;
    }

    // ---- /MN ----------------------------------------------------------------------------

    private void mn(int start, int end) {
      int k = start;
      while (k < end) {
        String text = lines[k];
        int line = k + 1;
        k++;
        if (text.isBlank()) {
          continue;
        }
        int p = skipSpaces(text, 0);
        int digitsStart = p;
        while (p < text.length() && Character.isDigit(text.charAt(p)) && text.charAt(p) < 128) {
          p++;
        }
        int digitsEnd = p;
        if (p > digitsStart && skipSpaces(text, p) > p && skipSpaces(text, p) < text.length()
            && text.charAt(skipSpaces(text, p)) == ':') {
          // " 3 :  R[2]=1 ;": spaces between the number and its ':'
          mend(line, "spaces between the line number and ':': read as '" + text.substring(digitsStart, p) + ":'");
          p = skipSpaces(text, p);
        }
        boolean numbered = p > digitsStart && p < text.length() && text.charAt(p) == ':';
        boolean colonOnly = !numbered && p == digitsStart && p < text.length() && text.charAt(p) == ':';
        int expected = instructions.size() + 1;
        boolean unnumbered = !numbered && !colonOnly && p == digitsStart && p < text.length()
            && (Character.isLetter(text.charAt(p)) || text.charAt(p) == '!' || text.startsWith("//", p));
        if (!numbered && !colonOnly && !unnumbered) {
          diags.add(Diagnostic.of(file, line, digitsStart + 1, Diagnostic.Severity.ERROR, Diagnostic.Kind.SYNTAX,
              "expected a numbered line 'N:  instruction ;', found '" + clip(text.strip()) + "'"));
          continue;
        }
        // the statement starts after the ':' (or, on a line without its number, at its first word)
        int from = unnumbered ? p : p + 1;
        boolean textMended = false;
        if (unnumbered) {
          // "J P[1] 100% FINE ;" typed without "N:": the offline converter numbers lines in file order
          mend(line, "a line without its number: read as line " + expected);
        } else if (colonOnly) {
          // "    : ! remark ;" after a finished statement: the offline converter numbers it
          mend(line, "a line with ':' and no number after a finished statement: read as line " + expected);
        } else {
          int number;
          try {
            number = Integer.parseInt(text.substring(digitsStart, digitsEnd));
          } catch (NumberFormatException e) {
            number = -1;
          }
          if (number != expected) {
            // Hand-edited files repeat or reorder numbers; the offline converter numbers lines in file order.
            mend(line, "line number " + clip(text.substring(digitsStart, digitsEnd)) + " out of order or repeated: read as line "
                + expected);
          }
        }
        Body body = body(text, from, line);
        String remarkAfter = null;
        if (!body.terminated) {
          int semi = remarkSemicolon(text, from);
          if (semi > 0) {
            // "R[1]=2 ; ! why": a remark after the ';' becomes a remark line of its own
            remarkAfter = text.substring(semi + 1).strip();
            body = body(text.substring(0, semi + 1), from, line);
          }
        }
        List<TpToken> tokens = body.tokens;
        boolean terminated = body.terminated;
        StringBuilder raw = new StringBuilder(body.text);
        int firstLine = k - 1;
        while (!terminated && k < end && isContinuation(lines[k]) && !isRemarkContinuation(lines[k])) {
          // C motion: "  5:C P[2]" then "    :  P[3] 100mm/sec FINE ;" form one statement;
          // other statements a controller lists over several lines continue the same way.
          String cont = lines[k];
          int colon = cont.indexOf(':');
          Body second = body(cont, colon + 1, k + 1);
          k++;
          List<TpToken> joined = new ArrayList<>(tokens.subList(0, tokens.size() - 1));
          joined.addAll(second.tokens);
          tokens = joined;
          terminated = second.terminated;
          raw.append('\n').append(cont, 0, cont.length() - (second.terminated ? cont.length() - cont.lastIndexOf(';') : 0));
        }
        Instruction in;
        final int lineBase = firstLine;
        List<TpToken> asWritten = tokens;
        tokens = bracketedRegisters(tokens);
        textMended |= tokens != asWritten;
        try {
          TpStatementParser.Parsed parsed = TpStatementParser.parseMendingHandEdits(tokens,
              l -> l - 1 >= lineBase && l - 1 < lines.length ? lines[l - 1] : null);
          in = parsed.instruction();
          for (String w : parsed.warnings()) {
            diags.add(Diagnostic.warning(file, line, w));
            textMended |= w.startsWith("mended: ");
          }
          if (in instanceof Instruction.Move m) {
            for (var o : m.options()) {
              if (o instanceof org.robotrun.program.Motion.RawOption r) {
                notSupported(line, 1, r.what(), true, " (the motion runs without it)");
              }
            }
          }
          if (!terminated) {
            mend(line, "no ';' at the end of the line: read as if it were there");
            textMended = true;
          }
        } catch (TpSyntaxError e) {
          String rawText = stripSemicolon(raw.toString().strip());
          if (e.unsupported().isPresent()) {
            String what = e.unsupported().get();
            in = new Instruction.Unsupported(rawText, what, e.runnable());
            notSupported(e.line(), e.column(), what, e.runnable(),
                e.runnable() ? " (the line is skipped when it runs)" : " (the line alarms when it runs)");
          } else {
            diags.add(Diagnostic.of(file, e.line(), e.column(), Diagnostic.Severity.ERROR, Diagnostic.Kind.SYNTAX,
                e.getMessage()));
            // Keep the numbering of the following lines: the bad line stays as commented-out text.
            String one = rawText.replace('\n', ' ');
            in = new Instruction.CommentedOut(one.startsWith("//") ? one.substring(2).stripTrailing() : one);
          }
        }
        int blockEnd = k;
        while (blockEnd < end && isSubLine(lines[blockEnd], p)) {
          blockEnd++;
        }
        if (blockEnd > k && blockEnd < end && lines[blockEnd].strip().startsWith("------")) {
          // A point-logic block under a motion ("TB .10sec,P-SPS" then indented "1:  DO[3]=ON ;"
          // lines and "------ ;"): kept with the motion's last option, written back as read.
          int blockStart = k;
          k = blockEnd + 1;
          StringBuilder block = new StringBuilder();
          for (int b = blockStart; b < k; b++) {
            block.append('\n').append(lines[b].stripTrailing());
          }
          in = withBlock(in, block.toString(), line);
        }
        if (textMended && !(in instanceof Instruction.CommentedOut)) {
          mendedText.add(instructions.size());
        }
        instructions.add(in);
        sourceLines.add(line);
        statementStart.add(line - 1);
        if (remarkAfter != null) {
          mend(line, "a remark after ';': kept as remark line " + (instructions.size() + 1));
          // as a '!' line keeps the text after the '!' (its leading space too)
          String r = remarkAfter.startsWith("//") ? remarkAfter.substring(2) : remarkAfter.substring(1);
          instructions.add(new Instruction.Comment(stripSemicolon(r.stripTrailing())));
          sourceLines.add(line);
          statementStart.add(line - 1);
        }
      }
    }

    /**
     * A warning for text a controller would not write and the offline converter mends. Saved
     * unedited, the file is written back as read; an edit writes its lines numbered afresh.
     */
    private void mend(int line, String what) {
      diags.add(Diagnostic.warning(file, line, "mended: " + what));
    }

    /** {@code R}, {@code PR}, {@code AR} or {@code SR} and a number, as in a hand-written {@code [R80]}. */
    private static final java.util.regex.Pattern BRACKETED_REGISTER =
        java.util.regex.Pattern.compile("(?i)(R|PR|AR|SR)([0-9]{1,9})");

    /**
     * The tokens with every {@code [R80]} where a value stands (after '=', an operator, '(' or
     * ',') read as {@code R[80]} (also {@code [PR3]}, {@code [AR1]}, {@code [SR2]}), each a
     * warning naming the line; the same list when there is none. An index ({@code R[80]},
     * {@code $X[R1]}), a remark and MESSAGE text are never touched.
     */
    private List<TpToken> bracketedRegisters(List<TpToken> tokens) {
      if (tokens.isEmpty() || tokens.get(0).is(TpToken.Kind.BANG)) {
        return tokens;
      }
      List<TpToken> out = null;
      for (int i = 0; i < tokens.size(); i++) {
        TpToken t = tokens.get(i);
        java.util.regex.Matcher m = i + 2 < tokens.size() && t.is(TpToken.Kind.LBRACKET)
            && tokens.get(i + 1).is(TpToken.Kind.WORD) && tokens.get(i + 2).is(TpToken.Kind.RBRACKET)
            && (i == 0 || !endsOperand(tokens.get(i - 1)))
            ? BRACKETED_REGISTER.matcher(tokens.get(i + 1).text()) : null;
        if (m != null && m.matches()) {
          if (out == null) {
            out = new ArrayList<>(tokens.subList(0, i));
          }
          String kind = m.group(1).toUpperCase(Locale.ROOT);
          int col = t.column();
          out.add(new TpToken(TpToken.Kind.WORD, kind, t.line(), col));
          out.add(new TpToken(TpToken.Kind.LBRACKET, "[", t.line(), col + kind.length()));
          out.add(new TpToken(TpToken.Kind.NUMBER, m.group(2), t.line(), col + kind.length() + 1));
          out.add(new TpToken(TpToken.Kind.RBRACKET, "]", t.line(), tokens.get(i + 2).column()));
          mend(t.line(), "read [" + tokens.get(i + 1).text() + "] as " + kind + "[" + m.group(2)
              + "] (a register written inside the brackets)");
          i += 2;
        } else if (out != null) {
          out.add(t);
        }
      }
      return out == null ? tokens : out;
    }

    /** Words a value follows: {@code IF [R3]>1}, {@code WAIT [R1]>2}, {@code [R1] AND [R2]}. */
    private static final Set<String> VALUE_AFTER = Set.of(
        "IF", "WAIT", "SELECT", "AND", "OR", "NOT", "MOD", "DIV", "TO", "DOWNTO", "WHEN");

    /** A token after which '[' opens an index or argument list ({@code R[}, {@code ][}, {@code $X[}), not a value. */
    private static boolean endsOperand(TpToken t) {
      if (t.is(TpToken.Kind.WORD) && VALUE_AFTER.contains(t.text().toUpperCase(Locale.ROOT))) {
        return false; // IF [R3]>1: a value follows the word
      }
      return switch (t.kind()) {
        case WORD, NUMBER, STRING, RBRACKET, RPAREN, ITEM_COMMENT, RAW -> true;
        default -> false;
      };
    }

    /** The index of a ';' followed only by a remark ({@code ! ...} or {@code // ...}), or -1. */
    private static int remarkSemicolon(String text, int from) {
      boolean quoted = false;
      int depth = 0;
      for (int i = from; i < text.length(); i++) {
        char c = text.charAt(i);
        if (c == '\'' || c == '"') {
          quoted = !quoted;
        } else if (!quoted && c == '[') {
          depth++;
        } else if (!quoted && c == ']') {
          depth--;
        } else if (!quoted && depth == 0 && c == ';') {
          String rest = text.substring(i + 1).strip();
          return rest.startsWith("!") || rest.startsWith("//") ? i : -1;
        }
      }
      return -1;
    }

    /** A ':' line holding a remark ({@code "    :  ! why ;"}): a line of its own, never the rest of a statement. */
    private static boolean isRemarkContinuation(String text) {
      int colon = text.indexOf(':');
      int p = skipSpaces(text, colon + 1);
      return p < text.length() && text.charAt(p) == '!';
    }

    private record Body(List<TpToken> tokens, boolean terminated, String text) {}

    /** Tokens of a statement starting at {@code from}, without its final {@code ;}. */
    private static Body body(String text, int from, int line) {
      int endIdx = text.length();
      while (endIdx > from && Character.isWhitespace(text.charAt(endIdx - 1))) {
        endIdx--;
      }
      boolean terminated = endIdx > from && text.charAt(endIdx - 1) == ';';
      if (terminated) {
        endIdx--;
      }
      String body = text.substring(from, endIdx);
      return new Body(TpLexer.tokenize(body, line, from + 1, true), terminated, body);
    }

    private static String stripSemicolon(String s) {
      return s.endsWith(";") ? s.substring(0, s.length() - 1).stripTrailing() : s;
    }

    /** Reports a kind RobotRun does not run once per file: the first line, and how many lines have it. */
    private void notSupported(int line, int column, String what, boolean runnable, String effect) {
      int[] seen = unsupportedSeen.get(what);
      String base = "not supported: " + what + effect;
      if (seen == null) {
        unsupportedSeen.put(what, new int[] {diags.size(), 0});
        diags.add(Diagnostic.of(file, line, column,
            runnable ? Diagnostic.Severity.WARNING : Diagnostic.Severity.ERROR, Diagnostic.Kind.UNSUPPORTED, base));
      } else {
        seen[1]++;
        Diagnostic d = diags.get(seen[0]);
        diags.set(seen[0], Diagnostic.of(d.file(), d.line(), d.column(), d.severity(), d.kind(),
            base + " (and " + seen[1] + " more line" + (seen[1] == 1 ? ")" : "s)")));
      }
    }


    /** A numbered line indented deeper than a statement whose ':' is at {@code colon}: a sub-line of its block. */
    private static boolean isSubLine(String text, int colon) {
      int p = skipSpaces(text, 0);
      int d = p;
      while (d < text.length() && text.charAt(d) >= '0' && text.charAt(d) <= '9') {
        d++;
      }
      return d > p && d < text.length() && text.charAt(d) == ':' && d > colon;
    }

    /** The motion with a point-logic block attached to its last (unsupported) option. */
    private Instruction withBlock(Instruction in, String block, int line) {
      if (in instanceof Instruction.Move m && !m.options().isEmpty()
          && m.options().get(m.options().size() - 1) instanceof org.robotrun.program.Motion.RawOption r) {
        List<org.robotrun.program.Motion.Option> opts = new ArrayList<>(m.options());
        opts.set(opts.size() - 1, new org.robotrun.program.Motion.RawOption(r.text() + block, r.what()));
        return new Instruction.Move(m.type(), m.target(), m.circularEnd(), m.speed(), m.termination(), opts, m.viaOptions());
      }
      diags.add(Diagnostic.error(file, line + 1,
          "indented sub-lines belong to a motion with a TIME BEFORE/AFTER or DISTANCE BEFORE point-logic action"));
      return in;
    }

    private static boolean isContinuation(String text) {
      int p = skipSpaces(text, 0);
      return p > 0 && p < text.length() && text.charAt(p) == ':';
    }

    // ---- helpers ------------------------------------------------------------------------

    private static int skipSpaces(String s, int from) {
      int p = from;
      while (p < s.length() && (s.charAt(p) == ' ' || s.charAt(p) == '\t')) {
        p++;
      }
      return p;
    }

    /** The section word if the line starts one ({@code /MN}), else null. */
    private static String sectionHeader(String line) {
      if (line.length() < 2 || line.charAt(0) != '/' || !Character.isLetter(line.charAt(1))) {
        return null;
      }
      int e = 1;
      while (e < line.length() && (Character.isLetterOrDigit(line.charAt(e)) || line.charAt(e) == '_')) {
        e++;
      }
      return line.substring(0, e).toUpperCase(Locale.ROOT);
    }

    private static boolean looksBinary(String line) {
      int bad = 0;
      for (int i = 0; i < line.length(); i++) {
        char c = line.charAt(i);
        // C0 and C1 control characters (the latter are what stray bytes 0x80-0x9F become).
        if ((c < 0x20 && c != '\t') || (c >= 0x7f && c < 0xa0) || c == '\uFFFD') {
          bad++;
        }
      }
      return bad > 0;
    }

    /** Lines split at LF, CRLF and a lone CR (old Mac editors), without their line ends. */
    private static String[] splitLines(String text) {
      List<String> out = new ArrayList<>();
      for (String raw : rawLines(text)) {
        int e = raw.length();
        if (e > 0 && raw.charAt(e - 1) == '\n') {
          e--;
        }
        if (e > 0 && raw.charAt(e - 1) == '\r') {
          e--;
        }
        out.add(raw.substring(0, e));
      }
      return out.toArray(String[]::new);
    }

    private static String defaultName(String file) {
      String base = file.substring(Math.max(file.lastIndexOf('/'), file.lastIndexOf('\\')) + 1);
      int dot = base.lastIndexOf('.');
      String stem = (dot > 0 ? base.substring(0, dot) : base).toUpperCase(Locale.ROOT);
      return Program.isValidName(stem) ? stem : "UNNAMED";
    }

    private static String clip(String s) {
      String t = s.length() > 40 ? s.substring(0, 40) + "..." : s;
      StringBuilder sb = new StringBuilder(t.length());
      for (int i = 0; i < t.length(); i++) {
        char c = t.charAt(i);
        sb.append(c < 0x20 || c == 0x7f ? '?' : c);
      }
      return sb.toString();
    }
  }
}
