package org.robotrun.program;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import org.robotrun.program.Instruction.FrameKind;

/**
 * jqwik generators of every instruction, motion option and expression model the program package
 * holds, in the form the parser gives back (so print → parse is the identity on them): an
 * operand the printer would have to parenthesise is generated as an {@link Expr.Group}, a
 * negative constant as a constant (the parser folds the sign in), a whole WAIT time as a real.
 * One generator per kind, keyed by the model's class, so a test can check every kind is covered.
 */
public final class TpModels {
  private TpModels() {}

  // ---- names, numbers, comments ---------------------------------------------------------------

  static Arbitrary<String> programName() {
    return Arbitraries.strings().withCharRange('A', 'Z').withCharRange('0', '9').withChars('_').ofMinLength(1)
        .ofMaxLength(12).filter(s -> Character.isLetter(s.charAt(0)));
  }

  /** An item comment as a controller keeps it: letters, digits, blanks and punctuation (no brackets). */
  static Arbitrary<String> comment() {
    return Arbitraries.oneOf(Arbitraries.just(""), Arbitraries.strings().withCharRange('A', 'Z')
        .withCharRange('a', 'z').withCharRange('0', '9').withChars(' ', '_', '-', '.', '#', '/', '(', ')', ',', '\'', '"')
        .ofMinLength(1).ofMaxLength(16));
  }

  /** Free text of a remark or message: anything on one line but a closing bracket for MESSAGE. */
  static Arbitrary<String> text() {
    return Arbitraries.strings().withCharRange(' ', '~').excludeChars(']').ofMaxLength(30)
        .map(String::stripTrailing);
  }

  /** A string constant: either quote, not both, and commas, brackets and parentheses. */
  static Arbitrary<String> stringValue() {
    Arbitrary<String> chars = Arbitraries.strings().withCharRange('A', 'Z').withCharRange('0', '9')
        .withChars(' ', ',', '[', ']', '(', ')', '_', ';', ':').ofMaxLength(12);
    return Arbitraries.oneOf(chars, Combinators.combine(chars, chars, Arbitraries.of('\'', '"'))
        .as((a, b, q) -> a + q + b));
  }

  static Arbitrary<Integer> small() {
    return Arbitraries.integers().between(1, 999);
  }

  static Arbitrary<Index> index() {
    return Arbitraries.oneOf(Arbitraries.integers().between(0, 99999).map(Index::of),
        Combinators.combine(small(), comment()).as(Index.Indirect::new),
        Arbitraries.integers().between(1, 99).map(Index.ViaArg::new));
  }

  static Arbitrary<Item> item() {
    return Combinators.combine(index(), comment()).as(Item::new);
  }

  static Arbitrary<LabelRef> label() {
    return Combinators.combine(index(), comment()).as(LabelRef::new);
  }

  /** j of PR[i,j]: 1..6, R[k] or AR[k]. */
  static Arbitrary<Index> element() {
    return Arbitraries.oneOf(Arbitraries.integers().between(1, 6).map(Index::of),
        Combinators.combine(small(), comment()).as(Index.Indirect::new),
        Arbitraries.integers().between(1, 9).map(Index.ViaArg::new));
  }

  static Arbitrary<Double> real() {
    return Arbitraries.oneOf(
        Arbitraries.doubles().between(-1e6, 1e6).ofScale(6),
        Arbitraries.integers().between(-100000, 100000).map(v -> v / 100.0),
        Arbitraries.of(0.0, 1.0, 0.5, 1e-7, 123456789.125, -2.0));
  }

  // ---- expressions -----------------------------------------------------------------------------

