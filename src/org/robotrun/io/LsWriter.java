package org.robotrun.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.robotrun.program.FanucFormat;
import org.robotrun.program.TpText;
import org.robotrun.program.Config;
import org.robotrun.program.Instruction;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Motion;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.ProgramSource;

/**
 * Writes a program as a FANUC ASCII {@code .LS} file a controller accepts: the five sections,
 * /ATTR with the controller's defaults for missing entries and the real LINE_COUNT, lines
 * numbered {@code "   7:"} with the motion type right after the colon ({@code "   7:J P[1] 30%
 * FINE    ;"}) and two spaces otherwise, register assignments and motions closed by four
 * spaces and {@code ;}, other statements by one, and position blocks in FANUC's number format.
 *
 * <p>The output is a function of the model only, so write → read → write gives the same bytes;
 * parentheses the model does not hold are added only where precedence needs them.
 */
public final class LsWriter {
  private LsWriter() {}

  /**
   * The file's bytes. A program read from a file and not edited since is written back byte for
   * byte; an edited one keeps the text of every part it did not change (lines, /ATTR, /APPL,
   * /POS, line ends, encoding), and new or changed parts are laid out as a controller writes them.
   */
  public static byte[] bytes(Program program) {
    if (program.source().isEmpty()) {
      return write(program).getBytes(StandardCharsets.UTF_8);
    }
    ProgramSource src = program.source().get();
    if (program.equals(src.asRead())) {
      return src.bytes();
    }
    return keepingSource(program, src).getBytes(src.charset());
  }

  /** The text of an edited program read from a file: untouched parts as read. */
  private static String keepingSource(Program program, ProgramSource src) {
    Program was = src.asRead();
    String eol = src.lineEnd();
    StringBuilder sb = new StringBuilder(src.bytes().length + 256);
    boolean sameHead = program.name().equals(was.name()) && program.comment().equals(was.comment())
        && withoutLineCount(program.attributes()).equals(withoutLineCount(was.attributes()));
    if (sameHead) {
      for (String h : src.header()) {
        sb.append(lineCountFixed(h, program.lineCount()));
      }
    } else {
      StringBuilder head = new StringBuilder();
      head.append("/PROG  ").append(program.name());
      String sub = program.attributes().get(Program.SUBTYPE_KEY);
      if (sub != null) {
        head.append('\t').append(sub);
      }
      head.append('\n');
      attributes(program, head);
      sb.append(head.toString().replace("\n", eol));
      src.appl().forEach(sb::append);
      sb.append("/MN").append(eol);
    }
    // Unchanged statements keep their text; identical statements are matched in order.
    Map<Instruction, java.util.ArrayDeque<List<String>>> pool = new java.util.HashMap<>();
    for (int i = 0; i < was.lineCount(); i++) {
      pool.computeIfAbsent(was.line(i + 1), k -> new java.util.ArrayDeque<>()).add(src.statements().get(i));
    }
    List<Instruction> lines = program.lines();
    for (int i = 0; i < lines.size(); i++) {
      java.util.ArrayDeque<List<String>> q = pool.get(lines.get(i));
      List<String> raw = q == null ? null : q.poll();
      if (raw == null || raw.isEmpty()) {
        StringBuilder one = new StringBuilder();
        line(i + 1, lines.get(i), one);
        sb.append(one.toString().replace("\n", eol));
      } else {
        sb.append(renumbered(raw.get(0), i + 1));
        for (int k = 1; k < raw.size(); k++) {
          sb.append(raw.get(k));
        }
      }
    }
    if (program.positions().equals(was.positions())) {
      src.tail().forEach(sb::append);
    } else {
      positionsKeepingSource(program, was, src.tail(), eol, sb);
    }
    return sb.toString();
  }

