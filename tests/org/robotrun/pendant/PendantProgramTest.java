package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.robotrun.pendant.PendantKeys.body;
import static org.robotrun.pendant.PendantKeys.run;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.Instruction;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/**
 * Key sequences that build, edit and run a program, read back from the LCD text, on the real
 * controller (the default cell's LR Mate 200iD). Jog figures are worked out by hand in
 * {@link ArmByHand} from the robot file and the documented jog rules, never read from a run.
 */
class PendantProgramTest {
  private final RobotControl control = RealController.control();
  private final Pendant p = new Pendant(control);

  /**
   * J1 at P[2]: 0.5 s of J1 (T1, 100 %) stopped at once by SHIFT. At HOME the pointer's tip and
   * the flange swing at 385 mm from J1's axis, so T1's 250 mm/s cap sets the pace once the ramp passes it.
   */
  private static final double[] J1_AT_P2 =
      ArmByHand.jointJogRange(1, ArmByHand.radiusFromJ1(ArmByHand.tcp(ArmByHand.HOME)), 0.5);
  /**
   * J2 at P[3]: 0.5 s of J2 likewise. With FANUC's coupled J3 the forearm keeps its attitude, so
   * the tip and the flange circle J2's axis at the upper arm's length (330 mm).
   */
  private static final double[] J2_AT_P3 = ArmByHand.jointJogRange(2, ArmByHand.upperArmMm(), 0.5);

  /** Creates PICK1 and records three points, jogging J1 then J2 between them (see {@link #J1_AT_P2}). */
  private void createWithThreePoints() {
    assertThat(control.mode()).isEqualTo(RobotControl.Mode.T1);
    assertThat(control.overridePct()).isEqualTo(100);
    run(p, """
        HOLD DEADMAN
        SELECT
        F1
        TYPE PICK1
        ENTER
        SHIFT+F1
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.5
        RELEASE +X/J1
        RELEASE SHIFT
        SHIFT+F1
        HOLD SHIFT
        HOLD +Y/J2
        WAIT 0.5
        RELEASE +Y/J2
        RELEASE SHIFT
        SHIFT+F1
        """);
  }

  @Test
  void createRecordEditInsertAndRunToTheEnd() {
    createWithThreePoints();
    assertThat(body(p)).contains("1:  J P[1] 100% FINE").contains("2:  J P[2] 100% FINE").contains("J P[3] 100% FINE");

    // line 2 becomes L 200mm/sec CNT50: type by choice list, speed and CNT by typed entry
    run(p, """
        UP
        RIGHT
        ENTER
        2
        RIGHT
        RIGHT
        TYPE 200
        ENTER
        RIGHT
        RIGHT
        TYPE 50
        ENTER
        """);
    assertThat(body(p)).contains("L P[2] 200mm/sec {CNT50}");
    Lcd.FieldSpan span = p.lcd().cursorField().orElseThrow();
    assertThat(p.lcd().row(span.row()).substring(span.openCol(), span.closeCol() + 1)).isEqualTo("{CNT50}");

    // a register statement and an IF at the end, through [INST]
    run(p, """
        DOWN *2
        F2
        1
        2
        DOWN
        F2
        3
        1
        TYPE R[1]>5
        ENTER
        """);
    assertThat(body(p)).contains("4:  R[1]=R[1]+1").contains("5:  IF {R[1]>5},JMP LBL[1]");

    // run from line 1
    run(p, """
        HOLD DEADMAN
        ITEM
        TYPE 1
        ENTER
        HOLD SHIFT
        FWD
        WAIT 0.1
        """);
    assertThat(p.lcd().statusLine()).contains("RUNNING");
    run(p, "WAIT 5\nRELEASE SHIFT");
    assertThat(p.lcd().statusLine()).doesNotContain("RUNNING").doesNotContain("PAUSED");
    assertThat(p.lcd().alarmLine()).isBlank();
    assertThat(control.registers().number(1)).isEqualTo(1.0);
    // the robot stands at P[3] (compared in the frames P[3] was taught in)
    org.robotrun.program.LocalPosition taught = control.program("PICK1").orElseThrow().position(3).orElseThrow();
    Position.Cartesian p3 = (Position.Cartesian) taught.position();
    Position.Cartesian here = control.currentPose(taught.userFrame(), taught.toolFrame());
    assertThat(here.xMm()).isCloseTo(p3.xMm(), within(1e-6));
    assertThat(here.yMm()).isCloseTo(p3.yMm(), within(1e-6));
    assertThat(here.zMm()).isCloseTo(p3.zMm(), within(1e-6));
  }

