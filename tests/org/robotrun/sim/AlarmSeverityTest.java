package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.program.AlarmCode;
import org.robotrun.program.AlarmSeverity;
import org.robotrun.program.Program;

/**
 * The program follows the alarm's severity (docs/alarms.md): a STOP-severity motion fault
 * (MOTN-017) pauses the program on the faulty line with its call stack; RESET then SHIFT+FWD
 * runs that line again and returns to the caller. An ABORT-severity fault ends the program.
 */
class AlarmSeverityTest {

  private static Program main(String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  MAIN\n/ATTR\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format(java.util.Locale.ROOT, "%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\n/END\n");
    LsReadResult r = LsReader.parse("MAIN.LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    return r.program();
  }

  private static void stepWhileRunning(Simulation sim, Controller c) {
    for (int i = 0; i < 20_000 && c.status().state() == ExecutionStatus.State.RUNNING; i++) {
      sim.step();
    }
  }

  @Test
  void motionFaultsAreStopSeverity() {
    assertThat(AlarmCode.MOTN_017.severity()).isEqualTo(AlarmSeverity.STOP);
    assertThat(AlarmCode.MOTN_018.severity()).isEqualTo(AlarmSeverity.STOP);
    assertThat(AlarmCode.MOTN_023.severity()).isEqualTo(AlarmSeverity.STOP);
  }

  @Test
  void jointLimitInACalledProgramPausesThereAndResumesAfterTheFix() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(ControllerTest.jointProgram("SUB", "J P[2] 50% FINE", new double[] {0, 0, 0, 0, -90, 0},
        new double[] {0, 0, 0, 0, -140, 0}));
    c.saveProgram(main("CALL SUB", "R[1]=R[1]+1"));
    assertThat(c.run("MAIN", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    stepWhileRunning(sim, c);

    // paused (alarmed) on SUB line 2, the caller still on the stack; the arm stands at P[1]
    assertThat(c.activeAlarms()).hasSize(1);
    assertThat(c.activeAlarms().get(0).code()).isEqualTo("MOTN-017");
    assertThat(c.status()).isEqualTo(new ExecutionStatus("SUB", 2, ExecutionStatus.State.ALARMED));
    assertThat(c.interpreter().callDepth()).isEqualTo(2);
    assertThat(c.currentJoints().j5Deg()).isCloseTo(-90, offset(1e-6));
    assertThat(c.run("SUB", 2, true)).isInstanceOf(RobotControl.Result.Refused.class);

    c.reset();
    assertThat(c.status()).isEqualTo(new ExecutionStatus("SUB", 2, ExecutionStatus.State.PAUSED));
    assertThat(c.interpreter().callDepth()).isEqualTo(2);

    // resuming without a fix runs the same line into the same alarm, still paused in SUB
    c.run("SUB", 2, true);
    stepWhileRunning(sim, c);
    assertThat(c.status()).isEqualTo(new ExecutionStatus("SUB", 2, ExecutionStatus.State.ALARMED));
    assertThat(c.interpreter().callDepth()).isEqualTo(2);
    c.reset();

    // the student re-teaches P[2] inside the limits; SHIFT+FWD re-runs line 2, SUB returns to MAIN
    c.saveProgram(ControllerTest.jointProgram("SUB", "J P[2] 50% FINE", new double[] {0, 0, 0, 0, -90, 0},
        new double[] {0, 0, 0, 0, -120, 0}));
    assertThat(c.run("SUB", 2, true)).isInstanceOf(RobotControl.Result.Ok.class);
    stepWhileRunning(sim, c);
    for (int i = 0; i < 2_000 && c.busy(); i++) {
      sim.step();
    }
    assertThat(c.hasActiveAlarm()).isFalse();
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(c.status().program()).isEqualTo("MAIN");
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.currentJoints().j5Deg()).isCloseTo(-120, offset(1e-6));
  }

  @Test
  void fctnAbortEndsAProgramAStopAlarmPaused() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(ControllerTest.jointProgram("SUB", "J P[2] 50% FINE", new double[] {0, 0, 0, 0, -90, 0},
        new double[] {0, 0, 0, 0, -140, 0}));
    c.saveProgram(main("CALL SUB", "R[1]=R[1]+1"));
    c.run("MAIN", 1, true);
    stepWhileRunning(sim, c);
    assertThat(c.interpreter().callDepth()).isEqualTo(2);
    c.abort();
    assertThat(c.interpreter().callDepth()).isZero();
    assertThat(c.hasActiveAlarm()).as("the alarm stays shown until RESET").isTrue();
    c.reset();
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    // a new start runs MAIN from line 1 again
    assertThat(c.run("MAIN", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    stepWhileRunning(sim, c);
    assertThat(c.status()).isEqualTo(new ExecutionStatus("SUB", 2, ExecutionStatus.State.ALARMED));
  }

  @Test
  void abortSeverityEndsTheProgramAndLosesTheCallStack() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(ControllerTest.jointProgram("SUB", "R[2]=1/R[3]", new double[] {0, 0, 0, 0, -90, 0}));
    c.saveProgram(main("CALL SUB", "R[1]=R[1]+1"));
    c.run("MAIN", 1, true);
    stepWhileRunning(sim, c);
    assertThat(c.activeAlarms().get(0).code()).isEqualTo("SIMU-001");
    assertThat(AlarmCode.SIMU_001.severity()).isEqualTo(AlarmSeverity.ABORT);
    assertThat(c.interpreter().callDepth()).isZero();
    c.reset();
    assertThat(c.status()).isEqualTo(new ExecutionStatus("SUB", 2, ExecutionStatus.State.IDLE));
    assertThat(c.registers().number(1)).isZero();
  }

  @Test
  void headlessRunStillEndsWithAlarmOnAStopSeverityFault() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(ControllerTest.jointProgram("SUB", "J P[2] 50% FINE", new double[] {0, 0, 0, 0, -90, 0},
        new double[] {0, 0, 0, 0, -140, 0}));
    c.saveProgram(main("CALL SUB", "R[1]=R[1]+1"));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "MAIN", 60, s -> {});
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.ALARM);
    assertThat(r.alarm().orElseThrow().code()).isEqualTo("MOTN-017");
    assertThat(r.alarm().orElseThrow().program()).isEqualTo("SUB");
    assertThat(r.alarm().orElseThrow().line()).isEqualTo(2);
  }
}
