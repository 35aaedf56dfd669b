package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.program.TpText;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;

class ExprTextTest {

  @ParameterizedTest
  @ValueSource(strings = {"R[2]+1", "(R[1]>2 AND DI[1]=ON)", "R[R[2:PTR]]*2.5", "(PR[10,3:STACK]-R[1] DIV 3)",
      "!F[3] OR (TIMER[1]>=1.5)", "-R[4] MOD 7", "AR[1]<>'PART_A'", "(GI[2]<=RO[1])", "-3", "R[1:COUNT]"})
  void formatOfParseGivesTheTextBack(String text) throws Exception {
    assertThat(TpText.expr(ExprText.parse(text))).isEqualTo(text);
  }

  @Test
  void precedenceInsideAnExpression() throws Exception {
    // Mixed logic: in parentheses + and * mix with the usual precedence (issue 13's entry rule).
    Expr e = ((Expr.Group) ExprText.parse("(R[1]+R[2]*3>4 AND DO[1]=ON)")).inner();
    Expr.Binary and = (Expr.Binary) e;
    assertThat(and.op()).isEqualTo(Expr.BinaryOp.AND);
    Expr.Binary gt = (Expr.Binary) and.left();
    assertThat(gt.op()).isEqualTo(Expr.BinaryOp.GT);
    Expr.Binary plus = (Expr.Binary) gt.left();
    assertThat(plus.op()).isEqualTo(Expr.BinaryOp.ADD);
    assertThat(plus.right()).isEqualTo(new Expr.Binary(Expr.BinaryOp.MUL, new Expr.Register(Item.of(2)),
        new Expr.IntConst(3)));
    assertThat(((Expr.Binary) and.right()).left()).isEqualTo(new Expr.Io(IoKind.DO, Item.of(1)));
  }

  @Test
  void theControllersEntryRulesAreEnforcedOutsideParentheses() throws Exception {
    assertThatThrownBy(() -> ExprText.parse("R[1]+R[2]*3")).hasMessageStartingWith(
        "The controller does not mix + or - with *, /, DIV or MOD on a line without parentheses");
    assertThatThrownBy(() -> ExprText.parse("DI[1]=ON AND DI[2]=ON OR DI[3]=ON")).hasMessageStartingWith(
        "The controller does not mix AND with OR");
    assertThat(ExprText.parse("R[1]+R[2]-3")).isInstanceOf(Expr.Binary.class);
    assertThat(ExprText.parse("R[1]*R[2] DIV 3 MOD 2")).isInstanceOf(Expr.Binary.class);
    assertThat(ExprText.parse("(R[1]+R[2]*3)")).isInstanceOf(Expr.Group.class);
    assertThatThrownBy(() -> ExprText.parse("(".repeat(3000) + "1" + ")".repeat(3000)))
        .hasMessageContaining("nested too deeply: at most 64");
    assertThatThrownBy(() -> ExprText.parse("-".repeat(3000) + "1")).hasMessageContaining("nested too deeply");
  }

  @Test
  void theControllersConditionCountsAreEnforced() throws Exception {
    // five conditions in a standard instruction, twenty in a mixed-logic one
    String five = String.join(" AND ", java.util.Collections.nCopies(5, "DI[1]=ON"));
    assertThat(ExprText.parse(five)).isInstanceOf(Expr.Binary.class);
    assertThatThrownBy(() -> ExprText.parse(five + " AND DI[2]=ON"))
        .hasMessageStartingWith("The controller takes at most 5 conditions joined by AND/OR");
    String twenty = "(" + String.join(" OR ", java.util.Collections.nCopies(20, "!DI[1]")) + ")";
    assertThat(ExprText.parse(twenty)).isInstanceOf(Expr.Group.class);
    assertThatThrownBy(() -> ExprText.parse("(" + twenty.substring(1, twenty.length() - 1) + " AND R[1]>2)"))
        .hasMessageContaining("at most 20 conditions in one mixed-logic instruction, this one has 21");
    // a file holding such a line reads, with check's warning (the pendant's refusal, kind style)
    var r = org.robotrun.io.LsReader.parse("W.LS", "/PROG  W\n/MN\n   1:  WAIT " + five + " AND DI[2]=ON    ;\n/POS\n/END\n");
    assertThat(r.hasAnyError()).isFalse();
    assertThat(r.diagnostics()).anyMatch(d -> d.message().contains("at most 5 conditions") && d.message().endsWith("(a pendant refuses this entry)"));
  }

  @Test
  void badTextSaysWhereAndWhat() {
    assertThatThrownBy(() -> ExprText.parse("R[1]+")).hasMessageStartingWith("column 6: expected a value (").hasMessageEndingWith("found end of line");
    assertThatThrownBy(() -> ExprText.parse("R[1] R[2]")).hasMessageStartingWith("column 6: expected the end of the expression");
    assertThatThrownBy(() -> ExprText.parse("X[1]")).hasMessageStartingWith("column 1: expected a value (number, R[i]");
    assertThatThrownBy(() -> ExprText.parse("(R[1]>2")).hasMessageStartingWith("column 8: expected ')'");
  }

  @Test
  void indicesOutsideTheirTablesAreRefusedAtEntry() throws Exception {
    assertThatThrownBy(() -> ExprText.parse("R[0]")).hasMessage("R[0]: index out of range (1..200)");
    assertThatThrownBy(() -> ExprText.parse("DO[4097]=ON")).hasMessage("DO[4097]: index out of range (1..4096)");
    // The cell decides its I/O sizes: DO[600] is typed in, and alarms when run on a controller with 512 outputs.
    assertThat(ExprText.parse("DO[600]=ON")).isNotNull();
    assertThatThrownBy(() -> ExprText.parse("PR[101,1]")).hasMessage("PR[101]: index out of range (1..100)");
    assertThatThrownBy(() -> ExprText.parseItem("TIMER", "11")).hasMessage("TIMER[11]: index out of range (1..10)");
    assertThatThrownBy(() -> ExprText.parse("R[R[201]]")).hasMessage("R[201]: index out of range (1..200)");
    assertThat(ExprText.parseItem("R", "R[200:LAST]")).isEqualTo(Item.of(200, "LAST"));
    assertThat(ExprText.parseIndex("R[3]")).isEqualTo(new Index.Indirect(3, ""));
  }
}
