package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.function.DoubleConsumer;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.CoordSystem;
import org.robotrun.control.RobotControl.ExecState;
import org.robotrun.control.RobotControl.Mode;
import org.robotrun.control.RobotControl.Result;
import org.robotrun.control.RobotControl.StartFrom;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.sim.CellStepper;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * The control port's contract, run on the real controller ({@code sim.ControllerPort}) and on the
 * pendant tests' light stand-in ({@link StandInRobotControl}): the same cases, the same answers
 * where the port promises them (switch decisions with their reasons, alarm codes, execution
 * states, data). Where the stand-in's toy arm differs (positions, the wording of the controller's
 * own refusals) only the kind of answer is compared.
 */
class ControlPortContractTest {
  /** A controller and the clock that advances it. */
  record Rig(String name, RobotControl control, DoubleConsumer clock) {
    @Override
    public String toString() {
      return name;
    }
  }

  static Stream<Arguments> rigs() {
    Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
    StandInRobotControl standIn = StandIn.control();
    return Stream.of(
        Arguments.of(new Rig("real controller", new ControllerPort(sim.controllers().get(0)), new CellStepper(sim)::advance)),
        Arguments.of(new Rig("stand-in", standIn, standIn::advance)));
  }

  private static Program waits() {
    String text = "/PROG  WAITS\n/ATTR\n/MN\n   1:  WAIT   1.00(sec) ;\n   2:  WAIT   1.00(sec) ;\n/POS\n/END\n";
    return LsReader.parse("WAITS.LS", text).program();
  }

  private static String reason(Result r) {
    return r instanceof Result.Refused no ? no.reason() : "";
  }

  @ParameterizedTest(name = "{0}")
  @MethodSource("rigs")
  void aPendantInHandStartsInT1WithTheTpEnabledAndNothingHeld(Rig rig) {
    RobotControl c = rig.control();
    assertThat(c.mode()).isEqualTo(Mode.T1);
    assertThat(c.tpEnabled()).isTrue();
    assertThat(c.deadmanHeld()).isFalse();
    assertThat(c.shiftHeld()).isFalse();
    assertThat(c.coordSystem()).isEqualTo(CoordSystem.JOINT);
    assertThat(c.status().state()).isEqualTo(ExecState.IDLE);
    assertThat(c.activeAlarm()).isEmpty();
    assertThat(c.emergencyStopped()).isFalse();
  }

  @ParameterizedTest(name = "{0}")
  @MethodSource("rigs")
  void aJogGoesOnlyWithEverySwitchRightAndTheReasonsAreTheSame(Rig rig) {
    RobotControl c = rig.control();
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
    rig.clock().accept(0.2);
    double moved = c.currentJoints().j1Deg();
    assertThat(moved).isGreaterThan(before);
    // SHIFT lets go: the jog stops, and the controller says so
    assertThat(c.setShift(false)).isEqualTo(new Result.Ok("Jog stopped: SHIFT released"));
    rig.clock().accept(0.2);
    assertThat(c.currentJoints().j1Deg()).isEqualTo(moved);
  }

  @ParameterizedTest(name = "{0}")
  @MethodSource("rigs")
  void lettingTheDeadmanGoWithTheTpEnabledIsSrvo003UntilReset(Rig rig) {
    RobotControl c = rig.control();
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

  @ParameterizedTest(name = "{0}")
  @MethodSource("rigs")
  void anEStopHoldsItsAlarmUntilReleasedAndReset(Rig rig) {
    RobotControl c = rig.control();
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

  @ParameterizedTest(name = "{0}")
  @MethodSource("rigs")
  void inT1AProgramRunsOnlyWhileShiftIsHeld(Rig rig) {
    RobotControl c = rig.control();
    c.saveProgram(waits());
    assertThat(reason(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true))).isEqualTo("Hold SHIFT and press FWD to run");
    c.setShift(true);
    assertThat(reason(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true))).isEqualTo("Hold the DEADMAN to run");
    c.setDeadman(true);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true)).isInstanceOf(Result.Ok.class);
    rig.clock().accept(0.1);
    assertThat(c.status().state()).isEqualTo(ExecState.RUNNING);
    assertThat(c.status().program()).isEqualTo("WAITS");
    assertThat(c.deleteProgram("WAITS")).isInstanceOf(Result.Refused.class);
    assertThat(c.setShift(false))
        .isEqualTo(new Result.Ok("Program paused: SHIFT released (hold-to-run in T1; SHIFT+FWD resumes)"));
    assertThat(c.status().state()).isEqualTo(ExecState.PAUSED);
    c.setShift(true);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", c.status().line(), true)).isInstanceOf(Result.Ok.class);
    rig.clock().accept(2.5);
    assertThat(c.status().state()).isEqualTo(ExecState.IDLE);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "NOPE", 1, true)).isInstanceOf(Result.Refused.class);
  }

  @ParameterizedTest(name = "{0}")
  @MethodSource("rigs")
  void cycleStartRunsInAutoWithTheTpDisabledOnly(Rig rig) {
    RobotControl c = rig.control();
    c.saveProgram(waits());
    assertThat(reason(c.mayStart(StartFrom.OPERATOR_PANEL, true)))
        .isEqualTo("CYCLE START works in AUTO: in T1 run from the pendant (SHIFT+FWD)");
    c.setMode(Mode.AUTO);
    assertThat(reason(c.run(StartFrom.OPERATOR_PANEL, "WAITS", 1, true)))
        .isEqualTo("CYCLE START refused: the TP is enabled (turn it OFF to run in AUTO)");
    c.setTpEnabled(false);
    assertThat(reason(c.mayStart(StartFrom.TEACH_PENDANT, true))).isEqualTo("Hold SHIFT and press FWD to run");
    assertThat(c.run(StartFrom.OPERATOR_PANEL, "WAITS", 1, true)).isInstanceOf(Result.Ok.class);
    rig.clock().accept(1.0);
    assertThat(c.status().state()).isEqualTo(ExecState.RUNNING);
    // AUTO is not hold-to-run: nothing held, the program goes on to its end
    rig.clock().accept(1.5);
    assertThat(c.status().state()).isEqualTo(ExecState.IDLE);
  }

  @ParameterizedTest(name = "{0}")
  @MethodSource("rigs")
  void turningTheModeSwitchOrTheTpOffPausesARunningProgram(Rig rig) {
    RobotControl c = rig.control();
    c.saveProgram(waits());
    c.setDeadman(true);
    c.setShift(true);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true)).isInstanceOf(Result.Ok.class);
    rig.clock().accept(0.1);
    c.setTpEnabled(false);
    assertThat(c.status().state()).isEqualTo(ExecState.PAUSED);
    c.setTpEnabled(true);
    assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", c.status().line(), true)).isInstanceOf(Result.Ok.class);
    rig.clock().accept(0.1);
    c.setMode(Mode.T2);
    assertThat(c.status().state()).isEqualTo(ExecState.PAUSED);
    c.abort();
    assertThat(c.status().state()).isIn(ExecState.ABORTED, ExecState.IDLE);
  }

  @ParameterizedTest(name = "{0}")
  @MethodSource("rigs")
  void dataFramesOverrideAndStepModeAreKeptAsSet(Rig rig) {
    RobotControl c = rig.control();
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