  /** Every kind of expression, one generator each. */
  public static Map<Class<? extends Expr>, Arbitrary<? extends Expr>> expressionKinds() {
    Map<Class<? extends Expr>, Arbitrary<? extends Expr>> m = new LinkedHashMap<>();
    m.put(Expr.IntConst.class, Arbitraries.integers().between(Integer.MIN_VALUE + 1, Integer.MAX_VALUE).map(Expr.IntConst::new));
    m.put(Expr.RealConst.class, real().map(Expr.RealConst::new));
    m.put(Expr.OnOff.class, Arbitraries.of(true, false).map(Expr.OnOff::new));
    m.put(Expr.StringConst.class, stringValue().map(Expr.StringConst::new));
    m.put(Expr.Register.class, item().map(Expr.Register::new));
    m.put(Expr.PosElement.class, Combinators.combine(item(), element()).as(Expr.PosElement::new));
    m.put(Expr.Io.class, Combinators.combine(Arbitraries.of(IoKind.values()), item()).as(Expr.Io::new));
    m.put(Expr.Timer.class, item().map(Expr.Timer::new));
    m.put(Expr.SysVar.class, Arbitraries.oneOf(Arbitraries.of(SystemVariables.SUPPORTED),
        Arbitraries.integers().between(1, 8).map(n -> "$MIX_BG[" + n + "].$STATUS")).map(Expr.SysVar::new));
    m.put(Expr.Arg.class, index().map(Expr.Arg::new));
    m.put(Expr.StringReg.class, item().map(Expr.StringReg::new));
    m.put(Expr.StringFunc.class, Arbitraries.of(Expr.StringFn.values()).flatMap(fn ->
        tight(1).list().ofSize(fn.arity()).map(args -> new Expr.StringFunc(fn, args))));
    m.put(Expr.Unary.class, unary(2));
    m.put(Expr.Binary.class, binary(2));
    m.put(Expr.Group.class, expr(1).map(Expr.Group::new));
    return m;
  }

  /** A value that needs no parentheses anywhere: constants, items, functions. */
  static Arbitrary<Expr> atom() {
    Map<Class<? extends Expr>, Arbitrary<? extends Expr>> m = new LinkedHashMap<>();
    m.put(Expr.IntConst.class, Arbitraries.integers().between(0, 99999).map(Expr.IntConst::new));
    m.put(Expr.RealConst.class, real().map(Math::abs).map(Expr.RealConst::new));
    m.put(Expr.OnOff.class, Arbitraries.of(true, false).map(Expr.OnOff::new));
    m.put(Expr.StringConst.class, stringValue().map(Expr.StringConst::new));
    m.put(Expr.Register.class, item().map(Expr.Register::new));
    m.put(Expr.PosElement.class, Combinators.combine(item(), element()).as(Expr.PosElement::new));
    m.put(Expr.Io.class, Combinators.combine(Arbitraries.of(IoKind.values()), item()).as(Expr.Io::new));
    m.put(Expr.Timer.class, item().map(Expr.Timer::new));
    m.put(Expr.SysVar.class, Arbitraries.of(SystemVariables.SUPPORTED).map(Expr.SysVar::new));
    m.put(Expr.Arg.class, index().map(Expr.Arg::new));
    m.put(Expr.StringReg.class, item().map(Expr.StringReg::new));
    List<Arbitrary<Expr>> all = new ArrayList<>();
    m.values().forEach(a -> all.add(a.map(e -> (Expr) e)));
    return Arbitraries.oneOf(all);
  }

  /** An operand that binds as tightly as a unary operator: an atom, a unary operation or a group. */
  static Arbitrary<Expr> tight(int depth) {
    if (depth <= 0) {
      return atom();
    }
    return Arbitraries.frequencyOf(
        net.jqwik.api.Tuple.of(4, atom()),
        net.jqwik.api.Tuple.of(1, unary(depth - 1)),
        net.jqwik.api.Tuple.of(1, expr(depth - 1).map(e -> (Expr) new Expr.Group(e))));
  }

  /** {@code -x} (x not a constant: the parser folds a sign into a constant) or {@code !x}. */
  static Arbitrary<Expr> unary(int depth) {
    return Combinators.combine(Arbitraries.of(Expr.UnaryOp.values()), tight(depth))
        .as((op, e) -> op == Expr.UnaryOp.MINUS && (e instanceof Expr.IntConst || e instanceof Expr.RealConst)
            ? new Expr.Unary(op, new Expr.Group(e)) : new Expr.Unary(op, e));
  }

