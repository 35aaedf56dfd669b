package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.sim.TaskProgs.program;
import static org.robotrun.sim.TaskProgs.steps;

import java.util.List;
import java.util.Optional;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.AlarmCode;
import org.robotrun.program.AlarmSeverity;
import org.robotrun.world.ProductionSetup;
import org.robotrun.world.ProductionSetup.Selection;

/**
 * Issue 26: a refused start (a PLC start, a RUN statement, a BG Logic slot) held the running main
 * program, though the controller lets it go on. The hold now follows the alarm's severity as
 * docs/alarms.md lists it: INTP-105 and INTP-267 are WARN (every program goes on); an alarm of any
 * other severity a task raises still holds the main program until RESET.
 */
class RefusedStartSeverityTest {

  private static ProductionSetup.Robot pns() {
    ProductionSetup.Robot d = ProductionSetup.Robot.defaults();
    return new ProductionSetup.Robot(true, true, Selection.PNS, 100, 0, List.of(0, 0, 0, 0, 0, 0, 0, 0),
        new TreeMap<>(), 0.2, false, false, Optional.empty(), List.of(), List.of(), d.bgScanSec(), List.of(), false);
  }

  /** A main program that counts in R[1] for ever (0.05 s a round). */
  private static Controller counting(Simulation sim) {
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", true, "LBL[1]", "R[1]=R[1]+1", "WAIT 0.05(sec)", "JMP LBL[1]"));
    assertThat(c.run("MAIN", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim, 10);
    return c;
  }

  private static void assertStillRunning(Simulation sim, Controller c, String code) {
    double before = c.registers().number(1);
    steps(sim, 100);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.RUNNING);
    assertThat(c.registers().number(1)).isGreaterThan(before);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.warnings()).extracting(ControllerAlarm::code).contains(code);
    assertThat(c.alarmHistory()).extracting(ControllerAlarm::code).contains(code);
    assertThat(c.uop().uo(Uop.FAULT)).isFalse();
    // the pendant's alarm line shows it until RESET
    ControllerPort port = new ControllerPort(c);
    assertThat(port.lastWarning()).get().extracting(RobotControl.AlarmEntry::code).isEqualTo(code);
    c.reset();
    assertThat(port.lastWarning()).isEmpty();
  }

  @Test
  void theSeveritiesOfARefusedStartAreWarnInTheCode() {
    assertThat(AlarmCode.INTP_105.severity()).isEqualTo(AlarmSeverity.WARN);
    assertThat(AlarmCode.INTP_267.severity()).isEqualTo(AlarmSeverity.WARN);
  }

  @Test
  void aPlcStartRefusedLeavesTheMainProgramRunning() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.configureProduction(pns());
    sim.step();
    c = counting(sim);
    Uop u = c.uop();
    // PNS 5 selects PNS0005, which does not exist: INTP-105
    u.setUi(Uop.SEL1, true);
    u.setUi(Uop.SEL1 + 2, true);
    u.setUi(Uop.PNSTROBE, true);
    sim.step();
    u.setUi(Uop.PROD_START, true);
    sim.step();
    u.setUi(Uop.PROD_START, false);
    steps(sim, 2);
    assertStillRunning(sim, c, "INTP-105");
  }

  @Test
  void aRunStatementRefusedLeavesItsProgramAndTheMainProgramRunning() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    // a task without a group RUNs a program that does not exist (MEMO-073), then counts in R[2]
    c.saveProgram(program("HELPER", false, "RUN GHOST", "R[2]=7"));
    c.saveProgram(program("MAIN", true, "RUN HELPER", "LBL[1]", "R[1]=R[1]+1", "WAIT 0.05(sec)", "JMP LBL[1]"));
    assertThat(c.run("MAIN", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim, 10);
    assertThat(c.registers().number(2)).isEqualTo(7);
    assertThat(c.warnings().get(0).program()).isEqualTo("HELPER");
    assertThat(c.warnings().get(0).line()).isEqualTo(1);
    assertStillRunning(sim, c, "INTP-267");
  }

  @Test
  void aBackgroundLogicRefusalLeavesTheMainProgramRunning() {
    Simulation sim = ControllerTest.cell();
    Controller c = counting(sim);
    c.bgLogic().configure(List.of("GHOST"));
    steps(sim, 3);
    assertThat(c.bgLogic().slots().get(0).running()).isFalse();
    assertStillRunning(sim, c, "INTP-105");
  }

  @Test
  void anAlarmOfAnotherSeverityInATaskStillHoldsTheMainProgram() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    // SIMU-001 (ABORT) in a task: the task ends, the main program is held until RESET
    c.saveProgram(program("BAD", false, "R[3]=1/R[4]"));
    c.saveProgram(program("MAIN", true, "RUN BAD", "LBL[1]", "R[1]=R[1]+1", "WAIT 0.05(sec)", "JMP LBL[1]"));
    assertThat(c.run("MAIN", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim, 10);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SIMU-001");
    double held = c.registers().number(1);
    steps(sim, 50);
    assertThat(c.registers().number(1)).isEqualTo(held);
    assertThat(c.status().state()).isNotEqualTo(ExecutionStatus.State.RUNNING);
    assertThat(c.warnings()).isEmpty();
  }
}