  @Test
  void stepBackwardReturnsToThePreviousPoint() {
    createWithThreePoints();
    run(p, """
        HOLD DEADMAN
        HOLD SHIFT
        FWD
        WAIT 0.1
        RELEASE SHIFT
        """);
    // cursor follows execution; the program runs all three moves
    run(p, "WAIT 5");
    assertThat(control.currentJoints().j2Deg()).isBetween(J2_AT_P3[0], J2_AT_P3[1]);
    assertThat(p.lcd().cursorRow().orElseThrow()).contains("3:");
    // the cursor stays on the last line after a run, as on a controller (docs/pendant.md), and
    // SHIFT+BWD from there backs out of that line (docs/tp-execution.md)
    run(p, """
        HOLD DEADMAN
        HOLD SHIFT
        BWD
        WAIT 5
        RELEASE SHIFT
        """);
    // backed out of line 3: the robot is at P[2] (J2 = 0) and the cursor is on line 3
    assertThat(control.currentJoints().j2Deg()).isCloseTo(0, within(1e-6));
    assertThat(control.currentJoints().j1Deg()).isBetween(J1_AT_P2[0], J1_AT_P2[1]);
    assertThat(p.lcd().cursorRow().orElseThrow()).contains("3:");
  }

  @Test
  void stepModeRunsOneLinePerShiftFwd() {
    createWithThreePoints();
    run(p, """
        HOLD DEADMAN
        ITEM
        TYPE 1
        ENTER
        STEP
        HOLD SHIFT
        FWD
        WAIT 3
        RELEASE SHIFT
        """);
    assertThat(p.lcd().statusLine()).contains("STEP").contains("PAUSED");
    assertThat(p.lcd().cursorRow().orElseThrow()).contains("2:");
    run(p, """
        HOLD DEADMAN
        HOLD SHIFT
        FWD
        WAIT 3
        RELEASE SHIFT
        """);
    assertThat(p.lcd().cursorRow().orElseThrow()).contains("3:");
  }

  @Test
  void theEditorFollowsExecutionIntoACalledProgramAndBack() {
    control.saveProgram(Program.of("MAIN", java.util.List.of(new Instruction.Call("SUB", java.util.List.of()),
        new Instruction.AssignRegister(org.robotrun.program.Item.of(2), new org.robotrun.program.Expr.IntConst(9)))));
    control.saveProgram(Program.of("SUB", java.util.List.of(
        new Instruction.AssignRegister(org.robotrun.program.Item.of(1), new org.robotrun.program.Expr.IntConst(5)),
        new Instruction.WaitTime(new org.robotrun.program.Expr.RealConst(1.0)))));
    run(p, """
        HOLD DEADMAN
        SELECT
        ENTER
        HOLD SHIFT
        FWD
        WAIT 0.5
        """);
    assertThat(p.lcd().row(2)).startsWith("EDIT SUB");
    assertThat(p.lcd().cursorRow().orElseThrow()).contains("2:").contains("WAIT");
    assertThat(p.lcd().statusLine()).startsWith("SUB").contains("RUNNING");
    run(p, "WAIT 1\nRELEASE SHIFT");
    assertThat(control.registers().number(2)).isEqualTo(9.0);
    // after END the state reads as on a controller
    assertThat(p.lcd().statusLine()).contains("ABORTED");
  }

