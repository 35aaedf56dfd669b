package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.sim.TaskProgs.program;
import static org.robotrun.sim.TaskProgs.steps;

import java.util.List;
import java.util.Optional;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.IoKind;
import org.robotrun.world.ProductionSetup;
import org.robotrun.world.ProductionSetup.ReferencePosition;
import org.robotrun.world.ProductionSetup.Selection;
import org.robotrun.world.ProductionSetup.Signal;

/**
 * The UOP signals with the controller's timing rules: CMDENBL needs remote, AUTO, pendant off and
 * *IMSTP/*HOLD/*SFSPD/ENBL on; PNSTROBE reads PNS1..8 on its rising edge and answers with SNO1..8
 * and a SNACK pulse; PROD_START and START act on their falling edge; RSR on its rising edge with
 * an ACK pulse, queued while a program runs; *IMSTP off is SRVO-037; reference position 1 drives
 * ATPERCH and its DO.
 */
class UopTest {
  private static final double TICK = Simulation.DEFAULT_TICK_SEC;

  private static ProductionSetup.Robot setup(Selection sel, List<Integer> rsr, List<ReferencePosition> refs) {
    ProductionSetup.Robot d = ProductionSetup.Robot.defaults();
    return new ProductionSetup.Robot(true, true, sel, 100, 0, rsr, new TreeMap<>(java.util.Map.of(3, "STYLE_C")), 0.2,
        false, false, Optional.empty(), refs, List.of(), d.bgScanSec(), List.of(), false);
  }

  private static final List<Integer> NO_RSR = List.of(0, 0, 0, 0, 0, 0, 0, 0);

  private static Controller cell(Simulation sim, ProductionSetup.Robot s) {
    Controller c = sim.controllers().get(0);
    c.configureProduction(s);
    sim.step();
    return c;
  }

  @Test
  void cmdenblNeedsRemoteAutoPendantOffAndTheSafetyInputs() {
    Simulation sim = ControllerTest.cell();
    Controller c = cell(sim, setup(Selection.PNS, NO_RSR, List.of()));
    Uop u = c.uop();
    assertThat(u.uo(Uop.CMDENBL)).isTrue();
    assertThat(u.uo(Uop.SYSRDY)).isTrue();
    u.setUi(Uop.ENBL, false);
    sim.step();
    assertThat(u.uo(Uop.CMDENBL)).isFalse();
    u.setUi(Uop.ENBL, true);
    u.setTpEnabled(true);
    sim.step();
    assertThat(u.uo(Uop.CMDENBL)).isFalse();
    assertThat(u.uo(Uop.TPENBL)).isTrue();
    u.setTpEnabled(false);
    c.setMode(RobotControl.Mode.T1);
    sim.step();
    assertThat(u.uo(Uop.CMDENBL)).isFalse();
    c.setMode(RobotControl.Mode.AUTO);
    sim.step();
    assertThat(u.uo(Uop.CMDENBL)).isTrue();
  }

  @Test
  void anOpenFenceKeepsTheOverrideAtItsLimitUntilSfspdReturns() {
    // *SFSPD off: the override is clamped to the fence limit and cannot be raised while it stays off.
    Simulation sim = ControllerTest.cell();
    Controller c = cell(sim, setup(Selection.PNS, NO_RSR, List.of()));
    Uop u = c.uop();
    c.setOverridePct(100);
    u.setUi(Uop.SFSPD, false);
    sim.step();
    assertThat(c.overridePct()).isEqualTo(Uop.FENCE_OVERRIDE_PCT);
    c.setOverridePct(80);  // the operator tries to speed up with the fence open
    sim.step();
    assertThat(c.overridePct()).isEqualTo(Uop.FENCE_OVERRIDE_PCT);
    u.setUi(Uop.SFSPD, true);
    sim.step();
    c.setOverridePct(80);
    sim.step();
    assertThat(c.overridePct()).isEqualTo(80);
  }

