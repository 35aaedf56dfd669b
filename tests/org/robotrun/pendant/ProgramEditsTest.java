package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robotrun.program.Expr;
import org.robotrun.program.Instruction;
import org.robotrun.program.Item;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Motion;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

class ProgramEditsTest {
  private static final Motion.Speed PCT = new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.PERCENT);

  private static Instruction.Move j(int p) {
    return Instruction.Move.of(Motion.Type.J, new Motion.Local(p, ""), PCT, new Motion.Fine(), List.of());
  }

  private static LocalPosition pos(int n, double j1) {
    return new LocalPosition(n, "P" + n, 0, 0, new Position.Joint(j1, 0, 0, 0, 0, 0));
  }

  private static List<String> text(Program p) {
    return p.lines().stream().map(i -> TpLine.text(i, p, List.of())).toList();
  }

  @Test
  void renumberFollowsTheOrderOfUseAndKeepsEachPositionWithItsLine() {
    Program p = Program.of("R", List.of(j(7), j(3), new Instruction.AssignPosReg(Item.of(1), new Instruction.FromLocal(9, "")),
        j(7)), List.of(pos(3, 30), pos(7, 70), pos(9, 90), pos(12, 120)));
    Program r = ProgramEdits.renumber(p);
    assertThat(text(r)).containsExactly("J P[1:P7] 100% FINE", "J P[2:P3] 100% FINE", "PR[1]=P[3]",
        "J P[1:P7] 100% FINE");
    assertThat(r.positions().keySet()).containsExactly(1, 2, 3, 4);
    assertThat(r.position(1).orElseThrow().position().element(1)).isEqualTo(70);
    assertThat(r.position(4).orElseThrow().comment()).isEqualTo("P12");
  }

  @Test
  void pasteModes() {
    Program p = Program.of("P", List.of(j(1), j(2)), List.of(pos(1, 10), pos(2, 20)));
    List<Instruction> clip = p.lines();
    assertThat(text(ProgramEdits.paste(p, 3, clip, ProgramEdits.PasteMode.AS_IS)))
        .containsExactly("J P[1:P1] 100% FINE", "J P[2:P2] 100% FINE", "J P[1:P1] 100% FINE", "J P[2:P2] 100% FINE");
    assertThat(text(ProgramEdits.paste(p, 1, clip, ProgramEdits.PasteMode.REVERSE)))
        .startsWith("J P[2:P2] 100% FINE", "J P[1:P1] 100% FINE");
    Program fresh = ProgramEdits.paste(p, 3, clip, ProgramEdits.PasteMode.NEW_POSITIONS);
    assertThat(text(fresh).subList(2, 4)).containsExactly("J P[3:P1] 100% FINE", "J P[4:P2] 100% FINE");
    assertThat(fresh.position(4).orElseThrow().position().element(1)).isEqualTo(20);
  }

  @Test
  void insertFillsABlankLineAndDeleteKeepsPositions() {
    Program p = Program.of("I", List.of(j(1), new Instruction.Blank(), j(2)), List.of(pos(1, 10), pos(2, 20)));
    Program in = ProgramEdits.insert(p, 2, List.of(new Instruction.End()), Map.of());
    assertThat(text(in)).containsExactly("J P[1:P1] 100% FINE", "END", "J P[2:P2] 100% FINE");
    Program blanks = ProgramEdits.insertBlanks(in, 1, 2);
    assertThat(blanks.lineCount()).isEqualTo(5);
    Program del = ProgramEdits.delete(blanks, 1, 3);
    assertThat(text(del)).containsExactly("END", "J P[2:P2] 100% FINE");
    assertThat(del.positions()).containsKeys(1, 2);
  }

  @Test
  void replaceGoesThroughEachFieldsValidation() {
    Program p = Program.of("X", List.of(j(1), new Instruction.AssignRegister(Item.of(100), new Expr.IntConst(100))),
        List.of(pos(1, 0)));
    ProgramEdits.Replaced r = ProgramEdits.replaceAll(p, "100", "250", List.of());
    // 250% is over 100% and R[250] out of range: both refused; 250 is a fine value
    assertThat(text(r.program())).containsExactly("J P[1:P1] 100% FINE", "R[100]=250");
    assertThat(r.replaced()).isEqualTo(1);
    assertThat(r.refused()).isEqualTo(2);
  }

  @Test
  void aPercentSpeedOver100IsRefusedAtEntry() {
    Motion.Speed ok = new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.PERCENT);
    Motion.Speed over = new Motion.Speed(new Motion.SpeedConst(300), Motion.SpeedUnit.PERCENT);
    Motion.Speed fast = new Motion.Speed(new Motion.SpeedConst(2000), Motion.SpeedUnit.MM_PER_SEC);
    org.assertj.core.api.Assertions.assertThatCode(() -> TpLine.checkedSpeed(ok)).doesNotThrowAnyException();
    org.assertj.core.api.Assertions.assertThatCode(() -> TpLine.checkedSpeed(fast)).doesNotThrowAnyException();
    org.assertj.core.api.Assertions.assertThatThrownBy(() -> TpLine.checkedSpeed(over))
        .hasMessageContaining("300%").hasMessageContaining("1 to 100");
  }

  @Test
  void nextPositionNumberCountsLinesAndTheBlock() {
    assertThat(ProgramEdits.nextPositionNumber(Program.of("N", List.of(j(4)), List.of(pos(2, 0))))).isEqualTo(5);
    assertThat(ProgramEdits.nextPositionNumber(Program.of("N", List.of()))).isEqualTo(1);
  }
}
