package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.function.BiFunction;
import java.util.function.Function;
import org.robotrun.pendant.ExprText.BadText;
import org.robotrun.program.FanucFormat;
import org.robotrun.program.TpStatementParser;
import org.robotrun.program.TpSyntaxError;
import org.robotrun.program.TpText;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;
import org.robotrun.program.LabelRef;
import org.robotrun.program.Motion;
import org.robotrun.program.Program;

/**
 * An instruction as the EDIT screen shows it: a list of {@link Field}s, each editable one
 * knowing how to build the changed instruction. The text follows FANUC's pendant display
 * ({@code L P[2] 200mm/sec CNT50}); each field's text is a piece of the one printer of TP text
 * ({@link TpText}), so a line reads on the pendant as it is written in a file, and typed text is
 * read by the one parser's fragment entry points ({@link TpStatementParser}).
 */
public final class TpLine {
  private TpLine() {}

  /** The fields of {@code in} for a robot with the controller's default maximum TCP speed. */
  public static List<Field> fields(Instruction in, Program program, List<String> programs) {
    return fields(in, program, programs, DEFAULT_MAX_MM_PER_SEC);
  }

  /** The default top of the mm/sec range ($SPEEDLIM) when the robot's own is not known. */
  static final double DEFAULT_MAX_MM_PER_SEC = 2000;

