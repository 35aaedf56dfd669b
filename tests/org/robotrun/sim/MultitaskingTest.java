package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.sim.TaskProgs.program;
import static org.robotrun.sim.TaskProgs.steps;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.IoKind;

/**
 * RUN starts a task beside the main program, as on an R-30iB: tasks share registers and I/O, a
 * task without a motion group runs while the main program moves, two tasks never hold group 1
 * (INTP-267, cause PROG-040), and RUN of a running program fails with INTP-267 (cause PROG-007).
 */
class MultitaskingTest {

  @Test
  void runStartsATaskThatRunsBesideTheMovingMainProgramAndSharesRegisters() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    // the task counts in R[2] while the main program waits for it and then moves
    c.saveProgram(program("COUNT", false, "FOR R[3]=1 TO 5", "R[2]=R[2]+1", "WAIT 0.10(sec)", "ENDFOR", "DO[7]=ON"));
    c.saveProgram(program("MAIN", true, "RUN COUNT", "R[1]=R[2]", "WAIT DO[7]=ON", "R[4]=R[2]"));
    assertThat(c.run("MAIN", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim, 2);
    // RUN did not wait: the main program went on at once and sees the task's first increment at most
    assertThat(c.registers().number(1)).isLessThanOrEqualTo(1);
    assertThat(c.tasks().list()).extracting(Tasks.Task::program).containsExactly("COUNT");
    assertThat(c.tasks().list().get(0).holdsMotionGroup()).isFalse();
    steps(sim, 200);
    // 5 x 0.1 s later the task set DO[7] and ended; the main program read the shared register
    assertThat(c.registers().bit(IoKind.DO, 7)).isTrue();
    assertThat(c.registers().number(4)).isEqualTo(5);
    assertThat(c.tasks().list()).isEmpty();
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(c.activeAlarms()).isEmpty();
  }

