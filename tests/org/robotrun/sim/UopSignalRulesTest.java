package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.sim.TaskProgs.program;
import static org.robotrun.sim.TaskProgs.steps;

import java.util.Collections;
import java.util.List;
import java.util.Map;
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
 * The UOP tables of docs/production.md, signal by signal, with the edges they act on: what each
 * input does (and does not do on the other edge, without CMDENBL, or with the UOP disabled), and
 * when each output is ON. Complements {@link UopTest} (the handshakes end to end).
 */
class UopSignalRulesTest {
  private static final List<Integer> NO_RSR = List.of(0, 0, 0, 0, 0, 0, 0, 0);

  /** A setup with the given switches; no PLC sequence (the active-low inputs start ON). */
  private static ProductionSetup.Robot setup(boolean uop, Selection sel, int pnsBase, int rsrBase, List<Integer> rsr,
      double ackSec, boolean continueOnly, Optional<String> home, List<ReferencePosition> refs) {
    return new ProductionSetup.Robot(uop, true, sel, pnsBase, rsrBase, rsr, new TreeMap<>(Map.of(1, "STY1")), ackSec,
        continueOnly, false, home, refs, List.of(), 0.008, List.of(), false);
  }

  private static ProductionSetup.Robot other() {
    return setup(true, Selection.OTHER, 0, 0, NO_RSR, 0.2, true, Optional.empty(), List.of());
  }

  private static Controller configured(Simulation sim, ProductionSetup.Robot s) {
    Controller c = sim.controllers().get(0);
    c.configureProduction(s);
    sim.step();
    return c;
  }

  /** UI[i] ON for a tick, then OFF for a tick: one rising and one falling edge. */
  private static void pulse(Simulation sim, Uop u, int ui) {
    u.setUi(ui, true);
    sim.step();
    u.setUi(ui, false);
    sim.step();
  }