  /**
   * /POS of an edited program read from a file: every block the edit did not change keeps its
   * text, and so does every block the model does not hold (a SCARA or rail position, one never
   * taught, another group's): nothing RobotRun cannot hold is lost. Changed and new positions are
   * laid out afresh; a deleted one is left out.
   */
  private static void positionsKeepingSource(Program program, Program was, List<String> tail, String eol,
      StringBuilder sb) {
    Map<Integer, LocalPosition> now = program.positions();
    java.util.Set<Integer> written = new java.util.HashSet<>();
    StringBuilder out = new StringBuilder();
    int k = 0;
    // the /POS header line (when there is one) as read
    if (k < tail.size() && tail.get(k).strip().toUpperCase(java.util.Locale.ROOT).startsWith("/POS")) {
      out.append(tail.get(k++));
    } else {
      out.append("/POS").append(eol);
    }
    while (k < tail.size()) {
      String line = tail.get(k);
      String t = line.strip();
      java.util.regex.Matcher m = BLOCK_START.matcher(t);
      if (t.toUpperCase(java.util.Locale.ROOT).startsWith("/END")) {
        break;
      }
      if (!m.lookingAt()) {
        out.append(line);
        k++;
        continue;
      }
      int n = Integer.parseInt(m.group(1));
      int end = k;
      while (end < tail.size() && !tail.get(end).strip().startsWith("};")) {
        end++;
      }
      end = Math.min(end + 1, tail.size());
      LocalPosition p = now.get(n);
      boolean keep = p == null ? !was.positions().containsKey(n) : p.equals(was.positions().get(n));
      if (keep) {
        for (int j = k; j < end; j++) {
          out.append(tail.get(j));
        }
      } else if (p != null) {
        StringBuilder one = new StringBuilder();
        position(p, one);
        out.append(one.toString().replace("\n", eol));
      }
      written.add(n);
      k = end;
    }
    for (LocalPosition p : now.values()) {
      if (!written.contains(p.number())) {
        StringBuilder one = new StringBuilder();
        position(p, one);
        out.append(one.toString().replace("\n", eol));
      }
    }
    for (; k < tail.size(); k++) {
      out.append(tail.get(k));
    }
    if (!out.toString().contains("/END")) {
      out.append("/END").append(eol);
    }
    sb.append(out);
  }

  private static final java.util.regex.Pattern BLOCK_START = java.util.regex.Pattern.compile("P\\[(\\d{1,9})");

  private static Map<String, String> withoutLineCount(Map<String, String> attrs) {
    Map<String, String> m = new java.util.LinkedHashMap<>(attrs);
    m.remove(LsAttributes.LINE_COUNT);
    return m;
  }

  /** A /ATTR LINE_COUNT line with the real count; any other line as it is. */
  private static String lineCountFixed(String line, int count) {
    String t = line.stripLeading();
    // ZEILEN: the German listing's LINE_COUNT
    String key = t.regionMatches(true, 0, "ZEILEN", 0, 6) ? "ZEILEN" : LsAttributes.LINE_COUNT;
    if (!t.regionMatches(true, 0, key, 0, key.length())
        || !(t.length() > key.length() && (t.charAt(key.length()) == '=' || Character.isWhitespace(t.charAt(key.length()))))) {
      return line;
    }
    int eq = line.indexOf('=');
    int semi = line.indexOf(';', eq + 1);
    if (eq < 0 || semi < 0) {
      return line;
    }
    int v = eq + 1;
    while (v < semi && line.charAt(v) == ' ') {
      v++;
    }
    return line.substring(0, v) + count + line.substring(semi);
  }

  /** A statement's first line with line number {@code n} in the controller's {@code "%4d:"} form. */
  private static String renumbered(String first, int n) {
    int colon = first.indexOf(':');
    if (colon < 0) {
      return first;
    }
    String digits = first.substring(0, colon).strip();
    if (digits.equals(Integer.toString(n))) {
      return first;
    }
    return String.format(java.util.Locale.ROOT, "%4d", n) + first.substring(colon);
  }

  /** The file text of a program laid out afresh (LF line ends), as a controller writes a new program. */
  public static String write(Program program) {
    StringBuilder sb = new StringBuilder(64 + program.lineCount() * 40);
    sb.append("/PROG  ").append(program.name());
    String sub = program.attributes().get(Program.SUBTYPE_KEY);
    if (sub != null) {
      sb.append('\t').append(sub);
    }
    sb.append('\n');
    attributes(program, sb);
    sb.append("/MN\n");
    List<Instruction> lines = program.lines();
    for (int i = 0; i < lines.size(); i++) {
      line(i + 1, lines.get(i), sb);
    }
    sb.append("/POS\n");
    for (LocalPosition p : program.positions().values()) {
      position(p, sb);
    }
    sb.append("/END\n");
    return sb.toString();
  }

  /** Writes the file through {@link AtomicFiles}, so a crash never leaves half a program. */
  public static void write(Program program, Path file) throws IOException {
    AtomicFiles.write(file, bytes(program));
  }

  // ---- /ATTR --------------------------------------------------------------------------------

  private static void attributes(Program program, StringBuilder sb) {
    sb.append("/ATTR\n");
    Map<String, String> attrs = program.attributes();
    for (Map.Entry<String, String> d : LsAttributes.DEFAULTS.entrySet()) {
      String key = d.getKey();
      String value = key.equals(LsAttributes.LINE_COUNT)
          ? Integer.toString(program.lineCount())
          : attrs.getOrDefault(key, d.getValue());
      attribute(key, value, sb);
      if (key.equals("OWNER")) {
        attribute(LsAttributes.COMMENT, "\"" + program.comment() + "\"", sb);
      }
    }
    for (Map.Entry<String, String> e : attrs.entrySet()) {
      if (!LsAttributes.DEFAULTS.containsKey(e.getKey()) && !e.getKey().equals(LsAttributes.COMMENT)
          && !e.getKey().equals(Program.SUBTYPE_KEY)) {
        attribute(e.getKey(), e.getValue(), sb);
      }
    }
  }