  /**
   * The fields of {@code in}; {@code program} names local positions, {@code programs} feeds CALL
   * choices, {@code maxMmPerSec} is the robot's maximum TCP speed (the top of the mm/sec range).
   */
  public static List<Field> fields(Instruction in, Program program, List<String> programs, double maxMmPerSec) {
    List<Field> f = new ArrayList<>();
    switch (in) {
      case Instruction.Move m -> move(m, program, f, maxMmPerSec);
      case Instruction.AssignRegister a -> {
        f.add(itemField("R", a.register(), i -> new Instruction.AssignRegister(i, a.value())));
        f.add(Field.fixed("="));
        String text = TpText.expr(a.value());
        f.add(new Field(text, Field.Edit.entry(text, t -> {
          Expr e = value(t);
          if (e instanceof Expr.StringConst) {
            // as the .LS reader refuses R[1]='A'
            throw new BadText("R[] holds a number, not a string constant: put the text in a string register SR[i]");
          }
          return new Instruction.AssignRegister(a.register(), e);
        })));
      }
      case Instruction.SkipCondition s -> {
        f.add(Field.fixed("SKIP CONDITION "));
        f.add(exprField(s.condition(), Instruction.SkipCondition::new));
      }
      case Instruction.OffsetCondition o -> {
        f.add(Field.fixed("OFFSET CONDITION "));
        f.add(itemField("PR", o.register(), i -> new Instruction.OffsetCondition(i, o.userFrame())));
        o.userFrame().ifPresent(j -> f.add(Field.fixed(",UFRAME[" + TpText.index(j) + "]")));
      }
      case Instruction.MacroCall c -> {
        f.add(new Field(c.name(), Field.Edit.both(programs,
            k -> new Instruction.MacroCall(programs.get(k), c.args()), c.name(),
            t -> new Instruction.MacroCall(macroName(t), c.args()))));
        if (!c.args().isEmpty()) {
          f.add(Field.fixed(TpText.call("", c.args())));
        }
      }
      case Instruction.Monitor mo -> {
        f.add(Field.fixed(mo.end() ? "MONITOR END " : "MONITOR "));
        f.add(new Field(mo.program(), Field.Edit.both(programs, k -> new Instruction.Monitor(programs.get(k), mo.end()),
            mo.program(), t -> new Instruction.Monitor(macroName(t), mo.end()))));
      }
      case Instruction.When w -> {
        f.add(Field.fixed("WHEN "));
        f.add(exprField(w.condition(), e -> new Instruction.When(e, w.action())));
        f.add(Field.fixed(",CALL "));
        f.add(callField(w.action(), programs, c -> new Instruction.When(w.condition(), c)));
      }
      case Instruction.AssignString a -> {
        f.add(itemField("SR", a.register(), i -> new Instruction.AssignString(i, a.value())));
        f.add(Field.fixed("="));
        f.add(exprField(a.value(), e -> new Instruction.AssignString(a.register(), e)));
      }
      case Instruction.SetSysVar s -> {
        f.add(Field.fixed(s.name()));
        f.add(Field.fixed("="));
        f.add(exprField(s.value(), e -> new Instruction.SetSysVar(s.name(), e)));
      }
      case Instruction.AssignPosReg a -> {
        f.add(itemField("PR", a.register(), i -> new Instruction.AssignPosReg(i, a.source())));
        f.add(Field.fixed("="));
        f.add(posSourceField(a));
      }
      case Instruction.AssignPosElement a -> {
        String target = TpText.expr(new Expr.PosElement(a.register(), a.element()));
        f.add(new Field(target,
            Field.Edit.entry(target, t -> {
              Expr e = ExprText.parse(t);
              if (!(e instanceof Expr.PosElement pe)) {
                throw new BadText("expected PR[i,j]");
              }
              return new Instruction.AssignPosElement(pe.register(), pe.element(), a.value());
            })));
        f.add(Field.fixed("="));
        f.add(exprField(a.value(), e -> new Instruction.AssignPosElement(a.register(), a.element(), e)));
      }
      case Instruction.SelectFrame s -> {
        // UTOOL_NUM[GP1]: the group as the line names it, kept through an edit
        String group = s.groupWritten() ? "[GP1]" : "";
        f.add(new Field(frameWord(s.kind()) + "_NUM" + group, Field.Edit.choice(List.of("UFRAME_NUM", "UTOOL_NUM"),
            k -> new Instruction.SelectFrame(k == 0 ? FrameKind.USER : FrameKind.TOOL, s.number(), s.groupWritten()))));
        f.add(Field.fixed("="));
        f.add(indexField(s.number(), i -> new Instruction.SelectFrame(s.kind(), i, s.groupWritten())));
      }
      case Instruction.SetFrame s -> {
        f.add(Field.fixed(frameWord(s.kind()) + "["));
        f.add(indexField(s.frame(), s.comment(), i -> new Instruction.SetFrame(s.kind(), i, s.comment(), s.register())));
        f.add(Field.fixed("]="));
        f.add(itemField("PR", s.register(), i -> new Instruction.SetFrame(s.kind(), s.frame(), s.comment(), i)));
      }
      case Instruction.Payload p -> {
        f.add(Field.fixed("PAYLOAD["));
        f.add(indexField(p.schedule(), p.comment(), i -> new Instruction.Payload(i, p.comment())));
        f.add(Field.fixed("]"));
      }
      case Instruction.Label l -> {
        f.add(Field.fixed("LBL["));
        String shown = TpText.index(new Index.Direct(l.number())) + (l.comment().isEmpty() ? "" : ":" + l.comment());
        f.add(new Field(shown,
            Field.Edit.entry(shown, t -> {
              LabelRef r = parseLabel(t);
              if (!(r.index() instanceof Index.Direct d)) {
                throw new BadText("a label is a plain number (LBL[R[i]] only in JMP)");
              }
              return new Instruction.Label(d.value(), r.comment());
            })));
        f.add(Field.fixed("]"));
      }
      case Instruction.Jump j -> {
        f.add(Field.fixed("JMP "));
        f.add(labelField(j.label(), Instruction.Jump::new));
      }
      case Instruction.Call c -> {
        f.add(Field.fixed("CALL "));
        f.add(callField(c, programs, call -> call));
      }
      case Instruction.Run r -> {
        f.add(Field.fixed("RUN "));
        f.add(callField(new Instruction.Call(r.program(), r.args()), programs,
            call -> new Instruction.Run(call.program(), call.args())));
      }
      case Instruction.End e -> f.add(Field.fixed("END"));
      case Instruction.Pause p -> f.add(Field.fixed("PAUSE"));
      case Instruction.Abort a -> f.add(Field.fixed("ABORT"));
      case Instruction.If i -> {
        f.add(Field.fixed("IF "));
        f.add(exprField(i.condition(), e -> new Instruction.If(e, i.branch())));
        f.add(Field.fixed(","));
        f.add(branchField(i.branch(), programs, b -> new Instruction.If(i.condition(), b)));
      }
      case Instruction.IfAction i -> {
        f.add(Field.fixed("IF "));
        f.add(exprField(i.condition(), e -> new Instruction.IfAction(e, i.action())));
        f.add(Field.fixed(","));
        // The action's own fields, each edit rebuilding the IF around the edited action.
        for (Field a : fields(i.action(), program, programs, maxMmPerSec)) {
          f.add(a.mapped(x -> Instruction.IfAction.allowedAction(x) ? new Instruction.IfAction(i.condition(), x) : i));
        }
      }
      case Instruction.IfThen i -> {
        f.add(Field.fixed("IF "));
        f.add(exprField(i.condition(), Instruction.IfThen::new));
        f.add(Field.fixed(" THEN"));
      }
      case Instruction.Else e -> f.add(Field.fixed("ELSE"));
      case Instruction.EndIf e -> f.add(Field.fixed("ENDIF"));
      case Instruction.Select s -> {
        f.add(Field.fixed("SELECT "));
        f.add(itemField("R", s.register(), r -> new Instruction.Select(r, s.value(), s.branch())));
        f.add(Field.fixed("="));
        f.add(exprField(s.value(), v -> new Instruction.Select(s.register(), v, s.branch())));
        f.add(Field.fixed(","));
        f.add(branchField(s.branch(), programs, b -> new Instruction.Select(s.register(), s.value(), b)));
      }
      case Instruction.SelectCase s -> {
        f.add(Field.fixed(TpText.SELECT_INDENT + "="));
        f.add(exprField(s.value(), v -> new Instruction.SelectCase(v, s.branch())));
        f.add(Field.fixed(","));
        f.add(branchField(s.branch(), programs, b -> new Instruction.SelectCase(s.value(), b)));
      }
      case Instruction.SelectElse s -> {
        f.add(Field.fixed(TpText.SELECT_INDENT + "ELSE,"));
        f.add(branchField(s.branch(), programs, Instruction.SelectElse::new));
      }
      case Instruction.For fo -> {
        f.add(Field.fixed("FOR "));
        f.add(itemField("R", fo.counter(), r -> new Instruction.For(r, fo.start(), fo.down(), fo.end())));
        f.add(Field.fixed("="));
        f.add(forBoundField(fo.start(), e -> new Instruction.For(fo.counter(), e, fo.down(), fo.end())));
        f.add(new Field(fo.down() ? " DOWNTO " : " TO ", Field.Edit.choice(List.of("TO", "DOWNTO"),
            k -> new Instruction.For(fo.counter(), fo.start(), k == 1, fo.end()))));
        f.add(forBoundField(fo.end(), e -> new Instruction.For(fo.counter(), fo.start(), fo.down(), e)));
      }
      case Instruction.EndFor e -> f.add(Field.fixed("ENDFOR"));
      case Instruction.WaitTime w -> {
        f.add(Field.fixed("WAIT "));
        boolean constant = w.seconds() instanceof Expr.IntConst || w.seconds() instanceof Expr.RealConst;
        // FANUC shows a constant wait with two decimals and no leading zero: WAIT .20(sec)
        String shown = constant ? FanucFormat.waitSeconds(number(w.seconds())).strip() : TpText.expr(w.seconds());
        f.add(new Field(shown, Field.Edit.entry(shown, t -> new Instruction.WaitTime(waitTime(t)))));
        if (!(w.seconds() instanceof Expr.Register)) {
          f.add(Field.fixed("(sec)"));
        }
      }
      case Instruction.WaitCondition w -> {
        f.add(Field.fixed("WAIT "));
        f.add(exprField(w.condition(), e -> new Instruction.WaitCondition(e, w.timeoutLabel())));
        // no timeout: an empty field the cursor can still reach to add one
        String shown = w.timeoutLabel().map(l -> " TIMEOUT," + TpText.label(l)).orElse("");
        f.add(new Field(shown, Field.Edit.both(List.of("no timeout", "TIMEOUT,LBL[...]"),
            k -> new Instruction.WaitCondition(w.condition(),
                k == 0 ? Optional.empty() : Optional.of(w.timeoutLabel().orElse(LabelRef.of(1)))),
            w.timeoutLabel().map(TpText::label).orElse(""),
            t -> new Instruction.WaitCondition(w.condition(),
                t.isBlank() ? Optional.empty() : Optional.of(parseLabel(t))))));
      }
      case Instruction.TimerSet t -> {
        f.add(itemField("TIMER", t.timer(), i -> new Instruction.TimerSet(i, t.action())));
        f.add(Field.fixed("="));
        f.add(new Field(t.action().name(), Field.Edit.choice(List.of("START", "STOP", "RESET"),
            k -> new Instruction.TimerSet(t.timer(), Instruction.TimerAction.values()[k]))));
      }
      case Instruction.SetIo s -> {
        f.add(ioField(s.kind(), s.port(), (k, p) -> new Instruction.SetIo(k, p, s.value())));
        f.add(Field.fixed("="));
        f.add(new Field(TpText.expr(s.value()), Field.Edit.both(
            s.kind().group() ? List.of() : List.of("ON", "OFF", "PULSE", "R[...]"),
            k -> switch (k) {
              case 0, 1 -> new Instruction.SetIo(s.kind(), s.port(), new Expr.OnOff(k == 0));
              case 2 -> new Instruction.Pulse(s.kind(), s.port(), OptionalDouble.empty());
              default -> new Instruction.SetIo(s.kind(), s.port(), new Expr.Register(Item.of(1)));
            },
            TpText.expr(s.value()), t -> new Instruction.SetIo(s.kind(), s.port(), value(t)))));
      }
      case Instruction.Pulse p -> {
        f.add(ioField(p.kind(), p.port(), (k, port) -> new Instruction.Pulse(k, port, p.widthSec())));
        f.add(Field.fixed("="));
        f.add(new Field("PULSE", Field.Edit.choice(List.of("ON", "OFF", "PULSE"), k -> k == 2 ? p
            : new Instruction.SetIo(p.kind(), p.port(), new Expr.OnOff(k == 0)))));
        // no width ($DEFPULSE applies): an empty field the cursor can still reach to add one
        String width = p.widthSec().isPresent() ? "," + FanucFormat.plain(p.widthSec().getAsDouble()) + "sec" : "";
        f.add(new Field(width, Field.Edit.entry(p.widthSec().isPresent() ? FanucFormat.plain(p.widthSec().getAsDouble()) : "",
            t -> new Instruction.Pulse(p.kind(), p.port(),
                t.isBlank() ? OptionalDouble.empty() : OptionalDouble.of(NumberEntry.positive("Pulse width", t))))));
      }
      case Instruction.Comment c -> {
        f.add(Field.fixed("!"));
        f.add(new Field(c.text(), Field.Edit.entry(c.text(), Instruction.Comment::new)));
      }
      case Instruction.CommentedOut c -> {
        f.add(Field.fixed("//"));
        f.add(new Field(c.text(), Field.Edit.entry(c.text(), Instruction.CommentedOut::new)));
      }
      case Instruction.Message m -> {
        f.add(Field.fixed("MESSAGE["));
        f.add(new Field(m.text(), Field.Edit.entry(m.text(), Instruction.Message::new)));
        f.add(Field.fixed("]"));
      }
      case Instruction.UserAlarm u -> {
        f.add(Field.fixed("UALM["));
        f.add(indexField(u.number(), u.comment(), i -> new Instruction.UserAlarm(i, u.comment())));
        f.add(Field.fixed("]"));
      }
      case Instruction.SetOverride o -> {
        f.add(Field.fixed("OVERRIDE="));
        String pct = TpText.expr(o.percent());
        f.add(new Field(pct, Field.Edit.entry(pct, t -> new Instruction.SetOverride(overridePercent(t)))));
        if (!(o.percent() instanceof Expr.Register)) {
          f.add(Field.fixed("%"));
        }
      }
      case Instruction.VisionRunFind v -> {
        f.add(Field.fixed("VISION RUN_FIND "));
        f.add(processField(v.process(), Instruction.VisionRunFind::new));
      }
      case Instruction.VisionGetOffset v -> {
        f.add(Field.fixed("VISION GET_OFFSET "));
        f.add(processField(v.process(), x -> new Instruction.VisionGetOffset(x, v.vr(), v.label())));
        f.add(Field.fixed(" "));
        f.add(itemField("VR", v.vr(), i -> new Instruction.VisionGetOffset(v.process(), i, v.label())));
        f.add(Field.fixed(" JMP,"));
        f.add(labelField(v.label(), l -> new Instruction.VisionGetOffset(v.process(), v.vr(), l)));
      }
      case Instruction.VisionGetNFound v -> {
        f.add(Field.fixed("VISION GET_NFOUND "));
        f.add(processField(v.process(), x -> new Instruction.VisionGetNFound(x, v.register())));
        f.add(Field.fixed(" "));
        f.add(itemField("R", v.register(), i -> new Instruction.VisionGetNFound(v.process(), i)));
      }
      case Instruction.AssignFromVr v -> {
        f.add(itemField("R", v.register(), i -> new Instruction.AssignFromVr(i, v.vr(), v.field(), v.element())));
        f.add(Field.fixed("="));
        f.add(itemField("VR", v.vr(), i -> new Instruction.AssignFromVr(v.register(), i, v.field(), v.element())));
        String field = "." + v.field().name() + (v.field() == Instruction.VisionField.MES ? "[" + v.element() + "]" : "");
        f.add(new Field(field, Field.Edit.choice(List.of(".MODELID", ".ENC", ".MES[1]"), k ->
            new Instruction.AssignFromVr(v.register(), v.vr(), Instruction.VisionField.values()[k], k == 2 ? 1 : 0))));
      }
      case Instruction.Blank b -> { }
      // Kept as written; the pendant shows it and can delete or comment it out, not edit it.
      case Instruction.Unsupported u -> f.add(Field.fixed(u.text()));
    }
    return f;
  }

