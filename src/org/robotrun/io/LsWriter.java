package org.robotrun.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.robotrun.program.FanucFormat;
import org.robotrun.program.TpLexer;
import org.robotrun.program.TpLimits;
import org.robotrun.program.TpStatementParser;
import org.robotrun.program.TpSyntaxError;
import org.robotrun.program.TpToken;
import org.robotrun.program.TpTokenCursor;
import org.robotrun.program.Config;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.Item;
import org.robotrun.program.LabelRef;
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
    statement(in, sb);
    sb.append(closesWithWideGap(in) ? "    ;\n" : " ;\n");
  }

  /** Controllers end motion and register-assignment lines with four spaces before the ';'. */
  private static boolean closesWithWideGap(Instruction in) {
    return in instanceof Instruction.AssignRegister
        || in instanceof Instruction.AssignPosReg
        || in instanceof Instruction.AssignPosElement;
  }

  private static void move(Instruction.Move m, StringBuilder sb) {
    String block = "";
    sb.append(m.type().name()).append(' ');
    target(m.target(), sb);
    for (Motion.Option o : m.viaOptions()) {
      sb.append(' ');
      option(o, sb);
    }
    if (m.circularEnd().isPresent()) {
      // Controllers pad the via line with four blanks, as they do before a motion line's ';'.
      sb.append("    \n    :  ");
      target(m.circularEnd().get(), sb);
    }
    sb.append(' ');
    switch (m.speed().value()) {
      case Motion.SpeedConst c -> sb.append(FanucFormat.plain(c.value()));
      case Motion.SpeedRegister r -> item("R", r.register(), sb);
    }
    sb.append(TpStatementParser.unitText(m.speed().unit())).append(' ');
    switch (m.termination()) {
      case Motion.Fine f -> sb.append("FINE");
      case Motion.Cnt c -> sb.append("CNT").append(c.value());
      case Motion.CntRegister c -> {
        sb.append("CNT ");
        item("R", c.register(), sb);
      }
    }
    for (Motion.Option o : m.options()) {
      sb.append(' ');
      String b = option(o, sb);
      if (!b.isEmpty()) {
        block = b;
      }
    }
    sb.append("    ;").append(block).append('\n');
  }

  /** Writes one motion option; answers the point-logic block (sub-lines) it carries, or "". */
  private static String option(Motion.Option o, StringBuilder sb) {
    switch (o) {
      case Motion.Offset x -> sb.append("Offset");
      case Motion.ToolOffset x -> sb.append("Tool_Offset");
      case Motion.OffsetPr x -> {
        sb.append("Offset,");
        item("PR", x.register(), sb);
      }
      case Motion.ToolOffsetPr x -> {
        sb.append("Tool_Offset,");
        item("PR", x.register(), sb);
      }
      case Motion.Acc x -> sb.append("ACC").append(x.percent());
      case Motion.AccRegister x -> {
        sb.append("ACC ");
        item("R", x.register(), sb);
      }
      case Motion.Skip x -> {
        sb.append("Skip,");
        label(x.label(), sb);
        x.store().ifPresent(r -> {
          sb.append(',');
          item("PR", r, sb);
          sb.append(x.storeJoint() ? "=JPOS" : "=LPOS");
        });
      }
      case Motion.Wjnt x -> sb.append("Wjnt");
      case Motion.Inc x -> sb.append("INC");
      case Motion.TimedAction x -> sb.append(x.text());
      case Motion.RawOption x -> {
        // A point-logic block kept with the last option: its sub-lines follow the motion line.
        int nl = x.text().indexOf('\n');
        sb.append(x.text(), 0, nl < 0 ? x.text().length() : nl);
        return nl < 0 ? "" : x.text().substring(nl);
      }
    }
    return "";
  }

  private static void target(Motion.Target t, StringBuilder sb) {
    switch (t) {
      case Motion.Local l -> sb.append("P[").append(l.number()).append(comment(l.comment())).append(']');
      case Motion.Register r -> item("PR", r.register(), sb);
    }
  }

  /** One term of a position sum: PR[j], P[j], LPOS or JPOS. */
  private static void posTerm(Instruction.PosSource s, StringBuilder sb) {
    switch (s) {
      case Instruction.FromPosReg f -> item("PR", f.register(), sb);
      case Instruction.FromLocal f -> sb.append("P[").append(f.number()).append(comment(f.comment())).append(']');
      case Instruction.CurrentLpos c -> sb.append("LPOS");
      case Instruction.CurrentJpos c -> sb.append("JPOS");
      default -> throw new IllegalArgumentException("not a position term: " + s);
    }
  }

  /** The statement text between the line prefix and the closing ';'. */
  static void statement(Instruction in, StringBuilder sb) {
    switch (in) {
      case Instruction.Move m -> throw new IllegalArgumentException("motion lines are written by move()");
      case Instruction.AssignRegister a -> {
        item("R", a.register(), sb);
        sb.append('=');
        expr(a.value(), sb);
      }
      case Instruction.AssignPosReg a -> {
        item("PR", a.register(), sb);
        sb.append('=');
        switch (a.source()) {
          case Instruction.FromPosReg f -> item("PR", f.register(), sb);
          case Instruction.FromLocal f -> sb.append("P[").append(f.number()).append(comment(f.comment())).append(']');
          case Instruction.CurrentLpos c -> sb.append("LPOS");
          case Instruction.CurrentJpos c -> sb.append("JPOS");
          case Instruction.FromFrame f -> {
            sb.append(f.kind() == Instruction.FrameKind.USER ? "UFRAME[" : "UTOOL[");
            index(f.frame(), sb);
            sb.append(comment(f.comment())).append(']');
          }
          case Instruction.PosSum p -> {
            posTerm(p.first(), sb);
            for (Instruction.PosTerm t : p.rest()) {
              sb.append(t.add() ? '+' : '-');
              posTerm(t.term(), sb);
            }
          }
          case Instruction.PosArithmetic p -> {
            item("PR", p.left(), sb);
            sb.append(p.add() ? '+' : '-');
            item("PR", p.right(), sb);
          }
        }
      }
      case Instruction.AssignPosElement a -> {
        sb.append("PR[");
        index(a.register().index(), sb);
        sb.append(',');
        index(a.element(), sb);
        sb.append(comment(a.register().comment())).append("]=");
        expr(a.value(), sb);
      }
      case Instruction.SelectFrame s -> {
        sb.append(s.kind() == Instruction.FrameKind.USER ? "UFRAME_NUM" : "UTOOL_NUM").append(s.groupWritten() ? "[GP1]=" : "=");
        numberOrRegister(s.number(), sb);
      }
      case Instruction.SetFrame s -> {
        sb.append(s.kind() == Instruction.FrameKind.USER ? "UFRAME[" : "UTOOL[");
        index(s.frame(), sb);
        sb.append(comment(s.comment())).append("]=");
        item("PR", s.register(), sb);
      }
      case Instruction.Payload p -> {
        sb.append("PAYLOAD[");
        index(p.schedule(), sb);
        sb.append(comment(p.comment())).append(']');
      }
      case Instruction.Label l -> sb.append("LBL[").append(l.number()).append(comment(l.comment())).append(']');
      case Instruction.Jump j -> branch(j, sb);
      case Instruction.Call c -> branch(c, sb);
      case Instruction.Run r -> {
        sb.append("RUN ");
        // the name and arguments as a CALL writes them
        StringBuilder call = new StringBuilder();
        branch(new Instruction.Call(r.program(), r.args()), call);
        sb.append(call, "CALL ".length(), call.length());
      }
      case Instruction.End e -> sb.append("END");
      case Instruction.Pause p -> sb.append("PAUSE");
      case Instruction.Abort a -> sb.append("ABORT");
      case Instruction.If f -> {
        sb.append("IF ");
        expr(f.condition(), sb);
        sb.append(',');
        branch(f.branch(), sb);
      }
      case Instruction.IfAction f -> {
        sb.append("IF ");
        expr(f.condition(), sb);
        sb.append(',');
        statement(f.action(), sb);
      }
      case Instruction.IfThen f -> {
        sb.append("IF ");
        expr(f.condition(), sb);
        sb.append(" THEN");
      }
      case Instruction.Else e -> sb.append("ELSE");
      case Instruction.EndIf e -> sb.append("ENDIF");
      case Instruction.Select s -> {
        sb.append("SELECT ");
        item("R", s.register(), sb);
        sb.append('=');
        expr(s.value(), sb);
        sb.append(',');
        branch(s.branch(), sb);
      }
      case Instruction.SelectCase s -> {
        // Aligned under the register of the SELECT line, as the pendant shows it.
        sb.append("       =");
        expr(s.value(), sb);
        sb.append(',');
        branch(s.branch(), sb);
      }
      case Instruction.SelectElse s -> {
        sb.append("       ELSE,");
        branch(s.branch(), sb);
      }
      case Instruction.For f -> {
        sb.append("FOR ");
        item("R", f.counter(), sb);
        sb.append('=');
        expr(f.start(), sb);
        sb.append(f.down() ? " DOWNTO " : " TO ");
        expr(f.end(), sb);
      }
      case Instruction.EndFor e -> sb.append("ENDFOR");
      case Instruction.WaitTime w -> {
        sb.append("WAIT ");
        switch (w.seconds()) {
          case Expr.RealConst c -> sb.append(FanucFormat.waitSeconds(c.value())).append("(sec)");
          case Expr.IntConst c -> sb.append(FanucFormat.waitSeconds(c.value())).append("(sec)");
          case Expr.Register r -> expr(r, sb);
          default -> {
            expr(w.seconds(), sb);
            sb.append("(sec)");
          }
        }
      }
      case Instruction.WaitCondition w -> {
        sb.append("WAIT ");
        // A bare constant (-5 included) or register would read back as a time: parenthesise it.
        Expr c = w.condition();
        boolean timeLike = c instanceof Expr.IntConst || c instanceof Expr.RealConst || c instanceof Expr.Register
            || c instanceof Expr.Unary;
        operand(c, timeLike, sb);
        w.timeoutLabel().ifPresent(l -> {
          sb.append(" TIMEOUT,");
          label(l, sb);
        });
      }
      case Instruction.TimerSet t -> {
        item("TIMER", t.timer(), sb);
        sb.append('=').append(t.action().name());
      }
      case Instruction.SetIo s -> {
        item(s.kind().name(), s.port(), sb);
        sb.append('=');
        expr(s.value(), sb);
      }
      case Instruction.Pulse p -> {
        item(p.kind().name(), p.port(), sb);
        sb.append("=PULSE");
        if (p.widthSec().isPresent()) {
          sb.append(',').append(FanucFormat.plain(p.widthSec().getAsDouble())).append("sec");
        }
      }
      // Trailing blanks would merge with the " ;" and not read back; the reader strips them too.
      case Instruction.Comment c -> sb.append('!').append(c.text().stripTrailing());
      case Instruction.CommentedOut c -> sb.append("//").append(c.text().stripTrailing());
      case Instruction.Message m -> sb.append("MESSAGE[").append(m.text()).append(']');
      case Instruction.SkipCondition s -> {
        sb.append("SKIP CONDITION ");
        expr(s.condition(), sb);
      }
      case Instruction.OffsetCondition o -> {
        sb.append("OFFSET CONDITION ");
        item("PR", o.register(), sb);
        if (o.userFrame().isPresent()) {
          sb.append(",UFRAME[");
          index(o.userFrame().get(), sb);
          sb.append(']');
        }
      }
      case Instruction.ToolOffsetCondition o -> {
        sb.append("TOOL_OFFSET CONDITION ");
        item("PR", o.register(), sb);
      }
      case Instruction.MacroCall c -> {
        sb.append(c.name());
        if (!c.args().isEmpty()) {
          sb.append('(');
          for (int i = 0; i < c.args().size(); i++) {
            if (i > 0) {
              sb.append(',');
            }
            expr(c.args().get(i), sb);
          }
          sb.append(')');
        }
      }
      case Instruction.SetSysVar s -> {
        sb.append(s.name()).append('=');
        expr(s.value(), sb);
      }
      case Instruction.Monitor mo -> sb.append(mo.end() ? "MONITOR END " : "MONITOR ").append(mo.program());
      case Instruction.When w -> {
        sb.append("WHEN ");
        expr(w.condition(), sb);
        sb.append(',');
        statement(w.action(), sb);
      }
      case Instruction.AssignString a -> {
        item("SR", a.register(), sb);
        sb.append('=');
        expr(a.value(), sb);
      }
      case Instruction.UserAlarm u -> {
        sb.append("UALM[");
        index(u.number(), sb);
        sb.append(comment(u.comment())).append(']');
      }
      case Instruction.SetOverride o -> {
        sb.append("OVERRIDE=");
        expr(o.percent(), sb);
        if (!(o.percent() instanceof Expr.Register)) {
          sb.append('%');
        }
      }
      case Instruction.Blank b -> {
        // nothing: "   5:   ;"
      }
      case Instruction.Unsupported u -> sb.append(u.text());
    }
  }

  private static void branch(Instruction.Branch b, StringBuilder sb) {
    switch (b) {
      case Instruction.Jump j -> {
        sb.append("JMP ");
        label(j.label(), sb);
      }
      case Instruction.Call c -> {
        sb.append("CALL ").append(c.program());
        if (!c.args().isEmpty()) {
          sb.append('(');
          for (int i = 0; i < c.args().size(); i++) {
            if (i > 0) {
              sb.append(',');
            }
            expr(c.args().get(i), sb);
          }
          sb.append(')');
        }
      }
    }
  }

  // ---- expressions --------------------------------------------------------------------------

  /** Binding strength of an expression as written: atoms bind tightest, then unary operators. */
  private static int strength(Expr e) {
    return switch (e) {
      case Expr.Binary b -> b.op().precedence();
      case Expr.Unary u -> 6;
      case Expr.IntConst c -> 7;
      case Expr.RealConst c -> 7;
      case Expr.OnOff c -> 7;
      case Expr.StringConst c -> 7;
      case Expr.Register r -> 7;
      case Expr.PosElement p -> 7;
      case Expr.Io io -> 7;
      case Expr.Timer t -> 7;
      case Expr.Arg a -> 7;
      case Expr.SysVar v -> 7;
      case Expr.StringReg r -> 7;
      case Expr.StringFunc f -> 7;
      case Expr.MathFunc f -> 7;
      case Expr.Group g -> 7;
    };
  }

  /**
   * Writes an expression. The reader and the pendant refuse nesting beyond {@link
   * TpLimits#MAX_NESTING}; a model built otherwise is refused here with a message rather than
   * overflowing the stack.
   *
   * @throws IllegalArgumentException when {@code e} is nested deeper than the limit
   */
  static void expr(Expr e, StringBuilder sb) {
    if (TpLimits.nesting(e, TpLimits.MAX_NESTING) > TpLimits.MAX_NESTING) {
      throw new IllegalArgumentException("expression nested deeper than " + TpLimits.MAX_NESTING
          + " levels of parentheses and signs: a controller would not read it");
    }
    exprUnchecked(e, sb);
  }

  private static void exprUnchecked(Expr e, StringBuilder sb) {
    switch (e) {
      case Expr.IntConst c -> sb.append(c.value());
      case Expr.RealConst c -> sb.append(FanucFormat.real(c.value()));
      case Expr.OnOff o -> sb.append(o.on() ? "ON" : "OFF");
      case Expr.StringConst s -> {
        char q = s.value().indexOf('\'') >= 0 ? '"' : '\'';
        sb.append(q).append(s.value()).append(q);
      }
      case Expr.Register r -> item("R", r.register(), sb);
      case Expr.PosElement p -> {
        sb.append("PR[");
        index(p.register().index(), sb);
        sb.append(',');
        index(p.element(), sb);
        sb.append(comment(p.register().comment())).append(']');
      }
      case Expr.Io io -> item(io.kind().name(), io.port(), sb);
      case Expr.Timer t -> item("TIMER", t.timer(), sb);
      case Expr.SysVar v -> sb.append(v.name());
      case Expr.StringReg r -> item("SR", r.register(), sb);
      case Expr.MathFunc f -> {
        sb.append(f.fn().name()).append('[');
        exprUnchecked(f.arg(), sb);
        sb.append(']');
      }
      case Expr.StringFunc f -> {
        sb.append(f.fn().name()).append(' ');
        for (int k = 0; k < f.args().size(); k++) {
          if (k > 0) {
            sb.append(',');
          }
          operand(f.args().get(k), strength(f.args().get(k)) < 6, sb);
        }
      }
      case Expr.Arg a -> {
        sb.append("AR[");
        index(a.index(), sb);
        sb.append(']');
      }
      case Expr.Unary u -> {
        sb.append(u.op().symbol());
        operand(u.operand(), strength(u.operand()) < 6, sb);
      }
      case Expr.Binary b -> {
        int p = b.op().precedence();
        operand(b.left(), strength(b.left()) < p, sb);
        String sym = b.op().symbol();
        boolean word = Character.isLetter(sym.charAt(0));
        sb.append(word ? " " + sym + " " : sym);
        operand(b.right(), strength(b.right()) <= p, sb);
      }
      case Expr.Group g -> {
        sb.append('(');
        exprUnchecked(g.inner(), sb);
        sb.append(')');
      }
    }
  }

  private static void operand(Expr e, boolean parenthesise, StringBuilder sb) {
    if (parenthesise) {
      sb.append('(');
      exprUnchecked(e, sb);
      sb.append(')');
    } else {
      exprUnchecked(e, sb);
    }
  }

  // ---- items ----------------------------------------------------------------------------------

  private static void item(String kind, Item item, StringBuilder sb) {
    sb.append(kind).append('[');
    index(item.index(), sb);
    sb.append(comment(item.comment())).append(']');
  }

  private static void label(LabelRef l, StringBuilder sb) {
    sb.append("LBL[");
    index(l.index(), sb);
    sb.append(comment(l.comment())).append(']');
  }

  private static void index(Index i, StringBuilder sb) {
    switch (i) {
      case Index.Direct d -> sb.append(d.value());
      case Index.Indirect r -> sb.append("R[").append(r.register()).append(comment(r.comment())).append(']');
      case Index.ViaArg a -> sb.append("AR[").append(a.arg()).append(']');
    }
  }

  /** {@code UFRAME_NUM=1} or {@code UFRAME_NUM=R[3]}: here an indirect index is the register itself. */
  private static void numberOrRegister(Index i, StringBuilder sb) {
    index(i, sb);
  }

  private static String comment(String c) {
    return c.isEmpty() ? "" : ":" + c;
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
