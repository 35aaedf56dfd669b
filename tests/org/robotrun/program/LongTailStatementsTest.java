package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;

/**
 * Statements of real controller files that run since issue 25's second round: TOOL_OFFSET
 * CONDITION with a plain Tool_Offset, CALL SR[i], offsets on a C motion's via point, and the
 * arithmetic functions. Each test names the controller behaviour it follows (FANUC R-30iB
 * Operator's Manual, "Program instructions"; docs/tp-language.md).
 */
class LongTailStatementsTest {

  /** A program of {@code lines} (with P[1], P[2] taught in UF 0 / UT 0 when {@code positions}). */
  static Program program(String name, boolean positions, String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  " + name + "\n/ATTR\nDEFAULT_GROUP\t= "
        + (positions ? "1,*,*,*,*" : "*,*,*,*,*") + ";\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format(Locale.ROOT, "%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\n");
    if (positions) {
      for (int p = 1; p <= 2; p++) {
        sb.append("P[").append(p).append("]{\n   GP1:\n\tUF : 0, UT : 0,\t\tCONFIG : 'N U T, 0, 0, 0',\n")
            .append(String.format(Locale.ROOT, "\tX =   %d.000  mm,\tY =     0.000  mm,\tZ =   300.000  mm,%n", 100 * p))
            .append("\tW =   180.000 deg,\tP =     0.000 deg,\tR =     0.000 deg\n};\n");
      }
    }
    sb.append("/END\n");
    LsReadResult r = LsReader.parse(name + ".LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    return r.program();
  }

  private static double x(java.util.Optional<Position> p) {
    return ((Position.Cartesian) p.orElseThrow()).xMm();
  }

  @Test
  void toolOffsetTakesThePrOfTheLastToolOffsetCondition() {
    // TOOL_OFFSET CONDITION PR[i] names the PR a plain Tool_Offset applies, read when the motion starts.
    Rig rig = new Rig(program("MAIN", true, "PR[5]=LPOS-LPOS", "PR[5,3]=(-40)", "TOOL_OFFSET CONDITION PR[5:TOFS]",
        "L P[1] 100mm/sec FINE Tool_Offset", "PR[5,3]=(-10)", "L P[2] 100mm/sec FINE Tool_Offset",
        "L P[2] 100mm/sec FINE"));
    Outcome o = rig.run();
    assertThat(o).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.port.requests()).hasSize(3);
    assertThat(((Position.Cartesian) rig.port.requests().get(0).toolOffset().orElseThrow()).zMm()).isEqualTo(-40);
    assertThat(((Position.Cartesian) rig.port.requests().get(1).toolOffset().orElseThrow()).zMm()).isEqualTo(-10);
    assertThat(rig.port.requests().get(2).toolOffset()).isEmpty();
  }

  @Test
  void toolOffsetWithoutAConditionAlarmsOnItsLine() {
    Rig rig = new Rig(program("MAIN", true, "R[1]=1", "L P[1] 100mm/sec FINE Tool_Offset"));
    Outcome o = rig.run();
    Alarm a = rig.alarm(o);
    assertThat(a.code()).isEqualTo("INTP-311");
    assertThat(a.line()).isEqualTo(2);
    assertThat(a.message()).contains("TOOL_OFFSET CONDITION");
  }

  @Test
  void callThroughAStringRegisterRunsTheProgramItNamesWithItsArguments() {
    // CALL SR[i]: the program whose name SR[i] holds when the line runs; args land in AR[].
    Program main = program("MAIN", false, "SR[2]='sub_a'", "CALL SR[2:NEXT](7)", "SR[2]='SUB_B'", "CALL SR[2]");
    Program a = program("SUB_A", false, "R[1]=AR[1]");
    Program b = program("SUB_B", false, "R[2]=5");
    Rig rig = new Rig(main, a, b);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(7);
    assertThat(rig.regs.number(2)).isEqualTo(5);
  }

  @Test
  void callThroughAnEmptyOrUnknownStringRegisterAlarmsAsAMissingProgram() {
    Rig empty = new Rig(program("MAIN", false, "CALL SR[4]"));
    Alarm a = empty.alarm(empty.run());
    assertThat(a.code()).isEqualTo("INTP-222");
    assertThat(a.message()).contains("SR[4] is empty");
    Rig unknown = new Rig(program("MAIN", false, "SR[4]='NOPE'", "CALL SR[4]"));
    Alarm b = unknown.alarm(unknown.run());
    assertThat(b.code()).isEqualTo("INTP-222");
    assertThat(b.message()).contains("NOPE");
  }

  @Test
  void aViaPointWithItsOwnOffsetIsShiftedByItAndTheEndPointByItsOwn() {
    Rig rig = new Rig(program("MAIN", true, "PR[7]=LPOS-LPOS", "PR[7,1]=(11)", "PR[8]=LPOS-LPOS", "PR[8,1]=(22)",
        "C P[1] Offset,PR[7]\n    :  P[2] 100mm/sec FINE Offset,PR[8]", "C P[1]\n    :  P[2] 100mm/sec FINE Offset,PR[8]"));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    MotionRequest own = rig.port.requests().get(0);
    assertThat(own.viaOwnOffsets()).isTrue();
    assertThat(x(own.viaOffset())).isEqualTo(11);
    assertThat(x(own.offset())).isEqualTo(22);
    // Without options on the via point both points take the end point's (as before).
    MotionRequest shared = rig.port.requests().get(1);
    assertThat(shared.viaOwnOffsets()).isFalse();
    assertThat(x(shared.offset())).isEqualTo(22);
  }