  /** The line's text with no cursor: what FIND searches and what a comment-out keeps. */
  public static String text(Instruction in, Program program, List<String> programs) {
    StringBuilder sb = new StringBuilder();
    for (Field f : fields(in, program, programs)) {
      sb.append(f.text());
    }
    return sb.toString();
  }

  // ---- motion --------------------------------------------------------------------------------

  private static void move(Instruction.Move m, Program program, List<Field> f, double maxMmPerSec) {
    f.add(new Field(m.type().name(), Field.Edit.choice(List.of("J", "L", "C", "A"),
        k -> withType(m, Motion.Type.values()[k], maxMmPerSec))));
    f.add(Field.fixed(" "));
    f.add(targetField(m.target(), program, t -> new Instruction.Move(m.type(), t, m.circularEnd(), m.speed(), m.termination(), m.options())));
    if (m.circularEnd().isPresent()) {
      f.add(Field.fixed(" : "));
      f.add(targetField(m.circularEnd().get(), program,
          t -> new Instruction.Move(m.type(), m.target(), Optional.of(t), m.speed(), m.termination(), m.options())));
    }
    f.add(Field.fixed(" "));
    String speed = TpText.speedValue(m.speed().value());
    f.add(new Field(speed, Field.Edit.entry(speed,
        t -> withSpeed(m, checkedSpeed(new Motion.Speed(speedValue(t), m.speed().unit()), maxMmPerSec)))));
    List<Motion.SpeedUnit> units = Arrays.stream(Motion.SpeedUnit.values()).filter(u -> u.fits(m.type())).toList();
    f.add(new Field(unit(m.speed().unit()), Field.Edit.choice(units.stream().map(TpLine::unit).toList(),
        k -> withSpeed(m, speedInRange(new Motion.Speed(m.speed().value(), units.get(k)), maxMmPerSec)))));
    f.add(Field.fixed(" "));
    String term = TpText.termination(m.termination());
    f.add(new Field(term, Field.Edit.both(List.of("FINE", "CNT"),
        k -> withTerm(m, k == 0 ? new Motion.Fine() : new Motion.Cnt(100)), term.equals("FINE") ? "" : term.substring(3).trim(),
        t -> withTerm(m, parseTermination(t)))));
    for (int i = 0; i < m.options().size(); i++) {
      int at = i;
      Motion.Option o = m.options().get(i);
      f.add(Field.fixed(" "));
      f.add(optionField(m, at, o));
    }
  }