  /** Issue 26: a PULSE still pending when its task ended stayed ON for ever (the task's interpreter counted it). */
  @Test
  void aPulsePendingWhenItsTaskEndsStillEndsOnTime() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("PULSER", false, "DO[5]=PULSE,0.2sec"));
    c.saveProgram(program("MAIN", true, "RUN PULSER", "WAIT 1.00(sec)"));
    assertThat(c.run("MAIN", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim, 10);  // 40 ms: the task pulsed and ended
    assertThat(c.tasks().list()).isEmpty();
    assertThat(c.registers().bit(IoKind.DO, 5)).isTrue();
    steps(sim, 45);  // 220 ms in all: the pulse is over although its task is gone
    assertThat(c.registers().bit(IoKind.DO, 5)).isFalse();
    // the main program's own pulse counts once per tick too (not faster with tasks around)
    Simulation sim2 = ControllerTest.cell();
    Controller c2 = sim2.controllers().get(0);
    c2.saveProgram(program("PULSER", false, "DO[5]=PULSE,0.2sec"));
    c2.saveProgram(program("MAIN2", true, "RUN PULSER", "DO[6]=PULSE,0.2sec", "WAIT 1.00(sec)"));
    assertThat(c2.run("MAIN2", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim2, 45);  // 180 ms
    assertThat(c2.registers().bit(IoKind.DO, 6)).isTrue();
    steps(sim2, 10);  // 220 ms
    assertThat(c2.registers().bit(IoKind.DO, 6)).isFalse();
  }

  @Test
  void aTaskMayRunAnotherTask() {
    // The task list grows while the tasks are being stepped (it threw ConcurrentModificationException).
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("SECOND", false, "R[6]=R[6]+1", "WAIT 0.05(sec)", "R[7]=1"));
    c.saveProgram(program("FIRST", false, "RUN SECOND", "R[5]=1"));
    c.saveProgram(program("MAIN", false, "RUN FIRST", "WAIT R[7]=1", "R[8]=1"));
    assertThat(c.run("MAIN", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim, 100);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(5)).isEqualTo(1);
    assertThat(c.registers().number(6)).isEqualTo(1);
    assertThat(c.registers().number(8)).isEqualTo(1);
    assertThat(c.tasks().list()).isEmpty();
  }

  @Test
  void aSecondProgramWithGroupOneIsRefusedWithProg040() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MOVER", true, "R[9]=1"));
    c.saveProgram(program("MAIN", true, "RUN MOVER", "R[1]=1"));
    c.run("MAIN", 1, true);
    steps(sim, 3);
    // INTP-267 is a WARN (docs/alarms.md): raised, and MAIN goes on with its next line
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.warnings()).hasSize(1);
    assertThat(c.warnings().get(0).code()).isEqualTo("INTP-267");
    assertThat(c.warnings().get(0).message()).contains("PROG-040 Already locked by other task").contains("MAIN");
    assertThat(c.warnings().get(0).line()).isEqualTo(1);
    assertThat(c.registers().number(9)).isZero();
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.alarmHistory()).extracting(ControllerAlarm::code).containsExactly("INTP-267");
  }

  @Test
  void aMainProgramWithoutGroupMayRunTheMotionProgram() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MOVER", true, "R[9]=1"));
    c.saveProgram(program("CELL", false, "RUN MOVER", "R[1]=1"));
    c.run("CELL", 1, true);
    steps(sim, 3);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(9)).isEqualTo(1);
  }

  @Test
  void runOfAProgramThatIsAlreadyRunningAlarms() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("LOOPER", false, "LBL[1]", "WAIT 0.05(sec)", "JMP LBL[1]"));
    c.saveProgram(program("MAIN", false, "RUN LOOPER", "RUN LOOPER"));
    c.run("MAIN", 1, true);
    steps(sim, 3);
    // INTP-267 RUN stmt failed, cause PROG-007 (FANUC's help text for a RUN of a running program): a WARN
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-267");
    assertThat(c.warnings().get(0).message()).contains("PROG-007").contains("LOOPER is already running");
    assertThat(c.warnings().get(0).line()).isEqualTo(2);
    assertThat(c.activeAlarms()).isEmpty();
    // and the pendant cannot start it either
    assertThat(c.run("LOOPER", 1, true)).isInstanceOf(RobotControl.Result.Refused.class);
  }

  @Test
  void aTaskWithoutGroupCannotMove() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    org.robotrun.program.Program mover = ControllerTest.jointProgram("NOGRP", "R[1]=1", new double[] {0, 0, 0, 0, -90, 0});
    java.util.Map<String, String> attrs = new java.util.LinkedHashMap<>(mover.attributes());
    attrs.put("DEFAULT_GROUP", "*,*,*,*,*");
    c.saveProgram(new org.robotrun.program.Program("NOGRP", attrs, "", mover.lines(), mover.positions()));
    c.saveProgram(program("MAIN", false, "RUN NOGRP"));
    c.run("MAIN", 1, true);
    steps(sim, 5);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).contains("SIMU-021");
  }

  @Test
  void perTaskPauseAndAbortAndHoldAndAbortOfAll() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("TICKER", false, "LBL[1]", "R[5]=R[5]+1", "WAIT 0.04(sec)", "JMP LBL[1]"));
    c.saveProgram(program("OTHER", false, "LBL[1]", "R[6]=R[6]+1", "WAIT 0.04(sec)", "JMP LBL[1]"));
    c.saveProgram(program("MAIN", false, "RUN TICKER", "RUN OTHER", "LBL[1]", "WAIT 0.04(sec)", "JMP LBL[1]"));
    c.run("MAIN", 1, true);
    steps(sim, 50);
    double r5 = c.registers().number(5);
    assertThat(r5).isGreaterThan(3);
    // PAUSE of one task: it stops counting, the other goes on
    assertThat(c.tasks().pause("TICKER")).isTrue();
    double r6 = c.registers().number(6);
    steps(sim, 50);
    assertThat(c.registers().number(5)).isEqualTo(r5);
    assertThat(c.registers().number(6)).isGreaterThan(r6);
    assertThat(c.tasks().list().get(0).status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    // ABORT of one task
    assertThat(c.tasks().abort("OTHER")).isTrue();
    assertThat(c.tasks().list()).extracting(Tasks.Task::program).containsExactly("TICKER");
    // HOLD pauses every program; SHIFT+FWD resumes them all
    c.hold();
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    c.run("MAIN", c.status().line(), true);
    steps(sim, 50);
    assertThat(c.registers().number(5)).isGreaterThan(r5);
    // ABORT (all) ends the main program and every task
    c.abort();
    assertThat(c.tasks().list()).isEmpty();
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
  }

  @Test
  void runIsWrittenBackAsRead() {
    org.robotrun.program.Program p = program("MAIN", false, "RUN PICK_TASK");
    assertThat(p.line(1)).isEqualTo(new org.robotrun.program.Instruction.Run("PICK_TASK", java.util.List.of()));
    assertThat(org.robotrun.io.LsWriter.write(p)).contains("   1:  RUN PICK_TASK ;");
  }
}
