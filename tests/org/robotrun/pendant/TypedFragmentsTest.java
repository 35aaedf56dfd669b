package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.program.Expr;
import org.robotrun.program.Instruction;
import org.robotrun.program.Item;
import org.robotrun.program.Motion;

/**
 * Text typed into an EDIT field is read by the TP grammar's one parser (its fragment entry
 * points), not split by hand: a string argument may hold commas, brackets and either quote, and a
 * field takes every form a .LS line may hold there.
 */
class TypedFragmentsTest {

  @Test
  void aCallArgumentMayHoldCommasBracketsAndEitherQuote() throws Exception {
    assertThat(TpLine.parseCall("show('A,B]',2)")).isEqualTo(new Instruction.Call("SHOW",
        List.of(new Expr.StringConst("A,B]"), new Expr.IntConst(2))));
    assertThat(TpLine.parseCall("SHOW(\"it's, (ok)\",R[1])")).isEqualTo(new Instruction.Call("SHOW",
        List.of(new Expr.StringConst("it's, (ok)"), new Expr.Register(Item.of(1)))));
    assertThat(TpLine.parseBranch("CALL SHOW(\"a,b\")", false)).isEqualTo(new Instruction.Call("SHOW",
        List.of(new Expr.StringConst("a,b"))));
  }

  @Test
  void aBadCallArgumentIsRefusedWithItsColumn() {
    assertThatThrownBy(() -> TpLine.parseCall("SHOW(1,")).isInstanceOf(ExprText.BadText.class)
        .hasMessageContaining("column 8");
    // the pendant's entry checks apply to each argument, as to any typed expression
    assertThatThrownBy(() -> TpLine.parseCall("SHOW(R[999])")).hasMessageContaining("R[999]: index out of range");
  }

  @Test
  void aPositionSourceTakesEverySumTheFileTakes() throws Exception {
    assertThat(TpLine.parsePosSource("lpos-pr[2]")).isEqualTo(new Instruction.PosSum(new Instruction.CurrentLpos(),
        List.of(new Instruction.PosTerm(false, new Instruction.FromPosReg(Item.of(2))))));
    assertThat(TpLine.parsePosSource("PR[1:A]+PR[2]")).isEqualTo(new Instruction.PosArithmetic(Item.of(1, "A"), true,
        Item.of(2)));
    assertThatThrownBy(() -> TpLine.parsePosSource("UFRAME[1]+PR[2]")).hasMessageContaining("cannot be added");
  }

  @Test
  void aDefaultMotionIsReadAsTheMotionLineItStandsFor() throws Exception {
    DefaultMotion d = DefaultMotion.parse("L R[2]mm/sec CNT R[3]");
    assertThat(d.speed()).isEqualTo(new Motion.Speed(new Motion.SpeedRegister(Item.of(2)), Motion.SpeedUnit.MM_PER_SEC));
    assertThat(d.termination()).isEqualTo(new Motion.CntRegister(Item.of(3)));
    assertThat(d.display()).isEqualTo("L P[] R[2]mm/sec CNT R[3]");
    assertThat(DefaultMotion.parse("C 100mm/sec FINE").line(4).circularEnd()).contains(new Motion.Local(5, ""));
    assertThatThrownBy(() -> DefaultMotion.parse("J 100mm/sec FINE")).hasMessageContaining("does not fit a J motion");
  }
}
