package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.sim.TaskProgs.program;
import static org.robotrun.sim.TaskProgs.steps;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.program.IoKind;

/**
 * Background logic runs each program from its first line to its end once every scan (8 ms by
 * default: every second 4 ms tick), with or without a program running, and refuses what the
 * controller refuses in a BG program.
 */
class BgLogicTest {

  @Test
  void aBgProgramRunsOnceEveryScanWhetherOrNotAProgramRuns() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("BGCOUNT", false, "R[1]=R[1]+1", "DO[3]=(DI[3] AND !DO[4])"));
    assertThat(c.bgLogic().add("BGCOUNT")).isEmpty();
    steps(sim, 100); // 0.4 s at 4 ms: 50 scans of 8 ms
    assertThat(c.registers().number(1)).isEqualTo(50);
    assertThat(c.bgLogic().scans()).isEqualTo(50);
    // the logic follows its input within one scan
    c.registers().setBit(IoKind.DI, 3, true);
    steps(sim, 2);
    assertThat(c.registers().bit(IoKind.DO, 3)).isTrue();
    // STOP on the setup screen: it no longer runs
    assertThat(c.bgLogic().setRunning("BGCOUNT", false)).isEmpty();
    double n = c.registers().number(1);
    steps(sim, 10);
    assertThat(c.registers().number(1)).isEqualTo(n);
    // no program ran all along: BG logic is not a program run
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(c.busy()).isFalse();
  }

  @Test
  void theBgListOffersOnlyWhatASlotTakesAndSaysWhyTheOthersAreMissing() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", true, "R[1]=1"));
    c.saveProgram(program("BGWAIT", false, "WAIT 1.0(sec)"));
    c.saveProgram(program("BGOK", false, "R[2]=R[2]+1"));
    c.saveProgram(program("BGIN", false, "R[3]=1"));
    assertThat(c.bgLogic().add("BGIN")).isEmpty();
    BgLogic.Offer o = c.bgLogic().offer(List.of("BGIN", "BGOK", "BGWAIT", "MAIN", "GONE"));
    assertThat(o.programs()).containsExactly("BGOK");
    assertThat(o.notOffered()).hasSize(3);
    assertThat(o.notOffered().get(0)).startsWith("BGWAIT line 1: ").endsWith("is not allowed in background logic");
    assertThat(o.notOffered().get(1)).startsWith("MAIN has motion group 1");
    assertThat(o.notOffered().get(2)).isEqualTo("program GONE does not exist");
    // what it offers, a slot takes
    assertThat(c.bgLogic().add(o.programs().get(0))).isEmpty();
  }

  @Test
  void aPulseSetByABgProgramEndsAfterItsWidth() {
    // The BG interpreter was stepped with no time, so its PULSE never switched the output off.
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("BGPULSE", false, "IF R[1]<>1,JMP LBL[1]", "DO[3]=PULSE,0.2sec", "R[1]=0", "LBL[1]"));
    c.registers().setInteger(1, 1);
    assertThat(c.bgLogic().add("BGPULSE")).isEmpty();
    steps(sim, 25);  // 0.1 s
    assertThat(c.registers().bit(IoKind.DO, 3)).isTrue();
    steps(sim, 75);  // 0.4 s in all
    assertThat(c.registers().bit(IoKind.DO, 3)).isFalse();
    assertThat(c.activeAlarms()).isEmpty();
  }

  @Test
  void theScanPeriodIsSetPerController() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("BG", false, "R[1]=R[1]+1"));
    c.bgLogic().setScanSec(0.020);
    c.bgLogic().add("BG");
    steps(sim, 50); // 0.2 s / 20 ms = 10 scans
    assertThat(c.registers().number(1)).isEqualTo(10);
  }

  @Test
  void whatTheControllerRefusesInABgProgramIsRefused() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MOTIONGRP", true, "R[1]=1"));
    c.saveProgram(program("WAITS", false, "R[1]=1", "WAIT DI[1]=ON"));
    c.saveProgram(program("CALLS", false, "CALL WAITS"));
    c.saveProgram(program("RUNS", false, "RUN WAITS"));
    assertThat(c.bgLogic().add("MOTIONGRP")).get().asString().contains("DEFAULT_GROUP = *,*,*,*,*");
    assertThat(c.bgLogic().add("WAITS")).get().asString().isEqualTo("WAITS line 2: WAIT is not allowed in background logic");
    assertThat(c.bgLogic().add("CALLS")).get().asString().contains("CALL is not allowed");
    assertThat(c.bgLogic().add("RUNS")).get().asString().contains("RUN is not allowed");
    assertThat(c.bgLogic().add("NOSUCH")).get().asString().contains("does not exist");
    assertThat(c.bgLogic().slots()).isEmpty();
  }

  @Test
  void aScenarioSlotWhoseProgramIsMissingStopsWithInt105AtItsFirstScan() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.bgLogic().configure(List.of("GHOST"));
    steps(sim, 2);
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-105");
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.bgLogic().slots().get(0).running()).isFalse();
  }

  @Test
  void anEndlessLoopInABgProgramStopsItWithTheRunawayAlarm() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("SPIN", false, "LBL[1]", "R[1]=R[1]+1", "JMP LBL[1]"));
    c.bgLogic().add("SPIN");
    steps(sim, 2);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SIMU-003");
    assertThat(c.bgLogic().slots().get(0).running()).isFalse();
  }
}