  @Test
  void pnsSelectsOnTheStrobeAndProdStartRunsOnItsFallingEdge() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("PNS0105", true, "R[1]=R[1]+1", "WAIT 0.20(sec)"));
    cell(sim, setup(Selection.PNS, NO_RSR, List.of()));
    Uop u = c.uop();
    // PNS number 5 = PNS1 + PNS3; base 100 selects PNS0105
    u.setUi(Uop.SEL1, true);
    u.setUi(Uop.SEL1 + 2, true);
    sim.step();
    assertThat(u.uo(Uop.SNACK)).isFalse(); // nothing read before the strobe
    u.setUi(Uop.PNSTROBE, true);
    sim.step();
    sim.step();
    assertThat(u.selectedProgram()).isEqualTo("PNS0105");
    assertThat(u.uo(Uop.ACK1)).isTrue();   // SNO1
    assertThat(u.uo(Uop.ACK1 + 1)).isFalse(); // SNO2
    assertThat(u.uo(Uop.ACK1 + 2)).isTrue();  // SNO3
    assertThat(u.uo(Uop.SNACK)).isTrue();
    // SNACK is a pulse of ackPulseMs (200 ms = 50 ticks)
    int on = 1;
    while (u.uo(Uop.SNACK) && on < 1000) {
      sim.step();
      on++;
    }
    assertThat(on * TICK).isBetween(0.196, 0.212);
    // PROD_START: nothing on the rising edge, the program starts on the falling edge
    u.setUi(Uop.PROD_START, true);
    steps(sim, 5);
    assertThat(c.registers().number(1)).isZero();
    u.setUi(Uop.PROD_START, false);
    steps(sim, 2);
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.status().program()).isEqualTo("PNS0105");
    assertThat(u.uo(Uop.PROGRUN)).isTrue();
    assertThat(u.uo(Uop.BUSY)).isTrue();
    steps(sim, 80);
    assertThat(u.uo(Uop.PROGRUN)).isFalse();
    assertThat(c.activeAlarms()).isEmpty();
  }

  @Test
  void aPnsNumberWithNoProgramIsRunRequestFailed() {
    Simulation sim = ControllerTest.cell();
    Controller c = cell(sim, setup(Selection.PNS, NO_RSR, List.of()));
    Uop u = c.uop();
    u.setUi(Uop.SEL1 + 1, true); // PNS 2 -> PNS0102, which does not exist
    u.setUi(Uop.PNSTROBE, true);
    sim.step();
    u.setUi(Uop.PROD_START, true);
    sim.step();
    u.setUi(Uop.PROD_START, false);
    steps(sim, 2);
    // a refused start is a WARN (docs/alarms.md): kept and shown, but not active and no FAULT
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-105");
    assertThat(c.warnings().get(0).message()).contains("PNS0102 does not exist");
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(u.uo(Uop.FAULT)).isFalse();
    // FAULT RESET (rising edge) clears it
    u.setUi(Uop.FAULT_RESET, true);
    steps(sim, 2);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(u.uo(Uop.FAULT)).isFalse();
  }

  @Test
  void rsrStartsItsProgramWithAnAckPulseAndQueuesWhileAProgramRuns() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("RSR0012", true, "R[1]=R[1]+1", "WAIT 0.10(sec)"));
    c.saveProgram(program("RSR0020", true, "R[2]=R[1]"));
    cell(sim, setup(Selection.RSR, List.of(12, 20, 0, 0, 0, 0, 0, 0), List.of()));
    Uop u = c.uop();
    u.setUi(Uop.SEL1, true); // RSR1 rises: RSR0012 starts at once
    steps(sim, 2);
    assertThat(c.status().program()).isEqualTo("RSR0012");
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(u.uo(Uop.ACK1)).isTrue();
    u.setUi(Uop.SEL1 + 1, true); // RSR2 while RSR0012 runs: queued
    steps(sim, 2);
    assertThat(c.registers().number(2)).isZero();
    assertThat(u.uo(Uop.ACK1 + 1)).isTrue();
    steps(sim, 40);
    // RSR0012 ended; the queued RSR0020 ran after it and saw its result
    assertThat(c.registers().number(2)).isEqualTo(1);
    // RSR3 has no number: the controller ignores it
    u.setUi(Uop.SEL1 + 2, true);
    steps(sim, 3);
    assertThat(c.activeAlarms()).isEmpty();
  }

  @Test
  void startOnItsFallingEdgeResumesAPausedProgram() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", true, "PAUSE", "R[1]=7"));
    cell(sim, setup(Selection.OTHER, NO_RSR, List.of()));
    Uop u = c.uop();
    c.run("MAIN", 1, true);
    steps(sim, 2);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    assertThat(u.uo(Uop.PAUSED)).isTrue();
    u.setUi(Uop.START, true);
    steps(sim, 3);
    assertThat(c.registers().number(1)).isZero();
    u.setUi(Uop.START, false);
    steps(sim, 2);
    assertThat(c.registers().number(1)).isEqualTo(7);
  }

  @Test
  void imstpOffIsAnImmediateStopUntilItIsBackOnAndReset() {
    Simulation sim = ControllerTest.cell();
    Controller c = cell(sim, setup(Selection.OTHER, NO_RSR, List.of()));
    Uop u = c.uop();
    u.setUi(Uop.IMSTP, false);
    steps(sim, 2);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-037");
    assertThat(u.uo(Uop.SYSRDY)).isFalse();
    assertThat(u.uo(Uop.CMDENBL)).isFalse();
    u.setUi(Uop.IMSTP, true);
    u.setUi(Uop.FAULT_RESET, true);
    steps(sim, 2);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(u.uo(Uop.SYSRDY)).isTrue();
  }

  @Test
  void holdOffPausesTheProgramAndShowsHeld() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", true, "WAIT 1.00(sec)", "R[1]=1"));
    cell(sim, setup(Selection.OTHER, NO_RSR, List.of()));
    Uop u = c.uop();
    c.run("MAIN", 1, true);
    steps(sim, 2);
    u.setUi(Uop.HOLD, false);
    steps(sim, 2);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    assertThat(u.uo(Uop.HELD)).isTrue();
    assertThat(u.uo(Uop.CMDENBL)).isFalse();
  }

  @Test
  void referencePositionOneDrivesAtperchAndItsHomeOutput() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    org.robotrun.program.Position.Joint q = c.currentJoints();
    List<Double> here = List.of(q.element(1), q.element(2), q.element(3), q.element(4), q.element(5), q.element(6));
    ReferencePosition home = new ReferencePosition(1, "HOME", here, java.util.Collections.nCopies(6, 2.0),
        Optional.of(new Signal("DO", 5)));
    cell(sim, setup(Selection.OTHER, NO_RSR, List.of(home)));
    assertThat(c.uop().uo(Uop.ATPERCH)).isTrue();
    assertThat(c.registers().bit(IoKind.DO, 5)).isTrue();
    // move J1 by 5 deg: outside the 2 deg tolerance
    c.saveProgram(ControllerTest.jointProgram("AWAY", "J P[2] 50% FINE",
        new double[] {here.get(0), here.get(1), here.get(2), here.get(3), here.get(4), here.get(5)},
        new double[] {here.get(0) + 5, here.get(1), here.get(2), here.get(3), here.get(4), here.get(5)}));
    HeadlessRun.run(sim, c, "AWAY", 30, s -> {});
    sim.step();
    assertThat(c.uop().uo(Uop.ATPERCH)).isFalse();
    assertThat(c.registers().bit(IoKind.DO, 5)).isFalse();
  }

  @Test
  void withoutRemoteThePlcCannotStartAnything() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("PNS0101", true, "R[1]=1"));
    ProductionSetup.Robot s = setup(Selection.PNS, NO_RSR, List.of());
    ProductionSetup.Robot local = new ProductionSetup.Robot(true, false, s.selection(), s.pnsBase(), 0, NO_RSR, s.styles(),
        0.2, false, false, Optional.empty(), List.of(), List.of(), 0.008, List.of(), false);
    cell(sim, local);
    Uop u = c.uop();
    u.setUi(Uop.SEL1, true);
    u.setUi(Uop.PNSTROBE, true);
    u.setUi(Uop.PROD_START, true);
    sim.step();
    u.setUi(Uop.PROD_START, false);
    steps(sim, 3);
    assertThat(u.uo(Uop.CMDENBL)).isFalse();
    assertThat(c.registers().number(1)).isZero();
    assertThat(c.activeAlarms()).isEmpty();
  }

  @Test
  void styleRunsTheStyleTablesProgramOnProdStartsFallingEdge() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("STYLE_C", true, "R[1]=3"));
    cell(sim, setup(Selection.STYLE, NO_RSR, List.of()));
    Uop u = c.uop();
    u.setUi(Uop.SEL1, true);
    u.setUi(Uop.SEL1 + 1, true); // style 3
    u.setUi(Uop.PROD_START, true);
    steps(sim, 2);
    assertThat(c.registers().number(1)).isZero();
    u.setUi(Uop.PROD_START, false);
    steps(sim, 2);
    assertThat(c.registers().number(1)).isEqualTo(3);
    assertThat(u.uo(Uop.ACK1)).isTrue();
    assertThat(u.uo(Uop.ACK1 + 1)).isTrue();
    // style 4 has no program: INTP-105
    u.setUi(Uop.SEL1, false);
    u.setUi(Uop.SEL1 + 1, false);
    u.setUi(Uop.SEL1 + 2, true);
    u.setUi(Uop.PROD_START, true);
    sim.step();
    u.setUi(Uop.PROD_START, false);
    steps(sim, 2);
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-105");
    assertThat(c.warnings().get(0).message()).contains("style 4");
  }

  @Test
  void homeRunsTheHomeProgramAndCstopiAbortsOnlyWhenSetTo() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("GOHOME", false, "R[7]=R[7]+1"));
    c.saveProgram(program("LONG", true, "WAIT 5.00(sec)", "R[1]=1"));
    ProductionSetup.Robot s = setup(Selection.OTHER, NO_RSR, List.of());
    ProductionSetup.Robot withHome = new ProductionSetup.Robot(true, true, Selection.OTHER, 0, 0, NO_RSR, s.styles(), 0.2,
        false, false, Optional.of("GOHOME"), List.of(), List.of(), 0.008, List.of(), false);
    cell(sim, withHome);
    Uop u = c.uop();
    u.setUi(Uop.HOME, true);
    steps(sim, 3);
    assertThat(c.registers().number(7)).isEqualTo(1);
    // CSTOPI with $USE_ABORT false: the program runs on
    c.run("LONG", 1, true);
    steps(sim, 2);
    u.setUi(Uop.CSTOPI, true);
    steps(sim, 2);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.RUNNING);
    u.setUi(Uop.CSTOPI, false);
    ProductionSetup.Robot aborting = new ProductionSetup.Robot(true, true, Selection.OTHER, 0, 0, NO_RSR, s.styles(), 0.2,
        false, true, Optional.of("GOHOME"), List.of(), List.of(), 0.008, List.of(), false);
    c.configureProduction(aborting);
    steps(sim, 2);
    u.setUi(Uop.CSTOPI, true);
    steps(sim, 2);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(c.registers().number(1)).isZero();
  }

  @Test
  void aPlcSequenceStepsOnItsConditionsAndDelays() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("PNS0001", true, "R[1]=R[1]+1"));
    java.util.Map<Signal, Boolean> on = new java.util.LinkedHashMap<>();
    on.put(new Signal("UI", 1), true);
    on.put(new Signal("UI", 2), true);
    on.put(new Signal("UI", 3), true);
    on.put(new Signal("UI", 8), true);
    List<ProductionSetup.PlcStep> plc = List.of(
        new ProductionSetup.PlcStep(Optional.empty(), 0, on, "safety"),
        new ProductionSetup.PlcStep(Optional.of(java.util.Map.entry(new Signal("UO", 1), true)), 0,
            java.util.Map.of(new Signal("UI", 9), true), "PNS1"),
        new ProductionSetup.PlcStep(Optional.empty(), 0.1, java.util.Map.of(new Signal("UI", 17), true), "strobe"),
        new ProductionSetup.PlcStep(Optional.of(java.util.Map.entry(new Signal("UO", 19), true)), 0,
            java.util.Map.of(new Signal("UI", 18), true), "prod start"),
        new ProductionSetup.PlcStep(Optional.empty(), 0.1, java.util.Map.of(new Signal("UI", 18), false), "release"));
    ProductionSetup.Robot s = new ProductionSetup.Robot(true, true, Selection.PNS, 0, 0, NO_RSR, new TreeMap<>(), 0.2,
        false, false, Optional.empty(), List.of(), List.of(), 0.008, plc, true);
    c.configureProduction(s);
    // before the sequence ran, the active-low inputs are off: nothing may start
    assertThat(c.uop().ui(Uop.IMSTP)).isFalse();
    steps(sim, 10);
    // 0.1 s delay before the strobe: not yet
    assertThat(c.uop().plcStep()).isEqualTo(2);
    steps(sim, 20);
    assertThat(c.uop().plcStep()).isEqualTo(4);
    assertThat(c.registers().number(1)).isZero();
    steps(sim, 30);
    assertThat(c.uop().plcDone()).isTrue();
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.activeAlarms()).isEmpty();
    // a restarted PLC begins again with every input off and runs its sequence once more (its first
    // step closes the safety inputs before the controller reads them, so no SRVO-037)
    c.uop().restartPlc();
    assertThat(c.uop().plcStep()).isZero();
    assertThat(c.uop().ui(Uop.PNSTROBE)).isFalse();
    steps(sim, 60);
    assertThat(c.registers().number(1)).isEqualTo(2);
    assertThat(c.activeAlarms()).isEmpty();
  }
}