  private static Field optionField(Instruction.Move m, int at, Motion.Option o) {
    String text = optionText(o);
    Field.Entry entry = switch (o) {
      case Motion.OffsetPr p -> t -> withOption(m, at, new Motion.OffsetPr(ExprText.parseItem("PR", t)));
      case Motion.ToolOffsetPr p -> t -> withOption(m, at, new Motion.ToolOffsetPr(ExprText.parseItem("PR", t)));
      case Motion.Acc a -> t -> withOption(m, at, new Motion.Acc(intIn(t, 0, 150, "ACC")));
      case Motion.Skip s -> t -> withOption(m, at, new Motion.Skip(parseLabel(t)));
      case Motion.Offset x -> null;
      case Motion.Wjnt x -> null;
      case Motion.Inc x -> null;
      case Motion.VisionOffset v -> t -> withOption(m, at, new Motion.VisionOffset(ExprText.parseItem("VR", t)));
      case Motion.RawOption x -> null;
      case Motion.TimedAction x -> null;
    };
    String initial = switch (o) {
      case Motion.OffsetPr p -> TpText.index(p.register().index());
      case Motion.ToolOffsetPr p -> TpText.index(p.register().index());
      case Motion.Acc a -> Integer.toString(a.percent());
      case Motion.Skip s -> TpText.index(s.label().index());
      case Motion.Offset x -> "";
      case Motion.Wjnt x -> "";
      case Motion.Inc x -> "";
      case Motion.VisionOffset v -> TpText.index(v.vr().index());
      case Motion.RawOption x -> "";
      case Motion.TimedAction x -> "";
    };
    return new Field(text, Field.Edit.both(List.of("(remove option)"), k -> withoutOption(m, at), initial, entry));
  }

