package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.robotrun.sim.TaskProgs.program;
import static org.robotrun.sim.TaskProgs.steps;

import org.junit.jupiter.api.Test;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Position;

/**
 * Idioms real controller programs lean on (issue 25), run on the simulated arm of a cell: IF
 * with an action, system variables, position sums, AR[] as an index, PR[i,R[j]], and macros
 * with arguments. Each test names the controller behaviour it follows (FANUC R-30iB
 * Operator's Manual, "Program instructions"; docs/tp-language.md).
 */
class RealIdiomsTest {

  @Test
  void ifWithAnActionRunsTheActionOnlyWhenTheConditionHolds() {
    // IF cond,action: the action is an assignment or an output; nothing happens when false.
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "R[1]=3", "IF R[1]>2,R[2]=(R[2]+1)", "IF R[1]>5,R[3]=(7)",
        "IF (R[1]=3),DO[2]=(ON)", "IF R[1]<>3,DO[3]=(ON)", "IF R[2]=1,PR[4,3]=(12.5)"));
    c.run("MAIN", 1, true);
    steps(sim, 20);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(2)).isEqualTo(1);
    assertThat(c.registers().number(3)).isZero();
    assertThat(c.registers().bit(IoKind.DO, 2)).isTrue();
    assertThat(c.registers().bit(IoKind.DO, 3)).isFalse();
    assertThat(c.registers().position(4).element(3)).isEqualTo(12.5);
  }

  @Test
  void ifWithAPulseTurnsTheOutputOnForItsWidth() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "IF DI[1]=OFF,DO[5]=PULSE,0.2sec", "WAIT 0.05(sec)", "R[1]=DO[5]",
        "WAIT 0.30(sec)", "R[2]=DO[5]"));
    c.run("MAIN", 1, true);
    steps(sim, 200);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.registers().number(2)).isZero();
  }

  @Test
  void frameNumberSystemVariablesReadAndSetTheActiveFrames() {
    // $MNUTOOLNUM[1] / $MNUFRAMENUM[1] are what UTOOL_NUM= / UFRAME_NUM= set.
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", true, "UTOOL_NUM[GP1]=2", "UFRAME_NUM=1", "R[1]=$MNUTOOLNUM[1]",
        "R[2]=$MNUFRAMENUM[1]", "$MNUFRAMENUM[1]=0", "R[3]=$JCR.$JOG_GP"));
    c.run("MAIN", 1, true);
    steps(sim, 20);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(1)).isEqualTo(2);
    assertThat(c.registers().number(2)).isEqualTo(1);
    assertThat(c.activeFrame(FrameKind.USER)).isZero();
    assertThat(c.registers().number(3)).isEqualTo(1);
  }

  @Test
  void backgroundLogicStatusIsTwoWhileItRunsAndOneWhenStopped() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("BGONE", false, "F[1]=(ON)"));
    c.saveProgram(program("MAIN", false, "R[1]=$MIX_BG[1].$STATUS", "R[2]=$MIX_BG[2].$STATUS",
        "IF $MIX_BG[1].$STATUS=2,F[5]=(ON)"));
    assertThat(c.bgLogic().add("BGONE")).isEmpty();
    c.run("MAIN", 1, true);
    steps(sim, 20);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(1)).isEqualTo(2);
    assertThat(c.registers().number(2)).isZero();
    assertThat(c.registers().bit(IoKind.F, 5)).isTrue();
    assertThat(c.bgLogic().setRunning("BGONE", false)).isEmpty();
    c.saveProgram(program("AGAIN", false, "R[3]=$MIX_BG[1].$STATUS"));
    c.run("AGAIN", 1, true);
    steps(sim, 20);
    assertThat(c.registers().number(3)).isEqualTo(1);
  }

  @Test
  void anUnknownSystemVariableAlarmsNamingIt() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    org.robotrun.io.LsReadResult r = org.robotrun.io.LsReader.parse("MAIN.LS",
        "/PROG  MAIN\n/ATTR\nDEFAULT_GROUP\t= *,*,*,*,*;\n/MN\n   1:  R[1]=$SOME_APP.$VALUE ;\n/POS\n/END\n");
    c.saveProgram(r.program());
    c.run("MAIN", 1, true);
    steps(sim, 10);
    assertThat(c.activeAlarms()).hasSize(1);
    assertThat(c.activeAlarms().get(0).message()).contains("$SOME_APP.$VALUE");
  }

  @Test
  void lposMinusLposZeroesAPositionRegisterAndSumsAddElementByElement() {
    // PR[i]=LPOS-LPOS: the controller's idiom for a Cartesian PR of zeros; sums go element by element.
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", true, "PR[1]=LPOS-LPOS", "PR[1,1]=10", "PR[1,3]=5", "PR[2]=LPOS",
        "PR[3]=PR[2]+PR[1]+PR[1]", "PR[4]=PR[3]-LPOS"));
    c.run("MAIN", 1, true);
    steps(sim, 20);
    assertThat(c.activeAlarms()).isEmpty();
    Position.Cartesian zero = (Position.Cartesian) c.registers().position(1);
    assertThat(zero.yMm()).isZero();
    assertThat(zero.xMm()).isEqualTo(10);
    Position.Cartesian here = (Position.Cartesian) c.registers().position(2);
    Position.Cartesian sum = (Position.Cartesian) c.registers().position(3);
    assertThat(sum.xMm()).isCloseTo(here.xMm() + 20, within(1e-9));
    assertThat(sum.zMm()).isCloseTo(here.zMm() + 10, within(1e-9));
    Position.Cartesian diff = (Position.Cartesian) c.registers().position(4);
    assertThat(diff.xMm()).isCloseTo(20, within(1e-6));
    assertThat(diff.yMm()).isCloseTo(0, within(1e-6));
  }

  @Test
  void aJointTermInACartesianSumIsATypeMismatch() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", true, "PR[1]=LPOS-JPOS"));
    c.run("MAIN", 1, true);
    steps(sim, 10);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("INTP-205");
  }

  @Test
  void argumentsIndexAndPositionElementsThroughRegistersResolveWhenTheLineRuns() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("SUB", false, "R[AR[1]]=AR[2]", "PR[5,R[9]]=AR[2]"));
    c.saveProgram(program("MAIN", false, "PR[5]=LPOS-LPOS", "R[9]=3", "CALL SUB(7,42)", "R[8]=PR[5,R[9]]"));
    c.run("MAIN", 1, true);
    steps(sim, 20);
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(7)).isEqualTo(42);
    assertThat(c.registers().number(8)).isEqualTo(42);
  }

  @Test
  void anElementIndexOutsideOneToSixAlarms() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", false, "PR[5]=LPOS-LPOS", "R[9]=7", "PR[5,R[9]]=1"));
    c.run("MAIN", 1, true);
    steps(sim, 20);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("INTP-204");
  }

  @Test
  void aMacroWithArgumentsRunsItsProgramWithThemAsArAndAlarmsWithoutATableEntry() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("OPENHAND", false, "R[1]=AR[1]"));
    c.saveProgram(program("MAIN", false, "OPENHAND(5)", "R[2]=1", "Program Status(13)", "R[3]=1"));
    c.run("MAIN", 1, true);
    steps(sim, 20);
    assertThat(c.registers().number(1)).isEqualTo(5);
    assertThat(c.registers().number(2)).isEqualTo(1);
    // "Program Status" is no program: the controller's macro table would say what it runs
    assertThat(c.activeAlarms()).hasSize(1);
    assertThat(c.activeAlarms().get(0).message()).containsIgnoringCase("Program Status").contains("macro table");
    assertThat(c.registers().number(3)).isZero();
  }

  @Test
  void toolOffsetAfterAConditionReachesWhatToolOffsetWithThatPrReaches() {
    // TOOL_OFFSET CONDITION PR[i] then Tool_Offset: the same shift as Tool_Offset,PR[i], in the tool frame.
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MAIN", true, "PR[1]=LPOS", "PR[2]=LPOS-LPOS", "PR[2,3]=(-30)", "TOOL_OFFSET CONDITION PR[2]",
        "L PR[1] 200mm/sec FINE Tool_Offset", "PR[3]=LPOS", "L PR[1] 200mm/sec FINE", "PR[4]=LPOS",
        "L PR[1] 200mm/sec FINE Tool_Offset,PR[2]", "PR[5]=LPOS"));
    c.run("MAIN", 1, true);
    steps(sim, 3000);
    assertThat(c.activeAlarms()).isEmpty();
    Position.Cartesian viaCondition = (Position.Cartesian) c.registers().position(3);
    Position.Cartesian plain = (Position.Cartesian) c.registers().position(4);
    Position.Cartesian viaPr = (Position.Cartesian) c.registers().position(5);
    assertThat(viaCondition.xMm()).isCloseTo(viaPr.xMm(), within(0.01));
    assertThat(viaCondition.yMm()).isCloseTo(viaPr.yMm(), within(0.01));
    assertThat(viaCondition.zMm()).isCloseTo(viaPr.zMm(), within(0.01));
    double moved = Math.sqrt(Math.pow(viaCondition.xMm() - plain.xMm(), 2) + Math.pow(viaCondition.yMm() - plain.yMm(), 2)
        + Math.pow(viaCondition.zMm() - plain.zMm(), 2));
    assertThat(moved).isCloseTo(30, within(0.01));
  }
}