  private static void attribute(String key, String value, StringBuilder sb) {
    if (key.equals(LsAttributes.TCD)) {
      // "TCD:  STACK_SIZE\t= 0," then one indented sub-entry per line, the last closed by ';'.
      String[] parts = value.split(",");
      for (int i = 0; i < parts.length; i++) {
        String part = parts[i].strip();
        int eq = part.indexOf('=');
        String sub = eq < 0 ? part : part.substring(0, eq).strip();
        String v = eq < 0 ? "" : part.substring(eq + 1).strip();
        String lead = (i == 0 ? "TCD:  " : "      ") + sub;
        sb.append(FanucFormat.padWithTabs(lead, 0)).append("= ").append(v).append(i == parts.length - 1 ? ";" : ",").append('\n');
      }
      return;
    }
    sb.append(FanucFormat.attrKey(key)).append("= ").append(value).append(";\n");
  }

  // ---- /MN ----------------------------------------------------------------------------------

  private static void line(int n, Instruction in, StringBuilder sb) {
    String num = Integer.toString(n);
    for (int i = num.length(); i < 4; i++) {
      sb.append(' ');
    }
    sb.append(num).append(':');
    if (in instanceof Instruction.Move m) {
      move(m, sb);
      return;
    }
    sb.append("  ");
    // the statement's text from the one printer of TP text
    TpText.statement(in, sb);
    sb.append(closesWithWideGap(in) ? "    ;\n" : " ;\n");
  }

  /** Controllers end motion and register-assignment lines with four spaces before the ';'. */
  private static boolean closesWithWideGap(Instruction in) {
    return in instanceof Instruction.AssignRegister
        || in instanceof Instruction.AssignPosReg
        || in instanceof Instruction.AssignPosElement
        // iRVision lines, as a controller lists them: "VISION RUN_FIND 'FIND'    ;", "R[4]=VR[1].MODELID    ;"
        || in instanceof Instruction.AssignFromVr
        || in instanceof Instruction.VisionRunFind
        || in instanceof Instruction.VisionGetOffset
        || in instanceof Instruction.VisionGetNFound;
  }

  private static void move(Instruction.Move m, StringBuilder sb) {
    // Controllers pad the via line of a C motion with four blanks, as they do before a motion line's ';'.
    TpText.move(m, TpText.CONTINUATION, sb);
    // A point-logic block kept with the last option: its sub-lines follow the motion line.
    String block = "";
    for (Motion.Option o : m.options()) {
      if (o instanceof Motion.RawOption x) {
        int nl = x.text().indexOf('\n');
        block = nl < 0 ? "" : x.text().substring(nl);
      }
    }
    sb.append("    ;").append(block).append('\n');
  }

  // ---- /POS ---------------------------------------------------------------------------------

  private static void position(LocalPosition p, StringBuilder sb) {
    sb.append("P[").append(p.number());
    if (!p.comment().isEmpty()) {
      sb.append(":\"").append(p.comment()).append('"');
    }
    sb.append("]{\n   GP1:\n\tUF : ").append(p.userFrame()).append(", UT : ").append(p.toolFrame()).append(',');
    switch (p.position()) {
      case Position.Cartesian c -> {
        sb.append("\t\tCONFIG : '").append(config(c.config())).append("',\n");
        sb.append("\tX =").append(FanucFormat.positionValue(c.xMm())).append("  mm,");
        sb.append("\tY =").append(FanucFormat.positionValue(c.yMm())).append("  mm,");
        sb.append("\tZ =").append(FanucFormat.positionValue(c.zMm())).append("  mm,\n");
        sb.append("\tW =").append(FanucFormat.positionValue(c.wDeg())).append(" deg,");
        sb.append("\tP =").append(FanucFormat.positionValue(c.pDeg())).append(" deg,");
        sb.append("\tR =").append(FanucFormat.positionValue(c.rDeg())).append(" deg\n");
      }
      case Position.Joint j -> {
        sb.append('\n');
        for (int k = 1; k <= 6; k++) {
          sb.append("\tJ").append(k).append("=").append(FanucFormat.positionValue(j.element(k))).append(" deg");
          sb.append(k == 6 ? "\n" : k == 3 ? ",\n" : ",");
        }
      }
    }
    sb.append("};\n");
  }

  /** {@code N U T, 0, 0, 0}. */
  static String config(Config c) {
    return (c.flip() ? "F" : "N") + " " + (c.up() ? "U" : "D") + " " + (c.top() ? "T" : "B")
        + ", " + c.turn1() + ", " + c.turn2() + ", " + c.turn3();
  }
}