  /** Option text as displayed ({@code Offset,PR[1]}, {@code ACC80}): the printer's ({@link TpText#option}). */
  public static String optionText(Motion.Option o) {
    return TpText.option(o);
  }

  static Instruction.Move withType(Instruction.Move m, Motion.Type type, double maxMmPerSec) {
    Motion.Speed speed = m.speed();
    if (!speed.unit().fits(type)) {
      // J uses % of the joints' top speed, L/C/A a TCP speed: a unit that does not fit becomes the
      // new type's default unit, keeping the number (as the controller does when retyping), within
      // the unit's range (L 2000mm/sec becomes J 100%).
      speed = speedInRange(new Motion.Speed(speed.value(), type == Motion.Type.J ? Motion.SpeedUnit.PERCENT : Motion.SpeedUnit.MM_PER_SEC),
          maxMmPerSec);
    }
    Optional<Motion.Target> end = Optional.empty();
    if (type == Motion.Type.C) {
      end = Optional.of(m.circularEnd().orElse(m.target() instanceof Motion.Local l
          ? new Motion.Local(l.number() + 1, "") : m.target()));
    }
    return new Instruction.Move(type, m.target(), end, speed, m.termination(), m.options());
  }

  /**
   * The range a controller takes for a motion speed in {@code unit} (R-30iB operator's manual,
   * motion speed table, recalled: % 1-100, mm/sec 1 to the robot's maximum Cartesian speed
   * $MRR_GRP.$SPEEDLIM ({@code maxMmPerSec}, 2000 by default), cm/min and inch/min up to the same
   * speed (12000 and 4724.4 for 2000 mm/sec), deg/sec 1-520 (the default $ROTSPEEDLIM), sec
   * 0.1-3200, msec 1-32000): {@code {lo, hi}}.
   */
  static double[] speedRange(Motion.SpeedUnit unit, double maxMmPerSec) {
    return switch (unit) {
      case PERCENT -> new double[] {1, 100};
      case MM_PER_SEC -> new double[] {1, maxMmPerSec};
      case CM_PER_MIN -> new double[] {1, Math.floor(maxMmPerSec * 6)};
      // 0.1 inch/min steps, rounded down so the top never exceeds the mm/sec maximum
      case INCH_PER_MIN -> new double[] {0.1, Math.floor(maxMmPerSec * 60 / 25.4 * 10) / 10};
      case DEG_PER_SEC -> new double[] {1, 520};
      case SEC -> new double[] {0.1, 3200};
      case MSEC -> new double[] {1, 32000};
    };
  }

  /**
   * A typed speed as the controller takes it: within {@link #speedRange} of its unit, else
   * "Value out of range" with the range, and the caller keeps the old speed (a speed register
   * is checked when the line runs).
   */
  static Motion.Speed checkedSpeed(Motion.Speed s) throws BadText {
    return checkedSpeed(s, DEFAULT_MAX_MM_PER_SEC);
  }

  /** As {@link #checkedSpeed(Motion.Speed)} for a robot whose maximum TCP speed is {@code maxMmPerSec}. */
  static Motion.Speed checkedSpeed(Motion.Speed s, double maxMmPerSec) throws BadText {
    if (s.value() instanceof Motion.SpeedConst c) {
      double[] r = speedRange(s.unit(), maxMmPerSec);
      if (!(c.value() >= r[0] && c.value() <= r[1])) {
        throw new BadText("Speed " + ExprText.plain(c.value()) + unit(s.unit()) + ": Value out of range, enter "
            + ExprText.plain(r[0]) + " to " + ExprText.plain(r[1]) + " " + unit(s.unit()), true);
      }
    }
    return s;
  }

  /** {@code s} with its constant moved into its unit's range (a unit chosen from the list). */
  static Motion.Speed speedInRange(Motion.Speed s, double maxMmPerSec) {
    if (s.value() instanceof Motion.SpeedConst c) {
      double[] r = speedRange(s.unit(), maxMmPerSec);
      return new Motion.Speed(new Motion.SpeedConst(Math.max(r[0], Math.min(r[1], c.value()))), s.unit());
    }
    return s;
  }

