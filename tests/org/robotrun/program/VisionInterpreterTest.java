package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;

/**
 * The iRVision statements as the interpreter runs them, against a fake vision system: GET_OFFSET
 * takes the results one by one and jumps when none is left, VR fields, VOFFSET, and the CVIS alarms.
 */
class VisionInterpreterTest {

  /** A vision system with one process FIND whose results are given. */
  static final class FakeVision implements VisionPort {
    final List<VisionResult> results = new ArrayList<>();
    int runs;

    @Override
    public boolean hasProcess(String name) {
      return name.equalsIgnoreCase("FIND");
    }

    @Override
    public Outcome runFind(String name) {
      runs++;
      return new Outcome.Found(results);
    }
  }

  static VisionResult result(int model, double x, double y, double rDeg, int uf) {
    Position.Cartesian found = new Position.Cartesian(x, y, 0, 0, 0, rDeg, Config.DEFAULT);
    // reference at the origin: the offset is the found pose itself
    return new VisionResult("FIND", model, found, found, uf, 90);
  }

  /** Reads a program (lines without numbers) with P[1] = (100, 0, 300, 180, 0, 0) in UF[uf]. */
  static Program program(int uf, String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  MAIN\n/ATTR\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format("%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\nP[1]{\n   GP1:\n\tUF : ").append(uf).append(", UT : 0,\t\tCONFIG : 'N U T, 0, 0, 0',\n")
        .append("\tX =   100.000  mm,\tY =     0.000  mm,\tZ =   300.000  mm,\n")
        .append("\tW =   180.000 deg,\tP =     0.000 deg,\tR =     0.000 deg\n};\n/END\n");
    LsReadResult r = LsReader.parse("MAIN.LS", sb.toString());
    assertThat(r.diagnostics()).as("no diagnostics: the vision forms run").isEmpty();
    return r.program();
  }

  static Rig rig(FakeVision v, Program p) {
    Rig rig = new Rig(p);
    rig.interp.setVisionPort(v);
    return rig;
  }

  @Test
  void getOffsetTakesTheResultsInTurnAndJumpsWhenNoneIsLeft() {
    FakeVision v = new FakeVision();
    v.results.add(result(1, 10, 20, 30, 0));
    v.results.add(result(2, 40, 50, 60, 0));
    Rig rig = rig(v, program(0,
        "  VISION RUN_FIND 'FIND'",
        "  VISION GET_NFOUND 'find' R[9:N]",
        "  LBL[1]",
        "  VISION GET_OFFSET 'FIND' VR[R[8]] JMP,LBL[2:DONE]",
        "  R[1]=R[1]+1",
        "  R[7]=R[1]+10",
        "  R[R[7]]=VR[R[8]].MODELID",
        "  PR[R[1]]=VR[R[8]].OFFSET",
        "  JMP LBL[1]",
        "  LBL[2:DONE]",
        "  R[20]=VR[3].MES[1]",
        "  PR[5]=VR[3].FOUND_POS[1]"));
    rig.regs.setInteger(8, 3);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(v.runs).isEqualTo(1);
    assertThat(rig.regs.number(9)).isEqualTo(2);
    assertThat(rig.regs.number(1)).isEqualTo(2);
    assertThat(rig.regs.number(11)).isEqualTo(1);
    assertThat(rig.regs.number(12)).isEqualTo(2);
    assertThat(((Position.Cartesian) rig.regs.position(1)).xMm()).isEqualTo(10);
    assertThat(((Position.Cartesian) rig.regs.position(2)).rDeg()).isEqualTo(60);
    // VR[3] keeps the last result after the jump
    assertThat(rig.regs.vision().get(3).orElseThrow().modelId()).isEqualTo(2);
    assertThat(rig.regs.number(20)).isEqualTo(90);
    assertThat(((Position.Cartesian) rig.regs.position(5)).yMm()).isEqualTo(50);
  }

  @Test
  void vOffsetMovesTheTargetByTheRegistersFrameOffset() {
    FakeVision v = new FakeVision();
    v.results.add(result(1, 10, 20, 90, 0));
    Rig rig = rig(v, program(0,
        "  VISION RUN_FIND 'FIND'",
        "  VISION GET_OFFSET 'FIND' VR[1] JMP,LBL[9]",
        "L P[1] 100mm/sec FINE VOFFSET,VR[1]",
        "  LBL[9]"));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    MotionRequest req = rig.port.requests().get(0);
    Position.Cartesian t = (Position.Cartesian) req.target().position();
    // O = Trans(10, 20) Rz(90): (100, 0, 300) -> (10, 20 + 100, 300), R 0 -> 90, W stays 180
    Transform expected = Xyzwpr.ofDegrees(10, 20, 0, 0, 0, 90).toTransform()
        .compose(Xyzwpr.ofDegrees(100, 0, 300, 180, 0, 0).toTransform());
    assertThat(t.toXyzwpr().toTransform().distanceTo(expected)).isLessThan(1e-9);
    assertThat(t.xMm()).isCloseTo(10, offset(1e-9));
    assertThat(t.yMm()).isCloseTo(120, offset(1e-9));
    assertThat(t.config()).isEqualTo(Config.DEFAULT);
  }

  @Test
  void aProcessNamedByAStringRegisterRuns() {
    FakeVision v = new FakeVision();
    v.results.add(result(4, 10, 20, 0, 0));
    Rig rig = rig(v, program(0,
        "  SR[1]='FIND'",
        "  SR[2]=SR[1]",
        "  VISION RUN_FIND SR[1]",
        "  VISION GET_NFOUND SR[2:PROC] R[3]",
        "  VISION GET_OFFSET SR[2] VR[1] JUMP,LBL[9]",
        "  R[4]=VR[1].MODELID",
        "  VISION GET_OFFSET SR[R[5]] VR[1] JMP LBL[9]",
        "  R[6]=1",
        "  LBL[9]"));
    rig.regs.setInteger(5, 1);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(v.runs).isEqualTo(1);
    assertThat(rig.regs.number(3)).isEqualTo(1);
    assertThat(rig.regs.number(4)).isEqualTo(4);
    // the second GET_OFFSET found nothing more: the jump skipped R[6]=1
    assertThat(rig.regs.number(6)).isEqualTo(0);
  }

