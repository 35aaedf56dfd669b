package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;
import static org.robotrun.sim.TaskProgs.program;
import static org.robotrun.sim.TaskProgs.steps;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.Result;
import org.robotrun.math.Xyzwpr;
import org.robotrun.motion.JogState;
import org.robotrun.program.Config;
import org.robotrun.program.Position;

/**
 * The controller's own rules, each from its documentation: when SHIFT+FWD is refused and what a
 * paused run does with a new line (docs/tp-execution.md), MOVE_TO's refusals, the incremental jog
 * sizes of docs/pendant.md (FINE 0.023 mm / 0.001°, VFINE 0.002 mm / 0.0001°), the E-stops and
 * RESET (docs/alarms.md), where an alarm from outside names the program, the alarm history and
 * warning lists, deleting programs, the override range and the cycle time.
 */
class ControllerRulesTest {

  private static String reason(Result r) {
    assertThat(r).isInstanceOf(Result.Refused.class);
    return ((Result.Refused) r).reason();
  }

  private static String message(Result r) {
    assertThat(r).isInstanceOf(Result.Ok.class);
    return ((Result.Ok) r).message();
  }

  @Test
  void shiftFwdIsRefusedOutsideTheProgramsLinesAndForAMissingProgram() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "R[1]=R[1]+1", "R[2]=R[2]+1", "R[3]=R[3]+1"));
    assertThat(reason(c.run("MAIN", 0, true))).isEqualTo("line 0 is not in MAIN (1..3)");
    assertThat(reason(c.run("MAIN", 4, true))).isEqualTo("line 4 is not in MAIN (1..3)");
    assertThat(reason(c.run("NONE", 1, true))).isEqualTo("no program NONE");
    assertThat(c.run("MAIN", 3, true)).isInstanceOf(Result.Ok.class);
    steps(sim, 2);
    assertThat(c.registers().number(3)).isEqualTo(1);
    assertThat(c.registers().number(1)).isZero();
    // an empty program may be started at line 1
    c.saveProgram(program("EMPTY", false));
    assertThat(c.run("EMPTY", 1, true)).isInstanceOf(Result.Ok.class);
    assertThat(reason(c.run("EMPTY", 2, true))).contains("line 2 is not in EMPTY");
  }

  @Test
  void aRunningProgramRefusesAnotherStartAndAPausedOneGoesOnFromTheLineChosen() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "R[1]=R[1]+1", "WAIT 0.10(sec)", "PAUSE", "R[2]=R[2]+1", "R[3]=R[3]+1"));
    c.saveProgram(program("OTHER", false, "R[9]=1"));
    c.run("MAIN", 1, true);
    steps(sim, 2);
    assertThat(reason(c.run("OTHER", 1, true))).isEqualTo("MAIN is running");
    assertThat(reason(c.run("MAIN", 1, true))).isEqualTo("MAIN is running");
    steps(sim, 40);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    assertThat(c.status().line()).isEqualTo(4);
    assertThat(c.busy()).isTrue();
    assertThat(reason(c.run("OTHER", 1, true))).isEqualTo("MAIN is paused: ABORT it first");
    assertThat(c.registers().number(9)).isZero();
    // SHIFT+FWD on line 5 of the paused program: it goes on from there (line 4 is skipped)
    assertThat(c.run("MAIN", 5, true)).isInstanceOf(Result.Ok.class);
    steps(sim, 3);
    assertThat(c.registers().number(2)).isZero();
    assertThat(c.registers().number(3)).isEqualTo(1);
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(c.busy()).isFalse();
  }

  @Test
  void deletingAProgramIsRefusedWhileItIsActiveOrMissing() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("SUB", false, "WAIT 0.20(sec)"));
    c.saveProgram(program("MAIN", false, "CALL SUB"));
    c.saveProgram(program("SPARE", false, "R[1]=1"));
    c.run("MAIN", 1, true);
    steps(sim, 3);
    assertThat(reason(c.deleteProgram("SUB"))).isEqualTo("SUB is running or paused: ABORT it first");
    assertThat(reason(c.deleteProgram("MAIN"))).contains("MAIN is running or paused");
    c.hold();
    assertThat(reason(c.deleteProgram("SUB"))).contains("ABORT it first");
    assertThat(c.deleteProgram("SPARE")).isInstanceOf(Result.Ok.class);
    assertThat(c.programNames()).containsExactly("MAIN", "SUB");
    assertThat(reason(c.deleteProgram("SPARE"))).isEqualTo("no program SPARE");
    c.abort();
    assertThat(c.deleteProgram("SUB")).isInstanceOf(Result.Ok.class);
    assertThat(c.program("SUB")).isEmpty();
  }

  @Test
  void registerCommentsArePerTableAndIndex() {
    Controller c = ControllerTest.cell().controllers().get(0);
    assertThat(c.registerComment("R", 3)).isEmpty();
    c.setRegisterComment("R", 3, "count");
    c.setRegisterComment("PR", 4, "above pick");
    assertThat(c.registerComment("R", 3)).isEqualTo("count");
    assertThat(c.registerComment("PR", 3)).isEmpty();
    assertThat(c.registerComment("R", 4)).isEmpty();
    assertThat(c.registerComment("PR", 4)).isEqualTo("above pick");
  }

  @Test
  void incrementalJogStepsAreThePendantsFineAndVeryFineSizes() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.setMode(RobotControl.Mode.T1);
    double j1 = c.currentJoints().element(1);
    double j6 = c.currentJoints().element(6);
    assertThat(message(c.jogIncrement(1, +1, false))).startsWith("FINE step:").contains("0.001 deg");
    assertThat(c.currentJoints().element(1)).isCloseTo(j1 + 0.001, within(1e-9));
    assertThat(message(c.jogIncrement(6, -1, true))).startsWith("VFINE step:").contains("0.0001 deg");
    assertThat(c.currentJoints().element(6)).isCloseTo(j6 - 0.0001, within(1e-9));
    assertThat(c.currentJoints().element(1)).isCloseTo(j1 + 0.001, within(1e-9));
    // WORLD: X, Y, Z in mm
    c.setCoordSystem(RobotControl.CoordSystem.WORLD);
    assertThat(c.coordSystem()).isEqualTo(RobotControl.CoordSystem.WORLD);
    Xyzwpr before = c.tcpInWorld();
    assertThat(message(c.jogIncrement(1, +1, false))).contains("0.023 mm");
    Xyzwpr after = c.tcpInWorld();
    assertThat(after.x() - before.x()).isCloseTo(0.023, within(1e-6));
    assertThat(after.y()).isCloseTo(before.y(), within(1e-6));
    assertThat(after.z()).isCloseTo(before.z(), within(1e-6));
    assertThat(message(c.jogIncrement(3, -1, true))).contains("0.002 mm");
    Xyzwpr down = c.tcpInWorld();
    assertThat(down.z() - after.z()).isCloseTo(-0.002, within(1e-6));
    assertThat(down.x()).isCloseTo(after.x(), within(1e-6));
    // a rotation in WORLD is in degrees
    assertThat(message(c.jogIncrement(4, +1, false))).contains("0.001 deg");
    // refused in AUTO, without the DEADMAN, with an alarm
    c.setMode(RobotControl.Mode.AUTO);
    assertThat(reason(c.jogIncrement(1, +1, false))).contains("AUTO");
    c.setMode(RobotControl.Mode.T2);
    c.setDeadman(false);
    assertThat(reason(c.jogIncrement(1, +1, false))).contains("DEADMAN");
    c.setDeadman(true);
    c.raiseAlarm("SRVO-050", "Collision Detect alarm");
    assertThat(reason(c.jogIncrement(1, +1, false))).contains("RESET");
    assertThat(c.tcpInWorld().x()).isCloseTo(down.x(), within(1e-6));
  }

  @Test
  void jogKeysNeedTheDeadmanAndNoProgramMotionAndLettingGoStopsThem() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.setMode(RobotControl.Mode.T1);
    assertThat(c.jogKeyDown(2, -1, JogState.Press.LATCHED)).isInstanceOf(Result.Ok.class);
    assertThat(c.jogDirection(2)).isEqualTo(-1);
    assertThat(c.jogDirection(1)).isZero();
    c.jogKeyUp(2, -1); // a latched key goes on
    assertThat(c.jogDirection(2)).isEqualTo(-1);
    c.jogStop();
    assertThat(c.jogDirection(2)).isZero();
    c.jogKeyDown(1, +1, JogState.Press.HELD);
    c.jogKeyUp(1, +1);
    assertThat(c.jogDirection(1)).isZero();
    c.jogKeyDown(3, +1, JogState.Press.LATCHED);
    c.setDeadman(false);
    assertThat(c.deadman()).isFalse();
    assertThat(c.jogDirection(3)).isZero();
    c.setDeadman(true);
    // a coordinate change stops every axis; the same one does not
    c.jogKeyDown(3, +1, JogState.Press.LATCHED);
    c.setCoordSystem(RobotControl.CoordSystem.JOINT);
    assertThat(c.jogDirection(3)).isEqualTo(1);
    c.setCoordSystem(RobotControl.CoordSystem.TOOL);
    assertThat(c.jogDirection(3)).isZero();
    // an E-stop refuses a jog
    c.emergencyStop(true);
    assertThat(reason(c.jogKeyDown(1, +1, JogState.Press.HELD))).contains("RESET");
    c.releaseEmergencyStop();
    c.reset();
    // a program moving the arm refuses it
    c.saveProgram(ControllerTest.jointProgram("AWAY", "J P[2] 10% FINE", new double[] {0, 0, 0, 0, -90, 0},
        new double[] {30, 0, 0, 0, -90, 0}));
    c.run("AWAY", 1, true);
    steps(sim, 5);
    assertThat(reason(c.jogKeyDown(1, +1, JogState.Press.HELD))).contains("cannot jog while the robot moves");
  }

  @Test
  void moveToIsRefusedWithAnAlarmARunningProgramAnUnreachableTargetOrOneOutsideTheLimits() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    assertThat(reason(c.moveTo(new Position.Joint(0, 500, 0, 0, -90, 0), 0, 0)))
        .isEqualTo("J2 would be outside its limits");
    assertThat(reason(c.moveTo(new Position.Joint(0, 0, 0, 0, -90, 1000), 0, 0)))
        .isEqualTo("J6 would be outside its limits");
    assertThat(reason(c.moveTo(Position.Cartesian.of(Xyzwpr.ofDegrees(5000, 0, 0, 180, 0, 0), Config.DEFAULT), 0, 0)))
        .startsWith("unreachable: ");
    c.saveProgram(program("MAIN", false, "WAIT 0.20(sec)"));
    c.run("MAIN", 1, true);
    steps(sim, 2);
    assertThat(reason(c.moveTo(new Position.Joint(5, 0, 0, 0, -90, 0), 0, 0))).contains("HOLD it first");
    c.abort();
    c.raiseAlarm("SRVO-050", "Collision Detect alarm");
    assertThat(reason(c.moveTo(new Position.Joint(5, 0, 0, 0, -90, 0), 0, 0))).contains("RESET first");
    c.reset();
    // MOVE_TO while one still moves is refused; a held one is replaced
    assertThat(c.moveTo(new Position.Joint(40, 0, 0, 0, -90, 0), 0, 0)).isInstanceOf(Result.Ok.class);
    steps(sim, 20);
    assertThat(reason(c.moveTo(new Position.Joint(-40, 0, 0, 0, -90, 0), 0, 0))).contains("moving");
    c.hold();
    steps(sim, 200);
    double held = c.currentJoints().element(1);
    assertThat(held).isBetween(0.1, 39.9);
    assertThat(c.moveTo(new Position.Joint(-10, 0, 0, 0, -90, 0), 0, 0)).isInstanceOf(Result.Ok.class);
    steps(sim, 1500);
    assertThat(c.currentJoints().element(1)).isCloseTo(-10, within(1e-6));
    // a Cartesian target is taken in the frames given
    Position.Cartesian here = c.currentPose(0, 0);
    Xyzwpr h = here.toXyzwpr();
    Position.Cartesian lower = Position.Cartesian.of(Xyzwpr.ofDegrees(h.x(), h.y(), h.z() - 30, h.wDeg(), h.pDeg(),
        h.rDeg()), here.config());
    assertThat(c.moveTo(lower, 0, 0)).isInstanceOf(Result.Ok.class);
    steps(sim, 1500);
    assertThat(c.currentPose(0, 0).toXyzwpr().z()).isCloseTo(h.z() - 30, within(1e-3));
  }

  @Test
  void eStopsAreSrvo001And002OnceEachAndResetWaitsForTheirRelease() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "WAIT 1.00(sec)", "R[1]=1"));
    c.run("MAIN", 1, true);
    steps(sim, 2);
    c.emergencyStop(true);
    c.emergencyStop(true);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-002");
    assertThat(c.activeAlarms().get(0).program()).isEqualTo("MAIN");
    assertThat(c.activeAlarms().get(0).line()).isEqualTo(1);
    assertThat(c.status().state()).isNotEqualTo(ExecutionStatus.State.RUNNING);
    c.emergencyStop(false);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-002", "SRVO-001");
    assertThat(c.estopped()).isTrue();
    assertThat(reason(c.run("MAIN", 1, true))).contains("E-stop pressed");
    c.reset();
    assertThat(c.activeAlarms()).hasSize(2);
    c.releaseEmergencyStop();
    assertThat(c.estopped()).isFalse();
    assertThat(reason(c.run("MAIN", 1, true))).startsWith("alarm active: RESET first (SRVO-002 (MAIN, 1)");
    c.reset();
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.alarmHistory()).extracting(ControllerAlarm::code).containsExactly("SRVO-001", "SRVO-002");
    assertThat(c.run("MAIN", 1, true)).isInstanceOf(Result.Ok.class);
    steps(sim, 300);
    assertThat(c.registers().number(1)).isEqualTo(1);
  }

  @Test
  void anAlarmFromOutsideNamesTheRunningProgramsLineOrNothing() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.raiseAlarm("SRVO-050", "Collision Detect alarm");
    assertThat(c.activeAlarms().get(0).program()).isEmpty();
    assertThat(c.activeAlarms().get(0).line()).isZero();
    assertThat(c.activeAlarms().get(0).display()).isEqualTo("SRVO-050 Collision Detect alarm");
    c.reset();
    c.saveProgram(program("MAIN", false, "R[1]=1", "WAIT 1.00(sec)", "R[2]=1"));
    c.run("MAIN", 1, true);
    steps(sim, 3);
    c.raiseAlarm("SRVO-050", "Collision Detect alarm");
    assertThat(c.activeAlarms().get(0).program()).isEqualTo("MAIN");
    assertThat(c.activeAlarms().get(0).line()).isEqualTo(2);
    assertThat(c.activeAlarms().get(0).simTimeSec()).isCloseTo(sim.timeSec(), within(1e-9));
    steps(sim, 300);
    assertThat(c.registers().number(2)).isZero();
    // while paused too
    c.reset();
    c.hold();
    c.raiseAlarm("SRVO-050", "again");
    assertThat(c.activeAlarms().get(0).program()).isEqualTo("MAIN");
  }

  @Test
  void theHistoryKeepsTheNewestHundredAndTheWarningsTheNewestThousand() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    for (int k = 1; k <= 105; k++) {
      c.raiseAlarm("SRVO-050", "hit " + k);
    }
    assertThat(c.activeAlarms()).hasSize(105);
    assertThat(c.hasActiveAlarm()).isTrue();
    assertThat(c.alarmHistory()).hasSize(100);
    assertThat(c.alarmHistory().get(0).message()).isEqualTo("hit 105");
    assertThat(c.alarmHistory().get(99).message()).isEqualTo("hit 6");
    c.clearAlarmHistory();
    assertThat(c.alarmHistory()).isEmpty();
    c.reset();
    assertThat(c.hasActiveAlarm()).isFalse();
    for (int k = 1; k <= 1001; k++) {
      c.raiseRunFailed("try " + k);
    }
    assertThat(c.warnings()).hasSize(1000);
    assertThat(c.warnings().get(0).message()).endsWith("try 2");
    assertThat(c.warnings().get(999).message()).endsWith("try 1001");
    assertThat(c.alarmHistory()).hasSize(100);
    assertThat(c.alarmHistory().get(0).message()).endsWith("try 1001");
    assertThat(c.shownWarning()).get().extracting(ControllerAlarm::message).asString().endsWith("try 1001");
    assertThat(c.activeAlarms()).isEmpty();
    c.reset();
    assertThat(c.shownWarning()).isEmpty();
    assertThat(c.warnings()).hasSize(1000);
  }

  @Test
  void theOverrideIsOneToAHundredPercent() {
    Controller c = ControllerTest.cell().controllers().get(0);
    assertThatThrownBy(() -> c.setOverridePct(0)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> c.setOverridePct(101)).isInstanceOf(IllegalArgumentException.class);
    c.setOverridePct(1);
    assertThat(c.overridePct()).isEqualTo(1);
    c.setOverridePct(100);
    assertThat(c.overridePct()).isEqualTo(100);
  }

  @Test
  void turningTheModeSwitchPausesARunningProgramButTheSameModeDoesNot() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "WAIT 0.50(sec)", "R[1]=1"));
    c.run("MAIN", 1, true);
    steps(sim, 2);
    c.setMode(RobotControl.Mode.AUTO);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.RUNNING);
    c.setMode(RobotControl.Mode.T2);
    assertThat(c.mode()).isEqualTo(RobotControl.Mode.T2);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
  }

  @Test
  void theCycleTimeRunsFromTheStartToTheEndAndAnAlarmedRunHasNone() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    assertThat(c.lastCycleTimeSec()).isNaN();
    steps(sim, 50); // the run starts 0.2 s after the controller did
    c.saveProgram(program("MAIN", false, "WAIT 0.20(sec)"));
    c.run("MAIN", 1, true);
    steps(sim, 100);
    double t = c.lastCycleTimeSec();
    assertThat(t).isBetween(0.2, 0.2 + 2 * Simulation.DEFAULT_TICK_SEC + 1e-9);
    c.saveProgram(program("BAD", false, "WAIT 0.20(sec)", "R[1]=1/R[2]"));
    c.run("BAD", 1, true);
    steps(sim, 100);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SIMU-001");
    c.reset();
    steps(sim, 5);
    assertThat(c.lastCycleTimeSec()).isEqualTo(t);
    // ABORT ends the program (docs/alarms.md): after RESET it is ended, the cursor on the alarm's line
    assertThat(c.status()).isEqualTo(new ExecutionStatus("BAD", 2, ExecutionStatus.State.IDLE));
  }

  @Test
  void anEditToAPausedProgramIsWhatRunsOnResume() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "R[1]=1", "PAUSE", "R[2]=2"));
    c.run("MAIN", 1, true);
    steps(sim, 3);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    c.saveProgram(program("MAIN", false, "R[1]=1", "PAUSE", "R[2]=20"));
    c.run("MAIN", c.status().line(), true);
    steps(sim, 3);
    assertThat(c.registers().number(2)).isEqualTo(20);
  }

  @Test
  void theProductionSetupBringsItsBgLogicSlotsAndScanPeriod() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("BG", false, "R[1]=R[1]+1"));
    org.robotrun.world.ProductionSetup.Robot d = org.robotrun.world.ProductionSetup.Robot.defaults();
    c.configureProduction(new org.robotrun.world.ProductionSetup.Robot(true, true, d.selection(), 0, 0, d.rsrNumbers(),
        d.styles(), 0.2, false, false, java.util.Optional.empty(), java.util.List.of(), java.util.List.of("BG"), 0.020,
        java.util.List.of(), false));
    assertThat(c.bgLogic().scanSec()).isEqualTo(0.020);
    steps(sim, 50); // 0.2 s: 10 scans of 20 ms
    assertThat(c.registers().number(1)).isEqualTo(10);
  }

  @Test
  void anAlarmFromOutsideHoldsTheTasksTooAndOnlyAServoAlarmTurnsTheServoOff() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("TICKER", false, "LBL[1]", "R[5]=R[5]+1", "WAIT 0.04(sec)", "JMP LBL[1]"));
    c.saveProgram(program("MAIN", false, "RUN TICKER", "WAIT 5.00(sec)"));
    c.run("MAIN", 1, true);
    steps(sim, 20);
    c.raiseAlarm("SRVO-050", "Collision Detect alarm");
    assertThat(c.tasks().list().get(0).status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    double n = c.registers().number(5);
    steps(sim, 30);
    assertThat(c.registers().number(5)).isEqualTo(n);
    assertThat(c.servoOff()).isTrue();
    c.reset();
    // an ABORT-severity program alarm is no servo alarm: SYSRDY stays on
    c.abort();
    c.saveProgram(program("BAD", false, "R[1]=1/R[2]"));
    c.run("BAD", 1, true);
    steps(sim, 2);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SIMU-001");
    assertThat(c.servoOff()).isFalse();
    assertThat(c.uop().uo(Uop.SYSRDY)).isTrue();
  }

  @Test
  void userAndJogFrameJogsGoAlongTheirFramesAxes() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.setMode(RobotControl.Mode.T1);
    // UFRAME[1] (active) turned 90 deg about z: its X is WORLD +Y; JOGFRAME[1] turned -90 deg: its X is WORLD -Y
    c.frames().setTransform(org.robotrun.program.Instruction.FrameKind.USER, 1,
        org.robotrun.math.Transform.rotation(0, 0, 1, Math.PI / 2));
    c.frames().setJogFrame(1, Position.Cartesian.of(Xyzwpr.ofDegrees(0, 0, 0, 0, 0, -90), Config.DEFAULT));
    c.setCoordSystem(RobotControl.CoordSystem.USER);
    Xyzwpr a = c.tcpInWorld();
    c.jogIncrement(1, +1, false);
    Xyzwpr b = c.tcpInWorld();
    assertThat(b.y() - a.y()).isCloseTo(0.023, within(1e-6));
    assertThat(b.x() - a.x()).isCloseTo(0, within(1e-6));
    c.setCoordSystem(RobotControl.CoordSystem.JGFRM);
    c.jogIncrement(1, +1, false);
    Xyzwpr d = c.tcpInWorld();
    assertThat(d.y() - b.y()).isCloseTo(-0.023, within(1e-6));
    assertThat(d.x() - b.x()).isCloseTo(0, within(1e-6));
  }
}
