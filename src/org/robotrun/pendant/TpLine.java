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
 * ({@code L P[2] 200mm/sec CNT50}); it is a display, not the .LS writer (that lives in
 * {@code io}, which the pendant may not import, and has no notion of fields).
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
        String text = ExprText.format(a.value());
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
        f.add(Field.fixed("SKIP CONDITION"));
        f.add(exprField(s.condition(), Instruction.SkipCondition::new));
      }
      case Instruction.OffsetCondition o -> {
        f.add(Field.fixed("OFFSET CONDITION"));
        f.add(itemField("PR", o.register(), i -> new Instruction.OffsetCondition(i, o.userFrame())));
        o.userFrame().ifPresent(j -> f.add(Field.fixed(",UFRAME[" + ExprText.index(j) + "]")));
      }
      case Instruction.MacroCall c -> {
        f.add(new Field(c.name(), Field.Edit.both(programs,
            k -> new Instruction.MacroCall(programs.get(k), c.args()), c.name(),
            t -> new Instruction.MacroCall(macroName(t), c.args()))));
        if (!c.args().isEmpty()) {
          f.add(Field.fixed("(" + String.join(",", c.args().stream().map(ExprText::format).toList()) + ")"));
        }
      }
      case Instruction.Monitor mo -> {
        f.add(Field.fixed(mo.end() ? "MONITOR END" : "MONITOR"));
        f.add(new Field(mo.program(), Field.Edit.both(programs, k -> new Instruction.Monitor(programs.get(k), mo.end()),
            mo.program(), t -> new Instruction.Monitor(macroName(t), mo.end()))));
      }
      case Instruction.When w -> {
        f.add(Field.fixed("WHEN"));
        f.add(exprField(w.condition(), e -> new Instruction.When(e, w.action())));
        f.add(Field.fixed(",CALL"));
        f.add(new Field(w.action().program(), Field.Edit.both(programs,
            k -> new Instruction.When(w.condition(), new Instruction.Call(programs.get(k), List.of())),
            w.action().program(), t -> new Instruction.When(w.condition(), new Instruction.Call(macroName(t), List.of())))));
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
        String target = ExprText.format(new Expr.PosElement(a.register(), a.element()));
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
        f.add(new Field(frameWord(s.kind()) + "_NUM", Field.Edit.choice(List.of("UFRAME_NUM", "UTOOL_NUM"),
            k -> new Instruction.SelectFrame(k == 0 ? FrameKind.USER : FrameKind.TOOL, s.number()))));
        f.add(Field.fixed("="));
        f.add(indexField(s.number(), i -> new Instruction.SelectFrame(s.kind(), i)));
      }
      case Instruction.SetFrame s -> {
        f.add(Field.fixed(frameWord(s.kind()) + "["));
        f.add(indexField(s.frame(), i -> new Instruction.SetFrame(s.kind(), i, s.register())));
        f.add(Field.fixed("]="));
        f.add(itemField("PR", s.register(), i -> new Instruction.SetFrame(s.kind(), s.frame(), i)));
      }
      case Instruction.Payload p -> {
        f.add(Field.fixed("PAYLOAD["));
        f.add(indexField(p.schedule(), Instruction.Payload::new));
        f.add(Field.fixed("]"));
      }
      case Instruction.Label l -> {
        f.add(Field.fixed("LBL["));
        f.add(new Field(l.number() + (l.comment().isEmpty() ? "" : ":" + l.comment()),
            Field.Edit.entry(l.number() + (l.comment().isEmpty() ? "" : ":" + l.comment()), t -> {
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
        f.add(Field.fixed("       ="));
        f.add(exprField(s.value(), v -> new Instruction.SelectCase(v, s.branch())));
        f.add(Field.fixed(","));
        f.add(branchField(s.branch(), programs, b -> new Instruction.SelectCase(s.value(), b)));
      }
      case Instruction.SelectElse s -> {
        f.add(Field.fixed("       ELSE,"));
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
        String shown = constant ? String.format(Locale.ROOT, "%.2f", number(w.seconds())).replaceFirst("^(-?)0\\.", "$1.")
            : ExprText.format(w.seconds());
        f.add(new Field(shown, Field.Edit.entry(shown, t -> new Instruction.WaitTime(waitTime(t)))));
        if (constant) {
          f.add(Field.fixed("(sec)"));
        }
      }
      case Instruction.WaitCondition w -> {
        f.add(Field.fixed("WAIT "));
        f.add(exprField(w.condition(), e -> new Instruction.WaitCondition(e, w.timeoutLabel())));
        // no timeout: an empty field the cursor can still reach to add one
        String shown = w.timeoutLabel().map(l -> " TIMEOUT," + ExprText.label(l)).orElse("");
        f.add(new Field(shown, Field.Edit.both(List.of("no timeout", "TIMEOUT,LBL[...]"),
            k -> new Instruction.WaitCondition(w.condition(),
                k == 0 ? Optional.empty() : Optional.of(w.timeoutLabel().orElse(LabelRef.of(1)))),
            w.timeoutLabel().map(ExprText::label).orElse(""),
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
        f.add(new Field(ExprText.format(s.value()), Field.Edit.both(
            s.kind().group() ? List.of() : List.of("ON", "OFF", "PULSE", "R[...]"),
            k -> switch (k) {
              case 0, 1 -> new Instruction.SetIo(s.kind(), s.port(), new Expr.OnOff(k == 0));
              case 2 -> new Instruction.Pulse(s.kind(), s.port(), OptionalDouble.empty());
              default -> new Instruction.SetIo(s.kind(), s.port(), new Expr.Register(Item.of(1)));
            },
            ExprText.format(s.value()), t -> new Instruction.SetIo(s.kind(), s.port(), value(t)))));
      }
      case Instruction.Pulse p -> {
        f.add(ioField(p.kind(), p.port(), (k, port) -> new Instruction.Pulse(k, port, p.widthSec())));
        f.add(Field.fixed("="));
        f.add(new Field("PULSE", Field.Edit.choice(List.of("ON", "OFF", "PULSE"), k -> k == 2 ? p
            : new Instruction.SetIo(p.kind(), p.port(), new Expr.OnOff(k == 0)))));
        // no width ($DEFPULSE applies): an empty field the cursor can still reach to add one
        String width = p.widthSec().isPresent() ? "," + ExprText.plain(p.widthSec().getAsDouble()) + "sec" : "";
        f.add(new Field(width, Field.Edit.entry(p.widthSec().isPresent() ? ExprText.plain(p.widthSec().getAsDouble()) : "",
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
        f.add(indexField(u.number(), Instruction.UserAlarm::new));
        f.add(Field.fixed("]"));
      }
      case Instruction.SetOverride o -> {
        f.add(Field.fixed("OVERRIDE="));
        String pct = ExprText.format(o.percent());
        f.add(new Field(pct, Field.Edit.entry(pct, t -> new Instruction.SetOverride(overridePercent(t)))));
        if (o.percent() instanceof Expr.IntConst) {
          f.add(Field.fixed("%"));
        }
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
    String speed = switch (m.speed().value()) {
      case Motion.SpeedConst c -> ExprText.plain(c.value());
      case Motion.SpeedRegister r -> ExprText.item("R", r.register());
    };
    f.add(new Field(speed, Field.Edit.entry(speed,
        t -> withSpeed(m, checkedSpeed(new Motion.Speed(speedValue(t), m.speed().unit()), maxMmPerSec)))));
    List<Motion.SpeedUnit> units = Arrays.stream(Motion.SpeedUnit.values()).filter(u -> u.fits(m.type())).toList();
    f.add(new Field(unit(m.speed().unit()), Field.Edit.choice(units.stream().map(TpLine::unit).toList(),
        k -> withSpeed(m, speedInRange(new Motion.Speed(m.speed().value(), units.get(k)), maxMmPerSec)))));
    f.add(Field.fixed(" "));
    String term = switch (m.termination()) {
      case Motion.Fine x -> "FINE";
      case Motion.Cnt c -> "CNT" + c.value();
      case Motion.CntRegister r -> "CNT " + ExprText.item("R", r.register());
    };
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
      case Motion.RawOption x -> null;
      case Motion.TimedAction x -> null;
    };
    String initial = switch (o) {
      case Motion.OffsetPr p -> ExprText.index(p.register().index());
      case Motion.ToolOffsetPr p -> ExprText.index(p.register().index());
      case Motion.Acc a -> Integer.toString(a.percent());
      case Motion.Skip s -> ExprText.index(s.label().index());
      case Motion.Offset x -> "";
      case Motion.Wjnt x -> "";
      case Motion.Inc x -> "";
      case Motion.RawOption x -> "";
      case Motion.TimedAction x -> "";
    };
    return new Field(text, Field.Edit.both(List.of("(remove option)"), k -> withoutOption(m, at), initial, entry));
  }

  /** Option text as displayed ({@code Offset,PR[1]}, {@code ACC80}). */
  public static String optionText(Motion.Option o) {
    return switch (o) {
      case Motion.Offset x -> "Offset";
      case Motion.OffsetPr p -> "Offset," + ExprText.item("PR", p.register());
      case Motion.ToolOffsetPr p -> "Tool_Offset," + ExprText.item("PR", p.register());
      case Motion.Acc a -> "ACC" + a.percent();
      case Motion.Skip s -> "Skip," + ExprText.label(s.label());
      case Motion.Wjnt x -> "Wjnt";
      case Motion.Inc x -> "INC";
      case Motion.TimedAction x -> x.text();
      // A point-logic block's sub-lines are not shown on the motion's line.
      case Motion.RawOption x -> x.text().lines().findFirst().orElse("");
    };
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

  /** Speed unit as displayed: {@code %}, {@code mm/sec}, {@code sec}. */
  public static String unit(Motion.SpeedUnit u) {
    return switch (u) {
      case PERCENT -> "%";
      case SEC -> "sec";
      case MSEC -> "msec";
      case MM_PER_SEC -> "mm/sec";
      case CM_PER_MIN -> "cm/min";
      case INCH_PER_MIN -> "inch/min";
      case DEG_PER_SEC -> "deg/sec";
    };
  }

  private static Field targetField(Motion.Target t, Program program, Function<Motion.Target, Instruction> make) {
    String text = targetText(t, program);
    String initial = switch (t) {
      case Motion.Local l -> Integer.toString(l.number());
      case Motion.Register r -> "PR[" + ExprText.index(r.register().index()) + "]";
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
        yield "P[" + l.number() + (c.isEmpty() ? "" : ":" + c) + "]";
      }
      case Motion.Register r -> ExprText.item("PR", r.register());
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
    String text = ExprText.item(kind, item);
    return new Field(text, Field.Edit.entry(ExprText.index(item.index()), t -> make.apply(ExprText.parseItem(kind, t))));
  }

  private static Field ioField(IoKind kind, Item port, BiFunction<IoKind, Item, Instruction> make) {
    String text = ExprText.item(kind.name(), port);
    List<IoKind> outs = Arrays.stream(IoKind.values()).filter(IoKind::writable).toList();
    return new Field(text, Field.Edit.both(outs.stream().map(k -> k.name() + "[...]").toList(),
        k -> make.apply(outs.get(k), port), ExprText.index(port.index()), t -> {
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
    String text = ExprText.format(e);
    return new Field(text, Field.Edit.entry(text, t -> make.apply(value(t))));
  }

  /** A FOR bound: the .LS reader takes a whole-number constant, R[i] or AR[i], nothing else. */
  private static Field forBoundField(Expr e, Function<Expr, Instruction> make) {
    String text = ExprText.format(e);
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

  private static Field indexField(Index i, Function<Index, Instruction> make) {
    String text = ExprText.index(i);
    return new Field(text, Field.Edit.entry(text, t -> make.apply(ExprText.parseIndex(t))));
  }

  private static Field labelField(LabelRef l, Function<LabelRef, Instruction> make) {
    String text = ExprText.label(l);
    return new Field(text, Field.Edit.entry(ExprText.index(l.index()), t -> make.apply(parseLabel(t))));
  }

  private static Field callField(Instruction.Call c, List<String> programs,
      Function<Instruction.Call, Instruction> make) {
    String text = callText(c);
    return new Field(text, Field.Edit.both(programs, k -> make.apply(new Instruction.Call(programs.get(k), c.args())),
        text, t -> make.apply(parseCall(t))));
  }

  private static Field branchField(Instruction.Branch b, List<String> programs,
      Function<Instruction.Branch, Instruction> make) {
    String text = switch (b) {
      case Instruction.Jump j -> "JMP " + ExprText.label(j.label());
      case Instruction.Call c -> "CALL " + callText(c);
    };
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

  /** The right side of {@code PR[i]=…} as displayed. */
  public static String posSourceText(Instruction.PosSource s) {
    return switch (s) {
      case Instruction.FromPosReg r -> ExprText.item("PR", r.register());
      case Instruction.FromLocal l -> "P[" + l.number() + (l.comment().isEmpty() ? "" : ":" + l.comment()) + "]";
      case Instruction.CurrentLpos x -> "LPOS";
      case Instruction.CurrentJpos x -> "JPOS";
      case Instruction.FromFrame fr -> frameWord(fr.kind()) + "[" + ExprText.index(fr.frame())
          + (fr.comment().isEmpty() ? "" : ":" + fr.comment()) + "]";
      case Instruction.PosArithmetic p -> ExprText.item("PR", p.left()) + (p.add() ? "+" : "-") + ExprText.item("PR", p.right());
      case Instruction.PosSum p -> {
        StringBuilder sb = new StringBuilder(posSourceText(p.first()));
        for (Instruction.PosTerm t : p.rest()) {
          sb.append(t.add() ? '+' : '-').append(posSourceText(t.term()));
        }
        yield sb.toString();
      }
    };
  }

  static Instruction.PosSource parsePosSource(String text) throws BadText {
    String t = text.trim().toUpperCase(Locale.ROOT).replace(" ", "");
    switch (t) {
      case "LPOS" -> {
        return new Instruction.CurrentLpos();
      }
      case "JPOS" -> {
        return new Instruction.CurrentJpos();
      }
      default -> { }
    }
    for (FrameKind k : FrameKind.values()) {
      String w = frameWord(k) + "[";
      if (t.startsWith(w) && t.endsWith("]")) {
        return new Instruction.FromFrame(k, ExprText.parseIndex(t.substring(w.length(), t.length() - 1)));
      }
    }
    if (t.startsWith("P[") && t.endsWith("]")) {
      return new Instruction.FromLocal(intIn(t.substring(2, t.length() - 1), 1, 9999, "position number"), "");
    }
    int op = Math.max(t.indexOf("]+PR"), t.indexOf("]-PR"));
    if (op > 0) {
      return new Instruction.PosArithmetic(ExprText.parseItem("PR", t.substring(0, op + 1)), t.charAt(op + 1) == '+',
          ExprText.parseItem("PR", t.substring(op + 2)));
    }
    if (t.startsWith("PR")) {
      return new Instruction.FromPosReg(ExprText.parseItem("PR", t));
    }
    throw new BadText("expected PR[j], P[j], LPOS, JPOS, UFRAME[n], UTOOL[n] or PR[j]+PR[k]");
  }

  static String frameWord(FrameKind k) {
    return switch (k) {
      case USER -> "UFRAME";
      case TOOL -> "UTOOL";
    };
  }

  static String callText(Instruction.Call c) {
    if (c.args().isEmpty()) {
      return c.program();
    }
    StringBuilder sb = new StringBuilder(c.program()).append('(');
    for (int i = 0; i < c.args().size(); i++) {
      sb.append(i == 0 ? "" : ",").append(ExprText.format(c.args().get(i)));
    }
    return sb.append(')').toString();
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

  static Instruction.Call parseCall(String text) throws BadText {
    String t = text.trim();
    int open = t.indexOf('(');
    String name = (open < 0 ? t : t.substring(0, open)).trim().toUpperCase(Locale.ROOT);
    if (!Program.isValidName(name)) {
      throw new BadText("'" + name + "' is not a program name (letters, digits, _; a letter first)");
    }
    List<Expr> args = new ArrayList<>();
    if (open >= 0) {
      if (!t.endsWith(")")) {
        throw new BadText("expected ')' at the end of the arguments");
      }
      String inner = t.substring(open + 1, t.length() - 1).trim();
      if (!inner.isEmpty()) {
        for (String a : splitTopLevel(inner)) {
          args.add(ExprText.parse(a));
        }
      }
    }
    return new Instruction.Call(name, args);
  }

  private static List<String> splitTopLevel(String s) {
    List<String> parts = new ArrayList<>();
    int depth = 0;
    int start = 0;
    boolean quoted = false;
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      if (c == '\'') {
        quoted = !quoted;
      } else if (!quoted && (c == '(' || c == '[')) {
        depth++;
      } else if (!quoted && (c == ')' || c == ']')) {
        depth--;
      } else if (!quoted && c == ',' && depth == 0) {
        parts.add(s.substring(start, i));
        start = i + 1;
      }
    }
    parts.add(s.substring(start));
    return parts;
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