  @Test
  void aPausedProgramsCursorCanBeMovedAndRunsOnFromThere() {
    createWithThreePoints();
    run(p, """
        HOLD DEADMAN
        ITEM
        TYPE 1
        ENTER
        STEP
        HOLD SHIFT
        FWD
        WAIT 3
        RELEASE SHIFT
        ITEM
        TYPE 3
        ENTER
        """);
    // paused after line 1; the operator moved the cursor to line 3 and it stays there
    assertThat(p.lcd().statusLine()).contains("PAUSED");
    assertThat(p.lcd().cursorRow().orElseThrow()).contains("3:");
    run(p, """
        HOLD DEADMAN
        HOLD SHIFT
        FWD
        WAIT 5
        RELEASE SHIFT
        """);
    // line 3 ran from the moved cursor: the robot is at P[3] (J1 and J2 as jogged)
    assertThat(control.currentJoints().j1Deg()).isBetween(J1_AT_P2[0], J1_AT_P2[1]);
    assertThat(control.currentJoints().j2Deg()).isBetween(J2_AT_P3[0], J2_AT_P3[1]);
  }

  @Test
  void programMessagesShowOnThePromptLineAndTheUserScreen() {
    control.saveProgram(Program.of("HELLO", java.util.List.of(new Instruction.Message("PART READY"),
        new Instruction.Message("DONE"))));
    run(p, """
        HOLD DEADMAN
        SELECT
        ENTER
        HOLD SHIFT
        FWD
        WAIT 0.1
        RELEASE SHIFT
        """);
    assertThat(p.lcd().promptLine()).startsWith("MESSAGE: DONE");
    run(p, """
        MENU
        8
        """);
    assertThat(p.lcd().row(2)).startsWith("USER");
    assertThat(p.lcd().body().get(0)).startsWith(" PART READY");
    assertThat(p.lcd().body().get(1)).startsWith(" DONE");
  }

  @Test
  void holdPausesAndShiftFwdResumes() {
    createWithThreePoints();
    run(p, """
        HOLD DEADMAN
        ITEM
        TYPE 1
        ENTER
        HOLD SHIFT
        FWD
        WAIT 0.3
        RELEASE SHIFT
        HOLD
        """);
    assertThat(p.lcd().statusLine()).contains("PAUSED");
    // HOLD decelerates along the path within 0.25 s (docs/motion.md); then the arm stands, short of P[1]
    run(p, "WAIT 0.3");
    Position.Joint held = control.currentJoints();
    assertThat(held.j1Deg()).isGreaterThan(1);
    run(p, "WAIT 1");
    assertThat(control.currentJoints()).isEqualTo(held);
    run(p, """
        HOLD DEADMAN
        HOLD SHIFT
        FWD
        WAIT 5
        RELEASE SHIFT
        """);
    assertThat(p.lcd().statusLine()).doesNotContain("PAUSED").doesNotContain("RUNNING");
  }

  @Test
  void userErrorsAreMessagesOnThePromptLine() {
    run(p, """
        SELECT
        F1
        TYPE 1BAD
        ENTER
        """);
    assertThat(p.lcd().promptLine()).contains("Bad name '1BAD'");
    run(p, """
        F1
        TYPE MAIN
        ENTER
        SELECT
        F1
        TYPE MAIN
        ENTER
        """);
    assertThat(p.lcd().promptLine()).contains("already taken");

    // a bad number in a field
    run(p, """
        EDIT
        SHIFT+F1
        RIGHT
        RIGHT
        RIGHT
        TYPE abc
        ENTER
        """);
    assertThat(p.lcd().promptLine()).contains("Speed abc: not a number, enter a number above 0");

    // duplicate label
    run(p, """
        DOWN
        F2
        5
        1
        DOWN
        F2
        5
        1
        """);
    assertThat(p.lcd().promptLine()).contains("Duplicate label: LBL[1]");
    assertThat(control.program("MAIN").orElseThrow().lines().stream().filter(i -> i instanceof Instruction.Label))
        .hasSize(1);

    // deleting the running program
    run(p, """
        HOLD DEADMAN
        F2
        4
        1
        ITEM
        TYPE 1
        ENTER
        HOLD SHIFT
        FWD
        RELEASE SHIFT
        HOLD
        SELECT
        F2
        F4
        """);
    // refused while it runs or is paused: ABORT first (docs/pendant.md, docs/tp-execution.md)
    assertThat(p.lcd().promptLine()).contains("MAIN").contains("running or paused").contains("ABORT");
    assertThat(control.program("MAIN")).isPresent();
  }

