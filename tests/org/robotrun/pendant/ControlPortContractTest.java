package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.function.DoubleConsumer;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.CoordSystem;
import org.robotrun.control.RobotControl.ExecState;
import org.robotrun.control.RobotControl.Mode;
import org.robotrun.control.RobotControl.Result;
import org.robotrun.control.RobotControl.StartFrom;
import org.robotrun.io.LsReader;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/**
 * The control port's contract on the real controller ({@code sim.ControllerPort} on the default
 * cell, as {@link RealController} makes it): what the pendant relies on at the port itself, keys
 * aside (switch decisions with their reasons, alarm codes, execution states, data). These cases
 * once also ran on a stand-in controller, to keep it in step; every pendant test now runs on the
 * real one, so the stand-in is gone.
 */
class ControlPortContractTest {
  private final RobotControl c = RealController.control();
  private final DoubleConsumer clock = RealController.clock(c);

  private static Program waits() {
    String text = "/PROG  WAITS\n/ATTR\n/MN\n   1:  WAIT   1.00(sec) ;\n   2:  WAIT   1.00(sec) ;\n/POS\n/END\n";
    return LsReader.parse("WAITS.LS", text).program();
  }

  private static String reason(Result r) {
    return r instanceof Result.Refused no ? no.reason() : "";
  }

  @Test
  void aPendantInHandStartsInT1WithTheTpEnabledAndNothingHeld() {
    assertThat(c.mode()).isEqualTo(Mode.T1);
    assertThat(c.tpEnabled()).isTrue();
    assertThat(c.deadmanHeld()).isFalse();
    assertThat(c.shiftHeld()).isFalse();
    assertThat(c.coordSystem()).isEqualTo(CoordSystem.JOINT);
    assertThat(c.status().state()).isEqualTo(ExecState.IDLE);
    assertThat(c.activeAlarm()).isEmpty();
    assertThat(c.emergencyStopped()).isFalse();
  }

  @Test
  void aJogGoesOnlyWithEverySwitchRightAndSaysWhyNot() {
    assertThat(reason(c.jogKeyDown(1, 1, false))).isEqualTo("Hold the DEADMAN to jog");
    c.setDeadman(true);
    assertThat(reason(c.jogKeyDown(1, 1, false))).isEqualTo("Hold SHIFT and the DEADMAN to jog");
    c.setShift(true);
    c.setTpEnabled(false);
    assertThat(reason(c.jogKeyDown(1, 1, false))).isEqualTo("TP disabled: turn TP ENABLE on to jog");
    c.setTpEnabled(true);
    c.setMode(Mode.AUTO);
    assertThat(reason(c.jogKeyDown(1, 1, false))).isEqualTo("AUTO mode: the pendant cannot jog (mode switch to T1)");
    c.setMode(Mode.T1);
    double before = c.currentJoints().j1Deg();
    assertThat(c.jogKeyDown(1, 1, false)).isInstanceOf(Result.Ok.class);
    clock.accept(0.2);
    // 0.2 s of J1 at 100 % in T1, worked out by hand (ArmByHand): T1 caps the pointer's tip at HOME's radius
    double[] range = ArmByHand.jointJogRange(1, ArmByHand.radiusFromJ1(ArmByHand.tcp(ArmByHand.HOME)), 0.2);
    double moved = c.currentJoints().j1Deg();
    assertThat(moved - before).isBetween(range[0], range[1]);
    // SHIFT lets go: the jog stops, and the controller says so
    assertThat(c.setShift(false)).isEqualTo(new Result.Ok("Jog stopped: SHIFT released"));
    clock.accept(0.2);
    assertThat(c.currentJoints().j1Deg()).isEqualTo(moved);
  }

  @Test
  void lettingTheDeadmanGoWithTheTpEnabledIsSrvo003UntilReset() {
    c.setDeadman(true);
    Result r = c.setDeadman(false);
    assertThat(r).isEqualTo(new Result.Ok("SRVO-003 Deadman switch released (hold DEADMAN, RESET)"));
    assertThat(c.activeAlarm()).hasValueSatisfying(a -> assertThat(a.code()).isEqualTo("SRVO-003"));
    c.reset();
    assertThat(c.activeAlarm()).isEmpty();
    // with the TP disabled the DEADMAN means nothing
    c.setTpEnabled(false);
    c.setDeadman(true);
    assertThat(c.setDeadman(false)).isEqualTo(Result.ok());
    assertThat(c.activeAlarm()).isEmpty();
  }

  @Test
  void anEStopHoldsItsAlarmUntilReleasedAndReset() {
    c.emergencyStop(true);
    assertThat(c.emergencyStopped()).isTrue();
    assertThat(c.activeAlarm()).hasValueSatisfying(a -> assertThat(a.code()).isEqualTo("SRVO-002"));
    c.setDeadman(true);
    c.setShift(true);
    assertThat(reason(c.jogKeyDown(1, 1, false))).isEqualTo("E-stop pressed: release it and RESET");
    c.reset();
    assertThat(c.activeAlarm()).isPresent();
    c.releaseEmergencyStop();
    c.reset();
    assertThat(c.activeAlarm()).isEmpty();
    c.emergencyStop(false);
    assertThat(c.activeAlarm()).hasValueSatisfying(a -> assertThat(a.code()).isEqualTo("SRVO-001"));
  }

