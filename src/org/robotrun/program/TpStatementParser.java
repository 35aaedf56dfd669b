package org.robotrun.program;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.robotrun.program.TpToken.Kind;
import org.robotrun.program.Instruction.FrameKind;

/**
 * Recursive-descent parser for one /MN statement (TP-LANGUAGE.md, "Statements"). It sees the
 * tokens of a single statement (a circular motion's continuation line appended), so a bad
 * statement is reported with {@link TpSyntaxError} and the reader continues with the next line.
 *
 * <p>Expressions use the precedence of {@link Expr.BinaryOp} everywhere, so FANUC's short form
 * {@code R[1]=R[2]+1} and a parenthesised expression are parsed alike. Parentheses may nest at
 * most {@link #MAX_NESTING} deep and a statement may hold at most {@link #MAX_OPERATORS}
 * operators: beyond that the statement is rejected with a diagnostic instead of risking a stack
 * overflow here or in whoever walks the tree later.
 */
public final class TpStatementParser extends TpTokenCursor {

  /** Deepest nesting of parentheses and prefix operators accepted ({@link TpLimits#MAX_NESTING}). */
  static final int MAX_NESTING = TpLimits.MAX_NESTING;

  /** Most operators in one statement ({@link TpLimits#MAX_OPERATORS}). */
  static final int MAX_OPERATORS = TpLimits.MAX_OPERATORS;

  private static final String VALUE_EXPECTED =
      "expected a value (number, R[i], PR[i,j], DI[i], F[i], TIMER[i], AR[i], ON, OFF or '('), found ";

  /** FANUC statements RobotRun knows by name but does not implement: first word → name. */
  private static final Map<String, String> UNSUPPORTED = Map.ofEntries(
      Map.entry("SKIP", "SKIP CONDITION"),
      Map.entry("OFFSET", "OFFSET CONDITION"),
      Map.entry("TOOL_OFFSET", "TOOL_OFFSET CONDITION"),
      Map.entry("COL", "COL DETECT"),
      Map.entry("LOCK", "LOCK PREG"),
      Map.entry("UNLOCK", "UNLOCK PREG"),
      Map.entry("VR", "vision registers VR[]"),
      Map.entry("SDI", "SDI[]"),
      Map.entry("SDO", "SDO[]"),
      Map.entry("WI", "weld input WI[]"),
      Map.entry("WO", "weld output WO[]"),
      Map.entry("JOINT_MAX_SPEED", "JOINT_MAX_SPEED"),
      Map.entry("LINEAR_MAX_SPEED", "LINEAR_MAX_SPEED"),
      Map.entry("TIMER_OVERFLOW", "TIMER_OVERFLOW"),
      Map.entry("RSR", "RSR"),
      Map.entry("DIAGNOSTIC", "DIAGNOSTIC"),
      Map.entry("STRING", "string operations"),
      Map.entry("POINT_LOGIC", "POINT_LOGIC"),
      Map.entry("SPOT", "spot welding SPOT[]"),
      Map.entry("ARC", "arc welding"),
      Map.entry("WELD", "arc welding"),
      Map.entry("PALLETIZING", "palletizing"),
      Map.entry("TC_ONLINE", "TC_ONLINE"),
      Map.entry("SKIP_CONDITION", "SKIP CONDITION"),
      Map.entry("PTH", "PTH"),
      Map.entry("MAX_SPEED", "max_speed"),
      Map.entry("WELD_SPEED", "arc welding speed WELD_SPEED"),
      Map.entry("WEAVE", "arc welding weave"),
      Map.entry("TRACK", "seam tracking"),
      Map.entry("VOFFSET", "vision offset VOFFSET"),
      Map.entry("VISION", "iRVision"),
      Map.entry("COORD", "coordinated motion COORD"),
      Map.entry("RTCP", "remote TCP (RTCP)"),
      Map.entry("ERROR_PROG", "ERROR_PROG"),
      Map.entry("RESUME_PROG", "RESUME_PROG"),
      Map.entry("CLEAR_RESUME_PROG", "CLEAR_RESUME_PROG"),
      Map.entry("RETURN_PATH_DSBL", "RETURN_PATH_DSBL"),
      Map.entry("MONITOR_END", "MONITOR END"),
      Map.entry("MAINT_PROG", "MAINT_PROG"),
      Map.entry("PL", "palletizing register PL[]"),
      Map.entry("PAL", "palletizing"),
      Map.entry("PALLETIZING_B", "PALLETIZING-B"),
      Map.entry("PALLETIZING_END", "PALLETIZING-END"),
      Map.entry("ARC_START", "arc welding"),
      Map.entry("ARC_END", "arc welding"),
      Map.entry("TRACK_END", "seam tracking"),
      Map.entry("SEMAPHORE", "SEMAPHORE"),
      Map.entry("POST_SEMAPHORE", "SEMAPHORE"),
      Map.entry("WAIT_SEMAPHORE", "SEMAPHORE"),
      Map.entry("SOFTFLOAT", "SOFTFLOAT"),
      Map.entry("SOFT_FLOAT", "SOFTFLOAT"),
      Map.entry("CNV", "conveyor tracking"),
      Map.entry("LINE_TRACK", "line tracking"),
      Map.entry("AIR", "AIR"),
      Map.entry("STICK", "STICK"),
      Map.entry("TOUCH", "touch sensing"),
      Map.entry("SEARCH", "touch sensing SEARCH"),
      Map.entry("GRIPPER", "gripper instruction"),
      Map.entry("HAND", "HAND"),
      Map.entry("PATH", "PATH"),
      Map.entry("USER_ALARM", "user alarm"),
      Map.entry("GROUP_OUTPUT", "group output"),
      Map.entry("PTOOL", "PTOOL"),
      Map.entry("CONST_PATH", "constant path"),
      Map.entry("FORCE", "force control"),
      Map.entry("FORCE_CTRL", "force control"),
      Map.entry("TORQ_LIMIT", "TORQ_LIMIT"),
      Map.entry("TORQ_LIMIT_END", "TORQ_LIMIT"),
      Map.entry("CD_PAIR", "coordinated motion"),
      Map.entry("ORG", "ORG"),
      Map.entry("SET", "SET instruction"),
      Map.entry("JOINT", "JOINT"),
      Map.entry("GET_OFFSET", "vision GET_OFFSET"),
      Map.entry("GET_PASSFAIL", "vision GET_PASSFAIL"),
      Map.entry("GET_NFOUND", "vision GET_NFOUND"),
      Map.entry("SET_REFERENCE", "vision SET_REFERENCE"),
      Map.entry("CAMERA_CALIB", "vision CAMERA_CALIB"),
      Map.entry("PRINT", "PRINT"),
      Map.entry("DEFAULT", "DEFAULT"),
      Map.entry("MACRO", "macro"),
      Map.entry("MROT", "MROT"),
      Map.entry("BREAK", "BREAK"),
      Map.entry("COL_DETECT", "COL DETECT"),
      Map.entry("COL_GUARD_ADJUST", "COL GUARD ADJUST"),
      Map.entry("REMARK", "remark"),
      Map.entry("FREE", "FREE"),
      Map.entry("STATION", "station sync"),
      Map.entry("DIAGNOSTIC_REC", "DIAGNOSTIC"));

  /**
   * Kinds the program can run on without (a warning, the line is skipped): settings, monitors
   * and diagnostics that change no position, flow or output a one-arm course relies on. Every
   * other unsupported kind is an error: the line alarms when it runs.
   */
  private static final java.util.Set<String> RUNNABLE = java.util.Set.of(
      "COL DETECT", "COL GUARD ADJUST", "JOINT_MAX_SPEED", "LINEAR_MAX_SPEED", "max_speed", "TIMER_OVERFLOW",
      "DIAGNOSTIC", "LOCK PREG", "UNLOCK PREG", "TC_ONLINE", "PTH", "remark", "system variable assignment",
      "RETURN_PATH_DSBL", "CLEAR_RESUME_PROG", "RESUME_PROG", "ERROR_PROG", "MAINT_PROG", "PRINT", "BREAK", "MROT",
      "constant path", "TORQ_LIMIT",
      // compliance to an outside force: the simulated arm meets none, so its path is the same
      "SOFTFLOAT");

