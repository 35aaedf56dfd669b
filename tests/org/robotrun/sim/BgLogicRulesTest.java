package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.robotrun.sim.TaskProgs.program;
import static org.robotrun.sim.TaskProgs.steps;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.program.IoKind;

/**
 * docs/production.md's BG Logic rules as a table: every statement kind it lists as refused is
 * refused naming the line and the statement, every kind it allows is taken; at most
 * {@value BgLogic#SLOTS} slots, each program once; F2 START re-checks the program; the scan runs
 * every {@code bgScanMs} in every mode and state, counting PULSE and TIMER by the time between
 * scans; {@code $MIX_BG[i].$STATUS} reads 2 running, 1 stopped, 0 empty.
 */
class BgLogicRulesTest {

  /** A refused statement on line 2 (after an allowed one) and a word the refusal must name. */
  private record Refused(String line, String names) {}

  private static final List<Refused> REFUSED = List.of(
      new Refused("J P[1] 100% FINE", "motion"),
      new Refused("L P[1] 100mm/sec FINE", "motion"),
      new Refused("WAIT 1.00(sec)", "WAIT"),
      new Refused("WAIT DI[1]=ON", "WAIT"),
      new Refused("CALL OTHER", "CALL"),
      new Refused("IF R[1]=1,CALL OTHER", "CALL"),
      new Refused("SELECT R[1]=1,CALL OTHER", "CALL"),
      new Refused("RUN OTHER", "RUN"),
      new Refused("PAUSE", "PAUSE"),
      new Refused("ABORT", "ABORT"),
      new Refused("UALM[1]", "UALM"),
      new Refused("MESSAGE[HELLO]", "MESSAGE"),
      new Refused("OVERRIDE=50%", "OVERRIDE"),
      new Refused("UFRAME_NUM=1", "UFRAME_NUM"),
      new Refused("UTOOL_NUM=1", "UTOOL_NUM"),
      new Refused("UFRAME[1]=PR[1]", "UFRAME"),
      new Refused("UTOOL[1]=PR[1]", "UTOOL"),
      new Refused("PAYLOAD[1]", "PAYLOAD"),
      new Refused("PR[1]=LPOS", "PR[]"),
      new Refused("PR[1,1]=5", "PR[]"),
      new Refused("IF R[1]=1,PR[1,1]=5", "PR[]"),
      new Refused("SR[1]=R[1]", "SR[]"),
      new Refused("$WAITTMOUT=100", "system variable"),
      new Refused("SKIP CONDITION DI[1]=ON", "SKIP CONDITION"),
      new Refused("OFFSET CONDITION PR[1]", "OFFSET CONDITION"),
      new Refused("MONITOR WATCH", "MONITOR"));

  /** Every kind the docs allow, in one program that the slot must take and run. */
  private static final String[] ALLOWED = {
      "! counts and copies",
      "R[1]=R[1]+1",
      "DO[2]=ON",
      "F[3]=(DI[4] AND !DO[5])",
      "IF R[1]=1,DO[6]=PULSE,0.2sec",
      "TIMER[1]=START",
      "FOR R[2]=1 TO 2",
      "R[3]=R[3]+1",
      "ENDFOR",
      "IF (R[1]>0) THEN",
      "R[4]=R[1]",
      "ELSE",
      "R[4]=0",
      "ENDIF",
      "SELECT R[9]=1,JMP LBL[1]",
      "       ELSE,JMP LBL[2]",
      "LBL[1]",
      "R[7]=99",
      "LBL[2]",
      "//R[8]=1",
      "",
      "END",
      "R[8]=1"};

