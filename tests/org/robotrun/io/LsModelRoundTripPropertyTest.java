package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalDouble;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.robotrun.program.Config;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Motion;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.SystemVariables;

/**
 * Any model RobotRun can hold is written as an .LS file and read back as the same model (issue
 * 25): the forms real controller files use (item comments on PAYLOAD/UFRAME/UALM, UTOOL_NUM[GP1],
 * PR[i,R[j]], AR[] as an index, IF with an action, position sums, system variables, macros with
 * arguments) among the older ones. jqwik with a fixed seed.
 */
class LsModelRoundTripPropertyTest {

  @Property(tries = 400, seed = "2025022501")
  void everyModelIsWrittenAndReadBackTheSame(@ForAll("programs") Program p) {
    String text = LsWriter.write(p);
    LsReadResult r = LsReader.parse("prop.ls", text);
    assertThat(r.hasErrors()).as(text).isFalse();
    assertThat(r.program().lines()).as(text).isEqualTo(p.lines());
    assertThat(r.program().positions()).as(text).isEqualTo(p.positions());
    assertThat(r.program().name()).isEqualTo(p.name());
    assertThat(r.program().comment()).isEqualTo(p.comment());
    // and written again, the same bytes
    assertThat(LsWriter.write(r.program().withoutSource())).isEqualTo(text);
  }

  @Provide
  Arbitrary<Program> programs() {
    Arbitrary<List<Instruction>> lines = instruction().list().ofMinSize(1).ofMaxSize(25);
    Arbitrary<List<LocalPosition>> points = position().list().ofMaxSize(4);
    Arbitrary<String> names = Arbitraries.of("MAIN", "PICK_1", "-KEPT", "CELL2");
    return Combinators.combine(names, word(), lines, points).as((name, comment, ls, ps) -> {
      Map<Integer, LocalPosition> byNumber = new LinkedHashMap<>();
      for (LocalPosition lp : ps) {
        byNumber.putIfAbsent(lp.number(), lp);
      }
      return new Program(name, Map.of(), comment, ls, byNumber);
    });
  }

  private static Arbitrary<String> word() {
    return Arbitraries.strings().withCharRange('A', 'Z').withChars('_').ofMinLength(1).ofMaxLength(8)
        .filter(s -> Character.isLetter(s.charAt(0)));
  }

  private static Arbitrary<String> comment() {
    return Arbitraries.oneOf(Arbitraries.just(""), word());
  }

  private static Arbitrary<Integer> small() {
    return Arbitraries.integers().between(1, 99);
  }

  private static Arbitrary<Index> index() {
    return Arbitraries.oneOf(small().map(Index::of), Combinators.combine(small(), comment()).as(Index.Indirect::new),
        Arbitraries.integers().between(1, 9).map(Index.ViaArg::new));
  }

  /** j of PR[i,j]: 1..6, R[k] or AR[k]. */
  private static Arbitrary<Index> element() {
    return Arbitraries.oneOf(Arbitraries.integers().between(1, 6).map(Index::of),
        Combinators.combine(small(), comment()).as(Index.Indirect::new), Arbitraries.integers().between(1, 9).map(Index.ViaArg::new));
  }

  private static Arbitrary<Item> item() {
    return Combinators.combine(index(), comment()).as(Item::new);
  }

  private static Arbitrary<Expr> operand() {
    return Arbitraries.oneOf(
        Arbitraries.integers().between(0, 9999).map(Expr.IntConst::new),
        item().map(Expr.Register::new),
        Arbitraries.integers().between(1, 9).map(i -> new Expr.Arg(Index.of(i))),
        Arbitraries.of(SystemVariables.SUPPORTED).map(Expr.SysVar::new),
        Arbitraries.integers().between(1, 8).map(n -> new Expr.SysVar("$MIX_BG[" + n + "].$STATUS")),
        Combinators.combine(item(), element()).as(Expr.PosElement::new),
        Combinators.combine(small(), comment()).as((n, c) -> new Expr.Io(IoKind.DI, new Item(Index.of(n), c))));
  }

  private static Arbitrary<Expr> expr() {
    return Arbitraries.oneOf(operand(),
        Combinators.combine(operand(), operand()).as((a, b) -> new Expr.Binary(Expr.BinaryOp.ADD, a, b)),
        operand().map(Expr.Group::new));
  }

  private static Arbitrary<Expr> condition() {
    return Combinators.combine(operand(), operand()).as((a, b) -> new Expr.Binary(Expr.BinaryOp.EQ, a, b));
  }