  /** The arithmetic functions of FANUC's math-function option, written {@code SQRT[R[1]]}. */
  private static final java.util.Set<String> MATH_FUNCTIONS = java.util.Set.of(
      "ABS", "SQRT", "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "ATAN2", "LN", "EXP", "TRUNC", "ROUND");

  private int nesting;
  private int operators;
  private java.util.function.IntFunction<String> lineText = l -> null;
  private final List<String> warnings = new ArrayList<>(0);
  /**
   * Reading a file (not the pendant's entry): complete a motion missing its speed or
   * termination, as a hand-edited file is read, and keep a register kind RobotRun does not know
   * in an expression as unsupported (a controller with that option wrote it).
   */
  private boolean fromFile;
  /** The I/O sizes a direct index is checked against (a warning beyond them). */
  private final IoRanges ioRanges = IoRanges.DEFAULT;

  private TpStatementParser(List<TpToken> tokens) {
    super(tokens);
  }

  /**
   * Parses one statement.
   *
   * @param tokens the statement's tokens, ending in one {@link Kind#EOL} (the terminating
   *     {@code ;} already removed by the reader)
   * @throws TpSyntaxError naming the line and what was expected
   */
  public static Parsed parse(List<TpToken> tokens) {
    return parse(tokens, l -> null);
  }

  /**
   * Parses one statement as {@link #parse(List)} does; {@code lineText} gives the text of a
   * line by number (columns of the tokens index into it), so options RobotRun does not run
   * are kept exactly as written. It may answer null; then they are rebuilt from the tokens.
   */
  public static Parsed parse(List<TpToken> tokens, java.util.function.IntFunction<String> lineText) {
    return parse(tokens, lineText, false);
  }

  /**
   * Parses one statement of a file as {@link #parse(List, java.util.function.IntFunction)}
   * does, and mends what hand-edited files lack the way RobotRun reads FANUC's offline converter
   * (docs/tp-language.md, "Program lines"): a motion without speed and/or termination is
   * completed from the first row of its type in the pendant's default-motion table ({@link
   * DefaultMotions}), with a {@code mended: ...} warning; and a register or port kind it does not
   * know in an expression ({@code M[1]}) is unsupported rather than a syntax error.
   */
  public static Parsed parseMendingHandEdits(List<TpToken> tokens, java.util.function.IntFunction<String> lineText) {
    return parse(tokens, lineText, true);
  }

  private static Parsed parse(List<TpToken> tokens, java.util.function.IntFunction<String> lineText, boolean mend) {
    TpStatementParser p = new TpStatementParser(tokens);
    p.lineText = lineText;
    p.fromFile = mend;
    Instruction in = p.statement();
    if (p.peek().is(Kind.SEMICOLON)) {
      throw p.error("text after ';': a line holds one statement (put a remark on its own '!' line)");
    }
    if (!p.peek().is(Kind.EOL)) {
      throw p.error("expected the end of the statement, found " + p.peek().describe());
    }
    Expr checked = switch (in) {
      case Instruction.AssignRegister a -> a.value();
      case Instruction.AssignPosElement a -> a.value();
      case Instruction.If f -> f.condition();
      case Instruction.IfAction f -> f.condition();
      case Instruction.IfThen f -> f.condition();
      case Instruction.WaitCondition w -> w.condition();
      case Instruction.SetIo s -> s.value();
      case Instruction.SetSysVar s -> s.value();
      case Instruction.AssignString a -> a.value();
      case Instruction.When w -> w.condition();
      case Instruction.SkipCondition s -> s.condition();
      default -> null;
    };
    if (checked != null) {
      EntryRules.refusal(checked).ifPresent(r -> p.warnings.add(r + " (a pendant refuses this entry)"));
    }
    return new Parsed(in, List.copyOf(p.warnings));
  }

  // ---- typed text (the pendant's field entry) ----------------------------------------------

  /**
   * Parses typed text as one expression, with the grammar and limits of a statement in a file
   * (the pendant's field entry uses this, so it accepts exactly what a file may hold). A whole
   * {@code 'string'} is a string constant (a CALL argument or a string register's value).
   *
   * @throws TpSyntaxError naming the column (line 1) and what was expected
   */
  public static Expr expressionText(String text) {
    TpStatementParser p = new TpStatementParser(TpLexer.tokenize(text, 1, 1, false));
    Expr e = p.peek().is(Kind.STRING) && p.peek(1).is(Kind.EOL) ? new Expr.StringConst(p.next().text()) : p.expression();
    p.expectEnd("the end of the expression");
    return e;
  }

  /**
   * Parses the text of one statement, as {@link TpText#statement} prints it and a /MN line holds
   * it between {@code "N:"} and {@code ;}: the fragment entry point for a whole line. A C motion's
   * end point may be on a continuation line ({@code "C P[1]\n    :  P[2] 100mm/sec FINE"}). A
   * statement RobotRun keeps but does not run is given back as {@link Instruction.Unsupported}
   * holding the text, as the .LS reader keeps it.
   *
   * @throws TpSyntaxError naming line (of {@code text}), column and what was expected
   */
  public static Parsed statementText(String text) {
    String[] lines = Objects.requireNonNull(text, "text").split("\n", -1);
    List<TpToken> tokens = new ArrayList<>(TpLexer.tokenize(lines[0], 1, 1, true));
    for (int k = 1; k < lines.length; k++) {
      int colon = lines[k].indexOf(':');
      if (colon < 0 || !lines[k].substring(0, colon).isBlank()) {
        throw new TpSyntaxError(k + 1, "expected a continuation line ':  ...', found '" + TpToken.clip(lines[k].strip()) + "'");
      }
      tokens.remove(tokens.size() - 1);
      tokens.addAll(TpLexer.tokenize(lines[k].substring(colon + 1), k + 1, colon + 2, false));
    }
    try {
      return parse(tokens, l -> l >= 1 && l <= lines.length ? lines[l - 1] : null);
    } catch (TpSyntaxError e) {
      if (e.unsupported().isPresent()) {
        return new Parsed(new Instruction.Unsupported(text.strip(), e.unsupported().get(), e.runnable()), List.of());
      }
      throw e;
    }
  }

  /** Parses typed text as a CALL's program and arguments: {@code NAME}, {@code NAME(1,'A,B',R[2])}. */
  public static Instruction.Call callText(String text) {
    TpStatementParser p = new TpStatementParser(TpLexer.tokenize(text, 1, 1, false));
    Instruction.Call c = (Instruction.Call) p.call();
    p.expectEnd("the end of the CALL");
    return c;
  }

  /**
   * Parses typed text as the right side of {@code PR[i]=}: {@code PR[2]}, {@code P[3]}, {@code LPOS},
   * {@code UFRAME[1]}, {@code PR[1]+PR[2]}, {@code LPOS-PR[4]}.
   */
  public static Instruction.PosSource posSourceText(String text) {
    TpStatementParser p = new TpStatementParser(TpLexer.tokenize(text, 1, 1, false));
    Instruction.PosSource s = p.positionSource();
    p.expectEnd("the end of the position");
    return s;
  }

  /** Parses typed text as an index: {@code 5} or {@code R[2]}. */
  public static Index indexText(String text) {
    TpStatementParser p = new TpStatementParser(TpLexer.tokenize(text, 1, 1, false));
    Index i = p.indexValue("index");
    p.expectEnd("the end of the index");
    return i;
  }

  /** Parses typed text as an item of {@code kind}: {@code R[3]}, {@code R[3:COUNT]}. */
  public static Item itemText(String kind, String text) {
    TpStatementParser p = new TpStatementParser(TpLexer.tokenize(text, 1, 1, false));
    p.expectWordNamed(kind, kind + "[i]");
    Item item = p.item(kind);
    p.expectEnd("the end of the item");
    return item;
  }

  private void expectEnd(String what) {
    if (!peek().is(Kind.EOL)) {
      throw error("expected " + what + ", found " + peek().describe());
    }
  }

  /**
   * A statement and the warnings about it (a register number outside the controller's table:
   * legal text, but running the line raises an alarm).
   */
  public record Parsed(Instruction instruction, List<String> warnings) {}

  // ---- statements -------------------------------------------------------------------------

  private Instruction statement() {
    TpToken t = peek();
    switch (t.kind()) {
      case EOL -> {
        return new Instruction.Blank();
      }
      case BANG -> {
        next();
        return new Instruction.Comment(next().text().stripTrailing());
      }
      case SLASH -> {
        if (!t.text().equals("//")) {
          throw error("expected a statement, found '/' (a commented-out line starts with '//')");
        }
        next();
        return new Instruction.CommentedOut(next().text().stripTrailing());
      }
      case MINUS -> {
        if (t.text().equals("--")) {
          throw unsupported(t, "remark (--eg:)", true);
        }
        throw error("expected a statement, found '-'");
      }
      case EQ -> {
        next();
        Expr value = expression();
        expect(Kind.COMMA, "',' after the SELECT value");
        return new Instruction.SelectCase(value, branch());
      }
      case WORD -> {
        return wordStatement(t);
      }
      default -> throw error("expected a statement, found " + t.describe());
    }
  }

  private Instruction wordStatement(TpToken t) {
    String w = t.text().toUpperCase(Locale.ROOT);
    if (isMotionType(w) && (peek(1).isWord("P") || peek(1).isWord("PR"))) {
      return motion();
    }
    if (isMotionType(w) && peek(1).is(Kind.WORD) && peek(2).is(Kind.LBRACKET)) {
      // J PAL_1[A_1] 100% CNT100, L VR[1]...: a target RobotRun has no positions for
      throw unsupported(peek(1), "motion to " + targetKind(peek(1).text()), false);
    }
    if (w.startsWith("$")) {
      Optional<String> known = SystemVariables.writable(w);
      if (known.isPresent() && peek(1).is(Kind.EQ)) {
        next();
        next();
        return new Instruction.SetSysVar(known.get(), expression());
      }
      throw unsupported(t, "system variable assignment", true);
    }
    next();
    IoKind io = ioKind(w);
    if (io != null && peek().is(Kind.LBRACKET)) {
      if (io.writable()) {
        return ioAssignment(io);
      }
      if (io == IoKind.DI || io == IoKind.RI || io == IoKind.GI || io == IoKind.SI || io == IoKind.AI) {
        throw error(t, w + "[] is an input: a program cannot set it (expected DO, RO, GO, AO or F)");
      }
      // SO[] (and the UOP outputs): driven by the controller itself
      throw unsupported(t, "assigning " + w + "[] (the controller sets it)", false);
    }
    return switch (w) {
      case "R" -> {
        Item reg = item("R");
        expect(Kind.EQ, "'=' after R[...]");
        if (peek().isWord("VR") && peek(1).is(Kind.LBRACKET)) {
          yield visionRead(reg);
        }
        if (peek().is(Kind.STRING) && peek(1).is(Kind.EOL)) {
          throw error("R[] holds a number, not a string constant: put the text in a string register SR[i]");
        }
        yield new Instruction.AssignRegister(reg, expression());
      }
      case "SR" -> {
        Item reg = item("SR");
        expect(Kind.EQ, "'=' after SR[...]");
        yield new Instruction.AssignString(reg, expression());
      }
      case "PR" -> positionRegisterAssignment();
      case "AR" -> throw error(t, "AR[] holds the CALL arguments: a program can read it but not set it");
      case "TIMER" -> {
        Item timer = item("TIMER");
        expect(Kind.EQ, "'=' after TIMER[...]");
        if (!peek().is(Kind.WORD)) {
          // TIMER[1]=((-3)): a timer set to a value, which newer systems allow
          throw unsupported(peek(), "TIMER[i] set to a value", false);
        }
        TpToken a = expectWord("START, STOP or RESET");
        yield switch (a.text().toUpperCase(Locale.ROOT)) {
          case "START" -> new Instruction.TimerSet(timer, Instruction.TimerAction.START);
          case "STOP" -> new Instruction.TimerSet(timer, Instruction.TimerAction.STOP);
          case "RESET" -> new Instruction.TimerSet(timer, Instruction.TimerAction.RESET);
          default -> throw error(a, "expected START, STOP or RESET after TIMER[...]=, found " + a.describe());
        };
      }
      case "UFRAME_NUM", "UTOOL_NUM" -> {
        boolean group = false;
        if (peek().is(Kind.LBRACKET)) {
          // UTOOL_NUM[GP1]=1: a multi-group controller names the group; RobotRun moves group 1
          next();
          TpToken g = expectWord("a motion group GPn in " + w + "[GPn]");
          if (!g.text().toUpperCase(Locale.ROOT).matches("GP[1-9]")) {
            throw error(g, "expected a motion group GP1..GP9 in " + w + "[...], found " + g.describe());
          }
          expect(Kind.RBRACKET, "']' closing " + w + "[GPn]");
          if (!g.isWord("GP1")) {
            throw unsupported(g, w + " of motion group " + g.text().toUpperCase(Locale.ROOT) + " (RobotRun moves group 1)", false);
          }
          group = true;
        }
        expect(Kind.EQ, "'=' after " + w);
        if (peek().is(Kind.WORD) && !peek().isWord("R") && !peek().isWord("AR")) {
          // UFRAME_NUM=Constant and the like: a value the controller listed by name
          throw unsupported(peek(), w + "=" + TpToken.clip(peek().text()), false);
        }
        yield new Instruction.SelectFrame(w.equals("UFRAME_NUM") ? FrameKind.USER : FrameKind.TOOL, numberOrRegister(w),
            group);
      }
      case "UFRAME", "UTOOL" -> {
        Item frame = item(w);
        expect(Kind.EQ, "'=' after " + w + "[...]");
        expectWordNamed("PR", "PR[i] (" + w + "[n] is set from a position register)");
        yield new Instruction.SetFrame(w.equals("UFRAME") ? FrameKind.USER : FrameKind.TOOL, frame.index(),
            frame.comment(), item("PR"));
      }
      case "PAYLOAD" -> {
        Item schedule = item("PAYLOAD");
        yield new Instruction.Payload(schedule.index(), schedule.comment());
      }
      case "LBL" -> {
        LabelRef l = labelRef();
        if (!(l.index() instanceof Index.Direct d)) {
          throw error("a label number must be a constant: LBL[n]");
        }
        if (d.value() < 1) {
          throw error("label numbers start at 1, found LBL[" + d.value() + "]");
        }
        yield new Instruction.Label(d.value(), l.comment());
      }
      case "SKIP" -> {
        if (!peek().isWord("CONDITION")) {
          throw unknownStatement(t);
        }
        next();
        yield new Instruction.SkipCondition(expression());
      }
      case "OFFSET" -> {
        if (!peek().isWord("CONDITION") || !peek(1).isWord("PR")) {
          throw unknownStatement(t);
        }
        next();
        next();
        Item pr = item("PR");
        if (peek().is(Kind.COMMA) && peek(1).isWord("UFRAME") && peek(2).is(Kind.LBRACKET)) {
          // OFFSET CONDITION PR[1],UFRAME[2]: the offset expressed in user frame 2
          next();
          next();
          yield new Instruction.OffsetCondition(pr, Optional.of(index("UFRAME")));
        }
        if (!peek().is(Kind.EOL)) {
          throw unsupported(t, "OFFSET CONDITION with " + TpToken.clip(peek(1).text()), false);
        }
        yield new Instruction.OffsetCondition(pr);
      }
      case "TOOL_OFFSET" -> {
        if (!peek().isWord("CONDITION") || !peek(1).isWord("PR")) {
          throw unknownStatement(t);
        }
        next();
        next();
        Item pr = item("PR");
        if (!peek().is(Kind.EOL)) {
          // TOOL_OFFSET CONDITION PR[1],UTOOL[2] and the like: kept as written, not run
          throw unsupported(t, "TOOL_OFFSET CONDITION with " + TpToken.clip(peek(1).text()), false);
        }
        yield new Instruction.ToolOffsetCondition(pr);
      }
      case "MONITOR" -> {
        boolean end = peek().isWord("END") && peek(1).is(Kind.WORD);
        if (end) {
          next();
        }
        TpToken name = expectWord("a condition program name after MONITOR");
        if (!Program.isValidName(name.text())) {
          throw error(name, "'" + TpToken.clip(name.text()) + "' is not a program name");
        }
        yield new Instruction.Monitor(name.text().toUpperCase(Locale.ROOT), end);
      }
      case "WHEN" -> {
        Expr cond = expression();
        expect(Kind.COMMA, "',' then CALL after the WHEN condition");
        if (!peek().isWord("CALL")) {
          throw unsupported(peek(), "WHEN with an action other than CALL", false);
        }
        next();
        TpToken at = peek();
        Instruction.Call action = (Instruction.Call) call();
        if (action.nameRegister().isPresent()) {
          throw unsupported(at, "WHEN ...,CALL through a string register SR[]", false);
        }
        yield new Instruction.When(cond, action);
      }
      case "VISION" -> vision(t);
      case "JMP" -> jump();
      case "CALL" -> call();
      case "RUN" -> run();
      case "END" -> new Instruction.End();
      case "PAUSE" -> new Instruction.Pause();
      case "ABORT" -> new Instruction.Abort();
      case "IF" -> ifStatement();
      case "ELSE" -> {
        if (peek().is(Kind.COMMA)) {
          next();
          yield new Instruction.SelectElse(branch());
        }
        yield new Instruction.Else();
      }
      case "ENDIF" -> new Instruction.EndIf();
      case "SELECT" -> {
        expectWordNamed("R", "R[i] after SELECT (SELECT R[i]=value,JMP LBL[n])");
        Item reg = item("R");
        expect(Kind.EQ, "'=' after SELECT R[...]");
        Expr value = expression();
        expect(Kind.COMMA, "',' after the SELECT value");
        yield new Instruction.Select(reg, value, branch());
      }
      case "FOR" -> forStatement();
      case "ENDFOR" -> new Instruction.EndFor();
      case "WAIT" -> waitStatement();
      case "MESSAGE" -> {
        expect(Kind.LBRACKET, "'[' after MESSAGE");
        String text = peek().is(Kind.RAW) ? next().text() : "";
        expect(Kind.RBRACKET, "']' closing MESSAGE[...]");
        yield new Instruction.Message(text);
      }
      case "UALM" -> {
        Item alarm = item("UALM");
        yield new Instruction.UserAlarm(alarm.index(), alarm.comment());
      }
      case "OVERRIDE" -> {
        expect(Kind.EQ, "'=' after OVERRIDE");
        Expr pct = operand();
        if (!(pct instanceof Expr.IntConst || pct instanceof Expr.RealConst || pct instanceof Expr.Register)) {
          throw error("expected a percentage (n% or R[i]) after OVERRIDE=");
        }
        if (peek().is(Kind.PERCENT)) {
          next();
        }
        yield new Instruction.SetOverride(pct);
      }
      default -> {
        // A macro listed by its one-word name (OPEN_HAND): run as a CALL of the program of that name.
        if (t.is(Kind.WORD) && peek().is(Kind.EOL) && !UNSUPPORTED.containsKey(w) && !w.startsWith("PAL")
            && Program.isValidName(w)) {
          yield new Instruction.MacroCall(w);
        }
        // A macro of several words ("HAND1 OPEN", "Open hand 1", "Program Status(13)"): the
        // controller's macro table says which program it runs.
        boolean setMacro = w.equals("SET") && macroArgsFollow();
        if (t.is(Kind.WORD) && (!UNSUPPORTED.containsKey(w) || setMacro) && !w.startsWith("PAL")) {
          Optional<Instruction.MacroCall> macro = macro(t);
          if (macro.isPresent()) {
            yield macro.get();
          }
        }
        throw unknownStatement(t);
      }
    };
  }

  /** The I/O kind named {@code w} (upper case), or null. */
  private static IoKind ioKind(String w) {
    for (IoKind k : IoKind.values()) {
      if (k.name().equals(w)) {
        return k;
      }
    }
    return null;
  }

  private static String targetKind(String word) {
    String w = word.toUpperCase(Locale.ROOT);
    return w.startsWith("PAL_") ? "a palletizing point (PAL_n)" : w + "[]";
  }

  private TpSyntaxError unknownStatement(TpToken t) {
    String w = t.text().toUpperCase(Locale.ROOT);
    String name = UNSUPPORTED.get(w);
    if (name != null) {
      return unsupported(t, name, RUNNABLE.contains(name));
    }
    if (w.startsWith("PALLETIZING") || w.startsWith("PAL_")) {
      return unsupported(t, "palletizing", false);
    }
    if (t.is(Kind.WORD) && onlyWordsFollow()) {
      // A macro is listed by its name alone ("OPEN_HAND", "HAND1 OPEN"); RobotRun has no macro table yet.
      return unsupported(t, "macro call " + TpToken.clip(t.text()), false);
    }
    if (t.is(Kind.WORD) && peek().is(Kind.LBRACKET)) {
      // WELD_PORT[1]=..., SDO[2]=ON, HOLD[1]: a register or port kind of an application package
      return unsupported(t, TpToken.clip(w) + "[]", false);
    }
    if (t.is(Kind.WORD) && peek().is(Kind.WORD)) {
      // Arc Start[1], Weave Sine[1], Touch Offset PR[1], Search Start[1]: application instructions
      return unsupported(t, "instruction " + TpToken.clip(t.text() + " " + peek().text()), false);
    }
    return error(t, "unknown statement '" + TpToken.clip(t.text())
        + "': expected a motion (J/L/C/A), an assignment, IF, SELECT, FOR, WAIT, JMP, CALL, LBL or another TP statement");
  }

  /**
   * The statement from {@code first} (consumed) as a macro call: words, numbers and hyphens
   * ({@code ENTER FIXT-ZONE}), then optionally arguments in parentheses ({@code Program Status(13)}),
   * then the end. Empty (nothing consumed) when the rest is not of that form.
   */
  private Optional<Instruction.MacroCall> macro(TpToken first) {
    int k = 0;
    while (peek(k).is(Kind.WORD) || peek(k).is(Kind.NUMBER) || peek(k).is(Kind.MINUS)) {
      k++;
    }
    if (!peek(k).is(Kind.EOL) && !peek(k).is(Kind.LPAREN)) {
      return Optional.empty();
    }
    StringBuilder name = new StringBuilder(first.text());
    TpToken prev = first;
    for (int j = 0; j < k; j++) {
      TpToken x = next();
      boolean adjacent = x.line() == prev.line() && x.column() == prev.column() + prev.text().length();
      name.append(adjacent ? "" : " ").append(x.text());
      prev = x;
    }
    List<Expr> args = new ArrayList<>();
    if (peek().is(Kind.LPAREN)) {
      next();
      if (!peek().is(Kind.RPAREN)) {
        do {
          args.add(expression());
        } while (accept(Kind.COMMA));
      }
      expect(Kind.RPAREN, "')' closing the macro's arguments");
    }
    if (!peek().is(Kind.EOL)) {
      throw error("expected the end of the macro call, found " + peek().describe());
    }
    return Optional.of(new Instruction.MacroCall(name.toString(), args));
  }

  /** Words then '(' arguments ')' to the end: {@code SET PATH(100)}, a macro rather than a SET statement. */
  private boolean macroArgsFollow() {
    int k = 0;
    while (peek(k).is(Kind.WORD) || peek(k).is(Kind.MINUS)) {
      k++;
    }
    return k > 0 && peek(k).is(Kind.LPAREN);
  }

  /** True when the rest of the statement (after the current token) is words and numbers only. */
  private boolean onlyWordsFollow() {
    for (int k = 0; ; k++) {
      TpToken x = peek(k);
      if (x.is(Kind.EOL)) {
        return true;
      }
      if (!x.is(Kind.WORD) && !x.is(Kind.NUMBER)) {
        return false;
      }
    }
  }

  private Instruction positionRegisterAssignment() {
    expect(Kind.LBRACKET, "'[' after PR");
    Index idx = indexValue("PR");
    if (peek().is(Kind.COMMA)) {
      next();
      Index element = elementIndex();
      String comment = itemCommentAndClose("PR[i,j]");
      expect(Kind.EQ, "'=' after PR[i,j]");
      return new Instruction.AssignPosElement(new Item(idx, comment), element, expression());
    }
    Item reg = new Item(idx, itemCommentAndClose("PR[...]"));
    expect(Kind.EQ, "'=' after PR[...]");
    return new Instruction.AssignPosReg(reg, positionSource());
  }

  /** The right side of {@code PR[i]=}: one source, or a sum of PR[], P[], LPOS and JPOS terms. */
  private Instruction.PosSource positionSource() {
    Instruction.PosSource src = posSource(true);
    if ((peek().is(Kind.PLUS) || peek().is(Kind.MINUS)) && src instanceof Instruction.FromVisionRegister) {
      throw unsupported(peek(), "PR[i]=vision registers VR[] in position arithmetic", false);
    }
    if (peek().is(Kind.PLUS) || peek().is(Kind.MINUS)) {
      // PR[1]=LPOS-LPOS, PR[1]=P[1]+PR[2], PR[1]=PR[2]+PR[3]-PR[4]: a sum of positions
      if (!Instruction.PosSum.isTerm(src) && !(src instanceof Instruction.PosArithmetic)) {
        throw error("UFRAME[n] and UTOOL[n] cannot be added to: position arithmetic takes PR[], P[], LPOS and JPOS");
      }
      Instruction.PosSource first = src instanceof Instruction.PosArithmetic a
          ? new Instruction.FromPosReg(a.left()) : src;
      List<Instruction.PosTerm> rest = new ArrayList<>();
      if (src instanceof Instruction.PosArithmetic a) {
        rest.add(new Instruction.PosTerm(a.add(), new Instruction.FromPosReg(a.right())));
      }
      while (peek().is(Kind.PLUS) || peek().is(Kind.MINUS)) {
        boolean add = next().is(Kind.PLUS);
        countOperator();
        TpToken at = peek();
        Instruction.PosSource term = posSource(false);
        if (term instanceof Instruction.FromVisionRegister) {
          // PR[1]=PR[1]+VR[1].OFFSET: a vision option's form, kept and not run
          throw unsupported(at, "PR[i]=vision registers VR[] in position arithmetic", false);
        }
        if (!Instruction.PosSum.isTerm(term)) {
          throw error("expected PR[], P[], LPOS or JPOS after '" + (add ? "+" : "-") + "' in position arithmetic");
        }
        rest.add(new Instruction.PosTerm(add, term));
      }
      src = new Instruction.PosSum(first, rest);
    }
    return src;
  }

  /** One operand of {@code PR[i]=...}: PR[j] (or PR[j]±PR[k] when {@code pair}), P[j], LPOS, JPOS, UFRAME[n] or UTOOL[n]. */
  private Instruction.PosSource posSource(boolean pair) {
    TpToken s = expectWord("PR[j], P[j], LPOS, JPOS, UFRAME[n] or UTOOL[n]");
    Instruction.PosSource src = switch (s.text().toUpperCase(Locale.ROOT)) {
      case "PR" -> {
        Item from = item("PR");
        if (pair && (peek().is(Kind.PLUS) || peek().is(Kind.MINUS)) && peek(1).isWord("PR")) {
          boolean add = next().is(Kind.PLUS);
          next();
          yield new Instruction.PosArithmetic(from, add, item("PR"));
        }
        yield new Instruction.FromPosReg(from);
      }
      case "P" -> {
        Item p = item("P");
        yield new Instruction.FromLocal(directNumber(p, "P"), p.comment());
      }
      case "LPOS" -> new Instruction.CurrentLpos();
      case "JPOS" -> new Instruction.CurrentJpos();
      case "VR" -> visionPosition(s);
      case "UFRAME", "UTOOL" -> {
        Item frame = item(s.text().toUpperCase(Locale.ROOT));
        yield new Instruction.FromFrame(s.isWord("UFRAME") ? FrameKind.USER : FrameKind.TOOL, frame.index(), frame.comment());
      }
      default -> {
        if (s.text().startsWith("$") || UNSUPPORTED.containsKey(s.text().toUpperCase(Locale.ROOT))) {
          String name = UNSUPPORTED.get(s.text().toUpperCase(Locale.ROOT));
          throw unsupported(s, "PR[i]=" + (name != null ? name : "system variable"), false);
        }
        throw error(s, "expected PR[j], P[j], LPOS, JPOS, UFRAME[n] or UTOOL[n] after PR[i]=, found " + s.describe());
      }
    };
    return src;
  }

  private Instruction ioAssignment(IoKind kind) {
    Item port = item(kind.name());
    expect(Kind.EQ, "'=' after " + kind + "[...]");
    if (peek().isWord("PULSE")) {
      if (kind != IoKind.DO && kind != IoKind.RO) {
        throw error("PULSE works on DO[] and RO[] only, not " + kind + "[]");
      }
      next();
      OptionalDouble width = OptionalDouble.empty();
      if (peek().is(Kind.COMMA)) {
        next();
        width = OptionalDouble.of(number("pulse width in seconds"));
        expectWordNamed("sec", "'sec' after the pulse width");
      }
      return new Instruction.Pulse(kind, port, width);
    }
    return new Instruction.SetIo(kind, port, expression());
  }

  // ---- iRVision (docs/vision.md) -----------------------------------------------------------

  /**
   * {@code VISION RUN_FIND p}, {@code VISION GET_OFFSET p VR[i] JMP,LBL[j]} ({@code JMP LBL},
   * {@code JUMP,LBL} alike) or {@code VISION GET_NFOUND p R[i]}, p a {@code 'NAME'} or {@code SR[i]}.
   * Any other VISION form (SET_REFERENCE, CAMERA_CALIB ...) or a malformed one is kept as written
   * and alarms when it runs ("iRVision"), as before it was read.
   */
  private Instruction vision(TpToken visionWord) {
    try {
      TpToken what = expectWord("RUN_FIND, GET_OFFSET or GET_NFOUND after VISION");
      String w = what.text().toUpperCase(Locale.ROOT);
      Instruction in = switch (w) {
        case "RUN_FIND" -> new Instruction.VisionRunFind(visionProcess());
        case "GET_OFFSET" -> {
          Instruction.VisionProcess p = visionProcess();
          expectWordNamed("VR", "VR[i] after the vision process");
          Item vr = item("VR");
          TpToken jmp = expectWord("JMP,LBL[n] after VR[i]");
          if (!jmp.isWord("JMP") && !jmp.isWord("JUMP")) {
            throw error(jmp, "expected JMP,LBL[n] after VR[i], found " + jmp.describe());
          }
          accept(Kind.COMMA);
          expectWordNamed("LBL", "LBL[n] after JMP");
          yield new Instruction.VisionGetOffset(p, vr, labelRef());
        }
        case "GET_NFOUND" -> {
          Instruction.VisionProcess p = visionProcess();
          expectWordNamed("R", "R[i] after the vision process");
          yield new Instruction.VisionGetNFound(p, item("R"));
        }
        default -> throw unsupported(visionWord, "iRVision", false);
      };
      expectEnd("the end of the VISION statement");
      return in;
    } catch (TpSyntaxError e) {
      if (e.unsupported().isPresent()) {
        throw e;
      }
      throw unsupported(visionWord, "iRVision", false);
    }
  }

  private Instruction.VisionProcess visionProcess() {
    if (peek().is(Kind.STRING)) {
      return new Instruction.VisionProcessName(next().text());
    }
    expectWordNamed("SR", "a vision process: 'NAME' or SR[i]");
    return new Instruction.VisionProcessInRegister(item("SR"));
  }

  /** {@code R[i]=VR[j].MODELID|ENC|MES[k]} after {@code R[i]=}; any other use of VR[] in an expression is kept, not run. */
  private Instruction visionRead(Item reg) {
    TpToken vrWord = next();
    Item vr = item("VR");
    if (peek().is(Kind.BAD_CHAR) && peek().text().equals(".") && peek(1).is(Kind.WORD)) {
      next();
      TpToken f = next();
      String field = f.text().toUpperCase(Locale.ROOT);
      Instruction.AssignFromVr read = null;
      if ((field.equals("MODELID") || field.equals("ENC")) && peek().is(Kind.EOL)) {
        read = new Instruction.AssignFromVr(reg, vr, Instruction.VisionField.valueOf(field), 0);
      } else if (field.equals("MES") && peek().is(Kind.LBRACKET) && peek(1).is(Kind.NUMBER) && peek(2).is(Kind.RBRACKET)
          && peek(3).is(Kind.EOL) && allDigits(peek(1).text(), 0) && peek(1).text().length() <= 2) {
        int k = Integer.parseInt(peek(1).text());
        if (k >= 1 && k <= 10) {
          next();
          next();
          next();
          read = new Instruction.AssignFromVr(reg, vr, Instruction.VisionField.MES, k);
        }
      }
      if (read != null) {
        return read;
      }
    }
    throw unsupported(vrWord, "vision registers VR[] in an expression", false);
  }

  /** {@code VR[j].OFFSET} or {@code VR[j].FOUND_POS[1]} after {@code PR[i]=} (the word VR consumed). */
  private Instruction.PosSource visionPosition(TpToken vrWord) {
    Item vr = item("VR");
    if (peek().is(Kind.BAD_CHAR) && peek().text().equals(".") && peek(1).is(Kind.WORD)) {
      if (peek(1).isWord("OFFSET")) {
        next();
        next();
        return new Instruction.FromVisionRegister(vr, false);
      }
      if (peek(1).isWord("FOUND_POS") && peek(2).is(Kind.LBRACKET) && peek(3).is(Kind.NUMBER)
          && peek(3).text().equals("1") && peek(4).is(Kind.RBRACKET)) {
        for (int k = 0; k < 5; k++) {
          next();
        }
        return new Instruction.FromVisionRegister(vr, true);
      }
    }
    throw unsupported(vrWord, "PR[i]=vision registers VR[]", false);
  }

  private Instruction jump() {
    expectWordNamed("LBL", "LBL[n] after JMP");
    return new Instruction.Jump(labelRef());
  }

  private Instruction call() {
    if (peek().isWord("SR") && peek(1).is(Kind.LBRACKET)) {
      // CALL SR[3]: the program a string register names when the line runs
      next();
      Item sr = item("SR");
      return Instruction.Call.viaString(sr, callArgs());
    }
    if (peek().is(Kind.BAD_CHAR) && peek().text().equals(".")) {
      // CALL ... : the pendant lists a CALL whose program was never chosen this way
      throw unsupported(peek(), "CALL with no program chosen (...)", false);
    }
    String dash = "";
    if (peek().is(Kind.MINUS) && peek(1).is(Kind.WORD) && peek(1).column() == peek().column() + 1) {
      // CALL -HELPER: a program whose name starts with '-'
      next();
      dash = "-";
    }
    TpToken word = expectWord("a program name after CALL");
    TpToken name = dash.isEmpty() ? word : new TpToken(Kind.WORD, dash + word.text(), word.line(), word.column() - 1);
    if (!Program.isValidName(name.text())) {
      throw error(name, "'" + TpToken.clip(name.text())
          + "' is not a program name: expected letters, digits and '_', starting with a letter");
    }
    return new Instruction.Call(name.text().toUpperCase(Locale.ROOT), callArgs());
  }

  /** The optional {@code (arg,...)} of a CALL. */
  private List<Expr> callArgs() {
    List<Expr> args = new ArrayList<>();
    if (peek().is(Kind.LPAREN)) {
      next();
      if (!peek().is(Kind.RPAREN)) {
        do {
          if (peek().is(Kind.WORD) && peek(1).is(Kind.EQ) && !peek().isWord("ON") && !peek().isWord("OFF")
              && !peek().text().startsWith("$")) {
            // CALL SUB(SPEED=5): arguments by name, a feature of newer systems
            throw unsupported(peek(), "named CALL arguments (NAME=value)", false);
          }
          args.add(expression());
        } while (accept(Kind.COMMA));
      }
      expect(Kind.RPAREN, "')' closing the CALL arguments");
    }
    return args;
  }

  /** {@code RUN NAME[(args)]}: starts NAME as a task of its own (multitasking), read like a CALL. */
  private Instruction run() {
    TpToken at = peek();
    Instruction.Call c = (Instruction.Call) call();
    if (c.nameRegister().isPresent()) {
      throw unsupported(at, "RUN through a string register SR[]", false);
    }
    return new Instruction.Run(c.program(), c.args());
  }

  private Instruction.Branch branch() {
    TpToken w = expectWord("JMP LBL[n] or CALL NAME");
    if (w.isWord("JMP")) {
      return (Instruction.Jump) jump();
    }
    if (w.isWord("CALL")) {
      return (Instruction.Call) call();
    }
    throw error(w, "expected JMP LBL[n] or CALL NAME, found " + w.describe());
  }

  private Instruction ifStatement() {
    Expr cond = expression();
    if (peek().isWord("THEN")) {
      next();
      return new Instruction.IfThen(cond);
    }
    expect(Kind.COMMA, "',' then JMP or CALL (or THEN) after the IF condition");
    if (!peek().isWord("JMP") && !peek().isWord("CALL") && !peek().is(Kind.EOL)) {
      // IF (DI[49]),DO[73]=PULSE,0.5sec ; IF R[1]=1,R[2]=(5): an action instead of a branch
      TpToken at = peek();
      Instruction action = statement();
      if (!Instruction.IfAction.allowedAction(action)) {
        throw unsupported(at, "IF with an action other than an assignment, output or pulse", false);
      }
      return new Instruction.IfAction(cond, action);
    }
    return new Instruction.If(cond, branch());
  }

  private Instruction forStatement() {
    expectWordNamed("R", "R[i] after FOR (FOR R[i]=start TO end)");
    Item counter = item("R");
    expect(Kind.EQ, "'=' after FOR R[...]");
    Expr start = forBound();
    TpToken dir = expectWord("TO or DOWNTO");
    boolean down;
    if (dir.isWord("TO")) {
      down = false;
    } else if (dir.isWord("DOWNTO")) {
      down = true;
    } else {
      throw error(dir, "expected TO or DOWNTO in FOR, found " + dir.describe());
    }
    return new Instruction.For(counter, start, down, forBound());
  }

  /** FOR bounds are a constant, R[i] or AR[i] (FANUC allows nothing else). */
  private Expr forBound() {
    Expr e = unary();
    return switch (e) {
      case Expr.IntConst c -> c;
      case Expr.Register r -> r;
      case Expr.Arg a -> a;
      default -> throw error("a FOR bound must be an integer constant, R[i] or AR[i]");
    };
  }

  /**
   * {@code WAIT t(sec)} and {@code WAIT R[i]} wait a time; anything else is a condition. A
   * constant without {@code (sec)} is neither.
   */
  private Instruction waitStatement() {
    if (peek().is(Kind.WORD) && peek(1).is(Kind.WORD) && onlyWordsFollow()) {
      // WAIT NEXT PATH: words and no condition, a macro the cell's macro table names
      return macro(tokens.get(tokens.indexOf(peek()) - 1)).orElseThrow();
    }
    Expr e = expression();
    if (peek().is(Kind.LPAREN) && peek(1).isWord("sec")) {
      // A negative constant would end the WAIT at once without a word; say so when the file is read.
      boolean negative = switch (e) {
        case Expr.IntConst i -> i.value() < 0;
        case Expr.RealConst r -> r.value() < 0;
        case Expr.Unary u -> u.op() == Expr.UnaryOp.MINUS
            && (u.operand() instanceof Expr.IntConst || u.operand() instanceof Expr.RealConst);
        default -> false;
      };
      if (negative) {
        throw error("WAIT time must be 0 or more seconds, found a negative constant");
      }
      expectSecUnit();
      return new Instruction.WaitTime(e instanceof Expr.IntConst i ? new Expr.RealConst(i.value()) : e);
    }
    if (e instanceof Expr.Register && peek().is(Kind.EOL)) {
      return new Instruction.WaitTime(e);
    }
    if (e instanceof Expr.IntConst || e instanceof Expr.RealConst) {
      throw error("expected '(sec)' after the wait time, found " + peek().describe());
    }
    Optional<LabelRef> timeout = Optional.empty();
    if (peek().isWord("TIMEOUT")) {
      next();
      expect(Kind.COMMA, "',' after TIMEOUT");
      expectWordNamed("LBL", "LBL[n] after TIMEOUT,");
      timeout = Optional.of(labelRef());
    }
    return new Instruction.WaitCondition(e, timeout);
  }

  private void expectSecUnit() {
    expect(Kind.LPAREN, "'(sec)' after the wait time");
    expectWordNamed("sec", "'(sec)' after the wait time");
    expect(Kind.RPAREN, "')' closing '(sec)'");
  }

  // ---- motion -----------------------------------------------------------------------------

  private static boolean isMotionType(String w) {
    return w.equals("J") || w.equals("L") || w.equals("C") || w.equals("A");
  }

  private Instruction motion() {
    Motion.Type type = Motion.Type.valueOf(next().text().toUpperCase(Locale.ROOT));
    Motion.Target target = motionTarget();
    Optional<Motion.Target> end = Optional.empty();
    List<Motion.Option> viaOptions = new ArrayList<>();
    if (type == Motion.Type.C) {
      // C P[1] Tool_Offset,PR[2] then ':  P[2] ...': an offset of the via point's own
      while ((peek().isWord("Offset") || peek().isWord("Tool_Offset")) && !(peek(1).is(Kind.LBRACKET))) {
        viaOptions.add(motionOption());
      }
      if (!(peek().isWord("P") || peek().isWord("PR"))) {
        if (peek().is(Kind.WORD) && !peek().isWord("CNT") && !peek().isWord("FINE")) {
          throw unsupported(peek(), "motion option " + TpToken.clip(peek().text()) + " on the via point of a C motion", false);
        }
        throw error("a C motion needs its end point on a continuation line ':  P[j] speed termination ;', found "
            + peek().describe());
      }
      end = Optional.of(motionTarget());
    }
    boolean noSpeed = fromFile && (peek().is(Kind.EOL) || isTermination(peek()) || isMotionOption(peek()));
    Motion.Speed speed = noSpeed ? DefaultMotions.first(type).speed() : speed(type);
    boolean noTermination = fromFile && (peek().is(Kind.EOL) || isMotionOption(peek()));
    Motion.Termination term = noTermination ? DefaultMotions.first(type).termination() : termination();
    if (noSpeed || noTermination) {
      DefaultMotions.Row row = DefaultMotions.first(type);
      String missing = noSpeed && noTermination ? "speed and termination" : noSpeed ? "speed" : "termination";
      String added = noSpeed && noTermination ? TpText.speed(speed) + " " + TpText.termination(term)
          : noSpeed ? TpText.speed(speed) : TpText.termination(term);
      warnings.add("mended: a " + type + " motion without " + missing + ": completed with " + added
          + " from the pendant's first default " + row.type() + " motion (" + row.type() + " P[] "
          + TpText.speed(row.speed()) + " " + TpText.termination(row.termination())
          + (row.type() == type ? ")" : "; its table has no " + type + " row)"));
    }
    List<Motion.Option> options = new ArrayList<>();
    while (!peek().is(Kind.EOL)) {
      options.add(motionOption());
    }
    return new Instruction.Move(type, target, end, speed, term, options, viaOptions);
  }

  private Motion.Target motionTarget() {
    TpToken w = next();
    if (peek().is(Kind.LBRACKET) && peek(1).is(Kind.WORD) && peek(1).text().regionMatches(true, 0, "GP", 0, 2)
        && !(peek(1).isWord("GP1") && peek(2).is(Kind.COLON)
            && (peek(3).is(Kind.NUMBER) && !peek(4).is(Kind.COMMA) || peek(3).isWord("R") && peek(7).is(Kind.RBRACKET)))) {
      // J PR[GP2:1], J PR[GP1:1,7]: a target of another motion group, or with extended axes
      // (J PR[GP1:5] names group 1, the arm RobotRun moves, and runs)
      throw unsupported(peek(1), "a group in " + w.text().toUpperCase(Locale.ROOT) + "[GPn:...] (multi-group)", false);
    }
    if (w.isWord("P")) {
      Item p = item("P");
      return new Motion.Local(directNumber(p, "P"), p.comment());
    }
    return new Motion.Register(item("PR"));
  }

  private Motion.Speed speed(Motion.Type type) {
    Motion.SpeedValue value;
    TpToken t = peek();
    if (t.is(Kind.NUMBER)) {
      value = new Motion.SpeedConst(number("speed"));
    } else if (t.isWord("R")) {
      next();
      value = new Motion.SpeedRegister(item("R"));
    } else if (t.is(Kind.WORD) && UNSUPPORTED.containsKey(t.text().toUpperCase(Locale.ROOT))) {
      throw unsupported(t, UNSUPPORTED.get(t.text().toUpperCase(Locale.ROOT)), false);
    } else {
      throw error("expected a speed (30%, 400mm/sec, 2sec, R[i]%...), found " + t.describe());
    }
    Motion.SpeedUnit unit = speedUnit();
    if (!unit.fits(type)) {
      String allowed = type == Motion.Type.J ? "%, sec or msec" : "mm/sec, cm/min, inch/min, deg/sec, sec or msec";
      throw error("speed unit " + TpText.unit(unit) + " does not fit a " + type + " motion: expected " + allowed);
    }
    // A constant speed out of range would only alarm at run time; say so when the file is read.
    if (value instanceof Motion.SpeedConst c) {
      String shown = FanucFormat.plain(c.value()) + TpText.unit(unit);
      if (!(c.value() > 0)) {
        throw error("speed " + shown + ": expected a speed greater than 0");
      }
      if (unit == Motion.SpeedUnit.PERCENT && c.value() > 100) {
        throw error("speed " + shown + ": expected 1..100%");
      }
    }
    return new Motion.Speed(value, unit);
  }

  private Motion.SpeedUnit speedUnit() {
    TpToken t = peek();
    if (t.is(Kind.PERCENT)) {
      next();
      return Motion.SpeedUnit.PERCENT;
    }
    if (!t.is(Kind.WORD)) {
      throw error("expected a speed unit (%, mm/sec, cm/min, inch/min, deg/sec, sec, msec), found " + t.describe());
    }
    next();
    String u = t.text().toLowerCase(Locale.ROOT);
    switch (u) {
      case "sec" -> {
        return Motion.SpeedUnit.SEC;
      }
      case "msec" -> {
        return Motion.SpeedUnit.MSEC;
      }
      default -> {
        // mm/sec, cm/min, inch/min, deg/sec
      }
    }
    if (!peek().is(Kind.SLASH)) {
      throw error(t, "expected a speed unit (%, mm/sec, cm/min, inch/min, deg/sec, sec, msec), found " + t.describe());
    }
    next();
    TpToken per = expectWord("sec or min after '/'");
    String full = u + "/" + per.text().toLowerCase(Locale.ROOT);
    return switch (full) {
      case "mm/sec" -> Motion.SpeedUnit.MM_PER_SEC;
      case "cm/min" -> Motion.SpeedUnit.CM_PER_MIN;
      case "inch/min" -> Motion.SpeedUnit.INCH_PER_MIN;
      case "deg/sec" -> Motion.SpeedUnit.DEG_PER_SEC;
      default -> throw error(t, "unknown speed unit '" + full + "': expected mm/sec, cm/min, inch/min or deg/sec");
    };
  }

  /** Words that start a motion option (after the termination), for the hand-edit mend only. */
  private static final java.util.Set<String> OPTION_WORDS = java.util.Set.of(
      "OFFSET", "TOOL_OFFSET", "SKIP", "WJNT", "INC", "ACC", "TB", "TA", "DB", "PTH", "RTCP", "COORD", "MROT",
      "BREAK", "CR", "PSPD", "VOFFSET", "EV", "IND.EV", "RT_LD", "AP_LD", "CORNER");

  private static boolean isMotionOption(TpToken t) {
    return t.is(Kind.WORD) && OPTION_WORDS.contains(t.text().toUpperCase(Locale.ROOT));
  }

  /** Letters, digits and '_', starting with a letter: a register or port kind's name ({@code M}, {@code WO}). */
  private static boolean isKindName(String w) {
    if (w.isEmpty() || !Character.isLetter(w.charAt(0)) || w.length() > 24) {
      return false;
    }
    for (int i = 0; i < w.length(); i++) {
      char c = w.charAt(i);
      if (!(c < 128 && (Character.isLetterOrDigit(c) || c == '_'))) {
        return false;
      }
    }
    return true;
  }

  /** FINE, CNT or CNTn: a termination starts here. */
  private static boolean isTermination(TpToken t) {
    return t.isWord("FINE") || t.isWord("CNT")
        || t.is(Kind.WORD) && t.text().regionMatches(true, 0, "CNT", 0, 3) && allDigits(t.text(), 3);
  }

  private Motion.Termination termination() {
    TpToken t = peek();
    if (t.isWord("FINE")) {
      next();
      return new Motion.Fine();
    }
    if (t.isWord("CNT")) {
      next();
      if (peek().is(Kind.NUMBER)) {
        return new Motion.Cnt(cntValue(intConst("CNT value")));
      }
      expectWordNamed("R", "a number or R[i] after CNT");
      return new Motion.CntRegister(item("R"));
    }
    if (t.is(Kind.WORD) && t.text().regionMatches(true, 0, "CNT", 0, 3) && allDigits(t.text(), 3)) {
      next();
      return new Motion.Cnt(cntValue(parseIntOrFail(t, t.text().substring(3))));
    }
    throw error("expected a termination (FINE, CNTn or CNT R[i]), found " + t.describe());
  }

  private int cntValue(int v) {
    if (v > 100) {
      throw error("CNT" + v + ": expected 0..100");
    }
    return v;
  }

  private Motion.Option motionOption() {
    TpToken t = next();
    if (t.is(Kind.WORD)) {
      String w = t.text().toUpperCase(Locale.ROOT);
      switch (w) {
        case "OFFSET" -> {
          if (peek().is(Kind.COMMA)) {
            next();
            expectWordNamed("PR", "PR[i] after Offset,");
            return new Motion.OffsetPr(item("PR"));
          }
          return new Motion.Offset();
        }
        case "TOOL_OFFSET" -> {
          if (!peek().is(Kind.COMMA)) {
            return new Motion.ToolOffset();
          }
          expect(Kind.COMMA, "',PR[i]' after Tool_Offset");
          expectWordNamed("PR", "PR[i] after Tool_Offset,");
          return new Motion.ToolOffsetPr(item("PR"));
        }
        case "SKIP" -> {
          expect(Kind.COMMA, "',LBL[n]' after Skip");
          expectWordNamed("LBL", "LBL[n] after Skip,");
          LabelRef l = labelRef();
          if (peek().is(Kind.COMMA) && peek(1).isWord("PR") && peek(2).is(Kind.LBRACKET)) {
            // Skip,LBL[1],PR[2]=LPOS: high-speed skip, storing where the condition turned true
            next();
            next();
            Item pr = item("PR");
            expect(Kind.EQ, "'=' then LPOS or JPOS after Skip,LBL[n],PR[i]");
            TpToken what = expectWord("LPOS or JPOS");
            if (!what.isWord("LPOS") && !what.isWord("JPOS")) {
              throw error(what, "expected LPOS or JPOS after Skip,LBL[n],PR[i]=, found " + what.describe());
            }
            return Motion.Skip.storing(l, pr, what.isWord("JPOS"));
          }
          if (peek().is(Kind.COMMA)) {
            return rawOption(t, "Skip,LBL[] with " + TpToken.clip(peek(1).text()));
          }
          return new Motion.Skip(l);
        }
        case "WJNT" -> {
          return new Motion.Wjnt();
        }
        case "VOFFSET" -> {
          if (!peek().is(Kind.COMMA) || !peek(1).isWord("VR") || !peek(2).is(Kind.LBRACKET)) {
            // VOFFSET alone: the offset of a VOFFSET CONDITION, which RobotRun does not run
            return rawOption(t, optionKind(w));
          }
          next();
          next();
          return new Motion.VisionOffset(item("VR"));
        }
        case "INC" -> {
          return new Motion.Inc();
        }
        default -> {
          if (w.equals("ACC") && peek().isWord("R") && peek(1).is(Kind.LBRACKET)) {
            // ACC R[5]: the acceleration override a register holds
            next();
            return new Motion.AccRegister(item("R"));
          }
          if (w.startsWith("ACC") && allDigits(w, 3)) {
            int acc = parseIntOrFail(t, w.substring(3));
            if (acc > 150 && acc <= 500) {
              // A controller whose acceleration limit was raised lists ACC up to 500; RobotRun's is 150.
              return rawOption(t, "ACC above 150 (a raised acceleration limit)");
            }
            if (acc > 150) {
              throw error(t, "ACC" + acc + ": expected 0..150 (0..500 where the controller's limit is raised)");
            }
            return new Motion.Acc(acc);
          }
          if (w.equals("TB") || w.equals("TA") || w.equals("TIME") || w.equals("DB") || w.equals("DISTANCE")) {
            int at = tokens.indexOf(t);
            Motion.RawOption raw = rawOption(t, optionKind(w));
            return timedAction(at, raw);
          }
          return rawOption(t, optionKind(w));
        }
      }
    }
    throw error(t, "expected a motion option or the end of the statement, found " + t.describe());
  }

  /**
   * {@code TB t sec,action} / {@code TA ...} / {@code TIME BEFORE|AFTER ...} from token {@code at}:
   * a {@link Motion.TimedAction} when the action is an output or a CALL without arguments, else
   * {@code raw} (POINT_LOGIC, CALL with arguments and other actions stay as written and are not run).
   */
  private Motion.Option timedAction(int at, Motion.RawOption raw) {
    if (at < 0) {
      return raw;
    }
    List<TpToken> rest = tokens.subList(at, tokens.size());
    int k = 1;
    Motion.When when;
    TpToken first = rest.get(0);
    if (first.isWord("TB") || first.isWord("TA")) {
      when = first.isWord("TA") ? Motion.When.TIME_AFTER : Motion.When.TIME_BEFORE;
    } else if (first.isWord("DB")) {
      when = Motion.When.DISTANCE_BEFORE;
    } else if (first.isWord("TIME") && (rest.get(1).isWord("BEFORE") || rest.get(1).isWord("AFTER"))) {
      when = rest.get(1).isWord("AFTER") ? Motion.When.TIME_AFTER : Motion.When.TIME_BEFORE;
      k = 2;
    } else if (first.isWord("DISTANCE") && rest.get(1).isWord("BEFORE")) {
      when = Motion.When.DISTANCE_BEFORE;
      k = 2;
    } else {
      return raw;
    }
    String unit = when == Motion.When.DISTANCE_BEFORE ? "mm" : "sec";
    if (rest.size() < k + 4 || !rest.get(k).is(Kind.NUMBER) || !rest.get(k + 1).isWord(unit)
        || !rest.get(k + 2).is(Kind.COMMA)) {
      return raw;
    }
    double amount = Double.parseDouble(rest.get(k).text());
    try {
      TpStatementParser p = new TpStatementParser(new ArrayList<>(rest.subList(k + 3, rest.size())));
      Instruction action = p.statement();
      if (p.peek().is(Kind.EOL) && (action instanceof Instruction.SetIo || action instanceof Instruction.Pulse
          || action instanceof Instruction.Call c && c.nameRegister().isEmpty())
          && Double.isFinite(amount)) {
        return new Motion.TimedAction(when, amount, action, raw.text());
      }
    } catch (TpSyntaxError e) {
      // an action RobotRun does not run: kept as written
    }
    return raw;
  }

  private static String optionKind(String w) {
    return switch (w) {
      case "TB", "TA", "TIME" -> "TIME BEFORE/AFTER (TB/TA)";
      case "DB", "DISTANCE" -> "DISTANCE BEFORE (DB)";
      case "VOFFSET" -> "vision offset VOFFSET";
      case "PTH" -> "PTH";
      case "RTCP" -> "remote TCP (RTCP)";
      case "COORD" -> "coordinated motion COORD";
      case "MROT" -> "MROT";
      case "BREAK" -> "BREAK";
      case "CR" -> "corner region CR";
      case "PSPD" -> "process speed PSPD";
      default -> {
        String name = UNSUPPORTED.get(w);
        yield name != null ? name + " (as a motion option)" : "motion option " + TpToken.clip(w);
      }
    };
  }

  /**
   * The rest of the statement from {@code from} (already consumed) to its end, kept as
   * written: a motion option RobotRun does not run yet. Options after it go with it.
   */
  private Motion.RawOption rawOption(TpToken from, String what) {
    TpToken last = from;
    while (!peek().is(Kind.EOL)) {
      last = next();
    }
    TpToken eol = peek();
    String text = lineText.apply(from.line());
    String raw;
    if (text != null && eol.line() == from.line() && eol.column() - 1 <= text.length() && from.column() >= 1) {
      raw = text.substring(from.column() - 1, eol.column() - 1).strip();
    } else {
      StringBuilder sb = new StringBuilder();
      for (int k = tokens.indexOf(from); k >= 0 && k <= tokens.indexOf(last); k++) {
        TpToken x = tokens.get(k);
        TpToken before = k > 0 ? tokens.get(k - 1) : null;
        if (before != null && sb.length() > 0 && before.line() == x.line() && before.column() + writtenWidth(before) < x.column()) {
          sb.append(' ');
        }
        sb.append(x.is(Kind.STRING) ? "'" + x.text() + "'" : x.text());
      }
      raw = sb.toString();
    }
    return new Motion.RawOption(raw, what);
  }

  /** How many columns a token takes in the file: a string with its quotes. */
  private static int writtenWidth(TpToken t) {
    return t.is(Kind.STRING) ? t.text().length() + 2 : t.text().length();
  }

  // ---- expressions ------------------------------------------------------------------------

  private Expr expression() {
    return binary(1);
  }

  /** Precedence climbing: all binary operators are left-associative. */
  private Expr binary(int minPrecedence) {
    Expr left = unary();
    while (true) {
      Expr.BinaryOp op = binaryOp(peek());
      if (op == null || op.precedence() < minPrecedence) {
        return left;
      }
      next();
      countOperator();
      Expr right = binary(op.precedence() + 1);
      left = new Expr.Binary(op, left, right);
    }
  }

  private static Expr.BinaryOp binaryOp(TpToken t) {
    return switch (t.kind()) {
      case STAR -> Expr.BinaryOp.MUL;
      case SLASH -> Expr.BinaryOp.DIVIDE;
      case PLUS -> Expr.BinaryOp.ADD;
      case MINUS -> Expr.BinaryOp.SUB;
      case EQ -> Expr.BinaryOp.EQ;
      case NE -> Expr.BinaryOp.NE;
      case LT -> Expr.BinaryOp.LT;
      case LE -> Expr.BinaryOp.LE;
      case GT -> Expr.BinaryOp.GT;
      case GE -> Expr.BinaryOp.GE;
      case WORD -> switch (t.text().toUpperCase(Locale.ROOT)) {
        case "DIV" -> Expr.BinaryOp.DIV;
        case "MOD" -> Expr.BinaryOp.MOD;
        case "AND" -> Expr.BinaryOp.AND;
        case "OR" -> Expr.BinaryOp.OR;
        default -> null;
      };
      default -> null;
    };
  }

  private Expr unary() {
    TpToken t = peek();
    if (t.is(Kind.MINUS)) {
      next();
      if (peek().is(Kind.NUMBER)) {
        return negate(constant(next()));
      }
      countOperator();
      return nestedUnary(Expr.UnaryOp.MINUS);
    }
    if (t.is(Kind.BANG)) {
      next();
      countOperator();
      return nestedUnary(Expr.UnaryOp.NOT);
    }
    return operand();
  }

  /** A prefix operator's operand, counted as one level of nesting (as a parenthesis is). */
  private Expr nestedUnary(Expr.UnaryOp op) {
    if (++nesting > MAX_NESTING) {
      throw error("expression nested too deeply: at most " + MAX_NESTING + " levels of parentheses and signs");
    }
    Expr operand = unary();
    nesting--;
    return new Expr.Unary(op, operand);
  }

  private Expr negate(Expr c) {
    return switch (c) {
      case Expr.IntConst i -> new Expr.IntConst(-i.value());
      case Expr.RealConst r -> new Expr.RealConst(-r.value());
      default -> throw new IllegalStateException("constant expected");
    };
  }

  private void countOperator() {
    if (++operators > MAX_OPERATORS) {
      throw error("expression too long: more than " + MAX_OPERATORS + " operators in one statement");
    }
  }

  /** A single value: constant, register, I/O, parenthesised expression. */
  private Expr operand() {
    TpToken t = next();
    switch (t.kind()) {
      case NUMBER -> {
        return constant(t);
      }
      case LPAREN -> {
        if (++nesting > MAX_NESTING) {
          throw error(t, "expression nested too deeply: at most " + MAX_NESTING + " levels of parentheses and signs");
        }
        Expr inner = expression();
        expect(Kind.RPAREN, "')' closing the '(' of column " + t.column());
        nesting--;
        return new Expr.Group(inner);
      }
      case STRING -> {
        // a string constant: a CALL argument, a string register's value (SR[1]=SR[2]+'_A'), a comparison
        return new Expr.StringConst(t.text());
      }
      case WORD -> {
        String w = t.text().toUpperCase(Locale.ROOT);
        return switch (w) {
          case "ON", "OFF" -> {
            if (edgeFollows(w.equals("ON") ? Kind.PLUS : Kind.MINUS)) {
              // WAIT DI[1]=ON+ : the rising (ON+) or falling (OFF-) edge of a signal
              throw unsupported(t, "edge detection " + w + (w.equals("ON") ? "+" : "-"), false);
            }
            yield new Expr.OnOff(w.equals("ON"));
          }
          case "ERR_NUM" -> throw unsupported(t, "ERR_NUM (the error-recovery option's alarm number)", false);
          case "R" -> new Expr.Register(item("R"));
          case "PR" -> positionElement();

          case "TIMER" -> new Expr.Timer(item("TIMER"));
          case "SR" -> new Expr.StringReg(item("SR"));
          case "STRLEN", "SUBSTR", "FINDSTR" -> {
            Expr.StringFn fn = Expr.StringFn.valueOf(w);
            List<Expr> args = new ArrayList<>(fn.arity());
            for (int k = 0; k < fn.arity(); k++) {
              if (k > 0) {
                expect(Kind.COMMA, "',' (" + w + " takes " + fn.arity() + " arguments)");
              }
              args.add(unary());
            }
            yield new Expr.StringFunc(fn, args);
          }
          case "AR" -> {
            Item a = item("AR");
            if (!a.comment().isEmpty()) {
              throw error(t, "AR[i] takes no comment");
            }
            yield new Expr.Arg(a.index());
          }
          default -> {
            IoKind io = ioKind(w);
            if (io != null && peek().is(Kind.LBRACKET)) {
              yield new Expr.Io(io, item(w));
            }
            String name = UNSUPPORTED.get(w);
            if (name != null) {
              throw unsupported(t, name + " in an expression", false);
            }
            if (MATH_FUNCTIONS.contains(w) && peek().is(Kind.LBRACKET) && !w.equals("ATAN2")) {
              next();
              if (++nesting > MAX_NESTING) {
                throw error(t, "expression nested too deeply: at most " + MAX_NESTING + " levels of parentheses and signs");
              }
              Expr arg = expression();
              nesting--;
              expect(Kind.RBRACKET, "']' closing " + w + "[...]");
              yield new Expr.MathFunc(Expr.MathFn.valueOf(w), arg);
            }
            if (MATH_FUNCTIONS.contains(w) && peek().is(Kind.LBRACKET)) {
              // ABS[R[1]], SQRT[...]: the arithmetic functions of a controller option
              throw unsupported(t, "arithmetic function " + w + "[]", false);
            }
            if (w.startsWith("$")) {
              Optional<String> known = SystemVariables.supported(w);
              if (known.isPresent()) {
                yield new Expr.SysVar(known.get());
              }
              // An application's or another option's variable: the line alarms naming it.
              throw unsupported(t, "system variable " + TpToken.clip(t.text()) + " in an expression", false);
            }
            if (fromFile && peek().is(Kind.LBRACKET) && isKindName(w)) {
              // M[1] (a marker), WO[2], an application's register or port kind: kept, the line alarms
              throw unsupported(t, TpToken.clip(w) + "[] in an expression", false);
            }
            throw error(t, VALUE_EXPECTED + t.describe());
          }
        };
      }
      default -> throw error(t, VALUE_EXPECTED + t.describe());
    }
  }

  /** {@code ON+} / {@code OFF-}: the sign right after the word, then the end of the operand. */
  private boolean edgeFollows(Kind sign) {
    TpToken after = peek(1);
    return peek().is(sign) && (after.is(Kind.EOL) || after.is(Kind.RPAREN) || after.is(Kind.COMMA)
        || after.isWord("AND") || after.isWord("OR") || after.isWord("TIMEOUT"));
  }

  private Expr positionElement() {
    expect(Kind.LBRACKET, "'[' after PR");
    Index idx = indexValue("PR");
    if (!peek().is(Kind.COMMA)) {
      throw error("PR[i] is a whole position: in an expression use one element, PR[i,j]");
    }
    next();
    Index element = elementIndex();
    return new Expr.PosElement(new Item(idx, itemCommentAndClose("PR[i,j]")), element);
  }

  /**
   * The j of {@code PR[i,j]}: 1..6 (X..R or J1..J6), or {@code R[k]} resolved when the line
   * runs. 7..9 address the extended axes of a robot that has them (a rail): read and kept, not
   * run (the arm RobotRun moves has six axes).
   */
  private Index elementIndex() {
    TpToken t = peek();
    if (t.isWord("R") || t.isWord("AR")) {
      return indexValue("PR[i,j] element");
    }
    int element = intConst("element number 1..6 in PR[i,j]");
    if (element >= 7 && element <= 9) {
      throw unsupported(t, "PR[i,j] of an extended axis (j = 7..9)", false);
    }
    if (element < 1 || element > 6) {
      throw error(t, "PR[i,j]: j must be 1..6 (X,Y,Z,W,P,R or J1..J6), or 7..9 for extended axes, found " + element);
    }
    return new Index.Direct(element);
  }

  private Expr constant(TpToken t) {
    String s = t.text();
    if (s.indexOf('.') >= 0) {
      return new Expr.RealConst(finite(t));
    }
    try {
      return new Expr.IntConst(Integer.parseInt(s));
    } catch (NumberFormatException e) {
      throw error(t, "integer " + TpToken.clip(s) + " is too large: expected at most " + Integer.MAX_VALUE);
    }
  }

  // ---- items and indexes ------------------------------------------------------------------

  /** {@code [index(:comment)]} after the word {@code what} (already consumed). */
  private Item item(String what) {
    return item(what, what + "[i]");
  }

  private Item item(String what, String form) {
    if (!peek().is(Kind.LBRACKET)) {
      throw error("expected '[' after " + what + " (" + form + "), found " + peek().describe());
    }
    next();
    Index idx = indexValue(what);
    return new Item(idx, itemCommentAndClose(what + "[...]"));
  }

  /** An index without a comment: {@code PAYLOAD[1]}, {@code UALM[2]}, {@code UFRAME[R[1]]}. */
  private Index index(String what) {
    Item i = item(what);
    if (!i.comment().isEmpty()) {
      throw error(what + "[...] takes no comment");
    }
    return i.index();
  }

  private LabelRef labelRef() {
    expect(Kind.LBRACKET, "'[' after LBL");
    Index idx = indexValue("LBL");
    return new LabelRef(idx, itemCommentAndClose("LBL[...]"));
  }

  /** The number inside brackets: a non-negative integer or {@code R[i]} (indirect). */
  private Index indexValue(String what) {
    TpToken t = peek();
    if (t.is(Kind.NUMBER)) {
      int n = intConst("index of " + what + "[...]");
      checkRange(what, n);
      return new Index.Direct(n);
    }
    if (t.isWord("R")) {
      next();
      expect(Kind.LBRACKET, "'[' after R");
      int reg = intConst("register number in R[...]");
      checkRange("R", reg);
      String comment = itemCommentAndClose("R[...]");
      return new Index.Indirect(reg, comment);
    }
    if (t.isWord("AR")) {
      next();
      expect(Kind.LBRACKET, "'[' after AR");
      int arg = intConst("argument number in AR[...]");
      if (arg < 1) {
        throw error("AR[" + arg + "]: argument numbers start at 1");
      }
      expect(Kind.RBRACKET, "']' closing AR[...]");
      return new Index.ViaArg(arg);
    }
    if (t.isWord("GP1") && peek(1).is(Kind.COLON)) {
      // PR[GP1:5]: a multi-group controller names the group; group 1 is the arm RobotRun moves
      // (written back as read; an edited line is written without it, the same statement).
      next();
      next();
      return indexValue(what);
    }
    if (t.is(Kind.WORD) && t.text().regionMatches(true, 0, "GP", 0, 2)) {
      throw unsupported(t, "a group in " + what + "[GPn:...] (multi-group)", false);
    }
    throw error("expected an index (a number or R[i]) inside " + what + "[...], found " + t.describe());
  }

  /** Table sizes of the controller RobotRun simulates (program.Registers); other items are not checked here. */
  private void checkRange(String table, int n) {
    int size = switch (table) {
      case "R" -> Registers.R_COUNT;
      case "PR" -> Registers.PR_COUNT;
      case "TIMER" -> Registers.TIMER_COUNT;
      case "SR" -> Registers.SR_COUNT;
      default -> ioKind(table) != null ? ioRanges.size(ioKind(table)) : 0;
    };
    if (size > 0 && (n < 1 || n > size)) {
      warnings.add(table + "[" + n + "]: index out of range (expected 1.." + size + "); running this line raises an alarm");
    }
  }

  /** Optional {@code :comment} then the closing bracket. */
  private String itemCommentAndClose(String what) {
    String comment = "";
    if (peek().is(Kind.COLON)) {
      next();
      if (peek().is(Kind.ITEM_COMMENT)) {
        comment = next().text();
      }
    }
    expect(Kind.RBRACKET, "']' closing " + what);
    return comment;
  }

  /** {@code n} or {@code R[i]} as in {@code UFRAME_NUM=n|R[i]}. */
  private Index numberOrRegister(String what) {
    TpToken t = peek();
    if (t.is(Kind.NUMBER)) {
      return new Index.Direct(intConst(what + " value"));
    }
    if (t.isWord("R")) {
      next();
      Item r = item("R");
      if (!(r.index() instanceof Index.Direct d)) {
        throw error(what + "=R[R[i]] is not allowed: expected a number or R[i]");
      }
      return new Index.Indirect(d.value(), r.comment());
    }
    throw error("expected a number or R[i] after " + what + "=, found " + t.describe());
  }

  private int directNumber(Item item, String what) {
    if (!(item.index() instanceof Index.Direct d)) {
      throw error(what + "[...] needs a constant number (P[R[i]] does not exist; use PR[R[i]])");
    }
    if (d.value() < 1) {
      throw error(what + "[" + d.value() + "]: numbers start at 1");
    }
    return d.value();
  }

  // ---- tokens -----------------------------------------------------------------------------

  private int intConst(String what) {
    TpToken t = peek();
    if (!t.is(Kind.NUMBER) || t.text().indexOf('.') >= 0) {
      throw error("expected an integer (" + what + "), found " + t.describe());
    }
    next();
    return parseIntOrFail(t, t.text());
  }

  private double number(String what) {
    TpToken t = peek();
    if (!t.is(Kind.NUMBER)) {
      throw error("expected a number (" + what + "), found " + t.describe());
    }
    next();
    return finite(t);
  }

  /** A number token's value; one with hundreds of digits would be infinite, and is refused. */
  private double finite(TpToken t) {
    double v = Double.parseDouble(t.text());
    if (Double.isInfinite(v)) {
      throw error(t, "number " + TpToken.clip(t.text()) + " is too large");
    }
    return v;
  }

  private int parseIntOrFail(TpToken t, String digits) {
    try {
      return Integer.parseInt(digits);
    } catch (NumberFormatException e) {
      throw error(t, "number " + TpToken.clip(digits) + " is too large");
    }
  }

  private static boolean allDigits(String s, int from) {
    if (s.length() <= from) {
      return false;
    }
    for (int i = from; i < s.length(); i++) {
      if (s.charAt(i) < '0' || s.charAt(i) > '9') {
        return false;
      }
    }
    return true;
  }
}