  @Test
  void everyStatementTheDocsRefuseIsRefusedNamingItsLineAndKind() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("OTHER", false, "R[9]=1"));
    for (int k = 0; k < REFUSED.size(); k++) {
      Refused r = REFUSED.get(k);
      String name = "BG" + k;
      c.saveProgram(program(name, false, "R[1]=1", r.line()));
      Optional<String> why = BgLogic.refusal(c.program(name).orElseThrow());
      assertThat(why).as(r.line()).isPresent();
      assertThat(why.get()).as(r.line()).startsWith(name + " line 2: ").endsWith(" is not allowed in background logic")
          .contains(r.names());
      assertThat(c.bgLogic().add(name)).as(r.line()).isEqualTo(why);
    }
    assertThat(c.bgLogic().slots()).isEmpty();
    // a CALL in a later SELECT case and in its ELSE too
    c.saveProgram(program("SELCASE", false, "SELECT R[1]=1,JMP LBL[1]", "       =2,CALL OTHER", "LBL[1]"));
    assertThat(c.bgLogic().add("SELCASE")).get().asString().startsWith("SELCASE line 2: CALL");
    c.saveProgram(program("SELELSE", false, "SELECT R[1]=1,JMP LBL[1]", "       ELSE,CALL OTHER", "LBL[1]"));
    assertThat(c.bgLogic().add("SELELSE")).get().asString().startsWith("SELELSE line 2: CALL");
    // a motion group alone is refused, even with nothing but allowed lines
    c.saveProgram(program("GRP", true, "R[1]=1"));
    assertThat(c.bgLogic().add("GRP")).get().asString().startsWith("GRP has motion group 1")
        .contains("DEFAULT_GROUP = *,*,*,*,*");
  }

  @Test
  void everyStatementTheDocsAllowIsTakenAndRunsToItsEndEachScan() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("LOGIC", false, ALLOWED));
    assertThat(BgLogic.refusal(c.program("LOGIC").orElseThrow())).isEmpty();
    c.registers().setBit(IoKind.DI, 4, true);
    assertThat(c.bgLogic().add("LOGIC")).isEmpty();
    steps(sim, 20); // 80 ms: 10 scans of 8 ms
    assertThat(c.bgLogic().scans()).isEqualTo(10);
    assertThat(c.registers().number(1)).isEqualTo(10);
    assertThat(c.registers().number(3)).isEqualTo(20); // the FOR ran twice a scan
    assertThat(c.registers().number(4)).isEqualTo(10);
    assertThat(c.registers().bit(IoKind.DO, 2)).isTrue();
    assertThat(c.registers().bit(IoKind.F, 3)).isTrue();
    assertThat(c.registers().number(7)).isZero();   // R[9] is 0: SELECT took the ELSE jump past it
    assertThat(c.registers().number(8)).isZero();   // END ends each scan before the last line
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.warnings()).isEmpty();
  }

  @Test
  void eightSlotsEachProgramOnceAndStartChecksTheProgramAgain() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    for (int k = 1; k <= BgLogic.SLOTS + 1; k++) {
      c.saveProgram(program("S" + k, false, "R[" + k + "]=R[" + k + "]+1"));
    }
    for (int k = 1; k <= BgLogic.SLOTS; k++) {
      assertThat(c.bgLogic().add("S" + k)).isEmpty();
    }
    assertThat(c.bgLogic().add("S1")).get().asString().isEqualTo("S1 is already in a BG Logic slot");
    assertThat(c.bgLogic().add("S9")).get().asString().isEqualTo("all 8 BG Logic slots are in use");
    assertThat(c.bgLogic().slots()).extracting(BgLogic.Slot::program)
        .containsExactly("S1", "S2", "S3", "S4", "S5", "S6", "S7", "S8");
    assertThat(c.bgLogic().slots()).allMatch(BgLogic.Slot::running);
    // a full list offers nothing but the program not yet in a slot
    assertThat(c.bgLogic().offer(c.programNames()).programs()).containsExactly("S9");
    // F4 REMOVE frees a slot
    assertThat(c.bgLogic().remove("S8")).isTrue();
    assertThat(c.bgLogic().remove("S8")).isFalse();
    assertThat(c.bgLogic().add("S9")).isEmpty();
    // F3 STOP / F2 START; a program that is not in a slot is named
    assertThat(c.bgLogic().setRunning("S2", false)).isEmpty();
    assertThat(c.bgLogic().slots().get(1).running()).isFalse();
    assertThat(c.bgLogic().setRunning("NOPE", true)).get().asString().isEqualTo("NOPE is not in a BG Logic slot");
    // an edit made S2 unfit while stopped: START refuses it and the slot stays stopped
    c.saveProgram(program("S2", false, "WAIT 1.00(sec)"));
    assertThat(c.bgLogic().setRunning("S2", true)).get().asString().contains("S2 line 1: WAIT");
    assertThat(c.bgLogic().slots().get(1).running()).isFalse();
    c.deleteProgram("S2");
    assertThat(c.bgLogic().setRunning("S2", true)).get().asString().isEqualTo("program S2 does not exist");
    c.saveProgram(program("S2", false, "R[2]=R[2]+1"));
    assertThat(c.bgLogic().setRunning("S2", true)).isEmpty();
    assertThat(c.bgLogic().slots().get(1).running()).isTrue();
  }

  @Test
  void anEditThatMakesARunningSlotsProgramUnfitStopsItWithInt105AtTheNextScan() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("BG", false, "R[1]=R[1]+1"));
    c.saveProgram(program("MAIN", false, "LBL[1]", "R[2]=R[2]+1", "WAIT 0.04(sec)", "JMP LBL[1]"));
    assertThat(c.bgLogic().add("BG")).isEmpty();
    c.run("MAIN", 1, true);
    steps(sim, 4);
    assertThat(c.registers().number(1)).isEqualTo(2);
    c.saveProgram(program("BG", false, "R[1]=R[1]+1", "CALL MAIN"));
    steps(sim, 2);
    assertThat(c.warnings()).extracting(ControllerAlarm::code).containsExactly("INTP-105");
    assertThat(c.warnings().get(0).message()).contains("BG Logic").contains("BG line 2: CALL");
    assertThat(c.bgLogic().slots().get(0).running()).isFalse();
    assertThat(c.registers().number(1)).isEqualTo(2);
    // a warning: the main program goes on
    double r2 = c.registers().number(2);
    steps(sim, 30);
    assertThat(c.registers().number(2)).isGreaterThan(r2);
    assertThat(c.activeAlarms()).isEmpty();
  }

  @Test
  void theScanRunsInEveryModeAndWhileAProgramIsHeldOrAlarmed() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("BG", false, "R[1]=R[1]+1"));
    c.saveProgram(program("MAIN", false, "WAIT 5.00(sec)"));
    c.bgLogic().add("BG");
    c.setMode(org.robotrun.control.RobotControl.Mode.T1);
    steps(sim, 10);
    assertThat(c.registers().number(1)).isEqualTo(5);
    c.setMode(org.robotrun.control.RobotControl.Mode.AUTO);
    c.run("MAIN", 1, true);
    steps(sim, 2);
    c.hold();
    steps(sim, 10);
    assertThat(c.registers().number(1)).isEqualTo(11);
    c.emergencyStop(true);
    steps(sim, 10);
    assertThat(c.registers().number(1)).isEqualTo(16);
  }

  @Test
  void theScanPeriodIsMoreThanZeroAndAtMostOneSecondAndATimerCountsTheControllersTime() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    BgLogic bg = c.bgLogic();
    assertThat(bg.scanSec()).isEqualTo(0.008); // the default: 8 ms
    assertThatThrownBy(() -> bg.setScanSec(0)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> bg.setScanSec(-0.004)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> bg.setScanSec(1.001)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> bg.setScanSec(Double.NaN)).isInstanceOf(IllegalArgumentException.class);
    bg.setScanSec(1);
    assertThat(bg.scanSec()).isEqualTo(1.0);
    bg.setScanSec(0.012);
    // a scan every 3 ticks of 4 ms; a TIMER started by BG logic counts the controller's time
    c.saveProgram(program("BG", false, "IF R[1]<>0,JMP LBL[1]", "TIMER[2]=START", "R[1]=1", "LBL[1]",
        "R[2]=TIMER[2]"));
    bg.add("BG");
    steps(sim, 3 * 25); // 0.3 s: 25 scans
    assertThat(bg.scans()).isEqualTo(25);
    // TIMER reads seconds (docs/tp-execution.md); started at the first scan, read 24 scans (0.288 s) later
    assertThat(c.registers().number(2)).isBetween(0.276, 0.300);
  }

  @Test
  void mixBgStatusReadsRunningStoppedOrEmpty() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("BG1", false, "R[9]=R[9]+1"));
    c.saveProgram(program("BG2", false, "R[8]=R[8]+1"));
    c.saveProgram(program("MAIN", false, "R[1]=$MIX_BG[1].$STATUS", "R[2]=$MIX_BG[2].$STATUS",
        "R[3]=$MIX_BG[3].$STATUS"));
    c.bgLogic().add("BG1");
    c.bgLogic().add("BG2");
    c.bgLogic().setRunning("BG2", false);
    c.run("MAIN", 1, true);
    steps(sim, 3);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(1)).isEqualTo(2);
    assertThat(c.registers().number(2)).isEqualTo(1);
    assertThat(c.registers().number(3)).isZero();
  }

  @Test
  void aBgPulseAndTimerCountTheControllersTimeOnceInEverySlotKind() {
    // a slot added on the setup screen, and one from the scenario's production setup
    for (boolean fromScenario : new boolean[] {false, true}) {
      Simulation sim = ControllerTest.cell();
      Controller c = sim.controllers().get(0);
      c.saveProgram(program("BGP", false, "IF R[1]<>0,JMP LBL[1]", "DO[3]=PULSE,0.2sec", "TIMER[4]=START", "R[1]=1",
          "LBL[1]", "R[2]=TIMER[4]"));
      if (fromScenario) {
        c.bgLogic().configure(List.of("BGP"));
      } else {
        assertThat(c.bgLogic().add("BGP")).isEmpty();
      }
      steps(sim, 2);   // the first scan: pulse and timer start
      steps(sim, 45);  // 0.18 s later
      assertThat(c.registers().bit(IoKind.DO, 3)).as("scenario=%s", fromScenario).isTrue();
      steps(sim, 8);   // 0.212 s
      assertThat(c.registers().bit(IoKind.DO, 3)).as("scenario=%s", fromScenario).isFalse();
      assertThat(c.registers().number(2)).as("scenario=%s", fromScenario).isBetween(0.19, 0.23);
    }
  }

  @Test
  void theScenariosSlotsReplaceTheOldOnes() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("A", false, "R[1]=R[1]+1"));
    c.saveProgram(program("B", false, "R[2]=R[2]+1"));
    c.bgLogic().configure(List.of("A"));
    c.bgLogic().configure(List.of("B"));
    assertThat(c.bgLogic().slots()).extracting(BgLogic.Slot::program).containsExactly("B");
    steps(sim, 4);
    assertThat(c.registers().number(1)).isZero();
    assertThat(c.registers().number(2)).isEqualTo(2);
  }

  @Test
  void aSlotStoppedByAnAlarmRunsAgainAfterResetAndStart() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("DIV", false, "R[3]=R[3]+1", "R[1]=1/R[2]"));
    c.bgLogic().add("DIV");
    steps(sim, 2);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SIMU-001");
    assertThat(c.bgLogic().slots().get(0).running()).isFalse();
    c.reset();
    c.registers().setInteger(2, 4);
    assertThat(c.bgLogic().setRunning("DIV", true)).isEmpty();
    steps(sim, 4);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(3)).isEqualTo(3);
    assertThat(c.registers().number(1)).isEqualTo(0.25);
  }
}
