package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.robotrun.pendant.PendantKeys.run;

import java.util.List;
import java.util.OptionalDouble;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.program.Expr;
import org.robotrun.program.Instruction;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;
import org.robotrun.program.Motion;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/**
 * Every number typed on the pendant is refused at entry when the .LS reader (or the scenario
 * loader) would refuse it on reading: a one-line message naming the field and the range, and the
 * old value kept.
 */
class PendantNumberEntryTest {
  private final RobotControl control = RealController.control();
  private final Pendant p = new Pendant(control);

  private String prompt() {
    return p.lcd().promptLine().strip();
  }

  /** Creates program N with P[1] recorded where the robot stands, and opens P[1]'s detail on X. */
  private void programWithPositionDetail() {
    run(p, """
        SELECT
        F1
        TYPE N
        ENTER
        SHIFT+F1
        UP
        NEXT
        F1
        """);
  }

  private Position p1() {
    return control.program("N").orElseThrow().position(1).orElseThrow().position();
  }

  @Test
  void positionDetailRefusesACoordinateBeyondTheFileBoundAndKeepsTheOldValue() {
    programWithPositionDetail();
    Position before = p1();
    run(p, """
        DOWN *2
        TYPE 1e308
        ENTER
        """);
    assertThat(prompt()).isEqualTo("P[1] Z 1e308: out of range, enter -100000 to 100000 mm");
    assertThat(p1()).isEqualTo(before);

    // the bound itself is accepted, and so is an ordinary value with an exponent
    run(p, """
        TYPE 100000
        ENTER
        UP
        TYPE -1.5e2
        ENTER
        """);
    assertThat(p1().element(3)).isEqualTo(100_000.0);
    assertThat(p1().element(2)).isEqualTo(-150.0);
  }

  @Test
  void positionDetailRefusesNanInfinityAndAnglesBeyondTheBound() {
    programWithPositionDetail();
    Position before = p1();
    for (String bad : List.of("NaN", "Infinity", "-Infinity", "0x10", "5f", "1e400")) {
      run(p, "TYPE " + bad + "\nENTER\n");
      assertThat(prompt()).as(bad).startsWith("P[1] X").endsWith("enter -100000 to 100000 mm");
    }
    run(p, """
        DOWN *3
        TYPE 36001
        ENTER
        """);
    assertThat(prompt()).isEqualTo("P[1] W 36001: out of range, enter -36000 to 36000 deg");
    assertThat(p1()).isEqualTo(before);
  }

  @Test
  void jointValuesOfAPositionRegisterHaveTheAngleBound() {
    control.registers().setPosition(1, Position.Joint.ZERO);
    run(p, """
        DATA
        F1
        2
        F2
        TYPE 99999999
        ENTER
        """);
    assertThat(prompt()).isEqualTo("PR[1] J1 99999999: out of range, enter -36000 to 36000 deg");
    assertThat(control.registers().position(1)).isEqualTo(Position.Joint.ZERO);
  }

  @Test
  void frameDirectEntryRefusesAnAbsurdCoordinateAndKeepsTheFrame() {
    run(p, """
        MENU
        5
        F2
        F2
        4
        DOWN
        TYPE 150
        ENTER
        TYPE 99999999
        ENTER
        """);
    assertThat(prompt()).isEqualTo("UTOOL[1] X 99999999: out of range, enter -100000 to 100000 mm");
    assertThat(control.frame(FrameKind.TOOL, 1).xMm()).isEqualTo(150.0);
    run(p, """
        DOWN *5
        TYPE -1e9
        ENTER
        """);
    assertThat(prompt()).isEqualTo("UTOOL[1] R -1e9: out of range, enter -36000 to 36000 deg");
    assertThat(control.frame(FrameKind.TOOL, 1).rDeg()).isEqualTo(0.0);
  }