  private static Arbitrary<Instruction> action() {
    return Arbitraries.oneOf(
        Combinators.combine(item(), expr()).as((i, e) -> new Instruction.AssignRegister(i, new Expr.Group(e))),
        Combinators.combine(item(), Arbitraries.of(true, false))
            .as((i, on) -> new Instruction.SetIo(IoKind.DO, i, new Expr.Group(new Expr.OnOff(on)))),
        item().map(i -> new Instruction.Pulse(IoKind.DO, i, OptionalDouble.of(0.5))),
        Combinators.combine(item(), Arbitraries.integers().between(1, 6), expr())
            .as((i, j, e) -> new Instruction.AssignPosElement(i, Index.of(j), new Expr.Group(e))));
  }

  private static Arbitrary<Instruction.PosSource> term() {
    return Arbitraries.oneOf(item().map(Instruction.FromPosReg::new),
        Combinators.combine(small(), comment()).as(Instruction.FromLocal::new),
        Arbitraries.just(new Instruction.CurrentLpos()), Arbitraries.just(new Instruction.CurrentJpos()));
  }

  private static Arbitrary<Instruction> instruction() {
    Arbitrary<Instruction> sum = Combinators.combine(item(), term(),
        Combinators.combine(Arbitraries.of(true, false), term()).as(Instruction.PosTerm::new).list().ofMinSize(1).ofMaxSize(3))
        .as((target, first, rest) -> {
          // PR[j]±PR[k] alone is the two-register form the reader gives back as PosArithmetic
          boolean pair = first instanceof Instruction.FromPosReg a && rest.size() == 1
              && rest.get(0).term() instanceof Instruction.FromPosReg b;
          Instruction.PosSource src = pair
              ? new Instruction.PosArithmetic(((Instruction.FromPosReg) first).register(), rest.get(0).add(),
                  ((Instruction.FromPosReg) rest.get(0).term()).register())
              : new Instruction.PosSum(first, rest);
          return new Instruction.AssignPosReg(target, src);
        });
    Arbitrary<Instruction> macro = Combinators.combine(word(), word().list().ofMaxSize(2), expr().list().ofMaxSize(3))
        .as((first, more, args) -> {
          List<String> words = new ArrayList<>(List.of("MAC" + first));
          more.forEach(w -> words.add(w.toLowerCase(java.util.Locale.ROOT)));
          return new Instruction.MacroCall(String.join(" ", words), args);
        });
    return Arbitraries.oneOf(
        Combinators.combine(item(), expr()).as(Instruction.AssignRegister::new),
        Combinators.combine(item(), element(), expr()).as(Instruction.AssignPosElement::new),
        Combinators.combine(condition(), action()).as(Instruction.IfAction::new),
        sum,
        Combinators.combine(Arbitraries.of(FrameKind.values()), Arbitraries.integers().between(0, 9),
            Arbitraries.of(true, false)).as((k, n, g) -> new Instruction.SelectFrame(k, Index.of(n), g)),
        Combinators.combine(Arbitraries.of(FrameKind.values()), small(), comment(), item())
            .as((k, n, c, pr) -> new Instruction.SetFrame(k, Index.of(n), c, pr)),
        Combinators.combine(Arbitraries.of(FrameKind.values()), small(), comment())
            .as((k, n, c) -> new Instruction.AssignPosReg(new Item(Index.of(1), ""), new Instruction.FromFrame(k, Index.of(n), c))),
        Combinators.combine(small(), comment()).as((n, c) -> new Instruction.Payload(Index.of(n), c)),
        Combinators.combine(small(), comment()).as((n, c) -> new Instruction.UserAlarm(Index.of(n), c)),
        Combinators.combine(Arbitraries.of(SystemVariables.WRITABLE), expr()).as(Instruction.SetSysVar::new),
        macro,
        word().map(Instruction.Comment::new),
        Combinators.combine(small(), small()).as((p, s) -> new Instruction.Move(Motion.Type.J, new Motion.Local(p, ""),
            java.util.Optional.empty(), new Motion.Speed(new Motion.SpeedConst(s), Motion.SpeedUnit.PERCENT),
            new Motion.Fine(), List.of())));
  }

  private static Arbitrary<LocalPosition> position() {
    Arbitrary<Double> mm = Arbitraries.integers().between(-200000, 200000).map(v -> v / 100.0);
    return Combinators.combine(small(), comment(), mm, mm, mm).as((n, c, x, y, z) ->
        new LocalPosition(n, c, 1, 1, new Position.Cartesian(x, y, z, 180, 0, 0, Config.DEFAULT)));
  }
}
