package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.Set;
import java.util.stream.Collectors;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.lifecycle.AddLifecycleHook;
import org.junit.jupiter.api.Test;

/**
 * The one printer and the one parser agree: every instruction model the program package can
 * hold, printed by {@link TpText} and read back by the parser's fragment entry points
 * ({@link TpStatementParser#statementText}, {@link TpStatementParser#expressionText}), is the
 * same model. Every kind of instruction, motion option and expression has a generator
 * ({@link TpModels}); the first tests fail when a kind is added without one. jqwik, fixed seeds;
 * fewer tries inside the mutation profile ({@link PitTries}).
 */
@AddLifecycleHook(PitTries.class)
class TpTextRoundTripPropertyTest {

  @Test
  void everyInstructionKindHasAGenerator() {
    assertThat(Set.<Class<?>>copyOf(TpModels.instructionKinds().keySet())).isEqualTo(records(Instruction.class));
  }

  @Test
  void everyMotionOptionKindHasAGenerator() {
    assertThat(Set.<Class<?>>copyOf(TpModels.optionKinds().keySet())).isEqualTo(records(Motion.Option.class));
  }

  @Test
  void everyExpressionKindHasAGenerator() {
    assertThat(Set.<Class<?>>copyOf(TpModels.expressionKinds().keySet())).isEqualTo(records(Expr.class));
  }

  /** The record types of a sealed interface (its nested sealed interfaces are not instructions themselves). */
  private static Set<Class<?>> records(Class<?> sealed) {
    return Arrays.stream(sealed.getPermittedSubclasses()).filter(Class::isRecord).collect(Collectors.toSet());
  }

  @Property(tries = 2500, seed = "2311202601")
  void everyInstructionIsPrintedAndParsedBackTheSame(@ForAll("instructions") Instruction in) {
    String text = TpText.statement(in);
    TpStatementParser.Parsed back = TpStatementParser.statementText(text);
    assertThat(back.instruction()).as(text).isEqualTo(in);
    assertThat(TpText.statement(back.instruction())).isEqualTo(text);
  }

  @Property(tries = 1000, seed = "2311202602")
  void everyExpressionIsPrintedAndParsedBackTheSame(@ForAll("expressions") Expr e) {
    String text = TpText.expr(e);
    assertThat(TpStatementParser.expressionText(text)).as(text).isEqualTo(e);
  }

  @Property(tries = 400, seed = "2311202603")
  void everyMotionOptionIsPrintedAndParsedBackTheSame(@ForAll("options") Motion.Option o) {
    Instruction.Move m = Instruction.Move.of(Motion.Type.L, new Motion.Local(1, ""),
        new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.MM_PER_SEC), new Motion.Fine(), java.util.List.of(o));
    String text = TpText.statement(m);
    assertThat(TpStatementParser.statementText(text).instruction()).as(text).isEqualTo(m);
  }

  @Provide
  Arbitrary<Instruction> instructions() {
    return TpModels.instruction();
  }

  @Provide
  Arbitrary<Expr> expressions() {
    return Arbitraries.oneOf(TpModels.expressionKinds().values().stream().map(a -> a.map(e -> (Expr) e)).toList());
  }

  @Provide
  Arbitrary<Motion.Option> options() {
    return Arbitraries.oneOf(TpModels.optionKinds().values().stream().map(a -> a.map(o -> (Motion.Option) o)).toList());
  }
}
