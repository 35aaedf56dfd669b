package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl.ExecState;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * Editing a paused program on the real controller: the next SHIFT+FWD runs the edited code
 * (docs/tp-execution.md, "Editing a paused program"), whatever was inserted or deleted around
 * the paused line, and a caller edited while a CALLed program is paused returns into its new
 * version.
 */
class PendantEditPausedProgramTest {
  private final Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
  private final Controller controller = sim.controllers().get(0);
  private final ControllerPort control = new ControllerPort(controller);
  private final org.robotrun.sim.CellStepper stepper = new org.robotrun.sim.CellStepper(sim);
  private final Pendant p = new Pendant(control, new LsLineParser());

  private void keys(String script) {
    KeyScript s = switch (KeyScript.parse("test.keys", script.lines().toList())) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new AssertionError(bad.error().display());
    };
    s.run(p, stepper::advance, text -> { });
  }

  /** A program from .LS body lines ("R[1]=1" …), stored on the controller. */
  private void store(String name, String... lines) {
    List<String> ls = new ArrayList<>(List.of("/PROG  " + name, "/ATTR", "/MN"));
    for (int i = 0; i < lines.length; i++) {
      ls.add(String.format("%4d:  %s ;", i + 1, lines[i]));
    }
    ls.addAll(List.of("/POS", "/END"));
    LsReadResult r = LsReader.parse(name + ".LS", String.join("\n", ls) + "\n");
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    control.saveProgram(r.program());
  }

  private static String jointPos(int n, double j1Deg) {
    return String.format(java.util.Locale.ROOT, """
        P[%d]{
           GP1:
        	UF : 0, UT : 0,
        	J1=  %8.3f deg,	J2=     0.000 deg,	J3=     0.000 deg,
        	J4=     0.000 deg,	J5=   -90.000 deg,	J6=     0.000 deg
        };""", n, j1Deg);
  }

  /** MOVE: J P[1] (J1 0), J P[2] (J1 60) slowly; held half-way along line 2. */
  private void heldHalfWayAlongLine2(String line2) {
    String text = String.join("\n", "/PROG  MOVE", "/ATTR", "/MN", "   1:  J P[1] 100% FINE ;",
        "   2:  " + line2 + " ;", "/POS", jointPos(1, 0), jointPos(2, 60), jointPos(3, -30), "/END") + "\n";
    LsReadResult r = LsReader.parse("MOVE.LS", text);
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    control.saveProgram(r.program());
    assertThat(controller.run("MOVE", 1, true)).isInstanceOf(org.robotrun.control.RobotControl.Result.Ok.class);
    for (int i = 0; i < 400 && control.status().line() < 2; i++) {
      stepper.advance(0.05);
    }
    stepper.advance(0.5);
    control.hold();
    stepper.advance(0.5);
    assertThat(control.status()).isEqualTo(new org.robotrun.control.RobotControl.ExecutionStatus("MOVE", 2, ExecState.PAUSED));
    assertThat(control.currentJoints().j1Deg()).isBetween(1.0, 59.0);
  }

  private void resumeAtStatusLineAndFinish() {
    assertThat(controller.run("MOVE", control.status().line(), true)).isInstanceOf(org.robotrun.control.RobotControl.Result.Ok.class);
    for (int i = 0; i < 600 && control.status().state() != ExecState.IDLE; i++) {
      stepper.advance(0.05);
    }
    assertThat(control.status().state()).isEqualTo(ExecState.IDLE);
    assertThat(control.activeAlarm()).isEmpty();
  }

  @Test
  void aHeldMotionContinuesAfterAnInsertionAboveIt() {
    heldHalfWayAlongLine2("J P[2] 10% FINE");
    Program before = control.program("MOVE").orElseThrow();
    List<org.robotrun.program.Instruction> lines = new ArrayList<>(before.lines());
    lines.add(0, new org.robotrun.program.Instruction.Comment("inserted"));
    control.saveProgram(new Program("MOVE", before.attributes(), before.comment(), lines, before.positions()));
    assertThat(control.status().line()).isEqualTo(3);
    resumeAtStatusLineAndFinish();
    assertThat(control.currentJoints().j1Deg()).isCloseTo(60, org.assertj.core.api.Assertions.within(0.01));
  }

  @Test
  void aHeldMotionWhoseLineWasEditedRunsTheEditedLineFromWhereTheArmStands() {
    heldHalfWayAlongLine2("J P[2] 10% FINE");
    Program before = control.program("MOVE").orElseThrow();
    List<org.robotrun.program.Instruction> lines = new ArrayList<>(before.lines());
    org.robotrun.program.Instruction.Move m = (org.robotrun.program.Instruction.Move) lines.get(1);
    lines.set(1, new org.robotrun.program.Instruction.Move(m.type(), new org.robotrun.program.Motion.Local(3, ""),
        m.circularEnd(), m.speed(), m.termination(), m.options()));
    control.saveProgram(new Program("MOVE", before.attributes(), before.comment(), lines, before.positions()));
    assertThat(control.status().line()).isEqualTo(2);
    resumeAtStatusLineAndFinish();
    assertThat(control.currentJoints().j1Deg()).isCloseTo(-30, org.assertj.core.api.Assertions.within(0.01));
  }

  /** Creates EDT on the pendant (open in EDIT) with {@code lines}, STEP on, runs line 1: paused at line 2. */
  private void pausedAtLine2(String... lines) {
    keys("""
        SELECT
        F1
        TYPE EDT
        ENTER
        """);
    store("EDT", lines);
    keys("""
        HOLD DEADMAN
        ITEM
        TYPE 1
        ENTER
        STEP
        HOLD SHIFT
        FWD
        WAIT 0.2
        RELEASE SHIFT
        """);
    assertThat(control.status()).isEqualTo(new org.robotrun.control.RobotControl.ExecutionStatus("EDT", 2, ExecState.PAUSED));
    assertThat(r(1)).isEqualTo(1);
  }

  private double r(int i) {
    return control.registers().number(i);
  }

  private int lineCount() {
    return control.program("EDT").map(Program::lineCount).orElseThrow();
  }

  @Test
  void aJumpInsertedBelowThePausedLineRunsAndAlarmsForItsMissingLabel() {
    pausedAtLine2("R[1]=1", "R[2]=2", "R[3]=3");
    // the QA reproduction: insert JMP LBL[1] (no such label) as line 3, back to the paused line
    keys("""
        HOLD DEADMAN
        DOWN
        F2
        5
        2
        ITEM
        TYPE 1
        ENTER
        UP
        STEP
        HOLD SHIFT
        FWD
        WAIT 0.5
        RELEASE SHIFT
        """);
    assertThat(lineCount()).isEqualTo(4);
    assertThat(r(2)).isEqualTo(2);
    assertThat(p.lcd().alarmLine()).contains("(EDT, 3)").contains("LBL[1]");
    assertThat(r(3)).isZero();
  }

  @Test
  void withTheCursorLeftOnTheInsertedJumpItRunsFromThere() {
    pausedAtLine2("R[1]=1", "R[2]=2", "R[3]=3");
    keys("""
        HOLD DEADMAN
        DOWN
        F2
        5
        2
        ITEM
        TYPE 1
        ENTER
        STEP
        HOLD SHIFT
        FWD
        WAIT 0.5
        RELEASE SHIFT
        """);
    assertThat(p.lcd().alarmLine()).contains("(EDT, 3)").contains("LBL[1]");
    assertThat(r(3)).isZero();
  }

  @Test
  void linesInsertedAboveThePausedLineShiftItAndTheCursorStaysOnTheEdit() {
    pausedAtLine2("R[1]=1", "R[2]=2", "R[3]=3", "R[4]=4");
    // two blank lines inserted at line 1: the paused R[2]=2 is now line 4
    keys("""
        UP
        F3
        1
        2
        ENTER
        """);
    assertThat(lineCount()).isEqualTo(6);
    assertThat(control.status()).isEqualTo(new org.robotrun.control.RobotControl.ExecutionStatus("EDT", 4, ExecState.PAUSED));
    // the operator's cursor stays on the inserted line (an edit is not execution moving)
    assertThat(p.lcd().body().get(0)).startsWith("> {1:}");
    keys("""
        HOLD DEADMAN
        DOWN *3
        STEP
        HOLD SHIFT
        FWD
        WAIT 0.5
        RELEASE SHIFT
        """);
    assertThat(control.status().state()).isEqualTo(ExecState.IDLE);
    assertThat(p.lcd().alarmLine()).isBlank();
    assertThat(new double[] {r(2), r(3), r(4)}).containsExactly(2, 3, 4);
  }

  @Test
  void deletingThePausedLineResumesAtTheLineThatTookItsPlace() {
    pausedAtLine2("R[1]=1", "R[2]=2", "R[3]=3", "R[4]=4");
    keys("""
        F3
        2
        F4
        F4
        """);
    assertThat(lineCount()).isEqualTo(3);
    assertThat(control.status()).isEqualTo(new org.robotrun.control.RobotControl.ExecutionStatus("EDT", 2, ExecState.PAUSED));
    keys("""
        HOLD DEADMAN
        STEP
        HOLD SHIFT
        FWD
        WAIT 0.5
        RELEASE SHIFT
        """);
    assertThat(control.status().state()).isEqualTo(ExecState.IDLE);
    assertThat(new double[] {r(2), r(3), r(4)}).containsExactly(0, 3, 4);
  }

  @Test
  void anEditedCallerIsReturnedToBelowItsCallInTheNewVersion() {
    store("SUB", "R[10]=1", "R[11]=1");
    keys("""
        SELECT
        F1
        TYPE EDT
        ENTER
        """);
    store("EDT", "CALL SUB", "R[2]=2", "R[3]=3");
    keys("""
        HOLD DEADMAN
        ITEM
        TYPE 1
        ENTER
        STEP
        HOLD SHIFT
        FWD
        WAIT 0.2
        RELEASE SHIFT
        """);
    // STEP goes into the callee: paused on SUB line 1, EDT waits for the return
    assertThat(control.status()).isEqualTo(new org.robotrun.control.RobotControl.ExecutionStatus("SUB", 1, ExecState.PAUSED));
    // the caller gains a line above the CALL (must not run) and one right after it (must run)
    store("EDT", "R[6]=6", "CALL SUB", "R[5]=5", "R[2]=2", "R[3]=3");
    assertThat(control.deleteProgram("EDT")).isInstanceOf(org.robotrun.control.RobotControl.Result.Refused.class);
    keys("""
        HOLD DEADMAN
        STEP
        HOLD SHIFT
        FWD
        WAIT 0.5
        RELEASE SHIFT
        """);
    assertThat(control.status()).isEqualTo(new org.robotrun.control.RobotControl.ExecutionStatus("EDT", 5, ExecState.IDLE));
    assertThat(p.lcd().alarmLine()).isBlank();
    assertThat(new double[] {r(10), r(11), r(5), r(2), r(3), r(6)}).containsExactly(1, 1, 5, 2, 3, 0);
  }
}
