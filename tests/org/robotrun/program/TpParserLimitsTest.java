package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The reader's limits at, below and above each bound (issue 31), from docs/tp-language.md: 64
 * levels of parentheses and signs together and 1000 operators per statement; the controller's
 * tables R[1..200], PR[1..100], F[1..200], TIMER[1..10], DO[1..512] (an index outside loads with
 * a warning, the line alarms when it runs); PR[i,j] with j = 1..6 (7..9, the extended axes, are
 * kept but not run); AR[i] from 1.
 */
class TpParserLimitsTest {

  private static String nested(String open, String inner, String close, int depth) {
    return open.repeat(depth) + inner + close.repeat(depth);
  }

  @Test
  void parenthesesAndSignsNestSixtyFourDeepTogetherAndNoDeeper() {
    assertThat(TpStatementParser.expressionText(nested("(", "1", ")", 64))).isNotNull();
    assertThatThrownBy(() -> TpStatementParser.expressionText(nested("(", "1", ")", 65)))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("nested too deeply: at most 64 levels");
    assertThat(TpStatementParser.expressionText("!".repeat(64) + "ON")).isNotNull();
    assertThatThrownBy(() -> TpStatementParser.expressionText("!".repeat(65) + "ON"))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("nested too deeply");
    // signs and parentheses count together: 32 + 32 is the limit, 33 + 32 is over
    assertThat(TpStatementParser.expressionText(nested("(", "!".repeat(32) + "ON", ")", 32))).isNotNull();
    assertThatThrownBy(() -> TpStatementParser.expressionText(nested("(", "!".repeat(32) + "ON", ")", 33)))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("nested too deeply");
    // a level ends with its parenthesis or its operand: groups and signs 40 deep side by side are fine
    // (a sign is an operator too: 20 × 40 signs and 19 ANDs stay under the 1000)
    String side = String.join("+", java.util.Collections.nCopies(40, nested("(", "1", ")", 40)));
    assertThat(TpStatementParser.expressionText(side)).isNotNull();
    String signs = String.join(" AND ", java.util.Collections.nCopies(20, "!".repeat(40) + "ON"));
    assertThat(TpStatementParser.expressionText(signs)).isNotNull();
  }

  @Test
  void oneStatementHoldsAThousandOperatorsAndNoMore() {
    assertThat(TpStatementParser.expressionText("1" + "+1".repeat(1000))).isNotNull();
    assertThatThrownBy(() -> TpStatementParser.expressionText("1" + "+1".repeat(1001)))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("more than 1000 operators");
    assertThat(TpStatementParser.statementText("R[1]=1" + "+1".repeat(1000)).instruction()).isNotInstanceOf(Instruction.Unsupported.class);
    assertThatThrownBy(() -> TpStatementParser.statementText("R[1]=1" + "+1".repeat(1001)))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("more than 1000 operators");
  }

  record Table(String name, int size, String statement) {}

  @Test
  void anIndexOutsideTheControllersTableIsAWarningNamingTheTable() {
    List<Table> tables = List.of(
        new Table("R", 200, "R[%d]=1"),
        new Table("PR", 100, "R[1]=PR[%d,1]"),
        new Table("F", 200, "F[%d]=(ON)"),
        new Table("TIMER", 10, "TIMER[%d]=START"),
        new Table("DO", 512, "DO[%d]=ON"));
    for (Table t : tables) {
      for (int n : new int[] {0, 1, 2, t.size() - 1, t.size(), t.size() + 1}) {
        List<String> warnings = TpStatementParser.statementText(String.format(t.statement(), n)).warnings();
        if (n >= 1 && n <= t.size()) {
          assertThat(warnings).as("%s[%d]", t.name(), n).isEmpty();
        } else {
          assertThat(warnings).as("%s[%d]", t.name(), n)
              .containsExactly(t.name() + "[" + n + "]: index out of range (expected 1.." + t.size() + "); running this line raises an alarm");
        }
      }
    }
    // the register of an indirect index is checked the same way
    assertThat(TpStatementParser.statementText("R[R[200]]=1").warnings()).isEmpty();
    assertThat(TpStatementParser.statementText("R[R[201]]=1").warnings())
        .containsExactly("R[201]: index out of range (expected 1..200); running this line raises an alarm");
    assertThat(TpStatementParser.statementText("JMP LBL[R[201]]").warnings())
        .containsExactly("R[201]: index out of range (expected 1..200); running this line raises an alarm");
  }