  /** {@code left op right} as the parser builds it: left-associative, tighter operands unparenthesised. */
  static Arbitrary<Expr> binary(int depth) {
    return binary(depth, 1);
  }

  /** A binary operation whose operator binds at least as tightly as {@code minPrecedence}. */
  private static Arbitrary<Expr> binary(int depth, int minPrecedence) {
    List<Expr.BinaryOp> ops = java.util.Arrays.stream(Expr.BinaryOp.values())
        .filter(o -> o.precedence() >= minPrecedence).toList();
    return Arbitraries.of(ops).flatMap(op -> {
      Arbitrary<Expr> left = side(depth, op.precedence());
      Arbitrary<Expr> right = side(depth, op.precedence() + 1);
      return Combinators.combine(left, right).as((l, r) -> (Expr) new Expr.Binary(op, l, r));
    });
  }

  private static Arbitrary<Expr> side(int depth, int minPrecedence) {
    if (depth <= 0 || minPrecedence > 5) {
      return tight(Math.max(0, depth - 1));
    }
    return Arbitraries.oneOf(tight(depth - 1), binary(depth - 1, minPrecedence));
  }

  /** Any expression the parser gives back. */
  public static Arbitrary<Expr> expr(int depth) {
    return Arbitraries.frequencyOf(
        net.jqwik.api.Tuple.of(3, tight(depth)),
        net.jqwik.api.Tuple.of(2, binary(depth)),
        net.jqwik.api.Tuple.of(1, Arbitraries.integers().between(Integer.MIN_VALUE + 1, -1).map(v -> (Expr) new Expr.IntConst(v))));
  }

  static Arbitrary<Expr> expr() {
    return expr(2);
  }

  /** Any expression but a bare string constant (R[i]='A' is refused). */
  static Arbitrary<Expr> number() {
    return expr().filter(e -> !(e instanceof Expr.StringConst));
  }

  // ---- motion -------------------------------------------------------------------------------

  static Arbitrary<Motion.Target> target() {
    return Arbitraries.oneOf(Combinators.combine(small(), comment()).as(Motion.Local::new),
        item().map(Motion.Register::new));
  }

  static Arbitrary<Motion.Speed> speed(Motion.Type type) {
    List<Motion.SpeedUnit> units = java.util.Arrays.stream(Motion.SpeedUnit.values()).filter(u -> u.fits(type)).toList();
    return Arbitraries.of(units).flatMap(u -> {
      Arbitrary<Double> v = u == Motion.SpeedUnit.PERCENT
          ? Arbitraries.oneOf(Arbitraries.integers().between(1, 100).map(i -> (double) i), Arbitraries.doubles().between(0.5, 100))
          : Arbitraries.oneOf(Arbitraries.integers().between(1, 5000).map(i -> (double) i), Arbitraries.doubles().between(0.001, 5000).ofScale(4));
      Arbitrary<Motion.SpeedValue> value = Arbitraries.oneOf(v.map(Motion.SpeedConst::new), item().map(Motion.SpeedRegister::new));
      return value.map(x -> new Motion.Speed(x, u));
    });
  }

  static Arbitrary<Motion.Termination> termination() {
    return Arbitraries.oneOf(Arbitraries.just(new Motion.Fine()),
        Arbitraries.integers().between(0, 100).map(Motion.Cnt::new), item().map(Motion.CntRegister::new));
  }

  /** An output or an argument-less CALL, as a TB/TA/DB action runs them. */
  static Arbitrary<Instruction> timedActionBody() {
    return Arbitraries.oneOf(
        Combinators.combine(Arbitraries.of(IoKind.DO, IoKind.RO, IoKind.F), item(), Arbitraries.of(true, false))
            .as((k, i, on) -> new Instruction.SetIo(k, i, new Expr.OnOff(on))),
        Combinators.combine(Arbitraries.of(IoKind.DO, IoKind.RO), item()).as((k, i) ->
            new Instruction.Pulse(k, i, OptionalDouble.of(0.5))),
        programName().map(n -> new Instruction.Call(n, List.of())));
  }