  static Instruction.Move withSpeed(Instruction.Move m, Motion.Speed s) {
    return new Instruction.Move(m.type(), m.target(), m.circularEnd(), s, m.termination(), m.options());
  }

  static Instruction.Move withTerm(Instruction.Move m, Motion.Termination t) {
    return new Instruction.Move(m.type(), m.target(), m.circularEnd(), m.speed(), t, m.options());
  }

  static Instruction.Move withOption(Instruction.Move m, int at, Motion.Option o) {
    List<Motion.Option> opts = new ArrayList<>(m.options());
    if (at >= opts.size()) {
      opts.add(o);
    } else {
      opts.set(at, o);
    }
    return new Instruction.Move(m.type(), m.target(), m.circularEnd(), m.speed(), m.termination(), opts);
  }

  static Instruction.Move withoutOption(Instruction.Move m, int at) {
    List<Motion.Option> opts = new ArrayList<>(m.options());
    opts.remove(at);
    return new Instruction.Move(m.type(), m.target(), m.circularEnd(), m.speed(), m.termination(), opts);
  }

  /** Speed unit as displayed: {@code %}, {@code mm/sec}, {@code sec} ({@link TpText#unit}). */
  public static String unit(Motion.SpeedUnit u) {
    return TpText.unit(u);
  }

  private static Field targetField(Motion.Target t, Program program, Function<Motion.Target, Instruction> make) {
    String text = targetText(t, program);
    String initial = switch (t) {
      case Motion.Local l -> Integer.toString(l.number());
      case Motion.Register r -> "PR[" + TpText.index(r.register().index()) + "]";
    };
    return new Field(text, Field.Edit.both(List.of("P[...]", "PR[...]"),
        k -> make.apply(k == 0 ? new Motion.Local(number(t), "") : new Motion.Register(Item.of(number(t)))),
        initial, s -> make.apply(parseTarget(s, t))));
  }

  private static int number(Motion.Target t) {
    return switch (t) {
      case Motion.Local l -> l.number();
      case Motion.Register r -> r.register().index() instanceof Index.Direct d ? d.value() : 1;
    };
  }

  /** {@code P[2:PICK]} (comment from the /POS block when the line has none) or {@code PR[R[1]]}. */
  public static String targetText(Motion.Target t, Program program) {
    return switch (t) {
      case Motion.Local l -> {
        String c = !l.comment().isEmpty() ? l.comment()
            : program.position(l.number()).map(p -> p.comment()).orElse("");
        yield TpText.target(new Motion.Local(l.number(), c));
      }
      case Motion.Register r -> TpText.target(r);
    };
  }

  static Motion.Target parseTarget(String text, Motion.Target current) throws BadText {
    String t = text.trim().toUpperCase(Locale.ROOT);
    if (t.startsWith("PR")) {
      return new Motion.Register(ExprText.parseItem("PR", t));
    }
    if (t.startsWith("P[")) {
      t = t.substring(2, t.endsWith("]") ? t.length() - 1 : t.length());
    }
    int n = intIn(t, 1, 9999, "position number");
    return switch (current) {
      case Motion.Local l -> new Motion.Local(n, "");
      case Motion.Register r -> new Motion.Register(Item.of(n));
    };
  }

  static Motion.SpeedValue speedValue(String text) throws BadText {
    String t = text.trim();
    if (t.toUpperCase(Locale.ROOT).startsWith("R")) {
      return new Motion.SpeedRegister(ExprText.parseItem("R", t));
    }
    return new Motion.SpeedConst(NumberEntry.positive("Speed", t));
  }

  static Motion.Termination parseTermination(String text) throws BadText {
    String t = text.trim().toUpperCase(Locale.ROOT);
    if (t.equals("FINE")) {
      return new Motion.Fine();
    }
    if (t.startsWith("CNT")) {
      t = t.substring(3).trim();
    }
    if (t.startsWith("R")) {
      return new Motion.CntRegister(ExprText.parseItem("R", t));
    }
    return new Motion.Cnt(intIn(t, 0, 100, "CNT"));
  }

  // ---- shared field builders -----------------------------------------------------------------

  private static Field itemField(String kind, Item item, Function<Item, Instruction> make) {
    String text = TpText.item(kind, item);
    return new Field(text, Field.Edit.entry(TpText.index(item.index()), t -> make.apply(ExprText.parseItem(kind, t))));
  }

  private static Field ioField(IoKind kind, Item port, BiFunction<IoKind, Item, Instruction> make) {
    String text = TpText.item(kind.name(), port);
    List<IoKind> outs = Arrays.stream(IoKind.values()).filter(IoKind::writable).toList();
    return new Field(text, Field.Edit.both(outs.stream().map(k -> k.name() + "[...]").toList(),
        k -> make.apply(outs.get(k), port), TpText.index(port.index()), t -> {
          String u = t.trim().toUpperCase(Locale.ROOT);
          if (!u.isEmpty() && Character.isDigit(u.charAt(0))) {
            return make.apply(kind, new Item(ExprText.parseIndex(u), ""));
          }
          Expr e = ExprText.parse(u);
          if (!(e instanceof Expr.Io io) || !io.kind().writable()) {
            throw new BadText("expected an output: DO[i], RO[i], GO[i] or F[i]");
          }
          return make.apply(io.kind(), io.port());
        }));
  }