  @Test
  void aNumericRegisterTakesAnyFiniteNumberAndRefusesTheRest() {
    run(p, """
        DATA
        TYPE NaN
        ENTER
        """);
    assertThat(prompt()).isEqualTo("R[1] NaN: not a number, enter digits, '.' and '-'");
    run(p, "TYPE 1e400\nENTER\n");
    assertThat(prompt()).startsWith("R[1] 1e400: not a number");
    assertThat(control.registers().number(1)).isEqualTo(0.0);
    run(p, "TYPE -2.5e3\nENTER\n");
    assertThat(control.registers().number(1)).isEqualTo(-2500.0);
    run(p, "TYPE +7\nENTER\n");
    assertThat(control.registers().isInteger(1)).isTrue();
    assertThat(control.registers().number(1)).isEqualTo(7.0);
  }

  @Test
  void groupIoRefusesAFractionWithTheRange() {
    run(p, """
        I/O
        F1
        6
        TYPE 2.5
        ENTER
        """);
    assertThat(prompt()).isEqualTo("GO[1] 2.5: not a whole number, enter 0 to 65535");
    assertThat(control.registers().value(IoKind.GO, 1)).isEqualTo(0);
  }

  /** Applies typed text to field {@code index} of {@code in}, as the EDIT screen does. */
  private static Instruction type(Instruction in, int index, String text) throws ExprText.BadText {
    Program prog = Program.of("X", List.of(in), List.of());
    Field f = TpLine.fields(in, prog, List.of()).get(index);
    return f.edit().orElseThrow().entry().orElseThrow().apply(text);
  }

  @Test
  void editFieldsRefuseWhatTheLsReaderRefuses() throws ExprText.BadText {
    Instruction wait = new Instruction.WaitTime(new Expr.RealConst(1));
    assertThatThrownBy(() -> type(wait, 1, "-1")).hasMessage("WAIT -1: out of range, enter 0 or more (sec) or R[i]");
    assertThatThrownBy(() -> type(wait, 1, "1" + "0".repeat(400) + ".0")).hasMessageContaining("is too large");
    assertThat(type(wait, 1, "2.5")).isEqualTo(new Instruction.WaitTime(new Expr.RealConst(2.5)));

    Instruction override = new Instruction.SetOverride(new Expr.IntConst(50));
    assertThatThrownBy(() -> type(override, 1, "150")).hasMessage("OVERRIDE 150: out of range, enter 1 to 100");
    assertThatThrownBy(() -> type(override, 1, "R[1]+1")).hasMessageContaining("OVERRIDE");
    assertThat(type(override, 1, "R[2]")).isEqualTo(new Instruction.SetOverride(new Expr.Register(Item.of(2))));

    Instruction loop = new Instruction.For(Item.of(1), new Expr.IntConst(1), false, new Expr.IntConst(3));
    assertThatThrownBy(() -> type(loop, 3, "1.5")).hasMessage("FOR 1.5: not allowed, enter an integer, R[i] or AR[i]");
    assertThatThrownBy(() -> type(loop, 3, "R[1]+1")).hasMessageContaining("FOR R[1]+1: not allowed");
    assertThat(type(loop, 3, "-2")).isEqualTo(new Instruction.For(Item.of(1), new Expr.IntConst(-2), false, new Expr.IntConst(3)));

    Instruction assign = new Instruction.AssignRegister(Item.of(1), new Expr.IntConst(0));
    // a string is a value since SR[] runs (SR[1]='A'), but not one R[] holds: refused as the .LS reader refuses it
    assertThatThrownBy(() -> type(assign, 2, "'A'")).hasMessageContaining("R[] holds a number, not a string constant");

    Instruction pulse = new Instruction.Pulse(IoKind.DO, Item.of(1), OptionalDouble.of(0.5));
    assertThatThrownBy(() -> type(pulse, 3, "NaN")).hasMessage("Pulse width NaN: not a number, enter a number above 0");
    assertThatThrownBy(() -> type(pulse, 3, "0")).hasMessage("Pulse width 0: out of range, enter a number above 0");
  }

  private static Instruction.Move move(Motion.Type type, double value, Motion.SpeedUnit unit) {
    return new Instruction.Move(type, new Motion.Local(1, ""), java.util.Optional.empty(),
        new Motion.Speed(new Motion.SpeedConst(value), unit), new Motion.Fine(), List.of());
  }