  @Test
  void withTheUopDisabledTheInputsAreIgnoredButTheOutputsShown() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "WAIT 1.00(sec)", "R[1]=1"));
    configured(sim, setup(false, Selection.OTHER, 0, 0, NO_RSR, 0.2, true, Optional.empty(), List.of()));
    Uop u = c.uop();
    assertThat(u.enabled()).isFalse();
    assertThat(u.setup()).isPresent();
    c.run("MAIN", 1, true);
    steps(sim, 2);
    u.setUi(Uop.IMSTP, false);
    u.setUi(Uop.HOLD, false);
    u.setUi(Uop.ENBL, false);
    u.setUi(Uop.SFSPD, false);
    steps(sim, 3);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.RUNNING);
    assertThat(c.overridePct()).isEqualTo(100);
    assertThat(u.uo(Uop.CMDENBL)).isFalse();
    assertThat(u.uo(Uop.HELD)).isFalse();
    assertThat(u.uo(Uop.PROGRUN)).isTrue();
    assertThat(u.uo(Uop.SYSRDY)).isTrue();
    // no setup at all: "Enable UI signals: FALSE"
    c.configureProduction(null);
    assertThat(u.enabled()).isFalse();
    assertThat(u.setup()).isEmpty();
    assertThat(u.plcDone()).isTrue();
  }

  @Test
  void imstpOffIsOneServoAlarmThatFaultResetClearsOnlyOnceImstpIsOnAgain() {
    Simulation sim = ControllerTest.cell();
    Controller c = configured(sim, other());
    Uop u = c.uop();
    u.setUi(Uop.IMSTP, false);
    steps(sim, 10);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-037");
    assertThat(c.alarmHistory()).extracting(ControllerAlarm::code).containsExactly("SRVO-037");
    assertThat(c.servoOff()).isTrue();
    assertThat(u.uo(Uop.SYSRDY)).isFalse();
    assertThat(u.uo(Uop.FAULT)).isTrue();
    // FAULT RESET while *IMSTP is still off: the stop goes on (servo stays off)
    pulse(sim, u, Uop.FAULT_RESET);
    steps(sim, 2);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-037");
    assertThat(u.uo(Uop.SYSRDY)).isFalse();
    // *IMSTP back on alone does not clear it either
    u.setUi(Uop.IMSTP, true);
    steps(sim, 3);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-037");
    pulse(sim, u, Uop.FAULT_RESET);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(u.uo(Uop.SYSRDY)).isTrue();
    assertThat(u.uo(Uop.FAULT)).isFalse();
    assertThat(u.uo(Uop.CMDENBL)).isTrue();
  }

  @Test
  void faultResetActsOnItsRisingEdgeOnlyAndNotWhileAnEstopIsPressed() {
    Simulation sim = ControllerTest.cell();
    Controller c = configured(sim, other());
    Uop u = c.uop();
    u.setUi(Uop.FAULT_RESET, true);
    steps(sim, 2);
    c.raiseAlarm("SRVO-050", "Collision Detect alarm");
    steps(sim, 5); // held ON: no new rising edge
    assertThat(c.activeAlarms()).hasSize(1);
    u.setUi(Uop.FAULT_RESET, false);
    steps(sim, 2); // the falling edge does nothing
    assertThat(c.activeAlarms()).hasSize(1);
    pulse(sim, u, Uop.FAULT_RESET);
    assertThat(c.activeAlarms()).isEmpty();
    // E-stop pressed: FAULT RESET (like RESET) does nothing
    c.emergencyStop(false);
    steps(sim, 2);
    assertThat(u.uo(Uop.SYSRDY)).isFalse();
    pulse(sim, u, Uop.FAULT_RESET);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-001");
    c.releaseEmergencyStop();
    pulse(sim, u, Uop.FAULT_RESET);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(u.uo(Uop.SYSRDY)).isTrue();
  }

  @Test
  void enblOrSfspdOffHoldsTheProgramAndStartIsIgnoredUntilTheyAreBack() {
    for (int input : new int[] {Uop.ENBL, Uop.SFSPD, Uop.HOLD}) {
      Simulation sim = ControllerTest.cell();
      Controller c = sim.controllers().get(0);
      c.saveProgram(program("MAIN", false, "WAIT 0.20(sec)", "R[1]=1"));
      configured(sim, other());
      Uop u = c.uop();
      c.run("MAIN", 1, true);
      steps(sim, 2);
      u.setUi(input, false);
      steps(sim, 2);
      String name = Uop.UI_NAMES.get(input);
      assertThat(c.status().state()).as(name).isEqualTo(ExecutionStatus.State.PAUSED);
      assertThat(u.uo(Uop.PAUSED)).as(name).isTrue();
      assertThat(u.uo(Uop.CMDENBL)).as(name).isFalse();
      assertThat(u.uo(Uop.HELD)).as(name).isEqualTo(input == Uop.HOLD); // HELD follows *HOLD only
      pulse(sim, u, Uop.START);
      steps(sim, 80);
      assertThat(c.status().state()).as(name).isEqualTo(ExecutionStatus.State.PAUSED);
      assertThat(c.registers().number(1)).as(name).isZero();
      u.setUi(input, true);
      steps(sim, 2);
      assertThat(u.uo(Uop.CMDENBL)).as(name).isTrue();
      pulse(sim, u, Uop.START);
      steps(sim, 80);
      assertThat(c.registers().number(1)).as(name).isEqualTo(1);
      assertThat(c.activeAlarms()).as(name).isEmpty();
    }
  }

  @Test
  void startOnlyContinuesUnlessStartForContinueOnlyIsOff() {
    for (boolean continueOnly : new boolean[] {true, false}) {
      Simulation sim = ControllerTest.cell();
      Controller c = sim.controllers().get(0);
      c.saveProgram(program("MAIN", false, "R[1]=R[1]+1", "R[2]=R[2]+1"));
      configured(sim, setup(true, Selection.OTHER, 0, 0, NO_RSR, 0.2, continueOnly, Optional.empty(), List.of()));
      Uop u = c.uop();
      // the pendant selects MAIN with the cursor on line 2
      c.interpreter().select("MAIN");
      c.interpreter().setCursor(2);
      double r1 = c.registers().number(1);
      double r2 = c.registers().number(2);
      assertThat(c.status()).isEqualTo(new ExecutionStatus("MAIN", 2, ExecutionStatus.State.IDLE));
      u.setUi(Uop.START, true);
      steps(sim, 3);
      assertThat(c.registers().number(2)).isEqualTo(r2); // the rising edge does nothing
      u.setUi(Uop.START, false);
      steps(sim, 3);
      if (continueOnly) {
        assertThat(c.registers().number(1)).isEqualTo(r1);
        assertThat(c.registers().number(2)).isEqualTo(r2);
      } else {
        // started at the cursor, not at line 1
        assertThat(c.registers().number(1)).isEqualTo(r1);
        assertThat(c.registers().number(2)).isEqualTo(r2 + 1);
      }
    }
  }

  @Test
  void prodStartInOtherRunsThePendantsProgramFromLineOneAndRefusesARunningOne() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "R[1]=R[1]+1", "WAIT 0.20(sec)", "R[2]=1"));
    configured(sim, other());
    Uop u = c.uop();
    // nothing selected yet: refused, a warning
    pulse(sim, u, Uop.PROD_START);
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-105");
    assertThat(c.warnings().get(0).message()).contains("no program selected");
    assertThat(u.lastRefusal()).isEqualTo("no program selected");
    // the pendant selects MAIN at line 3; PROD_START runs it from line 1
    c.interpreter().select("MAIN");
    c.interpreter().setCursor(3);
    pulse(sim, u, Uop.PROD_START);
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.RUNNING);
    // a second PROD_START while it runs: refused, and it goes on
    pulse(sim, u, Uop.PROD_START);
    assertThat(c.warnings()).hasSize(2);
    assertThat(c.warnings().get(1).message()).contains("MAIN is already running");
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.RUNNING);
    steps(sim, 60);
    assertThat(c.registers().number(2)).isEqualTo(1);
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.activeAlarms()).isEmpty();
  }

  @Test
  void homeRunsOnlyOnItsRisingEdgeWithCmdenblAndARefusalIsNamed() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("GOHOME", false, "R[7]=R[7]+1", "WAIT 0.10(sec)"));
    configured(sim, setup(true, Selection.OTHER, 0, 0, NO_RSR, 0.2, true, Optional.of("GOHOME"), List.of()));
    Uop u = c.uop();
    // T1: no CMDENBL, HOME ignored
    c.setMode(RobotControl.Mode.T1);
    pulse(sim, u, Uop.HOME);
    steps(sim, 3);
    assertThat(c.registers().number(7)).isZero();
    c.setMode(RobotControl.Mode.AUTO);
    steps(sim, 1);
    u.setUi(Uop.HOME, true);
    steps(sim, 3);
    assertThat(c.registers().number(7)).isEqualTo(1);
    assertThat(c.tasks().isRunning("GOHOME")).isTrue();
    // the falling edge does not run it again; a second rising edge while it runs is refused
    u.setUi(Uop.HOME, false);
    steps(sim, 2);
    u.setUi(Uop.HOME, true);
    steps(sim, 2);
    assertThat(c.registers().number(7)).isEqualTo(1);
    assertThat(u.lastRefusal()).startsWith("HOME: ").contains("PROG-007");
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-105");
    assertThat(c.activeAlarms()).isEmpty();
  }

  @Test
  void cstopiClearsTheRsrQueueOnItsRisingEdge() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("RSR0112", false, "R[1]=R[1]+1", "WAIT 0.20(sec)"));
    c.saveProgram(program("RSR0120", false, "R[2]=R[2]+1"));
    configured(sim, setup(true, Selection.RSR, 0, 100, List.of(12, 20, 0, 0, 0, 0, 0, 0), 0.2, true, Optional.empty(),
        List.of()));
    Uop u = c.uop();
    u.setUi(Uop.SEL1, true);      // RSR1: RSR(100 + 12) starts
    steps(sim, 2);
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(u.selectedProgram()).isEqualTo("RSR0112");
    u.setUi(Uop.SEL1 + 1, true);  // RSR2 while it runs: queued
    steps(sim, 2);
    u.setUi(Uop.CSTOPI, true);    // the queue is cleared; without cstopiAborts RSR0112 runs on
    steps(sim, 2);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.RUNNING);
    steps(sim, 80);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(c.registers().number(2)).isZero();
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.warnings()).isEmpty();
  }

  @Test
  void rsrAckIsAPulseOfAckPulseMsAndAnRsrWithoutCmdenblIsIgnored() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("RSR0003", false, "R[1]=R[1]+1"));
    configured(sim, setup(true, Selection.RSR, 0, 0, List.of(0, 0, 0, 0, 0, 0, 0, 3), 0.1, true, Optional.empty(),
        List.of()));
    Uop u = c.uop();
    c.setMode(RobotControl.Mode.T2);
    u.setUi(Uop.SEL1 + 7, true);
    steps(sim, 3);
    assertThat(c.registers().number(1)).isZero();
    assertThat(u.uo(Uop.ACK1 + 7)).isFalse();
    u.setUi(Uop.SEL1 + 7, false);
    c.setMode(RobotControl.Mode.AUTO);
    steps(sim, 2);
    u.setUi(Uop.SEL1 + 7, true); // RSR8 = program number 3
    sim.step();
    assertThat(c.registers().number(1)).isEqualTo(1);
    // ACK8 is on for 0.1 s = 25 ticks, the other ACKs stay off
    int on = 0;
    for (int k = 0; k < 60; k++) {
      if (u.uo(Uop.ACK1 + 7)) {
        on++;
      }
      for (int i = 0; i < 7; i++) {
        assertThat(u.uo(Uop.ACK1 + i)).isFalse();
      }
      sim.step();
    }
    assertThat(on).isBetween(24, 26);
    assertThat(u.uo(Uop.SNACK)).isFalse();
  }

  @Test
  void pnsShowsTheNumberOnSnoInBinaryAndNeedsCmdenblForTheStrobe() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("PNS0200", false, "R[1]=200"));
    configured(sim, setup(true, Selection.PNS, 0, 0, NO_RSR, 0.2, true, Optional.empty(), List.of()));
    Uop u = c.uop();
    int n = 200; // 1100 1000: PNS4, PNS7, PNS8
    for (int b = 0; b < 8; b++) {
      u.setUi(Uop.SEL1 + b, (n >> b & 1) != 0);
    }
    // without CMDENBL the strobe is not read
    u.setTpEnabled(true);
    pulse(sim, u, Uop.PNSTROBE);
    assertThat(u.selectedNumber()).isZero();
    assertThat(u.selectedProgram()).isEmpty();
    u.setTpEnabled(false);
    steps(sim, 1);
    u.setUi(Uop.PNSTROBE, true);
    steps(sim, 2);
    assertThat(u.selectedNumber()).isEqualTo(200);
    assertThat(u.selectedProgram()).isEqualTo("PNS0200");
    for (int b = 0; b < 8; b++) {
      assertThat(u.uo(Uop.ACK1 + b)).as("SNO%d", b + 1).isEqualTo((n >> b & 1) != 0);
    }
    pulse(sim, u, Uop.PROD_START);
    assertThat(c.registers().number(1)).isEqualTo(200);
    // PNS number 0 at the strobe: nothing selected, PROD_START refused
    for (int b = 0; b < 8; b++) {
      u.setUi(Uop.SEL1 + b, false);
    }
    u.setUi(Uop.PNSTROBE, false);
    steps(sim, 2);
    u.setUi(Uop.PNSTROBE, true);
    steps(sim, 2);
    assertThat(u.selectedProgram()).isEmpty();
    for (int b = 0; b < 8; b++) {
      assertThat(u.uo(Uop.ACK1 + b)).isFalse();
    }
    pulse(sim, u, Uop.PROD_START);
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-105");
    assertThat(c.warnings().get(0).message()).contains("PNS number 0");
  }

  @Test
  void styleReadsItsNumberAtProdStartAndPulsesSnack() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("STY1", false, "R[1]=R[1]+1"));
    configured(sim, setup(true, Selection.STYLE, 0, 0, NO_RSR, 0.2, true, Optional.empty(), List.of()));
    Uop u = c.uop();
    u.setUi(Uop.SEL1, true);
    u.setUi(Uop.PROD_START, true);
    steps(sim, 2);
    assertThat(u.uo(Uop.SNACK)).isFalse();
    u.setUi(Uop.PROD_START, false);
    steps(sim, 2);
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(u.selectedProgram()).isEqualTo("STY1");
    assertThat(u.selectedNumber()).isEqualTo(1);
    assertThat(u.uo(Uop.SNACK)).isTrue();
    assertThat(u.uo(Uop.ACK1)).isTrue();
    steps(sim, 60);
    assertThat(u.uo(Uop.SNACK)).isFalse();
    assertThat(u.uo(Uop.ACK1)).isTrue(); // SNO keeps the number
  }

  @Test
  void theOtherOutputsFollowTheirConditions() {
    Simulation sim = ControllerTest.cell();
    Controller c = configured(sim, other());
    Uop u = c.uop();
    assertThat(u.uo(Uop.BATALM)).isFalse();
    assertThat(u.uo(20)).isFalse();
    assertThat(u.uo(Uop.FAULT)).isFalse();
    assertThat(u.uo(Uop.TPENBL)).isFalse();
    u.setTpEnabled(true);
    assertThat(u.tpEnabled()).isTrue();
    sim.step();
    assertThat(u.uo(Uop.TPENBL)).isTrue();
    assertThat(u.uo(Uop.CMDENBL)).isFalse();
    u.setTpEnabled(false);
    // step mode takes CMDENBL away
    c.setStepMode(true);
    sim.step();
    assertThat(u.cmdEnabled()).isFalse();
    assertThat(u.uo(Uop.CMDENBL)).isFalse();
    c.setStepMode(false);
    sim.step();
    assertThat(u.uo(Uop.CMDENBL)).isTrue();
    // a warning is no FAULT, an alarm is
    c.saveProgram(program("MAIN", false, "RUN NOPE"));
    c.run("MAIN", 1, true);
    steps(sim, 3);
    assertThat(c.warnings()).isNotEmpty();
    assertThat(u.uo(Uop.FAULT)).isFalse();
    c.raiseAlarm("SRVO-050", "Collision Detect alarm");
    sim.step();
    assertThat(u.uo(Uop.FAULT)).isTrue();
    assertThat(u.uo(Uop.SYSRDY)).isFalse(); // SRVO-050 is a servo alarm
    c.reset();
    sim.step();
    assertThat(u.uo(Uop.FAULT)).isFalse();
    assertThat(u.uo(Uop.SYSRDY)).isTrue();
    // the arm moving under MOVE_TO is BUSY, not PROGRUN
    c.moveTo(new org.robotrun.program.Position.Joint(10, 0, 0, 0, -90, 0), 0, 0);
    steps(sim, 3);
    assertThat(u.uo(Uop.BUSY)).isTrue();
    assertThat(u.uo(Uop.PROGRUN)).isFalse();
  }

  @Test
  void aReferencePositionIsOnWithinItsToleranceOnEveryJointAndOnlyNumberOneIsAtperch() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    List<Double> home = List.of(0.0, 0.0, 0.0, 0.0, -90.0, 0.0);
    // reference position 2 at HOME (its DO follows, ATPERCH does not); 1 three degrees off on J1
    ReferencePosition two = new ReferencePosition(2, "HOME", home, Collections.nCopies(6, 1.0),
        Optional.of(new Signal("DO", 12)));
    ReferencePosition one = new ReferencePosition(1, "PERCH", List.of(3.0, 0.0, 0.0, 0.0, -90.0, 0.0),
        List.of(2.0, 1.0, 1.0, 1.0, 1.0, 1.0), Optional.of(new Signal("DO", 11)));
    configured(sim, setup(true, Selection.OTHER, 0, 0, NO_RSR, 0.2, true, Optional.empty(), List.of(two, one)));
    Uop u = c.uop();
    assertThat(c.registers().bit(IoKind.DO, 12)).isTrue();
    assertThat(c.registers().bit(IoKind.DO, 11)).isFalse();
    assertThat(u.uo(Uop.ATPERCH)).isFalse();
    assertThat(u.within(two)).isTrue();
    assertThat(u.within(one)).isFalse();
    // J1 at 1.5 deg: inside PERCH's 2 deg on J1 (3 - 1.5), outside HOME's 1 deg
    c.moveTo(new org.robotrun.program.Position.Joint(1.5, 0, 0, 0, -90, 0), 0, 0);
    steps(sim, 400);
    assertThat(c.currentJoints().element(1)).isCloseTo(1.5, org.assertj.core.data.Offset.offset(1e-6));
    assertThat(u.uo(Uop.ATPERCH)).isTrue();
    assertThat(c.registers().bit(IoKind.DO, 11)).isTrue();
    assertThat(c.registers().bit(IoKind.DO, 12)).isFalse();
    assertThat(u.within(one)).isTrue();
    assertThat(u.within(two)).isFalse();
    // on the edge of the tolerance counts as inside: J1 at 1.0 is exactly 2 deg from PERCH
    c.moveTo(new org.robotrun.program.Position.Joint(1.0, 0, 0, 0, -90, 0), 0, 0);
    steps(sim, 400);
    assertThat(u.within(one)).isTrue();
    assertThat(u.within(two)).isTrue();
    assertThat(u.uo(Uop.ATPERCH)).isTrue();
    assertThat(c.registers().bit(IoKind.DO, 12)).isTrue();
  }

  @Test
  void aPlcStepMayWaitForASignalToGoOff() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    List<ProductionSetup.PlcStep> plc = List.of(
        new ProductionSetup.PlcStep(Optional.of(Map.entry(new Signal("DO", 4), false)), 0,
            Map.of(new Signal("DI", 1), true), "DO[4] off"),
        new ProductionSetup.PlcStep(Optional.of(Map.entry(new Signal("DO", 4), true)), 0.05,
            Map.of(new Signal("DI", 2), true), "DO[4] on"));
    c.registers().setBit(IoKind.DO, 4, true);
    // UOP inputs off ("Enable UI signals: FALSE"): the sequence still runs, on DI here
    c.configureProduction(new ProductionSetup.Robot(false, true, Selection.OTHER, 0, 0, NO_RSR, new TreeMap<>(), 0.2,
        false, false, Optional.empty(), List.of(), List.of(), 0.008, plc, true));
    Uop u = c.uop();
    steps(sim, 5);
    assertThat(u.plcStep()).isZero();
    assertThat(c.registers().bit(IoKind.DI, 1)).isFalse();
    c.registers().setBit(IoKind.DO, 4, false);
    sim.step();
    assertThat(u.plcStep()).isEqualTo(1);
    assertThat(c.registers().bit(IoKind.DI, 1)).isTrue();
    c.registers().setBit(IoKind.DO, 4, true);
    steps(sim, 11); // the condition holds, then 50 ms (12.5 ticks) must pass
    assertThat(c.registers().bit(IoKind.DI, 2)).isFalse();
    assertThat(u.plcDone()).isFalse();
    steps(sim, 3);
    assertThat(c.registers().bit(IoKind.DI, 2)).isTrue();
    assertThat(u.plcDone()).isTrue();
    assertThat(u.simSec()).isCloseTo(sim.timeSec(), org.assertj.core.data.Offset.offset(1e-9));
  }

  @Test
  void restartPlcTurnsEveryInputOff() {
    Simulation sim = ControllerTest.cell();
    Controller c = configured(sim, other());
    Uop u = c.uop();
    for (int i = 1; i <= 18; i++) {
      u.setUi(i, true);
    }
    u.restartPlc();
    for (int i = 1; i <= 18; i++) {
      assertThat(u.ui(i)).as(Uop.UI_NAMES.get(i)).isFalse();
    }
    assertThat(u.plcStep()).isZero();
  }

  @Test
  void imstpOffRaisesSrvo037EvenWithAnotherAlarmActive() {
    Simulation sim = ControllerTest.cell();
    Controller c = configured(sim, other());
    c.raiseAlarm("SRVO-050", "Collision Detect alarm");
    c.uop().setUi(Uop.IMSTP, false);
    steps(sim, 2);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-050", "SRVO-037");
  }

  @Test
  void theControllerDrivesTheUoOutputsAStrayWriteLastsOneTick() {
    Simulation sim = ControllerTest.cell();
    Controller c = configured(sim, other());
    for (int o : new int[] {Uop.BATALM, 20, Uop.FAULT, Uop.HELD, Uop.SNACK}) {
      c.registers().setBit(IoKind.UO, o, true);
    }
    sim.step();
    for (int o : new int[] {Uop.BATALM, 20, Uop.FAULT, Uop.HELD, Uop.SNACK}) {
      assertThat(c.uop().uo(o)).as(Uop.UO_NAMES.get(o)).isFalse();
    }
  }

  @Test
  void rsrRequestsQueueInOrderWhileTheControllerIsBusyAndPnstrobeIsNoRsr() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("RSR0001", false, "R[1]=R[9]+1", "R[9]=R[1]", "WAIT 0.10(sec)"));
    c.saveProgram(program("RSR0002", false, "R[2]=R[9]+1", "R[9]=R[2]"));
    c.saveProgram(program("RSR0003", false, "R[3]=R[9]+1", "R[9]=R[3]"));
    c.saveProgram(program("BUSYTASK", false, "WAIT 0.10(sec)"));
    c.saveProgram(program("STARTER", false, "RUN BUSYTASK"));
    configured(sim, setup(true, Selection.RSR, 0, 0, List.of(1, 2, 3, 0, 0, 0, 0, 0), 0.2, true, Optional.empty(),
        List.of()));
    Uop u = c.uop();
    // in RSR mode UI[17] (PNSTROBE) is no ninth RSR
    pulse(sim, u, Uop.PNSTROBE);
    assertThat(c.warnings()).isEmpty();
    assertThat(c.activeAlarms()).isEmpty();
    // main program idle but a RUN task still runs: the controller is busy, RSR1 waits
    c.run("STARTER", 1, true);
    steps(sim, 3);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(c.busy()).isTrue();
    u.setUi(Uop.SEL1, true);
    steps(sim, 2);
    assertThat(c.registers().number(1)).isZero();
    // RSR3 then RSR2 come while it waits: they run after RSR1, in the order they came
    u.setUi(Uop.SEL1 + 2, true);
    steps(sim, 2);
    u.setUi(Uop.SEL1 + 1, true);
    steps(sim, 150);
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.registers().number(3)).isEqualTo(2);
    assertThat(c.registers().number(2)).isEqualTo(3);
    assertThat(c.warnings()).isEmpty();
  }

  @Test
  void aPlcStartOfAMotionProgramWhileATaskHoldsGroupOneIsRefusedWithProg040() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("HOLDER", true, "WAIT 1.00(sec)"));
    c.saveProgram(program("MOVER", true, "R[1]=1"));
    configured(sim, other());
    assertThat(c.tasks().run("HOLDER")).isEmpty();
    c.interpreter().select("MOVER");
    pulse(sim, c.uop(), Uop.PROD_START);
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-105");
    assertThat(c.warnings().get(0).message()).contains("PROG-040").contains("HOLDER holds group 1");
    assertThat(c.uop().lastRefusal()).contains("PROG-040");
    assertThat(c.registers().number(1)).isZero();
    assertThat(c.tasks().isRunning("HOLDER")).isTrue();
  }

  @Test
  void stepsWithoutConditionOrDelayPassInOneTickADelayedOneEndsItsTick() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    List<ProductionSetup.PlcStep> plc = List.of(
        new ProductionSetup.PlcStep(Optional.empty(), 0, Map.of(new Signal("DI", 1), true), "a"),
        new ProductionSetup.PlcStep(Optional.empty(), 0, Map.of(new Signal("DI", 2), true), "b"),
        new ProductionSetup.PlcStep(Optional.empty(), 0, Map.of(new Signal("DI", 3), true), "c"),
        new ProductionSetup.PlcStep(Optional.empty(), 0.004, Map.of(new Signal("DI", 4), true), "d"),
        new ProductionSetup.PlcStep(Optional.empty(), 0, Map.of(new Signal("DI", 5), true), "e"));
    c.configureProduction(new ProductionSetup.Robot(false, true, Selection.OTHER, 0, 0, NO_RSR, new TreeMap<>(), 0.2,
        false, false, Optional.empty(), List.of(), List.of(), 0.008, plc, true));
    sim.step();
    assertThat(c.uop().plcStep()).isEqualTo(3);
    assertThat(c.registers().bit(IoKind.DI, 3)).isTrue();
    assertThat(c.registers().bit(IoKind.DI, 4)).isFalse();
    sim.step(); // d's 4 ms have passed: d fires and ends the tick
    assertThat(c.uop().plcStep()).isEqualTo(4);
    assertThat(c.registers().bit(IoKind.DI, 5)).isFalse();
    sim.step();
    assertThat(c.uop().plcDone()).isTrue();
    assertThat(c.registers().bit(IoKind.DI, 5)).isTrue();
  }
}