  private static Field exprField(Expr e, Function<Expr, Instruction> make) {
    String text = TpText.expr(e);
    return new Field(text, Field.Edit.entry(text, t -> make.apply(value(t))));
  }

  /** A FOR bound: the .LS reader takes a whole-number constant, R[i] or AR[i], nothing else. */
  private static Field forBoundField(Expr e, Function<Expr, Instruction> make) {
    String text = TpText.expr(e);
    return new Field(text, Field.Edit.entry(text, t -> {
      Expr b = ExprText.parse(t);
      if (!(b instanceof Expr.IntConst || b instanceof Expr.Register || b instanceof Expr.Arg)) {
        throw NumberEntry.refusal("FOR", t, "not allowed", "an integer, R[i] or AR[i]");
      }
      return make.apply(b);
    }));
  }

  /** A typed expression, as the .LS reader takes it inside a statement. */
  static Expr value(String text) throws BadText {
    return ExprText.parse(text);
  }


  /** A WAIT time: 0 or more seconds, or an expression (the reader refuses a negative constant). */
  static Expr waitTime(String text) throws BadText {
    Expr e = value(text);
    boolean negative = switch (e) {
      case Expr.IntConst i -> i.value() < 0;
      case Expr.RealConst r -> r.value() < 0;
      default -> false;
    };
    if (negative) {
      throw NumberEntry.refusal("WAIT", text, "out of range", "0 or more (sec) or R[i]");
    }
    return e;
  }

  /** OVERRIDE=n% (1..100, as the controller accepts it) or OVERRIDE=R[i]. */
  static Expr overridePercent(String text) throws BadText {
    String t = text.trim();
    if (t.endsWith("%")) {
      t = t.substring(0, t.length() - 1).trim();
    }
    if (t.toUpperCase(Locale.ROOT).startsWith("R")) {
      try {
        return new Expr.Register(ExprText.parseItem("R", t));
      } catch (BadText e) {
        throw NumberEntry.refusal("OVERRIDE", t, "not allowed", "1 to 100 (%) or R[i]");
      }
    }
    return new Expr.IntConst(NumberEntry.wholeWithin("OVERRIDE", t, 1, 100));
  }

  /** A vision process: typed {@code 'NAME'} (or a bare name) or {@code SR[i]}. */
  private static Field processField(Instruction.VisionProcess p, Function<Instruction.VisionProcess, Instruction> make) {
    String text = switch (p) {
      case Instruction.VisionProcessName n -> TpText.expr(new Expr.StringConst(n.name()));
      case Instruction.VisionProcessInRegister r -> TpText.item("SR", r.register());
    };
    return new Field(text, Field.Edit.entry(text, t -> {
      String u = t.trim();
      if (u.toUpperCase(Locale.ROOT).startsWith("SR[")) {
        return make.apply(new Instruction.VisionProcessInRegister(ExprText.parseItem("SR", u)));
      }
      if (u.length() >= 2 && (u.charAt(0) == '\'' || u.charAt(0) == '"') && u.charAt(u.length() - 1) == u.charAt(0)) {
        u = u.substring(1, u.length() - 1);
      }
      if (u.isEmpty() || u.indexOf('\'') >= 0 && u.indexOf('"') >= 0) {
        throw new BadText("expected a vision process: 'NAME' or SR[i]");
      }
      return make.apply(new Instruction.VisionProcessName(u.toUpperCase(Locale.ROOT)));
    }));
  }

  private static Field indexField(Index i, Function<Index, Instruction> make) {
    return indexField(i, "", make);
  }

  /** An index with its item comment shown after it ({@code 2:TABLE}); an edit changes the index and keeps the comment. */
  private static Field indexField(Index i, String comment, Function<Index, Instruction> make) {
    String text = TpText.index(i);
    return new Field(text + (comment.isEmpty() ? "" : ":" + comment),
        Field.Edit.entry(text, t -> make.apply(ExprText.parseIndex(t))));
  }

  private static Field labelField(LabelRef l, Function<LabelRef, Instruction> make) {
    String text = TpText.label(l);
    return new Field(text, Field.Edit.entry(TpText.index(l.index()), t -> make.apply(parseLabel(t))));
  }

  private static Field callField(Instruction.Call c, List<String> programs,
      Function<Instruction.Call, Instruction> make) {
    String text = callText(c);
    return new Field(text, Field.Edit.both(programs, k -> make.apply(new Instruction.Call(programs.get(k), c.args())),
        text, t -> make.apply(parseCall(t))));
  }

  private static Field branchField(Instruction.Branch b, List<String> programs,
      Function<Instruction.Branch, Instruction> make) {
    String text = TpText.branch(b);
    return new Field(text, Field.Edit.both(List.of("JMP LBL[...]", "CALL ..."),
        k -> make.apply(k == 0 ? new Instruction.Jump(LabelRef.of(1))
            : new Instruction.Call(programs.isEmpty() ? "MAIN" : programs.get(0), List.of())),
        text, t -> make.apply(parseBranch(t, b instanceof Instruction.Call))));
  }

