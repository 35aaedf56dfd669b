package org.robotrun.program;

/**
 * The one printer of TP text (TP-LANGUAGE.md), beside the one parser ({@link TpStatementParser}):
 * statements, motion parts and expressions as a controller writes them. The .LS writer lays its
 * lines out with it, and the pendant builds the fields of a line from its pieces, so what a
 * file holds and what the pendant shows are the same text.
 *
 * <p>The text is a function of the model only; parentheses the model does not hold are added only
 * where precedence needs them, so {@code parse(print(x))} gives back {@code x} for any model the
 * parser can produce (TpTextRoundTripPropertyTest).
 */
public final class TpText {
  private TpText() {}

  /**
   * How a circular motion's continuation line is joined to its via point in {@link #statement}:
   * as a controller lists it, on a line of its own.
   */
  public static final String CONTINUATION = "    \n    :  ";

  /**
   * The statement text between the line prefix ({@code "   7:"}) and the closing {@code ;}. A
   * motion's point-logic block (the sub-lines after a {@link Motion.RawOption}) is not part of
   * it; a C motion's end point is on a continuation line ({@link #CONTINUATION}).
   */
  public static String statement(Instruction in) {
    StringBuilder sb = new StringBuilder(32);
    statement(in, sb);
    return sb.toString();
  }