  @Test
  void arithmeticFunctionsComputeInDegreesAndTruncAndRoundGiveIntegers() {
    Rig rig = new Rig(program("MAIN", false, "R[1]=(-3)", "R[2]=ABS[R[1]]", "R[3]=16", "R[4]=SQRT[R[3]]",
        "R[5]=30", "R[6]=SIN[R[5]]", "R[7]=ACOS[R[6]]", "R[8]=(-2.7)", "R[9]=TRUNC[R[8]]", "R[10]=ROUND[R[8]]",
        "R[11]=2.5", "R[12]=ROUND[R[11]]", "R[13]=ROUND[R[11]*(-1)]", "R[14]=LN[R[3]]/LN[2]", "R[15]=EXP[0]",
        "R[16]=TAN[45]+COS[R[5]*2]+ATAN[1]+ASIN[R[6]]"));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(2)).isEqualTo(3);
    assertThat(rig.regs.number(4)).isEqualTo(4);
    assertThat(rig.regs.number(6)).isCloseTo(0.5, within(1e-12));
    assertThat(rig.regs.number(7)).isCloseTo(60, within(1e-9));
    assertThat(rig.regs.number(9)).isEqualTo(-2);
    assertThat(rig.regs.number(10)).isEqualTo(-3);
    assertThat(rig.regs.number(12)).isEqualTo(3);
    assertThat(rig.regs.number(13)).isEqualTo(-3);
    assertThat(rig.regs.number(14)).isCloseTo(4, within(1e-12));
    assertThat(rig.regs.number(15)).isEqualTo(1);
    assertThat(rig.regs.number(16)).isCloseTo(1 + 0.5 + 45 + 30, within(1e-9));
  }

  @Test
  void aFunctionOutsideItsDomainAlarmsNamingIt() {
    Rig rig = new Rig(program("MAIN", false, "R[1]=(-4)", "R[2]=SQRT[R[1]]"));
    Alarm a = rig.alarm(rig.run());
    assertThat(a.code()).isEqualTo("INTP-304");
    assertThat(a.line()).isEqualTo(2);
    assertThat(a.message()).contains("SQRT");
    Rig string = new Rig(program("MAIN", false, "SR[1]='A'", "R[2]=ABS[SR[1]]"));
    assertThat(string.alarm(string.run()).code()).isEqualTo("INTP-205");
  }

  @Test
  void highSpeedSkipStoresWhereTheArmWasWhenTheConditionTurnedTrue() {
    // Skip,LBL[n],PR[i]=LPOS: as Skip,LBL[n], and PR[i] takes the position at the skip.
    Program p = program("MAIN", true, "SKIP CONDITION DI[1]=ON", "L P[1] 100mm/sec FINE Skip,LBL[9],PR[3:HIT]=LPOS",
        "R[1]=1", "L P[2] 100mm/sec FINE Skip,LBL[9],PR[4]=JPOS", "R[2]=1", "END", "LBL[9]", "R[3]=9");
    Rig rig = new Rig(InterpreterSettings.defaults(), 1.0, p);
    rig.interp.forward();
    for (int i = 0; i < 25; i++) {
      rig.tick(Rig.TICK_SEC);
    }
    rig.regs.setBit(IoKind.DI, 1, true);
    for (int i = 0; i < 5; i++) {
      rig.tick(Rig.TICK_SEC);
    }
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.regs.position(3)).isInstanceOf(Position.Cartesian.class);
    // the second motion's condition holds from its start: it stops at once and stores joints
    assertThat(rig.runUntilStopped(Rig.TICK_SEC, 2000)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.position(4)).isInstanceOf(Position.Joint.class);
    assertThat(rig.regs.number(2)).isEqualTo(1);
    assertThat(rig.regs.number(3)).isZero();
    assertThat(rig.port.cancelled()).hasSize(2);
  }

  @Test
  void highSpeedSkipWithoutTheConditionJumpsAndLeavesThePrAlone() {
    Program p = program("MAIN", true, "SKIP CONDITION DI[1]=ON", "L P[1] 100mm/sec FINE Skip,LBL[9],PR[3]=LPOS",
        "R[1]=1", "END", "LBL[9]", "R[3]=9");
    Rig rig = new Rig(p);
    Position before = rig.regs.position(3);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(3)).isEqualTo(9);
    assertThat(rig.regs.number(1)).isZero();
    assertThat(rig.regs.position(3)).isEqualTo(before);
  }

  @Test
  void aMotionToAPrOfGroupOneReadsAsThePr() {
    Program p = program("MAIN", true, "J PR[GP1:5:PICK] 100% FINE", "L PR[GP1:R[2]] 100mm/sec FINE");
    Instruction.Move m = (Instruction.Move) p.line(1);
    assertThat(m.target()).isEqualTo(new Motion.Register(Item.of(5, "PICK")));
    assertThat(((Instruction.Move) p.line(2)).target()).isEqualTo(new Motion.Register(new Item(Index.viaRegister(2), "")));
  }

  @Test
  void accFromARegisterIsReadWhenTheMotionStarts() {
    Rig rig = new Rig(program("MAIN", true, "R[5]=40", "L P[1] 100mm/sec FINE ACC R[5]", "R[5]=151",
        "L P[2] 100mm/sec FINE ACC R[5]"));
    Alarm a = rig.alarm(rig.run());
    assertThat(rig.port.requests()).hasSize(1);
    assertThat(rig.port.requests().get(0).accPercent()).isEqualTo(40);
    assertThat(a.code()).isEqualTo("INTP-304");
    assertThat(a.line()).isEqualTo(4);
  }
}