  @Test
  void aStringRegisterNamingNoProcessIsCvis015NamingTheRegister() {
    Alarm a = alarm(new FakeVision(), program(0, "  SR[3]='NOPE'", "  VISION RUN_FIND SR[3]"));
    assertThat(a.code()).isEqualTo("CVIS-015");
    assertThat(a.message()).contains("'NOPE'").contains("SR[3]");
    assertThat(a.line()).isEqualTo(2);
  }

  @Test
  void theVisionFormsAreStatementsOfTheGrammar() {
    Program p = program(0,
        "  VISION RUN_FIND SR[1]",
        "  VISION GET_OFFSET 'FIND' VR[R[2]:N] JMP,LBL[9:NONE]",
        "  PR[3:OFS]=VR[1].FOUND_POS[1]",
        "L P[1] 100mm/sec FINE VOFFSET,VR[1] Wjnt",
        "  LBL[9:NONE]");
    assertThat(p.line(1)).isEqualTo(new Instruction.VisionRunFind(new Instruction.VisionProcessInRegister(Item.of(1))));
    assertThat(p.line(2)).isEqualTo(new Instruction.VisionGetOffset(new Instruction.VisionProcessName("FIND"),
        new Item(new Index.Indirect(2, ""), "N"), new LabelRef(Index.of(9), "NONE")));
    assertThat(p.line(3)).isEqualTo(new Instruction.AssignPosReg(Item.of(3, "OFS"),
        new Instruction.FromVisionRegister(Item.of(1), true)));
    assertThat(((Instruction.Move) p.line(4)).options()).containsExactly(new Motion.VisionOffset(Item.of(1)),
        new Motion.Wjnt());
  }

  @Test
  void anUnknownProcessIsCvis015() {
    Alarm a = alarm(new FakeVision(), program(0, "  VISION RUN_FIND 'NOPE'"));
    assertThat(a.code()).isEqualTo("CVIS-015");
    assertThat(a.message()).contains("NOPE");
    assertThat(a.line()).isEqualTo(1);
  }

  @Test
  void withoutAVisionSystemEveryProcessIsUnknown() {
    Rig rig = new Rig(program(0, "  VISION RUN_FIND 'FIND'"));
    assertThat(rig.alarm(rig.run()).code()).isEqualTo("CVIS-015");
  }

  @Test
  void aVisionRegisterOutOfRangeIsCvis016() {
    FakeVision v = new FakeVision();
    assertThat(alarm(v, program(0, "  VISION RUN_FIND 'FIND'", "  VISION GET_OFFSET 'FIND' VR[11] JMP,LBL[1]",
        "  LBL[1]")).code()).isEqualTo("CVIS-016");
    assertThat(alarm(v, program(0, "  PR[1]=VR[0].OFFSET")).code()).isEqualTo("CVIS-016");
  }

  @Test
  void anEmptyVisionRegisterIsCvis017() {
    FakeVision v = new FakeVision();
    assertThat(alarm(v, program(0, "  PR[1]=VR[2].OFFSET")).code()).isEqualTo("CVIS-017");
    assertThat(alarm(v, program(0, "  R[1]=VR[2].MODELID")).code()).isEqualTo("CVIS-017");
    assertThat(alarm(v, program(0, "L P[1] 100mm/sec FINE VOFFSET,VR[2]")).code()).isEqualTo("CVIS-017");
  }

  @Test
  void resultsBeforeARunFindAreCvis018() {
    FakeVision v = new FakeVision();
    assertThat(alarm(v, program(0, "  VISION GET_OFFSET 'FIND' VR[1] JMP,LBL[1]", "  LBL[1]")).code())
        .isEqualTo("CVIS-018");
    assertThat(alarm(v, program(0, "  VISION GET_NFOUND 'FIND' R[1]")).code()).isEqualTo("CVIS-018");
  }

  @Test
  void aPositionInAnotherUserFrameIsCvis019() {
    FakeVision v = new FakeVision();
    v.results.add(result(1, 10, 20, 0, 1));
    Alarm a = alarm(v, program(0, "  VISION RUN_FIND 'FIND'", "  VISION GET_OFFSET 'FIND' VR[1] JMP,LBL[1]",
        "L P[1] 100mm/sec FINE VOFFSET,VR[1]", "  LBL[1]"));
    assertThat(a.code()).isEqualTo("CVIS-019");
    assertThat(a.line()).isEqualTo(3);
    assertThat(a.message()).contains("UF[0]").contains("UF[1]");
  }

  @Test
  void statementsThatAreNotRunStayNotSupported() {
    LsReadResult r = LsReader.parse("M.LS", "/PROG  M\n/ATTR\n/MN\n   1:  VISION SET_REFERENCE 'FIND' ;\n"
        + "   2:  IF VR[1].MODELID=1,JMP LBL[1] ;\n   3:  LBL[1] ;\n/END\n");
    assertThat(r.diagnostics()).extracting(d -> d.message()).anyMatch(m -> m.startsWith("not supported: iRVision"))
        .anyMatch(m -> m.contains("vision registers VR[]"));
  }

  private static Alarm alarm(FakeVision v, Program p) {
    Rig rig = rig(v, p);
    return rig.alarm(rig.run());
  }
}
