package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.sim.TaskProgs.program;
import static org.robotrun.sim.TaskProgs.steps;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.IoKind;

/**
 * The multitasking rules of docs/production.md ("Multitasking: RUN") one by one: RUN of a missing
 * program (INTP-267, cause MEMO-073), at most {@value Tasks#MAX_TASKS} tasks beside the main
 * program, group 1 held by a task or by any program on the main program's call stack (PROG-040),
 * a program in the main program's call stack counts as running (PROG-007), an alarm in a task
 * ends that task and shows with its program and line, and the UOP outputs PROGRUN, PAUSED and
 * BUSY over the main program and its tasks.
 */
class TaskRulesTest {

  private static Controller controller(Simulation sim) {
    return sim.controllers().get(0);
  }

  @Test
  void runOfAMissingProgramIsAWarningWithMemo073AndTheCallerGoesOn() {
    Simulation sim = ControllerTest.cell();
    Controller c = controller(sim);
    c.saveProgram(program("MAIN", false, "RUN GHOST", "R[1]=1"));
    c.run("MAIN", 1, true);
    steps(sim, 3);
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-267");
    assertThat(c.warnings().get(0).message()).contains("MEMO-073 Program does not exist").contains("GHOST");
    assertThat(c.warnings().get(0).program()).isEqualTo("MAIN");
    assertThat(c.warnings().get(0).line()).isEqualTo(1);
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.tasks().list()).isEmpty();
  }

  @Test
  void atMostEightTasksRunBesideTheMainProgram() {
    Simulation sim = ControllerTest.cell();
    Controller c = controller(sim);
    String[] lines = new String[Tasks.MAX_TASKS + 2];
    for (int k = 1; k <= Tasks.MAX_TASKS + 1; k++) {
      c.saveProgram(program("T" + k, false, "LBL[1]", "WAIT 0.04(sec)", "JMP LBL[1]"));
      lines[k - 1] = "RUN T" + k;
    }
    lines[Tasks.MAX_TASKS + 1] = "R[1]=1";
    c.saveProgram(program("MAIN", false, lines));
    c.run("MAIN", 1, true);
    steps(sim, 5);
    // the eight first started, the ninth was refused with a warning and MAIN went on
    assertThat(c.tasks().list()).hasSize(Tasks.MAX_TASKS);
    assertThat(c.tasks().list()).extracting(Tasks.Task::program)
        .containsExactly("T1", "T2", "T3", "T4", "T5", "T6", "T7", "T8");
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-267");
    assertThat(c.warnings().get(0).line()).isEqualTo(Tasks.MAX_TASKS + 1);
    assertThat(c.warnings().get(0).message()).contains("at most " + Tasks.MAX_TASKS);
    assertThat(c.registers().number(1)).isEqualTo(1);
    // one ended: a ninth task may start again
    assertThat(c.tasks().abort("T3")).isTrue();
    assertThat(c.tasks().run("T9")).isEmpty();
    assertThat(c.tasks().list()).hasSize(Tasks.MAX_TASKS);
  }

  @Test
  void aTaskThatHoldsGroupOneLocksItAgainstTheMainProgramAndAnotherTask() {
    Simulation sim = ControllerTest.cell();
    Controller c = controller(sim);
    c.saveProgram(program("MOVER", true, "LBL[1]", "WAIT 0.04(sec)", "JMP LBL[1]"));
    c.saveProgram(program("MOVER2", true, "R[2]=1"));
    c.saveProgram(program("CELL", false, "RUN MOVER", "WAIT 0.02(sec)", "RUN MOVER2", "R[1]=1"));
    c.saveProgram(program("OTHER", true, "R[3]=1"));
    c.run("CELL", 1, true);
    steps(sim, 20);
    assertThat(c.tasks().groupHolder()).contains("MOVER");
    assertThat(c.tasks().list()).extracting(Tasks.Task::holdsMotionGroup).containsExactly(true);
    // the second program with group 1 is refused naming the holder; CELL goes on
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-267");
    assertThat(c.warnings().get(0).message()).contains("PROG-040").contains("MOVER holds group 1");
    assertThat(c.registers().number(2)).isZero();
    assertThat(c.registers().number(1)).isEqualTo(1);
    // CELL has ended; a pendant start of a program with group 1 is refused too, one without is not
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    RobotControl.Result r = c.run("OTHER", 1, true);
    assertThat(r).isInstanceOf(RobotControl.Result.Refused.class);
    assertThat(((RobotControl.Result.Refused) r).reason()).contains("PROG-040").contains("MOVER");
    c.saveProgram(program("NOGRP", false, "R[4]=1"));
    assertThat(c.run("NOGRP", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim, 2);
    assertThat(c.registers().number(4)).isEqualTo(1);
    // once the holder ends, group 1 is free again
    assertThat(c.tasks().abort("MOVER")).isTrue();
    assertThat(c.tasks().groupHolder()).isEmpty();
    assertThat(c.run("OTHER", 1, true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim, 2);
    assertThat(c.registers().number(3)).isEqualTo(1);
  }

  @Test
  void aProgramWithGroupOneAnywhereOnTheMainStackHoldsTheGroupAndCountsAsRunning() {
    Simulation sim = ControllerTest.cell();
    Controller c = controller(sim);
    // CELL has no group; the SUB it CALLs has group 1 and waits there
    c.saveProgram(program("SUB", true, "RUN MOVER", "RUN SUB", "WAIT 0.20(sec)"));
    c.saveProgram(program("MOVER", true, "R[2]=1"));
    c.saveProgram(program("CELL", false, "CALL SUB", "R[1]=1"));
    c.run("CELL", 1, true);
    steps(sim, 5);
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-267", "INTP-267");
    assertThat(c.warnings().get(0).message()).contains("PROG-040").contains("SUB holds group 1");
    // SUB is in the main program's call stack: it is running, RUN of it is PROG-007
    assertThat(c.warnings().get(1).message()).contains("PROG-007").contains("SUB is already running");
    assertThat(c.tasks().isRunning("SUB")).isTrue();
    assertThat(c.tasks().isRunning("CELL")).isTrue();
    assertThat(c.tasks().isRunning("MOVER")).isFalse();
    assertThat(c.registers().number(2)).isZero();
    steps(sim, 60);
    // SUB returned to CELL, which ended: nothing holds the group any more
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.tasks().groupHolder()).isEmpty();
    assertThat(c.tasks().isRunning("SUB")).isFalse();
  }

  @Test
  void anAlarmInATaskEndsThatTaskShowsItsProgramAndLineAndHoldsTheMainProgram() {
    Simulation sim = ControllerTest.cell();
    Controller c = controller(sim);
    c.saveProgram(program("BAD", false, "R[1]=5", "R[2]=R[1]/R[3]", "R[4]=1"));
    c.saveProgram(program("MAIN", false, "RUN BAD", "LBL[1]", "R[5]=R[5]+1", "WAIT 0.04(sec)", "JMP LBL[1]"));
    c.run("MAIN", 1, true);
    steps(sim, 5);
    // SIMU-001 divide by zero is ABORT (docs/alarms.md): the task ends, the alarm names BAD line 2
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SIMU-001");
    assertThat(c.activeAlarms().get(0).program()).isEqualTo("BAD");
    assertThat(c.activeAlarms().get(0).line()).isEqualTo(2);
    assertThat(c.tasks().list()).isEmpty();
    assertThat(c.registers().number(4)).isZero();
    // an active alarm holds the main program until RESET (one alarm list per controller)
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    double counted = c.registers().number(5);
    steps(sim, 30);
    assertThat(c.registers().number(5)).isEqualTo(counted);
    assertThat(c.uop().uo(Uop.FAULT)).isTrue();
    c.reset();
    assertThat(c.run("MAIN", c.status().line(), true)).isInstanceOf(RobotControl.Result.Ok.class);
    steps(sim, 30);
    assertThat(c.registers().number(5)).isGreaterThan(counted);
  }

  @Test
  void progrunPausedAndBusyFollowTheMainProgramAndItsTasks() {
    Simulation sim = ControllerTest.cell();
    Controller c = controller(sim);
    c.saveProgram(program("TICKER", false, "LBL[1]", "R[5]=R[5]+1", "WAIT 0.04(sec)", "JMP LBL[1]"));
    c.saveProgram(program("MAIN", false, "RUN TICKER", "WAIT 0.10(sec)"));
    Uop u = c.uop();
    steps(sim, 1);
    assertThat(u.uo(Uop.PROGRUN)).isFalse();
    assertThat(u.uo(Uop.BUSY)).isFalse();
    assertThat(c.busy()).isFalse();
    c.run("MAIN", 1, true);
    steps(sim, 5);
    assertThat(u.uo(Uop.PROGRUN)).isTrue();
    assertThat(u.uo(Uop.PAUSED)).isFalse();
    // MAIN ends after 0.1 s; the task still runs: PROGRUN and BUSY stay on
    steps(sim, 40);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(u.uo(Uop.PROGRUN)).isTrue();
    assertThat(u.uo(Uop.BUSY)).isTrue();
    assertThat(c.busy()).isTrue();
    // the only task paused and nothing runs: PAUSED on, PROGRUN off, still BUSY (a program is active)
    assertThat(c.tasks().pause("TICKER")).isTrue();
    steps(sim, 2);
    assertThat(c.tasks().anyPaused()).isTrue();
    assertThat(c.tasks().anyRunning()).isFalse();
    assertThat(u.uo(Uop.PROGRUN)).isFalse();
    assertThat(u.uo(Uop.PAUSED)).isTrue();
    assertThat(u.uo(Uop.BUSY)).isTrue();
    assertThat(c.tasks().list().get(0).status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    assertThat(c.tasks().list().get(0).status().program()).isEqualTo("TICKER");
    // RESUME of that task: it counts again
    double n = c.registers().number(5);
    assertThat(c.tasks().resume("TICKER")).isTrue();
    steps(sim, 30);
    assertThat(c.registers().number(5)).isGreaterThan(n);
    assertThat(u.uo(Uop.PAUSED)).isFalse();
    assertThat(u.uo(Uop.PROGRUN)).isTrue();
    // a name that is not a task: nothing happens
    assertThat(c.tasks().pause("NOSUCH")).isFalse();
    assertThat(c.tasks().resume("NOSUCH")).isFalse();
    assertThat(c.tasks().abort("NOSUCH")).isFalse();
    assertThat(c.tasks().list()).hasSize(1);
    // ABORT of the last task: nothing is active any more
    assertThat(c.tasks().abort("TICKER")).isTrue();
    steps(sim, 2);
    assertThat(c.tasks().isEmpty()).isTrue();
    assertThat(u.uo(Uop.PROGRUN)).isFalse();
    assertThat(u.uo(Uop.PAUSED)).isFalse();
    assertThat(u.uo(Uop.BUSY)).isFalse();
  }

  @Test
  void startAfterHoldResumesOnlyThePausedTasksAndATaskPausedByItselfToo() {
    Simulation sim = ControllerTest.cell();
    Controller c = controller(sim);
    c.saveProgram(program("TICKER", false, "LBL[1]", "R[5]=R[5]+1", "WAIT 0.04(sec)", "JMP LBL[1]"));
    c.saveProgram(program("MAIN", false, "RUN TICKER", "LBL[1]", "WAIT 0.04(sec)", "JMP LBL[1]"));
    c.run("MAIN", 1, true);
    steps(sim, 10);
    c.hold();
    assertThat(c.tasks().list().get(0).status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    double n = c.registers().number(5);
    steps(sim, 30);
    assertThat(c.registers().number(5)).isEqualTo(n);
    // SHIFT+FWD (BWD does not resume the tasks)
    c.run("MAIN", c.status().line(), true);
    steps(sim, 30);
    assertThat(c.registers().number(5)).isGreaterThan(n);
    assertThat(c.tasks().list().get(0).status().state()).isEqualTo(ExecutionStatus.State.RUNNING);
  }

  @Test
  void aTasksPulseAndTimerCountTheControllersTimeOnce() {
    Simulation sim = ControllerTest.cell();
    Controller c = controller(sim);
    // the task keeps running while its pulse is on; its timer runs for 0.2 s
    c.saveProgram(program("PULSER", false, "TIMER[3]=START", "DO[5]=PULSE,0.2sec", "WAIT 0.20(sec)",
        "R[3]=TIMER[3]", "WAIT 1.00(sec)"));
    c.saveProgram(program("MAIN", false, "RUN PULSER", "WAIT 2.00(sec)"));
    c.run("MAIN", 1, true);
    steps(sim, 46); // 0.184 s after the task started
    assertThat(c.registers().bit(IoKind.DO, 5)).isTrue();
    steps(sim, 8);  // 0.216 s
    assertThat(c.registers().bit(IoKind.DO, 5)).isFalse();
    steps(sim, 5);
    // TIMER reads seconds (docs/tp-execution.md): about 0.2, not twice that
    assertThat(c.registers().number(3)).isBetween(0.19, 0.22);
  }

  @Test
  void aTaskRunsVisionWithTheCellsVisionSystem() {
    Simulation sim = VisionPickTest.cell(3);
    Controller c = controller(sim);
    c.saveProgram(program("LOOK", false, "VISION RUN_FIND 'FIND_BLOCKS'", "VISION GET_NFOUND 'FIND_BLOCKS' R[2]"));
    c.saveProgram(program("CELLMAIN", false, "RUN LOOK", "WAIT 0.10(sec)"));
    c.run("CELLMAIN", 1, true);
    steps(sim, 40);
    assertThat(c.activeAlarms()).isEmpty();
    VisionSystem vs = sim.vision().orElseThrow();
    assertThat(c.registers().number(2)).isEqualTo(vs.lastFound("FIND_BLOCKS").size()).isPositive();
  }

  @Test
  void abortingATaskThatMovesTheArmStopsTheArm() {
    for (boolean all : new boolean[] {false, true}) {
      Simulation sim = ControllerTest.cell();
      Controller c = controller(sim);
      c.saveProgram(ControllerTest.jointProgram("MOVER", "J P[2] 10% FINE", new double[] {0, 0, 0, 0, -90, 0},
          new double[] {60, 0, 0, 0, -90, 0}));
      c.saveProgram(program("CELL", false, "RUN MOVER", "LBL[1]", "WAIT 0.04(sec)", "JMP LBL[1]"));
      c.run("CELL", 1, true);
      steps(sim, 100);
      double j1 = c.currentJoints().element(1);
      assertThat(j1).as("moving").isBetween(1.0, 59.0);
      if (all) {
        c.abort(); // FCTN ABORT (ALL)
      } else {
        assertThat(c.tasks().abort("MOVER")).isTrue();
      }
      steps(sim, 500);
      // the arm decelerated to a stop: far short of P[2] (10 % of J1's 450 deg/s is 45 deg/s)
      double stopped = c.currentJoints().element(1);
      assertThat(stopped).as("all=%s", all).isLessThan(j1 + 10).isLessThan(59.0);
      steps(sim, 100);
      assertThat(c.currentJoints().element(1)).isEqualTo(stopped);
      assertThat(c.busy()).isEqualTo(!all); // CELL goes on after one task's ABORT
    }
  }
}