  @Test
  void inT1AProgramRunsOnlyWhileShiftIsHeld() {
    c.saveProgram(waits());
    assertThat(reason(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true))).isEqualTo("Hold SHIFT and press FWD to run");
    c.setShift(true);
    assertThat(reason(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true))).isEqualTo("Hold the DEADMAN to run");
    c.setDeadman(true);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true)).isInstanceOf(Result.Ok.class);
    clock.accept(0.1);
    assertThat(c.status().state()).isEqualTo(ExecState.RUNNING);
    assertThat(c.status().program()).isEqualTo("WAITS");
    assertThat(c.deleteProgram("WAITS")).isInstanceOf(Result.Refused.class);
    assertThat(c.setShift(false))
        .isEqualTo(new Result.Ok("Program paused: SHIFT released (hold-to-run in T1; SHIFT+FWD resumes)"));
    assertThat(c.status().state()).isEqualTo(ExecState.PAUSED);
    c.setShift(true);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", c.status().line(), true)).isInstanceOf(Result.Ok.class);
    clock.accept(2.5);
    assertThat(c.status().state()).isEqualTo(ExecState.IDLE);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "NOPE", 1, true)).isInstanceOf(Result.Refused.class);
  }

  @Test
  void cycleStartRunsInAutoWithTheTpDisabledOnly() {
    c.saveProgram(waits());
    assertThat(reason(c.mayStart(StartFrom.OPERATOR_PANEL, true)))
        .isEqualTo("CYCLE START works in AUTO: in T1 run from the pendant (SHIFT+FWD)");
    c.setMode(Mode.AUTO);
    assertThat(reason(c.run(StartFrom.OPERATOR_PANEL, "WAITS", 1, true)))
        .isEqualTo("CYCLE START refused: the TP is enabled (turn it OFF to run in AUTO)");
    c.setTpEnabled(false);
    assertThat(reason(c.mayStart(StartFrom.TEACH_PENDANT, true))).isEqualTo("Hold SHIFT and press FWD to run");
    assertThat(c.run(StartFrom.OPERATOR_PANEL, "WAITS", 1, true)).isInstanceOf(Result.Ok.class);
    clock.accept(1.0);
    assertThat(c.status().state()).isEqualTo(ExecState.RUNNING);
    // AUTO is not hold-to-run: nothing held, the program goes on to its end
    clock.accept(1.5);
    assertThat(c.status().state()).isEqualTo(ExecState.IDLE);
  }

  @Test
  void turningTheModeSwitchOrTheTpOffPausesARunningProgram() {
    c.saveProgram(waits());
    c.setDeadman(true);
    c.setShift(true);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true)).isInstanceOf(Result.Ok.class);
    clock.accept(0.1);
    c.setTpEnabled(false);
    assertThat(c.status().state()).isEqualTo(ExecState.PAUSED);
    c.setTpEnabled(true);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", c.status().line(), true)).isInstanceOf(Result.Ok.class);
    clock.accept(0.1);
    c.setMode(Mode.T2);
    assertThat(c.status().state()).isEqualTo(ExecState.PAUSED);
    c.abort();
    assertThat(c.status().state()).isIn(ExecState.ABORTED, ExecState.IDLE);
  }

  @Test
  void dataFramesOverrideAndStepModeAreKeptAsSet() {
    Position.Cartesian f = new Position.Cartesian(10, 20, 30, 0, 0, 90, Position.Cartesian.ZERO.config());
    c.setFrame(FrameKind.USER, 3, f);
    c.setFrameComment(FrameKind.USER, 3, "TABLE");
    c.selectFrame(FrameKind.USER, 3);
    assertThat(c.frame(FrameKind.USER, 3)).isEqualTo(f);
    assertThat(c.frameComment(FrameKind.USER, 3)).isEqualTo("TABLE");
    assertThat(c.activeFrame(FrameKind.USER)).isEqualTo(3);
    c.setComment(RobotControl.CommentTable.R, 5, "COUNT");
    assertThat(c.comment(RobotControl.CommentTable.R, 5)).isEqualTo("COUNT");
    c.setOverridePct(35);
    assertThat(c.overridePct()).isEqualTo(35);
    c.setStepMode(true);
    assertThat(c.stepMode()).isTrue();
    c.setCoordSystem(CoordSystem.WORLD);
    assertThat(c.coordSystem()).isEqualTo(CoordSystem.WORLD);
    c.saveProgram(waits());
    assertThat(c.programNames()).containsExactly("WAITS");
    assertThat(c.deleteProgram("WAITS")).isInstanceOf(Result.Ok.class);
    assertThat(c.programNames()).isEqualTo(List.of());
  }
}
