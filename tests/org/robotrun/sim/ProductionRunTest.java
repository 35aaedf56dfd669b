package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.robotrun.sim.TaskProgs.program;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.world.ProductionSetup;
import org.robotrun.world.ProductionSetup.PlcStep;
import org.robotrun.world.ProductionSetup.Selection;
import org.robotrun.world.ProductionSetup.Signal;

/**
 * {@code robotrun run} of a cell its PLC starts (docs/production.md, "The PLC"): nobody presses
 * SHIFT+FWD, the run ends when the PLC sequence is done and nothing runs any more, and reports the
 * program the PLC selected; a PLC that waits for an output that never comes ends at the time limit
 * (RUN-001) naming the step it waits on and the refused start; before the run, each BG Logic and
 * HOME program is checked, each message naming its JSON path.
 */
class ProductionRunTest {
  private static final List<Integer> NO_RSR = List.of(0, 0, 0, 0, 0, 0, 0, 0);

  /** Safety inputs on, PNS1 + PNSTROBE, wait SNACK, pulse PROD_START, then wait for PROGRUN off. */
  private static List<PlcStep> pnsSequence() {
    Map<Signal, Boolean> safety = new LinkedHashMap<>();
    for (int ui : new int[] {1, 2, 3, 8}) {
      safety.put(new Signal("UI", ui), true);
    }
    return List.of(
        new PlcStep(Optional.empty(), 0, safety, "safety on"),
        new PlcStep(Optional.of(Map.entry(new Signal("UO", 1), true)), 0, Map.of(new Signal("UI", 9), true), "PNS1"),
        new PlcStep(Optional.empty(), 0.02, Map.of(new Signal("UI", 17), true), "strobe"),
        new PlcStep(Optional.of(Map.entry(new Signal("UO", 19), true)), 0, Map.of(new Signal("UI", 18), true), "start"),
        new PlcStep(Optional.empty(), 0.02, Map.of(new Signal("UI", 18), false), "release"),
        new PlcStep(Optional.of(Map.entry(new Signal("UO", 3), true)), 0, Map.of(new Signal("UI", 17), false), "running"),
        new PlcStep(Optional.of(Map.entry(new Signal("UO", 3), false)), 0, Map.of(), "done"));
  }

  private static ProductionSetup.Robot setup(List<String> bg, Optional<String> home) {
    return new ProductionSetup.Robot(true, true, Selection.PNS, 0, 0, NO_RSR, new TreeMap<>(), 0.2, false, false, home,
        List.of(), bg, 0.008, pnsSequence(), true);
  }

  @Test
  void thePlcStartsTheSelectedJobAndTheRunEndsWhenItAndTheSequenceAreDone() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("PNS0001", false, "R[1]=R[1]+1", "WAIT 0.30(sec)", "R[2]=1"));
    TaskProgs.steps(sim, 100); // the cell has run 0.4 s before the PLC takes over
    c.configureProduction(setup(List.of(), Optional.empty()));
    HeadlessRun.CellResult r = ProductionRun.run(sim, c, 10, s -> {}, () -> false, "");
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(r.alarm()).isEmpty();
    assertThat(r.robots()).hasSize(1);
    HeadlessRun.RobotResult rr = r.robots().get(0);
    assertThat(rr.robot()).isEqualTo("robot1");
    assertThat(rr.program()).isEqualTo("PNS0001");
    assertThat(rr.status()).isEqualTo(HeadlessRun.RobotStatus.FINISHED);
    assertThat(rr.busyTimeSec()).isZero(); // the arm never moved
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.registers().number(2)).isEqualTo(1);
    assertThat(c.uop().plcDone()).isTrue();
    // at least the job's 0.3 s WAIT and the PLC's two 20 ms delays; ended within a few ticks of the job
    assertThat(r.cycleTimeSec()).isBetween(0.34, 0.40);
    assertThat(r.simTimeSec()).isCloseTo(sim.timeSec(), within(1e-9));
    assertThat(r.ticks()).isEqualTo(sim.ticks());
  }

  @Test
  void aJobThePlcCannotStartEndsAtTheTimeLimitNamingTheStepAndTheRefusal() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    TaskProgs.steps(sim, 100);
    c.configureProduction(setup(List.of(), Optional.empty())); // no PNS0001 loaded
    HeadlessRun.CellResult r = ProductionRun.run(sim, c, 1.0, s -> {}, () -> false, "");
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.ALARM);
    ControllerAlarm a = r.alarm().orElseThrow();
    assertThat(a.code()).isEqualTo("RUN-001");
    // the PLC waits on "running" (step 6 of 7) for a PROGRUN that never comes
    assertThat(a.message()).contains("1.0 s").contains("PLC step 6 of 7")
        .contains("the PLC's start was refused: INTP-105").contains("PNS0001 does not exist");
    assertThat(r.cycleTimeSec()).isCloseTo(1.0, within(0.005));
    assertThat(r.simTimeSec()).isCloseTo(1.4, within(0.005));
    assertThat(r.robots().get(0).status()).isEqualTo(HeadlessRun.RobotStatus.ALARM);
    assertThat(r.robots().get(0).program()).isEqualTo("PNS0001"); // what the PLC selected
  }

  @Test
  void anAlarmEndsTheRunAndTheCallersStopIsAskedAboutOnceASecond() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("PNS0001", false, "R[1]=1/R[2]"));
    c.configureProduction(setup(List.of(), Optional.empty()));
    HeadlessRun.CellResult r = ProductionRun.run(sim, c, 10, s -> {}, () -> false, "");
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.ALARM);
    assertThat(r.alarm().orElseThrow().code()).isEqualTo("SIMU-001");
    assertThat(r.robots().get(0).program()).isEqualTo("PNS0001");
    // a caller's stop (the wall-clock limit) ends it with RUN-002 and the caller's reason
    Simulation sim2 = ControllerTest.cell();
    Controller c2 = sim2.controllers().get(0);
    c2.saveProgram(program("PNS0001", false, "WAIT 5.00(sec)"));
    c2.configureProduction(setup(List.of(), Optional.empty()));
    int[] asked = {0};
    HeadlessRun.CellResult r2 = ProductionRun.run(sim2, c2, 10, s -> {}, () -> ++asked[0] >= 2, "wall clock");
    assertThat(r2.alarm().orElseThrow().code()).isEqualTo("RUN-002");
    assertThat(r2.alarm().get().message()).isEqualTo("wall clock");
    assertThat(r2.simTimeSec()).isCloseTo(2.0, within(1e-9)); // asked every 250 ticks of 4 ms
  }

  @Test
  void theCheckNamesTheJsonPathOfEachMissingOrRefusedProgram() {
    Controller c = ControllerTest.cell().controllers().get(0);
    c.saveProgram(program("LAMP", false, "DO[1]=ON"));
    c.saveProgram(program("WAITS", false, "WAIT DI[1]=ON"));
    List<String> out = ProductionRun.check("robot1", setup(List.of("LAMP", "GONE", "WAITS"), Optional.of("HOMEPRG")), c);
    assertThat(out).containsExactly(
        "production.robot1.backgroundLogic[1]: no program GONE among the loaded files",
        "production.robot1.backgroundLogic[2]: WAITS line 1: WAIT is not allowed in background logic",
        "production.robot1.homeProgram: no program HOMEPRG among the loaded files");
    c.saveProgram(program("HOMEPRG", true, "R[1]=1"));
    assertThat(ProductionRun.check("robot1", setup(List.of("LAMP"), Optional.of("HOMEPRG")), c)).isEmpty();
  }
}