  /** Every kind of motion option, one generator each. */
  public static Map<Class<? extends Motion.Option>, Arbitrary<? extends Motion.Option>> optionKinds() {
    Map<Class<? extends Motion.Option>, Arbitrary<? extends Motion.Option>> m = new LinkedHashMap<>();
    m.put(Motion.Offset.class, Arbitraries.just(new Motion.Offset()));
    m.put(Motion.OffsetPr.class, item().map(Motion.OffsetPr::new));
    m.put(Motion.ToolOffsetPr.class, item().map(Motion.ToolOffsetPr::new));
    m.put(Motion.Acc.class, Arbitraries.integers().between(0, 150).map(Motion.Acc::new));
    m.put(Motion.Skip.class, label().map(Motion.Skip::new));
    m.put(Motion.Wjnt.class, Arbitraries.just(new Motion.Wjnt()));
    m.put(Motion.Inc.class, Arbitraries.just(new Motion.Inc()));
    m.put(Motion.VisionOffset.class, item().map(Motion.VisionOffset::new));
    m.put(Motion.TimedAction.class, Combinators.combine(Arbitraries.of(Motion.When.values()),
        Arbitraries.integers().between(0, 2000).map(v -> v / 100.0), timedActionBody(), Arbitraries.of(true, false))
        .as((when, amount, action, longForm) -> {
          String word = switch (when) {
            case TIME_BEFORE -> longForm ? "TIME BEFORE" : "TB";
            case TIME_AFTER -> longForm ? "TIME AFTER" : "TA";
            case DISTANCE_BEFORE -> longForm ? "DISTANCE BEFORE" : "DB";
          };
          String unit = when == Motion.When.DISTANCE_BEFORE ? "mm" : "sec";
          return new Motion.TimedAction(when, amount, action,
              word + " " + FanucFormat.plain(amount) + unit + "," + TpText.statement(action));
        }));
    m.put(Motion.RawOption.class, Arbitraries.of(
        new Motion.RawOption("PTH", "PTH"),
        new Motion.RawOption("VOFFSET", "vision offset VOFFSET"),
        new Motion.RawOption("RTCP", "remote TCP (RTCP)"),
        new Motion.RawOption("COORD[1]", "coordinated motion COORD"),
        new Motion.RawOption("CR50", "motion option CR50"),
        new Motion.RawOption("TB .50sec,CALL OPEN(1)", "TIME BEFORE/AFTER (TB/TA)")));
    return m;
  }

  static Arbitrary<List<Motion.Option>> options() {
    List<Arbitrary<Motion.Option>> plain = new ArrayList<>();
    List<Arbitrary<Motion.Option>> last = new ArrayList<>();
    optionKinds().forEach((k, a) -> {
      boolean restOfLine = k == Motion.RawOption.class || k == Motion.TimedAction.class;
      (restOfLine ? last : plain).add(a.map(o -> (Motion.Option) o));
    });
    Arbitrary<Motion.Option> raw = Arbitraries.oneOf(last);
    // an option kept as written (and a TB/TA/DB, whose text is kept) takes the rest of the line: it is the last one
    return Combinators.combine(Arbitraries.oneOf(plain).list().ofMaxSize(3), raw.optional())
        .as((os, r) -> {
          List<Motion.Option> all = new ArrayList<>(os);
          r.ifPresent(all::add);
          return all;
        });
  }

  static Arbitrary<Instruction> move() {
    return Arbitraries.of(Motion.Type.values()).flatMap(type -> Combinators.combine(target(), target(), speed(type),
        termination(), options()).as((t, end, s, term, os) -> (Instruction) new Instruction.Move(type, t,
            type == Motion.Type.C ? Optional.of(end) : Optional.empty(), s, term, os)));
  }

  // ---- statements ---------------------------------------------------------------------------

  static Arbitrary<Instruction.Branch> branch() {
    return Arbitraries.oneOf(label().map(Instruction.Jump::new), call().map(c -> c));
  }

