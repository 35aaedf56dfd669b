package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Optional;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Combinators;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.LsWriter;
import org.robotrun.pendant.ExprText;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.Item;
import org.robotrun.program.Program;

/**
 * Issue 18: whatever the pendant's text entry accepts, {@code check} accepts and the reader
 * reads back as the same program. Generated typed expressions (operators, signs, parentheses,
 * registers, I/O, numbers, and noise), fixed seed, small budget.
 */
class PendantTextEntryPropertyTest {

  @Property(tries = 400, seed = "20261123")
  void whatTheEntryAcceptsReadsBackAsTheSameProgram(@ForAll("typed") String typed) {
    Expr e;
    try {
      e = ExprText.parse(typed);
    } catch (ExprText.BadText refused) {
      return; // refused at entry with a message: nothing is saved
    } catch (RuntimeException other) {
      throw new AssertionError("entry of '" + typed + "' threw " + other, other);
    }
    for (Instruction in : List.of(
        new Instruction.AssignRegister(new Item(new Index.Direct(1), ""), e),
        new Instruction.If(e, new Instruction.Jump(new org.robotrun.program.LabelRef(new Index.Direct(1), ""))),
        new Instruction.WaitCondition(e, Optional.empty()))) {
      Program p = Program.of("T", List.of(in, new Instruction.Label(1, "")));
      Optional<String> refused = new LsLineParser().refusal(Program.of("T", List.of()), p);
      if (refused.isPresent()) {
        continue; // the pendant refuses this edit with the reason: nothing is saved
      }
      String text = LsWriter.write(p);
      LsReadResult r = LsReader.parse("T.LS", text);
      assertThat(r.hasAnyError()).as("%s%n%s", text, r.diagnostics()).isFalse();
      assertThat(r.program().lines()).as(text).isEqualTo(p.lines());
    }
  }

  @Property(tries = 200, seed = "20261124")
  void typedValueExpressionsAreNotRefusedOnSave(@ForAll("expressions") String typed) {
    // A well-formed expression the entry accepts is one a controller file holds: no edit is refused.
    Expr e;
    try {
      e = ExprText.parse(typed);
    } catch (ExprText.BadText refused) {
      // only the controller's entry rules refuse a well-formed expression
      assertThat(refused.getMessage()).as(typed).startsWith("The controller does not mix");
      return;
    }
    Program p = Program.of("T", List.of(new Instruction.AssignRegister(new Item(new Index.Direct(1), ""), e)));
    assertThat(new LsLineParser().refusal(Program.of("T", List.of()), p)).as(typed).isEmpty();
  }

  @Provide
  Arbitrary<String> typed() {
    Arbitrary<String> noise = Arbitraries.strings().withChars("R[]()0123456789.+-*/<>=!ANDORMODIVFTX ,:'\"$").ofMaxLength(30);
    return Arbitraries.oneOf(expressions(), noise, deep());
  }

  @Provide
  Arbitrary<String> expressions() {
    return Arbitraries.recursive(this::atom, this::combine, 0, 4);
  }

  private Arbitrary<String> atom() {
    return Arbitraries.oneOf(
        Arbitraries.integers().between(0, 999).map(String::valueOf),
        Arbitraries.integers().between(0, 9999).map(n -> n / 100.0).map(d -> Double.toString(d)),
        Arbitraries.integers().between(1, 200).map(n -> "R[" + n + "]"),
        Arbitraries.integers().between(1, 64).map(n -> "DI[" + n + "]"),
        Arbitraries.integers().between(1, 200).map(n -> "F[" + n + "]"),
        Arbitraries.integers().between(1, 100).map(n -> "PR[" + n + ",3]"),
        Arbitraries.of("ON", "OFF"));
  }

  private Arbitrary<String> combine(Arbitrary<String> inner) {
    Arbitrary<String> op = Arbitraries.of("+", "-", "*", "/", " DIV ", " MOD ", "=", "<>", "<", "<=", ">", ">=", " AND ",
        " OR ");
    return Arbitraries.oneOf(
        Combinators.combine(inner, op, inner).as((a, o, b) -> a + o + b),
        inner.map(a -> "(" + a + ")"),
        inner.map(a -> "-" + a),
        inner.map(a -> "!" + a));
  }

  /** Issue 18's reproducers and their neighbours: 3000 parentheses, 3000 minus signs, 300-deep. */
  private Arbitrary<String> deep() {
    return Arbitraries.of(63, 64, 65, 300, 3000).flatMap(n -> Arbitraries.of(
        "(".repeat(n) + "1" + ")".repeat(n),
        "-".repeat(n) + "1",
        "!".repeat(n) + "ON",
        "-(".repeat(n) + "R[1]" + ")".repeat(n)));
  }
}