  /** Appends {@link #statement(Instruction)}. */
  public static void statement(Instruction in, StringBuilder sb) {
    switch (in) {
      case Instruction.Move m -> move(m, CONTINUATION, sb);
      case Instruction.AssignRegister a -> {
        item("R", a.register(), sb);
        sb.append('=');
        expr(a.value(), sb);
      }
      case Instruction.AssignPosReg a -> {
        item("PR", a.register(), sb);
        sb.append('=');
        posSource(a.source(), sb);
      }
      case Instruction.AssignPosElement a -> {
        posElement(a.register(), a.element(), sb);
        sb.append('=');
        expr(a.value(), sb);
      }
      case Instruction.SelectFrame s -> {
        sb.append(frameWord(s.kind())).append("_NUM").append(s.groupWritten() ? "[GP1]=" : "=");
        index(s.number(), sb);
      }
      case Instruction.SetFrame s -> {
        frame(s.kind(), s.frame(), s.comment(), sb);
        sb.append('=');
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
        call(r.program(), r.args(), sb);
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
        sb.append(SELECT_INDENT).append('=');
        expr(s.value(), sb);
        sb.append(',');
        branch(s.branch(), sb);
      }
      case Instruction.SelectElse s -> {
        sb.append(SELECT_INDENT).append("ELSE,");
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
        waitTime(w.seconds(), sb);
      }
      case Instruction.WaitCondition w -> {
        sb.append("WAIT ");
        // A bare constant (-5 included) or register would read back as a time: parenthesise it.
        Expr c = w.condition();
        boolean timeLike = c instanceof Expr.IntConst || c instanceof Expr.RealConst || c instanceof Expr.Register
            || c instanceof Expr.Unary;
        checkNesting(c);
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
      case Instruction.MacroCall c -> {
        sb.append(c.name());
        arguments(c.args(), sb);
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
      case Instruction.VisionRunFind v -> {
        sb.append("VISION RUN_FIND ");
        process(v.process(), sb);
      }
      case Instruction.VisionGetOffset v -> {
        sb.append("VISION GET_OFFSET ");
        process(v.process(), sb);
        sb.append(' ');
        item("VR", v.vr(), sb);
        sb.append(" JMP,");
        label(v.label(), sb);
      }
      case Instruction.VisionGetNFound v -> {
        sb.append("VISION GET_NFOUND ");
        process(v.process(), sb);
        sb.append(' ');
        item("R", v.register(), sb);
      }
      case Instruction.AssignFromVr a -> {
        item("R", a.register(), sb);
        sb.append('=');
        item("VR", a.vr(), sb);
        sb.append('.').append(a.field().name());
        if (a.field() == Instruction.VisionField.MES) {
          sb.append('[').append(a.element()).append(']');
        }
      }
      case Instruction.Unsupported u -> sb.append(u.text());
    }
  }

  /** {@code 'NAME'} or {@code SR[i]}. */
  private static void process(Instruction.VisionProcess p, StringBuilder sb) {
    switch (p) {
      case Instruction.VisionProcessName n -> exprUnchecked(new Expr.StringConst(n.name()), sb);
      case Instruction.VisionProcessInRegister r -> item("SR", r.register(), sb);
    }
  }

  /** What a SELECT's further lines start with, so their {@code =} stands under the register. */
  public static final String SELECT_INDENT = "       ";

  // ---- motion -------------------------------------------------------------------------------

  /**
   * {@code type target [continuation end] speed termination [options]}; a {@link
   * Motion.RawOption}'s point-logic sub-lines are left out (the .LS writer puts them after the
   * {@code ;}).
   */
  public static void move(Instruction.Move m, String continuation, StringBuilder sb) {
    sb.append(m.type().name()).append(' ');
    target(m.target(), sb);
    if (m.circularEnd().isPresent()) {
      sb.append(continuation);
      target(m.circularEnd().get(), sb);
    }
    sb.append(' ').append(speed(m.speed())).append(' ').append(termination(m.termination()));
    for (Motion.Option o : m.options()) {
      sb.append(' ').append(option(o));
    }
  }

  /** {@code P[2:PICK]} or {@code PR[R[1]]}. */
  public static String target(Motion.Target t) {
    StringBuilder sb = new StringBuilder();
    target(t, sb);
    return sb.toString();
  }

  private static void target(Motion.Target t, StringBuilder sb) {
    switch (t) {
      case Motion.Local l -> sb.append("P[").append(l.number()).append(comment(l.comment())).append(']');
      case Motion.Register r -> item("PR", r.register(), sb);
    }
  }

  /** {@code 400mm/sec}, {@code R[3]%}. */
  public static String speed(Motion.Speed s) {
    return speedValue(s.value()) + unit(s.unit());
  }

  /** The number of a speed: {@code 400}, {@code 0.5}, {@code R[3]}. */
  public static String speedValue(Motion.SpeedValue v) {
    return switch (v) {
      case Motion.SpeedConst c -> FanucFormat.plain(c.value());
      case Motion.SpeedRegister r -> item("R", r.register());
    };
  }

  /** How a speed unit is written: {@code %}, {@code mm/sec}, {@code sec}. */
  public static String unit(Motion.SpeedUnit unit) {
    return switch (unit) {
      case PERCENT -> "%";
      case SEC -> "sec";
      case MSEC -> "msec";
      case MM_PER_SEC -> "mm/sec";
      case CM_PER_MIN -> "cm/min";
      case INCH_PER_MIN -> "inch/min";
      case DEG_PER_SEC -> "deg/sec";
    };
  }

  /** {@code FINE}, {@code CNT50}, {@code CNT R[2]}. */
  public static String termination(Motion.Termination t) {
    return switch (t) {
      case Motion.Fine f -> "FINE";
      case Motion.Cnt c -> "CNT" + c.value();
      case Motion.CntRegister c -> "CNT " + item("R", c.register());
    };
  }

  /** A motion option as written ({@code Offset,PR[1]}, {@code ACC80}); a kept option's first line only. */
  public static String option(Motion.Option o) {
    return switch (o) {
      case Motion.Offset x -> "Offset";
      case Motion.OffsetPr x -> "Offset," + item("PR", x.register());
      case Motion.ToolOffsetPr x -> "Tool_Offset," + item("PR", x.register());
      case Motion.Acc x -> "ACC" + x.percent();
      case Motion.Skip x -> "Skip," + label(x.label());
      case Motion.Wjnt x -> "Wjnt";
      case Motion.Inc x -> "INC";
      case Motion.VisionOffset x -> "VOFFSET," + item("VR", x.vr());
      case Motion.TimedAction x -> x.text();
      case Motion.RawOption x -> {
        int nl = x.text().indexOf('\n');
        yield nl < 0 ? x.text() : x.text().substring(0, nl);
      }
    };
  }

  // ---- parts of statements --------------------------------------------------------------------

  /** The right side of {@code PR[i]=…}. */
  public static String posSource(Instruction.PosSource s) {
    StringBuilder sb = new StringBuilder();
    posSource(s, sb);
    return sb.toString();
  }

  private static void posSource(Instruction.PosSource s, StringBuilder sb) {
    switch (s) {
      case Instruction.FromPosReg f -> item("PR", f.register(), sb);
      case Instruction.FromLocal f -> sb.append("P[").append(f.number()).append(comment(f.comment())).append(']');
      case Instruction.CurrentLpos c -> sb.append("LPOS");
      case Instruction.CurrentJpos c -> sb.append("JPOS");
      case Instruction.FromFrame f -> frame(f.kind(), f.frame(), f.comment(), sb);
      case Instruction.FromVisionRegister v -> {
        item("VR", v.vr(), sb);
        sb.append(v.foundPos() ? ".FOUND_POS[1]" : ".OFFSET");
      }
      case Instruction.PosSum p -> {
        posSource(p.first(), sb);
        for (Instruction.PosTerm t : p.rest()) {
          sb.append(t.add() ? '+' : '-');
          posSource(t.term(), sb);
        }
      }
      case Instruction.PosArithmetic p -> {
        item("PR", p.left(), sb);
        sb.append(p.add() ? '+' : '-');
        item("PR", p.right(), sb);
      }
    }
  }

  /** {@code UFRAME} or {@code UTOOL}. */
  public static String frameWord(Instruction.FrameKind k) {
    return switch (k) {
      case USER -> "UFRAME";
      case TOOL -> "UTOOL";
    };
  }

  private static void frame(Instruction.FrameKind kind, Index frame, String comment, StringBuilder sb) {
    sb.append(frameWord(kind)).append('[');
    index(frame, sb);
    sb.append(comment(comment)).append(']');
  }

  /** {@code JMP LBL[3]} or {@code CALL NAME(args)}. */
  public static String branch(Instruction.Branch b) {
    StringBuilder sb = new StringBuilder();
    branch(b, sb);
    return sb.toString();
  }

  private static void branch(Instruction.Branch b, StringBuilder sb) {
    switch (b) {
      case Instruction.Jump j -> {
        sb.append("JMP ");
        label(j.label(), sb);
      }
      case Instruction.Call c -> {
        sb.append("CALL ");
        call(c.program(), c.args(), sb);
      }
    }
  }

  /** A CALL's program and arguments: {@code NAME} or {@code NAME(1,'A',R[2])}. */
  public static String call(String program, java.util.List<Expr> args) {
    StringBuilder sb = new StringBuilder();
    call(program, args, sb);
    return sb.toString();
  }

  private static void call(String program, java.util.List<Expr> args, StringBuilder sb) {
    sb.append(program);
    arguments(args, sb);
  }

  private static void arguments(java.util.List<Expr> args, StringBuilder sb) {
    if (args.isEmpty()) {
      return;
    }
    sb.append('(');
    for (int i = 0; i < args.size(); i++) {
      if (i > 0) {
        sb.append(',');
      }
      expr(args.get(i), sb);
    }
    sb.append(')');
  }

  /** A WAIT's time: {@code    .20(sec)} (FANUC's six-wide seconds) or {@code R[2]}. */
  public static String waitTime(Expr seconds) {
    StringBuilder sb = new StringBuilder();
    waitTime(seconds, sb);
    return sb.toString();
  }

  private static void waitTime(Expr seconds, StringBuilder sb) {
    switch (seconds) {
      case Expr.RealConst c -> sb.append(FanucFormat.waitSeconds(c.value())).append("(sec)");
      case Expr.IntConst c -> sb.append(FanucFormat.waitSeconds(c.value())).append("(sec)");
      case Expr.Register r -> expr(r, sb);
      default -> {
        expr(seconds, sb);
        sb.append("(sec)");
      }
    }
  }

  // ---- expressions --------------------------------------------------------------------------

  /**
   * An expression. The reader and the pendant refuse nesting beyond {@link TpLimits#MAX_NESTING};
   * a model built otherwise is refused here with a message rather than overflowing the stack.
   *
   * @throws IllegalArgumentException when {@code e} is nested deeper than the limit
   */
  public static String expr(Expr e) {
    StringBuilder sb = new StringBuilder();
    expr(e, sb);
    return sb.toString();
  }

  /** Appends {@link #expr(Expr)}. */
  public static void expr(Expr e, StringBuilder sb) {
    checkNesting(e);
    exprUnchecked(e, sb);
  }

  private static void checkNesting(Expr e) {
    if (TpLimits.nesting(e, TpLimits.MAX_NESTING) > TpLimits.MAX_NESTING) {
      throw new IllegalArgumentException("expression nested deeper than " + TpLimits.MAX_NESTING
          + " levels of parentheses and signs: a controller would not read it");
    }
  }

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
      case Expr.Group g -> 7;
    };
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
      case Expr.PosElement p -> posElement(p.register(), p.element(), sb);
      case Expr.Io io -> item(io.kind().name(), io.port(), sb);
      case Expr.Timer t -> item("TIMER", t.timer(), sb);
      case Expr.SysVar v -> sb.append(v.name());
      case Expr.StringReg r -> item("SR", r.register(), sb);
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

  /** {@code KIND[index:comment]}. */
  public static String item(String kind, Item item) {
    StringBuilder sb = new StringBuilder();
    item(kind, item, sb);
    return sb.toString();
  }

  private static void item(String kind, Item item, StringBuilder sb) {
    sb.append(kind).append('[');
    index(item.index(), sb);
    sb.append(comment(item.comment())).append(']');
  }

  /** {@code PR[i,j:comment]}. */
  private static void posElement(Item register, Index element, StringBuilder sb) {
    sb.append("PR[");
    index(register.index(), sb);
    sb.append(',');
    index(element, sb);
    sb.append(comment(register.comment())).append(']');
  }

  /** {@code LBL[n:comment]}. */
  public static String label(LabelRef l) {
    StringBuilder sb = new StringBuilder();
    label(l, sb);
    return sb.toString();
  }

  private static void label(LabelRef l, StringBuilder sb) {
    sb.append("LBL[");
    index(l.index(), sb);
    sb.append(comment(l.comment())).append(']');
  }

  /** The number inside brackets: {@code 5}, {@code R[2:PTR]}, {@code AR[1]}. */
  public static String index(Index i) {
    StringBuilder sb = new StringBuilder();
    index(i, sb);
    return sb.toString();
  }

  private static void index(Index i, StringBuilder sb) {
    switch (i) {
      case Index.Direct d -> sb.append(d.value());
      case Index.Indirect r -> sb.append("R[").append(r.register()).append(comment(r.comment())).append(']');
      case Index.ViaArg a -> sb.append("AR[").append(a.arg()).append(']');
    }
  }

  private static String comment(String c) {
    return c.isEmpty() ? "" : ":" + c;
  }
}