  private static Field posSourceField(Instruction.AssignPosReg a) {
    String text = posSourceText(a.source());
    List<String> choices = List.of("PR[...]", "P[...]", "LPOS", "JPOS", "UFRAME[...]", "UTOOL[...]", "PR[...]+PR[...]",
        "PR[...]-PR[...]");
    return new Field(text, Field.Edit.both(choices, k -> new Instruction.AssignPosReg(a.register(), switch (k) {
      case 0 -> new Instruction.FromPosReg(Item.of(1));
      case 1 -> new Instruction.FromLocal(1, "");
      case 2 -> new Instruction.CurrentLpos();
      case 3 -> new Instruction.CurrentJpos();
      case 4 -> new Instruction.FromFrame(FrameKind.USER, Index.of(1));
      case 5 -> new Instruction.FromFrame(FrameKind.TOOL, Index.of(1));
      case 6 -> new Instruction.PosArithmetic(Item.of(1), true, Item.of(2));
      default -> new Instruction.PosArithmetic(Item.of(1), false, Item.of(2));
    }), text, t -> new Instruction.AssignPosReg(a.register(), parsePosSource(t))));
  }

  /** The right side of {@code PR[i]=…} as displayed ({@link TpText#posSource}). */
  public static String posSourceText(Instruction.PosSource s) {
    return TpText.posSource(s);
  }

  /** Typed text as the right side of {@code PR[i]=}, read by the one parser. */
  static Instruction.PosSource parsePosSource(String text) throws BadText {
    try {
      return TpStatementParser.posSourceText(text);
    } catch (TpSyntaxError x) {
      throw new BadText("column " + x.column() + ": " + x.getMessage()
          + " (expected PR[j], P[j], LPOS, JPOS, UFRAME[n], UTOOL[n] or a sum such as PR[j]+PR[k])");
    }
  }

  static String frameWord(FrameKind k) {
    return TpText.frameWord(k);
  }

  static String callText(Instruction.Call c) {
    return TpText.call(c.program(), c.args());
  }

  /** {@code NAME} or {@code NAME(arg,...)}. */
  /** A macro's name as typed: a program name (the macro runs the program of that name). */
  static String macroName(String text) throws BadText {
    String name = text.trim().toUpperCase(Locale.ROOT);
    if (!Program.isValidName(name)) {
      throw new BadText("'" + name + "' is not a program name (letters, digits, _; a letter first)");
    }
    return name;
  }

  /**
   * {@code NAME} or {@code NAME(arg,...)}, read by the one parser (so a string argument may hold
   * commas, brackets and either quote: {@code CALL SHOW('A,B]')}, {@code CALL SHOW("it's")}).
   */
  static Instruction.Call parseCall(String text) throws BadText {
    String t = text.trim();
    int open = t.indexOf('(');
    String name = (open < 0 ? t : t.substring(0, open)).trim().toUpperCase(Locale.ROOT);
    if (!Program.isValidName(name)) {
      throw new BadText("'" + name + "' is not a program name (letters, digits, _; a letter first)");
    }
    Instruction.Call call;
    try {
      call = TpStatementParser.callText(t);
    } catch (TpSyntaxError x) {
      throw new BadText("column " + x.column() + ": " + x.getMessage());
    }
    for (Expr a : call.args()) {
      // the pendant's entry checks, as for any typed expression
      ExprText.checked(a);
    }
    return call;
  }

  /**
   * {@code JMP LBL[3]}, {@code CALL NAME(...)}; without the keyword a number is a jump and, when
   * {@code callByDefault}, a name is a call.
   */
  static Instruction.Branch parseBranch(String text, boolean callByDefault) throws BadText {
    String t = text.trim();
    String u = t.toUpperCase(Locale.ROOT);
    if (u.startsWith("CALL")) {
      return parseCall(t.substring(4));
    }
    if (callByDefault && !u.startsWith("JMP")) {
      // the field already holds a CALL: typed text names the program (and its arguments)
      return parseCall(t);
    }
    if (u.startsWith("JMP")) {
      t = t.substring(3);
    }
    return new Instruction.Jump(parseLabel(t));
  }

  /** {@code 3}, {@code 3:LOOP}, {@code LBL[3]}, {@code LBL[R[2]]}. */
  static LabelRef parseLabel(String text) throws BadText {
    String t = text.trim();
    if (t.toUpperCase(Locale.ROOT).startsWith("LBL")) {
      t = t.substring(3).trim();
      if (!t.startsWith("[") || !t.endsWith("]")) {
        throw new BadText("expected LBL[n]");
      }
      t = t.substring(1, t.length() - 1);
    }
    String comment = "";
    int colon = t.lastIndexOf(':');
    if (colon >= 0 && !t.substring(colon).contains("]")) {
      comment = t.substring(colon + 1).trim();
      t = t.substring(0, colon);
    }
    Index i = ExprText.parseIndex(t);
    if (i instanceof Index.Direct d && d.value() < 1) {
      throw new BadText("label numbers start at 1");
    }
    return new LabelRef(i, comment);
  }

  static int intIn(String text, int lo, int hi, String what) throws BadText {
    try {
      int v = Integer.parseInt(text.trim());
      if (v < lo || v > hi) {
        throw new BadText(what + " must be " + lo + ".." + hi + ", got " + v);
      }
      return v;
    } catch (NumberFormatException e) {
      throw new BadText(what + ": '" + text.trim() + "' is not a whole number");
    }
  }

  private static double number(Expr e) {
    return switch (e) {
      case Expr.IntConst i -> i.value();
      case Expr.RealConst r -> r.value();
      default -> Double.NaN;
    };
  }
}