  @Test
  void namesCanBeEnteredWithPendantStyleLetters() {
    // F1 cycles A..F, F3 M..R, F5 Y Z _ @ *; RIGHT (or another group) accepts the letter
    run(p, """
        SELECT
        F1
        F1 *2
        RIGHT
        F1 *5
        F3 *2
        F5 *3
        1
        ENTER
        """);
    assertThat(control.program("BEN_1")).isPresent();
    assertThat(p.lcd().row(2)).startsWith("EDIT BEN_1");
  }

  @Test
  void undoGoesBackAtLeastFiftySteps() {
    run(p, """
        SELECT
        F1
        TYPE UNDO1
        ENTER
        """);
    for (int i = 0; i < 60; i++) {
      run(p, """
          F2
          8
          1
          """);
    }
    assertThat(control.program("UNDO1").orElseThrow().lineCount()).isEqualTo(60);
    for (int i = 0; i < 55; i++) {
      run(p, """
          NEXT
          F4
          NEXT
          """);
    }
    assertThat(control.program("UNDO1").orElseThrow().lineCount()).isEqualTo(5);
  }

  @Test
  void aCursorOnAFieldThatUndoRemovedFallsBackToTheLineNumber() {
    createWithThreePoints();
    // add two options to line 3, put the cursor on the last one, then undo both
    run(p, """
        F4
        6
        F4
        7
        RIGHT *8
        NEXT
        F4
        F4
        NEXT
        LEFT
        """);
    assertThat(p.lcd().cursorRow().orElseThrow()).contains("{3:}");
  }

  @Test
  void copyPasteReverseAndRenumber() {
    createWithThreePoints();
    // select lines 1-3 and copy, paste with new position numbers at [End]
    run(p, """
        ITEM
        TYPE 1
        ENTER
        F3
        3
        DOWN *2
        F2
        DOWN
        F3
        4
        2
        """);
    Program prog = control.program("PICK1").orElseThrow();
    assertThat(prog.lineCount()).isEqualTo(6);
    assertThat(body(p)).contains("J P[4] 100% FINE").contains("J P[6] 100% FINE");
    assertThat(prog.positions()).containsKeys(4, 5, 6);
    // paste reversed: the last copied line comes first
    run(p, """
        ITEM
        TYPE 7
        ENTER
        F3
        4
        3
        """);
    prog = control.program("PICK1").orElseThrow();
    assertThat(prog.lineCount()).isEqualTo(9);
    assertThat(((Instruction.Move) prog.line(7)).target()).isEqualTo(new org.robotrun.program.Motion.Local(3, ""));
    // comment out line 1 and back
    run(p, """
        ITEM
        TYPE 1
        ENTER
        F3
        8
        """);
    assertThat(body(p)).contains("//J P[1] 100% FINE");
    run(p, """
        F3
        8
        """);
    assertThat(control.program("PICK1").orElseThrow().line(1)).isInstanceOf(Instruction.Move.class);
    // find
    run(p, """
        F3
        5
        TYPE P[5]
        ENTER
        """);
    assertThat(p.lcd().promptLine()).contains("Found 'P[5]' at line 5");
    // replace speeds (replace works field by field: the number, not the unit)
    run(p, """
        F3
        6
        TYPE 100
        ENTER
        TYPE 50
        ENTER
        """);
    assertThat(p.lcd().promptLine()).contains("9 field(s) replaced");
    assertThat(body(p)).contains("J P[1] 50% FINE");
  }

  @Test
  void enteringPayloadOrWjntWarnsThatItHasNoEffectInTheSimulator() {
    Program before = Program.of("P", java.util.List.of(new Instruction.Comment("x")));
    Program withPayload = Program.of("P", java.util.List.of(new Instruction.Comment("x"),
        new Instruction.Payload(new org.robotrun.program.Index.Direct(1))));
    assertThat(Pendant.noEffectAdded(before, withPayload)).hasValueSatisfying(w -> assertThat(w).startsWith("PAYLOAD has no effect"));
    // a line that was there already is not warned about again
    assertThat(Pendant.noEffectAdded(withPayload, withPayload)).isEmpty();
    assertThat(Pendant.noEffectAdded(withPayload, before)).isEmpty();
  }
}