  static Arbitrary<Instruction.Call> call() {
    return Combinators.combine(programName(), expr(1).list().ofMaxSize(3)).as(Instruction.Call::new);
  }

  static Arbitrary<Instruction.PosSource> posTerm() {
    return Arbitraries.oneOf(item().map(Instruction.FromPosReg::new),
        Combinators.combine(small(), comment()).as(Instruction.FromLocal::new),
        Arbitraries.just(new Instruction.CurrentLpos()), Arbitraries.just(new Instruction.CurrentJpos()));
  }

  static Arbitrary<Instruction.PosSource> posSource() {
    Arbitrary<Instruction.PosSource> sum = Combinators.combine(posTerm(),
        Combinators.combine(Arbitraries.of(true, false), posTerm()).as(Instruction.PosTerm::new).list().ofMinSize(1).ofMaxSize(3))
        .as(Instruction.PosSum::new)
        // PR[j]±PR[k] alone is the two-register form, PosArithmetic
        .filter(s -> !(s.first() instanceof Instruction.FromPosReg && s.rest().size() == 1
            && s.rest().get(0).term() instanceof Instruction.FromPosReg))
        .map(s -> (Instruction.PosSource) s);
    return Arbitraries.oneOf(posTerm(),
        Combinators.combine(Arbitraries.of(FrameKind.values()), index(), comment()).as(Instruction.FromFrame::new),
        Combinators.combine(item(), Arbitraries.of(true, false)).as(Instruction.FromVisionRegister::new),
        sum,
        Combinators.combine(item(), Arbitraries.of(true, false), item()).as(Instruction.PosArithmetic::new));
  }

  static Arbitrary<Instruction> ifAction() {
    return Arbitraries.oneOf(
        Combinators.combine(item(), number()).as(Instruction.AssignRegister::new),
        Combinators.combine(Arbitraries.of(IoKind.DO, IoKind.RO, IoKind.GO, IoKind.AO, IoKind.F), item(), expr())
            .as(Instruction.SetIo::new),
        Combinators.combine(Arbitraries.of(IoKind.DO, IoKind.RO), item(), width()).as(Instruction.Pulse::new),
        Combinators.combine(item(), element(), expr()).as(Instruction.AssignPosElement::new));
  }

  static Arbitrary<OptionalDouble> width() {
    return Arbitraries.oneOf(Arbitraries.just(OptionalDouble.empty()),
        Arbitraries.integers().between(0, 10000).map(v -> OptionalDouble.of(v / 100.0)));
  }

  /** A macro's name: one word, or several words and numbers ({@code MACOPEN hand 1}). */
  static Arbitrary<String> macroName() {
    Arbitrary<String> word = Arbitraries.strings().withCharRange('a', 'z').ofMinLength(1).ofMaxLength(6);
    Arbitrary<String> part = Arbitraries.oneOf(word, Arbitraries.integers().between(1, 99).map(String::valueOf));
    return Combinators.combine(programName(), part.list().ofMaxSize(2))
        .as((first, more) -> {
          List<String> words = new ArrayList<>(List.of("MAC" + first + "_"));
          words.addAll(more);
          return String.join(" ", words);
        });
  }