  @Test
  void aPositionElementIsOneToSixOrAnExtendedAxisKeptButNotRun() {
    for (int j = 1; j <= 6; j++) {
      Expr e = TpStatementParser.expressionText("PR[1," + j + "]");
      assertThat(TpText.expr(e)).isEqualTo("PR[1," + j + "]");
    }
    for (int j : new int[] {0, 10, 11}) {
      assertThatThrownBy(() -> TpStatementParser.expressionText("PR[1," + j + "]")).as("j=%d", j)
          .isInstanceOf(TpSyntaxError.class).hasMessageContaining("j must be 1..6").satisfies(
              x -> assertThat(((TpSyntaxError) x).unsupported()).isEmpty());
    }
    for (int j = 7; j <= 9; j++) {
      Instruction in = TpStatementParser.statementText("R[1]=PR[1," + j + "]").instruction();
      assertThat(in).as("j=%d", j).isInstanceOf(Instruction.Unsupported.class);
    }
  }

  @Test
  void argumentsAreNumberedFromOne() {
    assertThat(TpText.expr(TpStatementParser.expressionText("AR[1]"))).isEqualTo("AR[1]");
    assertThat(TpText.statement(TpStatementParser.statementText("R[1]=R[AR[1]]").instruction())).isEqualTo("R[1]=R[AR[1]]");
    assertThatThrownBy(() -> TpStatementParser.statementText("R[1]=R[AR[0]]"))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("AR[0]: argument numbers start at 1");
  }

  @Test
  void anIndexIsAnInteger() {
    assertThatThrownBy(() -> TpStatementParser.statementText("R[1.5]=1"))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("expected an integer");
    assertThatThrownBy(() -> TpStatementParser.statementText("R[R[2.0]]=1"))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("expected an integer");
  }

  @Test
  void functionBracketsNestAsParenthesesDo() {
    assertThat(TpStatementParser.expressionText(nested("ABS[", "1", "]", 64))).isNotNull();
    assertThatThrownBy(() -> TpStatementParser.expressionText(nested("ABS[", "1", "]", 65)))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("nested too deeply: at most 64 levels");
    // a level ends with its bracket: forty 40-deep functions side by side are fine
    String side = String.join("+", java.util.Collections.nCopies(40, nested("ABS[", "1", "]", 40)));
    assertThat(TpStatementParser.expressionText(side)).isNotNull();
  }

  @Test
  void signsAndPositionArithmeticCountAsOperators() {
    // 20 operands with 50 signs each and 19 ANDs: 1019 operators
    String nots = String.join(" AND ", java.util.Collections.nCopies(20, "!".repeat(50) + "ON"));
    assertThatThrownBy(() -> TpStatementParser.expressionText(nots)).isInstanceOf(TpSyntaxError.class)
        .hasMessageContaining("more than 1000 operators");
    String minus = String.join("+", java.util.Collections.nCopies(20, "-".repeat(50) + "R[1]"));
    assertThatThrownBy(() -> TpStatementParser.expressionText(minus)).isInstanceOf(TpSyntaxError.class)
        .hasMessageContaining("more than 1000 operators");
    assertThat(TpStatementParser.statementText("PR[1]=LPOS" + "+PR[2]".repeat(1000)).instruction())
        .isInstanceOf(Instruction.AssignPosReg.class);
    assertThatThrownBy(() -> TpStatementParser.statementText("PR[1]=LPOS" + "+PR[2]".repeat(1001)))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("more than 1000 operators");
  }

  @Test
  void theEntryRulesWalkAModelOfAnyDepthWithoutOverflowingTheStack() {
    // TpLimits: no walk of an expression may overflow the stack, whoever built the model
    Expr and = new Expr.OnOff(true);
    Expr group = new Expr.OnOff(true);
    Expr mul = new Expr.IntConst(1);
    for (int i = 0; i < 300_000; i++) {
      and = new Expr.Binary(Expr.BinaryOp.AND, and, new Expr.OnOff(false));
      group = new Expr.Unary(Expr.UnaryOp.NOT, new Expr.Group(new Expr.Binary(Expr.BinaryOp.OR, group, new Expr.OnOff(false))));
      mul = new Expr.Binary(Expr.BinaryOp.MUL, mul, new Expr.IntConst(2));
    }
    assertThat(EntryRules.refusal(and)).get().asString().contains("at most 5 conditions");
    assertThat(EntryRules.refusal(group)).get().asString().contains("at most 20 conditions");
    assertThat(EntryRules.refusal(new Expr.Binary(Expr.BinaryOp.ADD, new Expr.IntConst(1), mul))).get().asString()
        .contains("does not mix + or -");
  }
}
