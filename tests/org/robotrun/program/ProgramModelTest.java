package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Xyzwpr;

/** The program model's own rules: invariants, registers' ranges, position elements. */
class ProgramModelTest {

  @Test
  void programNamesFollowFanucRules() {
    assertThat(Program.isValidName("PICK3")).isTrue();
    assertThat(Program.isValidName("A_1")).isTrue();
    assertThat(Program.isValidName("1ABC")).isFalse();
    assertThat(Program.isValidName("")).isFalse();
    assertThat(Program.isValidName("BAD-NAME")).isFalse();
    assertThat(Program.isValidName("A".repeat(36))).isTrue();
    assertThat(Program.isValidName("A".repeat(37))).isFalse();
  }

  @Test
  void programKeepsAttributesInTheOrderRead() {
    Map<String, String> attrs = new LinkedHashMap<>();
    attrs.put("OWNER", "MNEDITOR");
    attrs.put("PROG_SIZE", "0");
    attrs.put("CREATE", "DATE 25-01-10  TIME 09:00:00");
    Program p = new Program("P", attrs, "demo", List.of(new Instruction.Blank()), Map.of());
    assertThat(p.attributes().keySet()).containsExactly("OWNER", "PROG_SIZE", "CREATE");
    assertThat(p.line(1)).isEqualTo(new Instruction.Blank());
    assertThatThrownBy(() -> p.attributes().put("X", "Y")).isInstanceOf(UnsupportedOperationException.class);
  }

  @Test
  void positionsAreKeyedByTheirOwnNumber() {
    LocalPosition p2 = Tp.pos(2);
    assertThatThrownBy(() -> new Program("P", Map.of(), "", List.of(), Map.of(3, p2)))
        .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("P[3]");
    assertThat(Program.of("P", List.of(), List.of(p2)).position(2)).contains(p2);
    assertThat(Program.of("P", List.of(), List.of(p2)).position(1)).isEmpty();
  }

  @Test
  void onlyCircularMotionHasAnEndPoint() {
    Motion.Speed s = Tp.mmPerSec(100);
    assertThatThrownBy(() -> new Instruction.Move(Motion.Type.L, Tp.p(1), Optional.of(Tp.p(2)), s, new Motion.Fine(), List.of()))
        .isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new Instruction.Move(Motion.Type.C, Tp.p(1), Optional.empty(), s, new Motion.Fine(), List.of()))
        .isInstanceOf(IllegalArgumentException.class);
    assertThat(Instruction.Move.circular(Tp.p(1), Tp.p(2), s, new Motion.Fine(), List.of()).circularEnd()).contains(Tp.p(2));
  }

  @Test
  void speedUnitsFitTheirMotionTypes() {
    assertThat(Motion.SpeedUnit.PERCENT.fits(Motion.Type.J)).isTrue();
    assertThat(Motion.SpeedUnit.PERCENT.fits(Motion.Type.L)).isFalse();
    assertThat(Motion.SpeedUnit.MM_PER_SEC.fits(Motion.Type.J)).isFalse();
    assertThat(Motion.SpeedUnit.SEC.fits(Motion.Type.J)).isTrue();
    assertThat(Motion.SpeedUnit.DEG_PER_SEC.fits(Motion.Type.C)).isTrue();
  }

  @Test
  void positionElementsAreOneBased() {
    Position.Cartesian c = new Position.Cartesian(1, 2, 3, 4, 5, 6, Config.DEFAULT);
    for (int j = 1; j <= 6; j++) {
      assertThat(c.element(j)).isEqualTo(j);
      assertThat(c.withElement(j, 9).element(j)).isEqualTo(9);
    }
    Position.Joint q = new Position.Joint(1, 2, 3, 4, 5, 6);
    assertThat(q.withElement(5, -90)).isEqualTo(new Position.Joint(1, 2, 3, 4, -90, 6));
    assertThatThrownBy(() -> q.element(7)).isInstanceOf(IndexOutOfBoundsException.class);
  }

  @Test
  void cartesianConvertsToTheMathPoseInRadians() {
    // Tolerance 1e-12 deg: a degree → radian → degree round trip.
    Position.Cartesian c = new Position.Cartesian(350, -120, 40, 180, 0, -90, Config.DEFAULT);
    Xyzwpr pose = c.toXyzwpr();
    assertThat(pose.w()).isEqualTo(Math.PI);
    assertThat(Position.Cartesian.of(pose, Config.DEFAULT).rDeg()).isCloseTo(-90, org.assertj.core.data.Offset.offset(1e-12));
  }

  @Test
  void registersKeepIntegerAndRealApartAndCheckRanges() {
    Registers r = new Registers();
    assertThat(r.isInteger(1)).isTrue();
    r.setReal(1, 2.0);
    assertThat(r.isInteger(1)).isFalse();
    r.setInteger(200, 7);
    assertThat(r.number(200)).isEqualTo(7);
    assertThatThrownBy(() -> r.number(201)).isInstanceOf(RegisterIndexException.class)
        .hasMessage("R[201]: index out of range (expected 1..200)");
    assertThatThrownBy(() -> r.position(0)).isInstanceOf(RegisterIndexException.class);
    assertThat(r.bit(IoKind.DO, 512)).isFalse();
    assertThatThrownBy(() -> r.bit(IoKind.DO, 513)).isInstanceOf(RegisterIndexException.class)
        .hasMessage("DO[513]: index out of range (expected 1..512)");
    assertThatThrownBy(() -> r.setBit(IoKind.RO, 9, true)).isInstanceOf(RegisterIndexException.class);
    r.setBit(IoKind.F, 200, true);
    assertThat(r.bit(IoKind.F, 200)).isTrue();
    r.setValue(IoKind.GO, 1, 300);
    assertThat(r.value(IoKind.GO, 1)).isEqualTo(300);
    r.setValue(IoKind.DO, 1, 300);
    assertThat(r.value(IoKind.DO, 1)).isEqualTo(1);
    assertThatThrownBy(() -> r.timerSec(11)).isInstanceOf(RegisterIndexException.class);
  }

  @Test
  void timersCountOnlyWhileStarted() {
    Registers r = new Registers();
    r.startTimer(2);
    r.advanceTimers(0.5);
    r.stopTimer(2);
    r.advanceTimers(0.5);
    assertThat(r.timerSec(2)).isEqualTo(0.5);
    r.startTimer(2);
    r.advanceTimers(0.25);
    assertThat(r.timerSec(2)).isEqualTo(0.75);
    r.resetTimer(2);
    assertThat(r.timerSec(2)).isZero();
    assertThat(r.timerRunning(2)).isFalse();
  }

  @Test
  void operatorsCarryTheirSpellingAndPrecedence() {
    assertThat(Expr.BinaryOp.MOD.symbol()).isEqualTo("MOD");
    assertThat(Expr.BinaryOp.NE.symbol()).isEqualTo("<>");
    assertThat(Expr.BinaryOp.MUL.precedence()).isGreaterThan(Expr.BinaryOp.ADD.precedence());
    assertThat(Expr.BinaryOp.ADD.precedence()).isGreaterThan(Expr.BinaryOp.LT.precedence());
    assertThat(Expr.BinaryOp.LT.precedence()).isGreaterThan(Expr.BinaryOp.AND.precedence());
    assertThat(Expr.BinaryOp.AND.precedence()).isGreaterThan(Expr.BinaryOp.OR.precedence());
  }
}