  /** Every kind of instruction, one generator each. */
  public static Map<Class<? extends Instruction>, Arbitrary<? extends Instruction>> instructionKinds() {
    Map<Class<? extends Instruction>, Arbitrary<? extends Instruction>> m = new LinkedHashMap<>();
    m.put(Instruction.Move.class, move());
    m.put(Instruction.AssignRegister.class, Combinators.combine(item(), number()).as(Instruction.AssignRegister::new));
    m.put(Instruction.AssignString.class, Combinators.combine(item(), expr()).as(Instruction.AssignString::new));
    m.put(Instruction.AssignPosReg.class, Combinators.combine(item(), posSource()).as(Instruction.AssignPosReg::new));
    m.put(Instruction.AssignPosElement.class, Combinators.combine(item(), element(), expr())
        .as(Instruction.AssignPosElement::new));
    m.put(Instruction.SelectFrame.class, Combinators.combine(Arbitraries.of(FrameKind.values()),
        Arbitraries.oneOf(Arbitraries.integers().between(0, 10).map(Index::of),
            Combinators.combine(small(), comment()).as(Index.Indirect::new)),
        Arbitraries.of(true, false)).as(Instruction.SelectFrame::new));
    m.put(Instruction.SetFrame.class, Combinators.combine(Arbitraries.of(FrameKind.values()), index(), comment(), item())
        .as(Instruction.SetFrame::new));
    m.put(Instruction.Payload.class, Combinators.combine(index(), comment()).as(Instruction.Payload::new));
    m.put(Instruction.Label.class, Combinators.combine(small(), comment()).as(Instruction.Label::new));
    m.put(Instruction.Jump.class, label().map(Instruction.Jump::new));
    m.put(Instruction.Call.class, call());
    m.put(Instruction.Run.class, call().map(c -> new Instruction.Run(c.program(), c.args())));
    m.put(Instruction.End.class, Arbitraries.just(new Instruction.End()));
    m.put(Instruction.Pause.class, Arbitraries.just(new Instruction.Pause()));
    m.put(Instruction.Abort.class, Arbitraries.just(new Instruction.Abort()));
    m.put(Instruction.If.class, Combinators.combine(expr(), branch()).as(Instruction.If::new));
    m.put(Instruction.IfAction.class, Combinators.combine(expr(), ifAction()).as(Instruction.IfAction::new));
    m.put(Instruction.IfThen.class, expr().map(Instruction.IfThen::new));
    m.put(Instruction.Else.class, Arbitraries.just(new Instruction.Else()));
    m.put(Instruction.EndIf.class, Arbitraries.just(new Instruction.EndIf()));
    m.put(Instruction.Select.class, Combinators.combine(item(), expr(), branch()).as(Instruction.Select::new));
    m.put(Instruction.SelectCase.class, Combinators.combine(expr(), branch()).as(Instruction.SelectCase::new));
    m.put(Instruction.SelectElse.class, branch().map(Instruction.SelectElse::new));
    Arbitrary<Expr> bound = Arbitraries.oneOf(Arbitraries.integers().between(-9999, 9999).map(Expr.IntConst::new),
        item().map(Expr.Register::new), index().map(Expr.Arg::new));
    m.put(Instruction.For.class, Combinators.combine(item(), bound, Arbitraries.of(true, false), bound)
        .as(Instruction.For::new));
    m.put(Instruction.EndFor.class, Arbitraries.just(new Instruction.EndFor()));
    m.put(Instruction.WaitTime.class, Arbitraries.oneOf(
        Arbitraries.integers().between(0, 100000).map(v -> (Expr) new Expr.RealConst(v / 100.0)),
        Arbitraries.doubles().between(0, 1000).ofScale(5).map(v -> (Expr) new Expr.RealConst(v)),
        item().map(Expr.Register::new),
        index().map(Expr.Arg::new),
        expr(1).map(Expr.Group::new)).map(Instruction.WaitTime::new));
    m.put(Instruction.WaitCondition.class, Combinators.combine(
        expr().filter(c -> !(c instanceof Expr.IntConst || c instanceof Expr.RealConst || c instanceof Expr.Register
            || c instanceof Expr.Unary)),
        label().optional()).as(Instruction.WaitCondition::new));
    m.put(Instruction.TimerSet.class, Combinators.combine(item(), Arbitraries.of(Instruction.TimerAction.values()))
        .as(Instruction.TimerSet::new));
    m.put(Instruction.SetIo.class, Combinators.combine(
        Arbitraries.of(java.util.Arrays.stream(IoKind.values()).filter(IoKind::writable).toList()), item(), expr())
        .as(Instruction.SetIo::new));
    m.put(Instruction.Pulse.class, Combinators.combine(Arbitraries.of(IoKind.DO, IoKind.RO), item(), width())
        .as(Instruction.Pulse::new));
    m.put(Instruction.Comment.class, text().map(Instruction.Comment::new));
    m.put(Instruction.CommentedOut.class, text().map(Instruction.CommentedOut::new));
    m.put(Instruction.SetSysVar.class, Combinators.combine(Arbitraries.of(SystemVariables.WRITABLE), expr())
        .as(Instruction.SetSysVar::new));
    m.put(Instruction.SkipCondition.class, expr().map(Instruction.SkipCondition::new));
    m.put(Instruction.OffsetCondition.class, Combinators.combine(item(),
        Arbitraries.oneOf(Arbitraries.integers().between(0, 9).map(Index::of),
            Combinators.combine(small(), comment()).as(Index.Indirect::new)).optional())
        .as(Instruction.OffsetCondition::new));
    m.put(Instruction.MacroCall.class, Combinators.combine(macroName(), expr(1).list().ofMaxSize(3))
        .as(Instruction.MacroCall::new));
    m.put(Instruction.Monitor.class, Combinators.combine(programName(), Arbitraries.of(true, false))
        .as(Instruction.Monitor::new));
    m.put(Instruction.When.class, Combinators.combine(expr(), call()).as(Instruction.When::new));
    m.put(Instruction.Message.class, text().map(Instruction.Message::new));
    m.put(Instruction.UserAlarm.class, Combinators.combine(index(), comment()).as(Instruction.UserAlarm::new));
    m.put(Instruction.SetOverride.class, Arbitraries.oneOf(
        Arbitraries.integers().between(0, 100).map(v -> (Expr) new Expr.IntConst(v)),
        Arbitraries.integers().between(1, 1000).map(v -> (Expr) new Expr.RealConst(v / 10.0)),
        item().map(Expr.Register::new)).map(Instruction.SetOverride::new));
    m.put(Instruction.Blank.class, Arbitraries.just(new Instruction.Blank()));
    Arbitrary<Instruction.VisionProcess> process = Arbitraries.oneOf(
        stringValue().filter(v -> !v.isEmpty()).map(Instruction.VisionProcessName::new),
        item().map(Instruction.VisionProcessInRegister::new));
    m.put(Instruction.VisionRunFind.class, process.map(Instruction.VisionRunFind::new));
    m.put(Instruction.VisionGetOffset.class, Combinators.combine(process, item(), label())
        .as(Instruction.VisionGetOffset::new));
    m.put(Instruction.VisionGetNFound.class, Combinators.combine(process, item()).as(Instruction.VisionGetNFound::new));
    m.put(Instruction.AssignFromVr.class, Combinators.combine(item(), item(), Arbitraries.of(Instruction.VisionField.values()),
        Arbitraries.integers().between(1, 10)).as((r, vr, f, k) ->
            new Instruction.AssignFromVr(r, vr, f, f == Instruction.VisionField.MES ? k : 0)));
    m.put(Instruction.Unsupported.class, Arbitraries.of(
        new Instruction.Unsupported("COL DETECT ON", "COL DETECT", true),
        new Instruction.Unsupported("LOCK PREG", "LOCK PREG", true),
        new Instruction.Unsupported("VISION SET_REFERENCE 'FIND1'", "iRVision", false),
        new Instruction.Unsupported("VISION GET_OFFSET 'A' VR[1]", "iRVision", false),
        new Instruction.Unsupported("R[1]=VR[1].MES[11]", "vision registers VR[] in an expression", false),
        new Instruction.Unsupported("PR[1]=VR[1].FOUND_POS[2]", "PR[i]=vision registers VR[]", false),
        new Instruction.Unsupported("PALLETIZING-B_1", "palletizing", false),
        new Instruction.Unsupported("Arc Start[1]", "arc welding", false),
        new Instruction.Unsupported("CALL SR[3]", "CALL through a string register SR[]", false)));
    return m;
  }

  /** One arbitrary over every instruction kind. */
  public static Arbitrary<Instruction> instruction() {
    List<Arbitrary<Instruction>> all = new ArrayList<>();
    instructionKinds().values().forEach(a -> all.add(a.map(i -> (Instruction) i)));
    return Arbitraries.oneOf(all);
  }
}