  /** Field 4 of a motion line is its speed (type, blank, target, blank, speed, unit). */
  private static final int SPEED_FIELD = 4;

  @Test
  void aMotionSpeedBeyondTheControllersRangeIsValueOutOfRangeInEveryUnit() throws ExprText.BadText {
    record Case(Motion.Type type, Motion.SpeedUnit unit, String over, double max, String under, double min) {}
    List<Case> cases = List.of(
        new Case(Motion.Type.J, Motion.SpeedUnit.PERCENT, "101", 100, "0.5", 1),
        new Case(Motion.Type.L, Motion.SpeedUnit.MM_PER_SEC, "999999", 2000, "0.5", 1),
        new Case(Motion.Type.L, Motion.SpeedUnit.CM_PER_MIN, "12001", 12000, "0.5", 1),
        new Case(Motion.Type.L, Motion.SpeedUnit.INCH_PER_MIN, "4724.5", 4724.4, "0.05", 0.1),
        new Case(Motion.Type.L, Motion.SpeedUnit.DEG_PER_SEC, "521", 520, "0.5", 1),
        new Case(Motion.Type.J, Motion.SpeedUnit.SEC, "3201", 3200, "0.05", 0.1),
        new Case(Motion.Type.L, Motion.SpeedUnit.MSEC, "32001", 32000, "0.5", 1));
    for (Case c : cases) {
      Instruction.Move m = move(c.type(), 50, c.unit());
      String unit = TpLine.unit(c.unit());
      assertThatThrownBy(() -> type(m, SPEED_FIELD, c.over())).as(unit)
          .hasMessageStartingWith("Speed " + c.over() + unit + ": Value out of range, enter ")
          .hasMessageEndingWith(" to " + ExprText.plain(c.max()) + " " + unit);
      assertThatThrownBy(() -> type(m, SPEED_FIELD, c.under())).as(unit).hasMessageContaining("Value out of range");
      assertThat(((Instruction.Move) type(m, SPEED_FIELD, ExprText.plain(c.max()))).speed())
          .isEqualTo(new Motion.Speed(new Motion.SpeedConst(c.max()), c.unit()));
      assertThat(((Instruction.Move) type(m, SPEED_FIELD, ExprText.plain(c.min()))).speed())
          .isEqualTo(new Motion.Speed(new Motion.SpeedConst(c.min()), c.unit()));
    }
    assertThatThrownBy(() -> DefaultMotion.parse("L 999999mm/sec FINE")).hasMessageContaining("Value out of range");
    assertThatCode(() -> DefaultMotion.parse("L 2000mm/sec FINE")).doesNotThrowAnyException();
  }

  @Test
  void thePendantKeepsTheOldSpeedAndSaysValueOutOfRange() {
    run(p, """
        SELECT
        F1
        TYPE N
        ENTER
        F1
        ENTER
        """);
    Program before = control.program("N").orElseThrow();
    assertThat(before.lines()).isNotEmpty();
    // from the line number to the speed field: type, target, speed
    run(p, "RIGHT *3\nTYPE 999999\nENTER\n");
    assertThat(prompt()).contains("Value out of range");
    assertThat(control.program("N").orElseThrow()).isEqualTo(before);
  }

  @Test
  void theMmPerSecRangeEndsAtTheRobotsOwnMaximumFromTheControlPort() {
    // a CRX's controller limits a TCP speed to 1000 mm/s (its model's $SPEEDLIM), not 2000
    RobotControl control = RealController.control(RobotDefinitions.load("crx10ia"));
    assertThat(control.maxLinearSpeedMmPerSec()).isEqualTo(1000);
    Pendant p = new Pendant(control);
    run(p, """
        SELECT
        F1
        TYPE N
        ENTER
        F1
        DOWN *2
        ENTER
        """);
    Program before = control.program("N").orElseThrow();
    run(p, "RIGHT *3\nTYPE 1500\nENTER\n");
    assertThat(p.lcd().promptLine().strip()).isEqualTo("Speed 1500mm/sec: Value out of range, enter 1 to 1000 mm/sec");
    assertThat(control.program("N").orElseThrow()).isEqualTo(before);
    run(p, "TYPE 1000\nENTER\n");
    assertThat(control.program("N").orElseThrow().line(1)).isInstanceOfSatisfying(Instruction.Move.class,
        m -> assertThat(m.speed().value()).isEqualTo(new Motion.SpeedConst(1000)));
    // the other linear units end at the same speed; ED_DEF checks the same way
    assertThatThrownBy(() -> TpLine.checkedSpeed(new Motion.Speed(new Motion.SpeedConst(6001), Motion.SpeedUnit.CM_PER_MIN), 1000))
        .hasMessageEndingWith("1 to 6000 cm/min");
    assertThatThrownBy(() -> TpLine.checkedSpeed(new Motion.Speed(new Motion.SpeedConst(2362.3), Motion.SpeedUnit.INCH_PER_MIN), 1000))
        .hasMessageEndingWith("0.1 to 2362.2 inch/min");
    assertThatThrownBy(() -> DefaultMotion.parse("L 1001mm/sec FINE", 1000)).hasMessageContaining("Value out of range");
    assertThatCode(() -> DefaultMotion.parse("L 2000mm/sec FINE", 2000)).doesNotThrowAnyException();
    // mm/sec chosen from the list brings the speed into this robot's range
    assertThat(TpLine.speedInRange(new Motion.Speed(new Motion.SpeedConst(1800), Motion.SpeedUnit.MM_PER_SEC), 1000))
        .isEqualTo(new Motion.Speed(new Motion.SpeedConst(1000), Motion.SpeedUnit.MM_PER_SEC));
  }

  @Test
  void choosingAUnitOrTypeBringsTheSpeedIntoItsRange() {
    Instruction.Move l = move(Motion.Type.L, 2000, Motion.SpeedUnit.MM_PER_SEC);
    assertThat(TpLine.withType(l, Motion.Type.J, 2000).speed())
        .isEqualTo(new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.PERCENT));
    Program prog = Program.of("X", List.of(l), List.of());
    Field unit = TpLine.fields(l, prog, List.of()).get(SPEED_FIELD + 1);
    int deg = unit.edit().orElseThrow().choices().indexOf("deg/sec");
    assertThat(((Instruction.Move) unit.edit().orElseThrow().choose().apply(deg)).speed())
        .isEqualTo(new Motion.Speed(new Motion.SpeedConst(520), Motion.SpeedUnit.DEG_PER_SEC));
  }

  @Test
  void aDefaultMotionOver100PercentIsRefused() {
    assertThatThrownBy(() -> DefaultMotion.parse("J 300% FINE")).hasMessageContaining("300%");
    assertThatCode(() -> DefaultMotion.parse("J 100% FINE")).doesNotThrowAnyException();
  }

  @Test
  void everyRefusalFitsThePromptLine() {
    // the longest field names, with typed texts of the longest length a message repeats
    List<ExprText.BadText> refusals = List.of(
        NumberEntry.refusal("UFRAME[10] X", "-999999.9", "out of range", "-100000 to 100000 mm"),
        NumberEntry.refusal("PR[100] J6", "123456789", "out of range", "-36000 to 36000 deg"),
        NumberEntry.refusal("R[200]", "1.2.3.4.5", "not a number", "digits, '.' and '-'"),
        NumberEntry.refusal("WAIT", "-123456.7", "out of range", "0 or more (sec) or R[i]"),
        NumberEntry.refusal("FOR", "1234567.8", "not allowed", "an integer, R[i] or AR[i]"),
        NumberEntry.refusal("OVERRIDE", "R[1]+R[2]", "not allowed", "1 to 100 (%) or R[i]"),
        NumberEntry.refusal("Pulse width", "1234567.8", "not a number", "a number above 0"));
    for (ExprText.BadText r : refusals) {
      assertThat(r.promptText().length()).as(r.getMessage()).isLessThanOrEqualTo(Lcd.WIDTH);
    }
  }
}
