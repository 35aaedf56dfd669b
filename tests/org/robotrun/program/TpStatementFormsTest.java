package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.junit.jupiter.api.Test;

/**
 * Statement forms of docs/tp-language.md read into the model the docs give them, and written back
 * as a controller writes them (issue 31). Expected models are built here from the docs' tables, not
 * taken from the parser: the same statement spelled the ways real files spell it (lower case,
 * {@code JUMP,LBL}, {@code TIME BEFORE}...) is one model, and the printer gives the controller's
 * spelling. Also the fragment entry points the pendant's fields use ({@code callText},
 * {@code posSourceText}, {@code indexText}, {@code itemText}) and the warnings a statement carries.
 */
class TpStatementFormsTest {

  private static Instruction parsed(String text) {
    return TpStatementParser.statementText(text).instruction();
  }

  private static List<String> warnings(String text) {
    return TpStatementParser.statementText(text).warnings();
  }

  /** {@code text} reads as {@code model} and {@code model} is written as {@code text}. */
  private static void form(String text, Instruction model) {
    assertThat(parsed(text)).as(text).isEqualTo(model);
    assertThat(TpText.statement(model)).isEqualTo(text);
  }

  private static Item r(int i) {
    return new Item(new Index.Direct(i), "");
  }

  private static Expr.Register reg(int i) {
    return new Expr.Register(r(i));
  }

  private static Expr.IntConst n(int v) {
    return new Expr.IntConst(v);
  }

  private static LabelRef lbl(int i) {
    return new LabelRef(new Index.Direct(i), "");
  }

  private static Motion.Speed mmPerSec(double v) {
    return new Motion.Speed(new Motion.SpeedConst(v), Motion.SpeedUnit.MM_PER_SEC);
  }

  private static Instruction.Move lin(Motion.Option... options) {
    return Instruction.Move.of(Motion.Type.L, new Motion.Local(1, ""), mmPerSec(100), new Motion.Fine(), List.of(options));
  }

  private static Motion.Option option(String text) {
    Instruction.Move m = (Instruction.Move) parsed("L P[1] 100mm/sec FINE " + text);
    assertThat(m.options()).as(text).hasSize(1);
    return m.options().get(0);
  }

  // ---- registers, frames, I/O ---------------------------------------------------------------

  @Test
  void frameSelectionsTakeANumberOrARegisterAndMayNameGroupOne() {
    form("UFRAME_NUM=2", new Instruction.SelectFrame(Instruction.FrameKind.USER, new Index.Direct(2), false));
    form("UTOOL_NUM=R[3]", new Instruction.SelectFrame(Instruction.FrameKind.TOOL, new Index.Indirect(3, ""), false));
    form("UTOOL_NUM[GP1]=1", new Instruction.SelectFrame(Instruction.FrameKind.TOOL, new Index.Direct(1), true));
    assertThat(parsed("uframe_num[gp1]=r[4:FRAME]"))
        .isEqualTo(new Instruction.SelectFrame(Instruction.FrameKind.USER, new Index.Indirect(4, "FRAME"), true));
    form("UFRAME[2:TABLE]=PR[5]", new Instruction.SetFrame(Instruction.FrameKind.USER, new Index.Direct(2), "TABLE", r(5)));
    form("UTOOL[1]=PR[6:TCP]", new Instruction.SetFrame(Instruction.FrameKind.TOOL, new Index.Direct(1), "",
        new Item(new Index.Direct(6), "TCP")));
    form("PAYLOAD[1:GRIPPER]", new Instruction.Payload(new Index.Direct(1), "GRIPPER"));
    form("UALM[2:NO PART]", new Instruction.UserAlarm(new Index.Direct(2), "NO PART"));
  }

  @Test
  void positionRegistersTakeOneSourceOrASum() {
    form("PR[1]=PR[2]", new Instruction.AssignPosReg(r(1), new Instruction.FromPosReg(r(2))));
    form("PR[1]=P[3:PICK]", new Instruction.AssignPosReg(r(1), new Instruction.FromLocal(3, "PICK")));
    form("PR[1]=LPOS", new Instruction.AssignPosReg(r(1), new Instruction.CurrentLpos()));
    form("PR[1]=JPOS", new Instruction.AssignPosReg(r(1), new Instruction.CurrentJpos()));
    form("PR[1]=UTOOL[2]", new Instruction.AssignPosReg(r(1),
        new Instruction.FromFrame(Instruction.FrameKind.TOOL, new Index.Direct(2), "")));
    form("PR[1]=PR[2]-PR[3]", new Instruction.AssignPosReg(r(1), new Instruction.PosArithmetic(r(2), false, r(3))));
    form("PR[1]=PR[2]+PR[3]", new Instruction.AssignPosReg(r(1), new Instruction.PosArithmetic(r(2), true, r(3))));
    form("PR[1]=LPOS-LPOS", new Instruction.AssignPosReg(r(1), new Instruction.PosSum(new Instruction.CurrentLpos(),
        List.of(new Instruction.PosTerm(false, new Instruction.CurrentLpos())))));
    form("PR[1]=PR[2]+PR[3]-JPOS", new Instruction.AssignPosReg(r(1), new Instruction.PosSum(new Instruction.FromPosReg(r(2)),
        List.of(new Instruction.PosTerm(true, new Instruction.FromPosReg(r(3))),
            new Instruction.PosTerm(false, new Instruction.CurrentJpos())))));
    form("PR[1]=P[1]+PR[2]", new Instruction.AssignPosReg(r(1), new Instruction.PosSum(new Instruction.FromLocal(1, ""),
        List.of(new Instruction.PosTerm(true, new Instruction.FromPosReg(r(2)))))));
    form("PR[1,3:Z]=R[2]", new Instruction.AssignPosElement(new Item(new Index.Direct(1), "Z"), new Index.Direct(3), reg(2)));
    form("PR[1,R[2]]=0", new Instruction.AssignPosElement(r(1), new Index.Indirect(2, ""), n(0)));
    form("PR[1]=VR[2].OFFSET", new Instruction.AssignPosReg(r(1), new Instruction.FromVisionRegister(r(2), false)));
    form("PR[1]=VR[2].FOUND_POS[1]", new Instruction.AssignPosReg(r(1), new Instruction.FromVisionRegister(r(2), true)));
    // PR[GP1:i]: group 1 named, the same register
    assertThat(parsed("PR[GP1:1]=PR[GP1:2]")).isEqualTo(parsed("PR[1]=PR[2]"));
    assertThat(parsed("R[1]=PR[GP1:5,1]")).isEqualTo(parsed("R[1]=PR[5,1]"));
  }

  @Test
  void outputsPulsesAndTimers() {
    form("DO[1]=ON", new Instruction.SetIo(IoKind.DO, r(1), new Expr.OnOff(true)));
    form("RO[2:GRIP]=OFF", new Instruction.SetIo(IoKind.RO, new Item(new Index.Direct(2), "GRIP"), new Expr.OnOff(false)));
    form("GO[1]=R[2]", new Instruction.SetIo(IoKind.GO, r(1), reg(2)));
    form("AO[1]=100", new Instruction.SetIo(IoKind.AO, r(1), n(100)));
    form("F[1]=(DI[1] AND DI[2])", new Instruction.SetIo(IoKind.F, r(1), new Expr.Group(new Expr.Binary(Expr.BinaryOp.AND,
        new Expr.Io(IoKind.DI, r(1)), new Expr.Io(IoKind.DI, r(2))))));
    form("DO[3]=PULSE", new Instruction.Pulse(IoKind.DO, r(3), OptionalDouble.empty()));
    form("RO[1]=PULSE,0.5sec", new Instruction.Pulse(IoKind.RO, r(1), OptionalDouble.of(0.5)));
    form("DO[1]=PULSE,2sec", new Instruction.Pulse(IoKind.DO, r(1), OptionalDouble.of(2)));
    for (Instruction.TimerAction a : Instruction.TimerAction.values()) {
      form("TIMER[1]=" + a.name(), new Instruction.TimerSet(r(1), a));
      assertThat(parsed("timer[1]=" + a.name().toLowerCase(java.util.Locale.ROOT))).isEqualTo(new Instruction.TimerSet(r(1), a));
    }
  }

  @Test
  void systemVariablesRobotRunRunsAreSetTheOthersAreSkipped() {
    form("$WAITTMOUT=500", new Instruction.SetSysVar("$WAITTMOUT", n(500)));
    assertThat(parsed("$waittmout=5")).isEqualTo(new Instruction.SetSysVar("$WAITTMOUT", n(5)));
    form("$MCR.$GENOVERRIDE=R[1]", new Instruction.SetSysVar("$MCR.$GENOVERRIDE", reg(1)));
    form("$MNUTOOLNUM[1]=2", new Instruction.SetSysVar("$MNUTOOLNUM[1]", n(2)));
    form("$MNUFRAMENUM[1]=3", new Instruction.SetSysVar("$MNUFRAMENUM[1]", n(3)));
    // read only, or unknown: kept, the line is skipped
    for (String t : List.of("$JCR.$JOG_GP=1", "$SCR.$ITP_SPEED=100", "$WAITTMOUT", "$WAITTMOUT 5")) {
      assertThat(parsed(t)).as(t).isEqualTo(new Instruction.Unsupported(t, "system variable assignment", true));
    }
    // read in an expression
    assertThat(TpStatementParser.expressionText("$JCR.$JOG_GP")).isEqualTo(new Expr.SysVar("$JCR.$JOG_GP"));
    assertThat(TpStatementParser.expressionText("$mix_bg[2].$status")).isEqualTo(new Expr.SysVar("$MIX_BG[2].$STATUS"));
  }

  // ---- flow ---------------------------------------------------------------------------------

  @Test
  void flowStatements() {
    form("LBL[10:LOOP]", new Instruction.Label(10, "LOOP"));
    form("LBL[1]", new Instruction.Label(1, ""));
    form("JMP LBL[R[1]]", new Instruction.Jump(new LabelRef(new Index.Indirect(1, ""), "")));
    form("CALL -KEPT", new Instruction.Call("-KEPT", List.of()));
    form("CALL SUB(1,'A,B',R[2])", new Instruction.Call("SUB", List.of(n(1), new Expr.StringConst("A,B"), reg(2))));
    assertThat(parsed("call sub()")).isEqualTo(new Instruction.Call("SUB", List.of()));
    form("RUN TASK2", new Instruction.Run("TASK2", List.of()));
    form("RUN TASK2(3)", new Instruction.Run("TASK2", List.of(n(3))));
    form("IF R[1]>=3,JMP LBL[2]", new Instruction.If(new Expr.Binary(Expr.BinaryOp.GE, reg(1), n(3)),
        new Instruction.Jump(lbl(2))));
    form("IF DI[1]=ON,CALL GRIP", new Instruction.If(new Expr.Binary(Expr.BinaryOp.EQ, new Expr.Io(IoKind.DI, r(1)),
        new Expr.OnOff(true)), new Instruction.Call("GRIP", List.of())));
    form("IF (DI[1]) THEN", new Instruction.IfThen(new Expr.Group(new Expr.Io(IoKind.DI, r(1)))));
    form("IF R[1]=1,R[2]=(5)", new Instruction.IfAction(new Expr.Binary(Expr.BinaryOp.EQ, reg(1), n(1)),
        new Instruction.AssignRegister(r(2), new Expr.Group(n(5)))));
    form("IF (DI[49]),DO[73]=PULSE,0.5sec", new Instruction.IfAction(new Expr.Group(new Expr.Io(IoKind.DI, r(49))),
        new Instruction.Pulse(IoKind.DO, r(73), OptionalDouble.of(0.5))));
    form("ELSE", new Instruction.Else());
    form("ENDIF", new Instruction.EndIf());
    form("SELECT R[1]=1,JMP LBL[1]", new Instruction.Select(r(1), n(1), new Instruction.Jump(lbl(1))));
    form(TpText.SELECT_INDENT + "=2,CALL B", new Instruction.SelectCase(n(2), new Instruction.Call("B", List.of())));
    form(TpText.SELECT_INDENT + "ELSE,JMP LBL[9]", new Instruction.SelectElse(new Instruction.Jump(lbl(9))));
    form("FOR R[1]=1 TO 1", new Instruction.For(r(1), n(1), false, n(1)));
    form("FOR R[1]=R[2] DOWNTO AR[1]", new Instruction.For(r(1), reg(2), true, new Expr.Arg(new Index.Direct(1))));
    form("FOR R[1]=-3 TO 3", new Instruction.For(r(1), n(-3), false, n(3)));
    form("ENDFOR", new Instruction.EndFor());
    form("END", new Instruction.End());
    form("PAUSE", new Instruction.Pause());
    form("ABORT", new Instruction.Abort());
  }

  @Test
  void waits() {
    form("WAIT    .50(sec)", new Instruction.WaitTime(new Expr.RealConst(0.5)));
    // an integer time is a real one: the controller shows seconds with two decimals
    assertThat(parsed("WAIT 2(sec)")).isEqualTo(new Instruction.WaitTime(new Expr.RealConst(2)));
    assertThat(parsed("WAIT 0(sec)")).isEqualTo(new Instruction.WaitTime(new Expr.RealConst(0)));
    assertThat(parsed("WAIT 0.0(sec)")).isEqualTo(new Instruction.WaitTime(new Expr.RealConst(0)));
    assertThat(parsed("WAIT .00(sec)")).isEqualTo(new Instruction.WaitTime(new Expr.RealConst(0)));
    form("WAIT R[4]", new Instruction.WaitTime(reg(4)));
    assertThat(parsed("WAIT R[4](sec)")).isEqualTo(new Instruction.WaitTime(reg(4)));
    assertThat(parsed("WAIT (-1)(sec)")).isEqualTo(new Instruction.WaitTime(new Expr.Group(n(-1))));
    form("WAIT DI[1]=ON", new Instruction.WaitCondition(new Expr.Binary(Expr.BinaryOp.EQ, new Expr.Io(IoKind.DI, r(1)),
        new Expr.OnOff(true)), Optional.empty()));
    form("WAIT DI[1]=ON TIMEOUT,LBL[3]", new Instruction.WaitCondition(new Expr.Binary(Expr.BinaryOp.EQ,
        new Expr.Io(IoKind.DI, r(1)), new Expr.OnOff(true)), Optional.of(lbl(3))));
    // a bare register or constant as a condition is written in parentheses, so it does not read as a time
    form("WAIT (R[1])", new Instruction.WaitCondition(new Expr.Group(reg(1)), Optional.empty()));
    assertThat(TpText.statement(new Instruction.WaitCondition(reg(1), Optional.empty()))).isEqualTo("WAIT (R[1])");
    assertThat(TpText.statement(new Instruction.WaitCondition(n(-5), Optional.empty()))).isEqualTo("WAIT (-5)");
    assertThat(TpText.statement(new Instruction.WaitCondition(new Expr.RealConst(2), Optional.empty()))).isEqualTo("WAIT (2.0)");
    assertThat(TpText.statement(new Instruction.WaitCondition(new Expr.Unary(Expr.UnaryOp.NOT, new Expr.Io(IoKind.DI, r(1))),
        Optional.empty()))).isEqualTo("WAIT (!DI[1])");
    assertThat(TpText.statement(new Instruction.WaitCondition(new Expr.Io(IoKind.DI, r(1)), Optional.empty()))).isEqualTo("WAIT DI[1]");
    // the edges ON+ / OFF- are kept, not run
    for (String t : List.of("WAIT DI[1]=ON+", "WAIT DI[1]=OFF-", "WAIT (DI[1]=ON+)", "WAIT DI[1]=ON+ AND DI[2]=ON",
        "WAIT DI[1]=ON+ OR DI[2]=ON", "WAIT DI[1]=ON+ TIMEOUT,LBL[1]", "IF DI[1]=OFF-,JMP LBL[1]")) {
      assertThat(parsed(t)).as(t).isInstanceOf(Instruction.Unsupported.class);
      assertThat(((Instruction.Unsupported) parsed(t)).what()).startsWith("edge detection O");
    }
    // ON followed by a sign that is arithmetic is no edge
    assertThat(parsed("R[1]=ON+1")).isEqualTo(new Instruction.AssignRegister(r(1),
        new Expr.Binary(Expr.BinaryOp.ADD, new Expr.OnOff(true), n(1))));
    assertThat(parsed("R[1]=OFF-R[2]")).isInstanceOf(Instruction.AssignRegister.class);
    assertThat(parsed("R[1]=ON-1")).isInstanceOf(Instruction.AssignRegister.class);
    // a macro of words after WAIT
    assertThat(parsed("WAIT NEXT PATH")).isEqualTo(new Instruction.MacroCall("WAIT NEXT PATH", List.of()));
  }

  @Test
  void otherStatements() {
    form("! stack three parts", new Instruction.Comment(" stack three parts"));
    form("//L P[1] 100mm/sec FINE", new Instruction.CommentedOut("L P[1] 100mm/sec FINE"));
    assertThat(parsed("!remark   ")).isEqualTo(new Instruction.Comment("remark"));
    form("MESSAGE[Gripper did not close]", new Instruction.Message("Gripper did not close"));
    form("MESSAGE[]", new Instruction.Message(""));
    form("OVERRIDE=50%", new Instruction.SetOverride(n(50)));
    form("OVERRIDE=R[1]", new Instruction.SetOverride(reg(1)));
    assertThat(parsed("OVERRIDE=50")).isEqualTo(new Instruction.SetOverride(n(50)));
    assertThat(parsed("OVERRIDE=R[1]%")).isEqualTo(new Instruction.SetOverride(reg(1)));
    form("OVERRIDE=12.5%", new Instruction.SetOverride(new Expr.RealConst(12.5)));
    form("", new Instruction.Blank());
    form("MONITOR WATCH", new Instruction.Monitor("WATCH", false));
    form("MONITOR END WATCH", new Instruction.Monitor("WATCH", true));
    assertThat(parsed("monitor end")).isEqualTo(new Instruction.Monitor("END", false));
    form("WHEN DI[1]=ON,CALL STOPIT", new Instruction.When(new Expr.Binary(Expr.BinaryOp.EQ, new Expr.Io(IoKind.DI, r(1)),
        new Expr.OnOff(true)), new Instruction.Call("STOPIT", List.of())));
    form("SKIP CONDITION DI[2]=ON", new Instruction.SkipCondition(new Expr.Binary(Expr.BinaryOp.EQ,
        new Expr.Io(IoKind.DI, r(2)), new Expr.OnOff(true))));
    form("OFFSET CONDITION PR[3:SHIFT]", new Instruction.OffsetCondition(new Item(new Index.Direct(3), "SHIFT")));
    form("OFFSET CONDITION PR[3],UFRAME[R[4]]", new Instruction.OffsetCondition(r(3), Optional.of(new Index.Indirect(4, ""))));
    form("TOOL_OFFSET CONDITION PR[5]", new Instruction.ToolOffsetCondition(r(5)));
    form("SR[1]=SUBSTR SR[2],1,3", new Instruction.AssignString(r(1), new Expr.StringFunc(Expr.StringFn.SUBSTR,
        List.of(new Expr.StringReg(r(2)), n(1), n(3)))));
    form("R[1]=STRLEN SR[2]", new Instruction.AssignRegister(r(1), new Expr.StringFunc(Expr.StringFn.STRLEN,
        List.of(new Expr.StringReg(r(2))))));
    form("R[1]=FINDSTR SR[2],SR[3]", new Instruction.AssignRegister(r(1), new Expr.StringFunc(Expr.StringFn.FINDSTR,
        List.of(new Expr.StringReg(r(2)), new Expr.StringReg(r(3))))));
  }

  @Test
  void macrosAreWordsWithHyphensAndArguments() {
    form("OPEN_HAND", new Instruction.MacroCall("OPEN_HAND", List.of()));
    form("HAND1 OPEN", new Instruction.MacroCall("HAND1 OPEN", List.of()));
    form("Open hand 1", new Instruction.MacroCall("Open hand 1", List.of()));
    form("ENTER WORK-ZONE(2)", new Instruction.MacroCall("ENTER WORK-ZONE", List.of(n(2))));
    form("Program Status(13,R[1])", new Instruction.MacroCall("Program Status", List.of(n(13), reg(1))));
    assertThat(parsed("Program Status()")).isEqualTo(new Instruction.MacroCall("Program Status", List.of()));
    // SET PATH(100): words then arguments are a macro, not the SET instruction
    form("SET PATH(100)", new Instruction.MacroCall("SET PATH", List.of(n(100))));
    assertThat(parsed("SET PATH")).isEqualTo(new Instruction.Unsupported("SET PATH", "SET instruction", false));
    assertThat(parsed("SET (1)")).isEqualTo(new Instruction.Unsupported("SET (1)", "SET instruction", false));
    // a word RobotRun knows by name is no macro
    assertThat(parsed("PTH")).isEqualTo(new Instruction.Unsupported("PTH", "PTH", true));
    assertThat(parsed("COL DETECT ON")).isEqualTo(new Instruction.Unsupported("COL DETECT ON", "COL DETECT", true));
    assertThat(parsed("PALLET")).isEqualTo(new Instruction.Unsupported("PALLET", "macro call PALLET", false));
  }

  @Test
  void theKindsRobotRunKeepsAreWarningsOnlyWhereTheProgramCanRunWithoutThem() {
    for (String t : List.of("JOINT_MAX_SPEED[1]=100", "LINEAR_MAX_SPEED=500", "TIMER_OVERFLOW[1]=ON", "DIAGNOSTIC",
        "LOCK PREG", "UNLOCK PREG", "TC_ONLINE (DI[1])", "ERROR_PROG=ERR", "RESUME_PROG[1]=RES", "CLEAR_RESUME_PROG",
        "RETURN_PATH_DSBL", "MAINT_PROG[1]=M", "PRINT R[1]", "BREAK", "MROT", "CONST_PATH", "TORQ_LIMIT 50",
        "SOFTFLOAT[1]", "COL GUARD_ADJUST 100")) {
      Instruction in = parsed(t);
      assertThat(in).as(t).isInstanceOf(Instruction.Unsupported.class);
      assertThat(((Instruction.Unsupported) in).runnable()).as(t).isTrue();
    }
    for (String t : List.of("SPOT[1]", "Arc Start[1]", "PALLETIZING-B_1", "SEMAPHORE[1]=ON", "VISION SET_REFERENCE 'A'",
        "RSR[1]=ENABLE", "STRING", "POINT_LOGIC", "PATH")) {
      Instruction in = parsed(t);
      assertThat(in).as(t).isInstanceOf(Instruction.Unsupported.class);
      assertThat(((Instruction.Unsupported) in).runnable()).as(t).isFalse();
    }
  }

  // ---- iRVision (docs/vision.md) --------------------------------------------------------------

  @Test
  void visionStatements() {
    Instruction.VisionProcess a = new Instruction.VisionProcessName("A");
    form("VISION RUN_FIND 'A'", new Instruction.VisionRunFind(a));
    form("VISION RUN_FIND SR[2]", new Instruction.VisionRunFind(new Instruction.VisionProcessInRegister(r(2))));
    Instruction getOffset = new Instruction.VisionGetOffset(a, r(1), lbl(9));
    form("VISION GET_OFFSET 'A' VR[1] JMP,LBL[9]", getOffset);
    assertThat(parsed("VISION GET_OFFSET 'A' VR[1] JMP LBL[9]")).isEqualTo(getOffset);
    assertThat(parsed("VISION GET_OFFSET 'A' VR[1] JUMP,LBL[9]")).isEqualTo(getOffset);
    form("VISION GET_NFOUND 'A' R[3]", new Instruction.VisionGetNFound(a, r(3)));
    form("R[1]=VR[2].MODELID", new Instruction.AssignFromVr(r(1), r(2), Instruction.VisionField.MODELID, 0));
    form("R[1]=VR[2].ENC", new Instruction.AssignFromVr(r(1), r(2), Instruction.VisionField.ENC, 0));
    form("R[1]=VR[2].MES[1]", new Instruction.AssignFromVr(r(1), r(2), Instruction.VisionField.MES, 1));
    form("R[1]=VR[2].MES[10]", new Instruction.AssignFromVr(r(1), r(2), Instruction.VisionField.MES, 10));
    for (String t : List.of("R[1]=VR[2].MES[0]", "R[1]=VR[2].MES[11]", "R[1]=VR[2].MES[001]", "R[1]=VR[2].MES[1.5]",
        "R[1]=VR[2].MES[1]+1", "R[1]=VR[2].MES", "R[1]=VR[2].ENC+1", "R[1]=VR[2].FOO", "R[1]=VR[2]", "R[1]=VR[2].1",
        "R[1]=VR[2].MES[1", "R[1]=VR[2].MES 1]")) {
      assertThat(parsed(t)).as(t).isEqualTo(new Instruction.Unsupported(t, "vision registers VR[] in an expression", false));
    }
    // any other VISION form, or a malformed one, is kept and alarms as "iRVision"
    for (String t : List.of("VISION CAMERA_CALIB 'A'", "VISION RUN_FIND 'A' X", "VISION GET_OFFSET 'A' VR[1] GOTO,LBL[1]",
        "VISION GET_OFFSET 'A' R[1] JMP,LBL[1]", "VISION GET_NFOUND 'A' VR[1]", "VISION RUN_FIND 5", "VISION 5",
        "VISION GET_OFFSET 'A' VR[1] JMP,PR[1]")) {
      assertThat(parsed(t)).as(t).isEqualTo(new Instruction.Unsupported(t, "iRVision", false));
    }
  }

  // ---- motion ---------------------------------------------------------------------------------

  @Test
  void motionsOfEveryTypeSpeedAndTermination() {
    form("J P[1:HOME] 30% FINE", Instruction.Move.of(Motion.Type.J, new Motion.Local(1, "HOME"),
        new Motion.Speed(new Motion.SpeedConst(30), Motion.SpeedUnit.PERCENT), new Motion.Fine(), List.of()));
    form("J P[1] 100% CNT0", Instruction.Move.of(Motion.Type.J, new Motion.Local(1, ""),
        new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.PERCENT), new Motion.Cnt(0), List.of()));
    form("L PR[R[2]] 400mm/sec CNT100", Instruction.Move.of(Motion.Type.L, new Motion.Register(new Item(new Index.Indirect(2, ""), "")),
        mmPerSec(400), new Motion.Cnt(100), List.of()));
    form("A P[2] 100mm/sec CNT R[3]", Instruction.Move.of(Motion.Type.A, new Motion.Local(2, ""), mmPerSec(100),
        new Motion.CntRegister(r(3)), List.of()));
    form("C P[1]" + TpText.CONTINUATION + "P[2] 200mm/sec FINE", Instruction.Move.circular(new Motion.Local(1, ""),
        new Motion.Local(2, ""), mmPerSec(200), new Motion.Fine(), List.of()));
    form("J P[1] R[4]% FINE", Instruction.Move.of(Motion.Type.J, new Motion.Local(1, ""),
        new Motion.Speed(new Motion.SpeedRegister(r(4)), Motion.SpeedUnit.PERCENT), new Motion.Fine(), List.of()));
    for (Motion.SpeedUnit u : Motion.SpeedUnit.values()) {
      for (Motion.Type t : Motion.Type.values()) {
        String text = t + " P[1] 2" + TpText.unit(u) + " FINE";
        if (t == Motion.Type.C) {
          text = "C P[1]" + TpText.CONTINUATION + "P[2] 2" + TpText.unit(u) + " FINE";
        }
        if (u.fits(t)) {
          assertThat(((Instruction.Move) parsed(text)).speed()).as(text).isEqualTo(new Motion.Speed(new Motion.SpeedConst(2), u));
          assertThat(TpText.statement(parsed(text))).isEqualTo(text);
        } else {
          String shown = text;
          assertThatThrownBy(() -> parsed(shown)).as(text).isInstanceOf(TpSyntaxError.class).hasMessageContaining("does not fit");
        }
      }
    }
    // the docs' table: J takes %, sec and msec; the others every unit but %
    assertThat(Motion.SpeedUnit.PERCENT.fits(Motion.Type.J)).isTrue();
    assertThat(Motion.SpeedUnit.MM_PER_SEC.fits(Motion.Type.J)).isFalse();
    assertThat(Motion.SpeedUnit.SEC.fits(Motion.Type.L)).isTrue();
    assertThat(Motion.SpeedUnit.PERCENT.fits(Motion.Type.A)).isFalse();
    // units in any case, CNT with a space
    assertThat(parsed("l p[1] 100MM/SEC cnt 50")).isEqualTo(Instruction.Move.of(Motion.Type.L, new Motion.Local(1, ""),
        mmPerSec(100), new Motion.Cnt(50), List.of()));
    // speed bounds: 1..100 % at and beyond, any positive other speed
    assertThat(parsed("J P[1] 100% FINE")).isInstanceOf(Instruction.Move.class);
    assertThat(parsed("J P[1] 1% FINE")).isInstanceOf(Instruction.Move.class);
    assertThat(parsed("J P[1] 0.5% FINE")).isInstanceOf(Instruction.Move.class);
    assertThat(parsed("L P[1] 5000mm/sec FINE")).isInstanceOf(Instruction.Move.class);
    assertThat(parsed("J P[1] 250sec FINE")).isInstanceOf(Instruction.Move.class);
  }

  @Test
  void motionOptions() {
    assertThat(option("Offset")).isEqualTo(new Motion.Offset());
    assertThat(option("Offset,PR[2]")).isEqualTo(new Motion.OffsetPr(r(2)));
    assertThat(option("Tool_Offset")).isEqualTo(new Motion.ToolOffset());
    assertThat(option("Tool_Offset,PR[3]")).isEqualTo(new Motion.ToolOffsetPr(r(3)));
    assertThat(option("Wjnt")).isEqualTo(new Motion.Wjnt());
    assertThat(option("INC")).isEqualTo(new Motion.Inc());
    assertThat(option("ACC R[5]")).isEqualTo(new Motion.AccRegister(r(5)));
    assertThat(option("Skip,LBL[4]")).isEqualTo(new Motion.Skip(lbl(4)));
    assertThat(option("Skip,LBL[4],PR[2]=LPOS")).isEqualTo(Motion.Skip.storing(lbl(4), r(2), false));
    assertThat(option("Skip,LBL[4],PR[2]=JPOS")).isEqualTo(Motion.Skip.storing(lbl(4), r(2), true));
    assertThat(option("VOFFSET,VR[1]")).isEqualTo(new Motion.VisionOffset(r(1)));
    for (String o : List.of("Offset,PR[2]", "Tool_Offset,PR[3]", "Wjnt", "INC", "ACC R[5]", "Skip,LBL[4]",
        "Skip,LBL[4],PR[2]=LPOS", "Skip,LBL[4],PR[2]=JPOS", "VOFFSET,VR[1]", "ACC0", "ACC150", "Offset", "Tool_Offset")) {
      assertThat(TpText.option(option(o))).isEqualTo(o);
    }
    // ACC: 0..150 runs; up to 500 (a raised limit) is kept with a warning; beyond is an error
    assertThat(option("ACC0")).isEqualTo(new Motion.Acc(0));
    assertThat(option("ACC150")).isEqualTo(new Motion.Acc(150));
    assertThat(option("ACC151")).isEqualTo(new Motion.RawOption("ACC151", "ACC above 150 (a raised acceleration limit)"));
    assertThat(option("ACC500")).isEqualTo(new Motion.RawOption("ACC500", "ACC above 150 (a raised acceleration limit)"));
    assertThatThrownBy(() -> option("ACC501")).isInstanceOf(TpSyntaxError.class);
    assertThat(option("ACC")).isEqualTo(new Motion.RawOption("ACC", "motion option ACC"));
    assertThat(option("ACCX")).isEqualTo(new Motion.RawOption("ACCX", "motion option ACCX"));
    // options RobotRun does not run are kept as written, everything after them with them
    assertThat(option("Skip,LBL[4],X")).isEqualTo(new Motion.RawOption("Skip,LBL[4],X", "Skip,LBL[] with X"));
    assertThat(option("VOFFSET")).isEqualTo(new Motion.RawOption("VOFFSET", "vision offset VOFFSET"));
    assertThat(option("VOFFSET,R[1]")).isEqualTo(new Motion.RawOption("VOFFSET,R[1]", "vision offset VOFFSET"));
    assertThat(option("VOFFSET,VR 1")).isEqualTo(new Motion.RawOption("VOFFSET,VR 1", "vision offset VOFFSET"));
    assertThat(option("COORD  Wjnt")).isEqualTo(new Motion.RawOption("COORD  Wjnt", "coordinated motion COORD"));
    assertThat(option("PTH")).isEqualTo(new Motion.RawOption("PTH", "PTH"));
    assertThat(option("RTCP")).isEqualTo(new Motion.RawOption("RTCP", "remote TCP (RTCP)"));
    assertThat(option("MROT")).isEqualTo(new Motion.RawOption("MROT", "MROT"));
    assertThat(option("BREAK")).isEqualTo(new Motion.RawOption("BREAK", "BREAK"));
    assertThat(option("CR50")).isEqualTo(new Motion.RawOption("CR50", "motion option CR50"));
    assertThat(option("CR")).isEqualTo(new Motion.RawOption("CR", "corner region CR"));
    assertThat(option("PSPD")).isEqualTo(new Motion.RawOption("PSPD", "process speed PSPD"));
    assertThat(option("Weave")).isEqualTo(new Motion.RawOption("Weave", "arc welding weave (as a motion option)"));
    assertThat(option("ODD")).isEqualTo(new Motion.RawOption("ODD", "motion option ODD"));
  }

  @Test
  void timedActionsRunOutputsAndCallsAndKeepTheRestAsWritten() {
    Instruction doOn = new Instruction.SetIo(IoKind.DO, r(3), new Expr.OnOff(true));
    assertThat(option("TB .20sec,DO[3]=ON")).isEqualTo(new Motion.TimedAction(Motion.When.TIME_BEFORE, 0.2, doOn, "TB .20sec,DO[3]=ON"));
    assertThat(option("TA 1.5sec,DO[3]=ON")).isEqualTo(new Motion.TimedAction(Motion.When.TIME_AFTER, 1.5, doOn, "TA 1.5sec,DO[3]=ON"));
    assertThat(option("DB 10mm,DO[3]=ON")).isEqualTo(new Motion.TimedAction(Motion.When.DISTANCE_BEFORE, 10, doOn, "DB 10mm,DO[3]=ON"));
    assertThat(option("TIME BEFORE .5sec,CALL BEEP")).isEqualTo(new Motion.TimedAction(Motion.When.TIME_BEFORE, 0.5,
        new Instruction.Call("BEEP", List.of()), "TIME BEFORE .5sec,CALL BEEP"));
    assertThat(option("TIME AFTER .5sec,RO[1]=PULSE,0.5sec")).isEqualTo(new Motion.TimedAction(Motion.When.TIME_AFTER, 0.5,
        new Instruction.Pulse(IoKind.RO, r(1), OptionalDouble.of(0.5)), "TIME AFTER .5sec,RO[1]=PULSE,0.5sec"));
    assertThat(option("DISTANCE BEFORE 20mm,GO[1]=R[2]")).isEqualTo(new Motion.TimedAction(Motion.When.DISTANCE_BEFORE, 20,
        new Instruction.SetIo(IoKind.GO, r(1), reg(2)), "DISTANCE BEFORE 20mm,GO[1]=R[2]"));
    assertThat(option("TB .5sec,CALL BEEP(1)")).isEqualTo(new Motion.TimedAction(Motion.When.TIME_BEFORE, 0.5,
        new Instruction.Call("BEEP", List.of(n(1))), "TB .5sec,CALL BEEP(1)"));
    // kept as written: the wrong unit, another action, a CALL through SR[], something after the action
    for (String t : List.of("TB .5mm,DO[3]=ON", "DB 10sec,DO[3]=ON", "TB .5sec,POINT_LOGIC", "TB .5sec,R[1]=1",
        "TB .5sec,CALL SR[1]", "TB .5sec,DO[3]=ON X", "TB .5sec DO[3]=ON", "TB sec,DO[3]=ON", "TB .5sec,",
        "TIME .5sec,DO[3]=ON", "DISTANCE AFTER 5mm,DO[3]=ON", "TIME BEFORE .5sec", "TB", "TB .5sec,DO[")) {
      Motion.Option o = option(t);
      assertThat(o).as(t).isInstanceOf(Motion.RawOption.class);
      assertThat(((Motion.RawOption) o).text()).isEqualTo(t);
    }
    assertThat(option("TB .5sec,POINT_LOGIC")).isEqualTo(new Motion.RawOption("TB .5sec,POINT_LOGIC", "TIME BEFORE/AFTER (TB/TA)"));
    assertThat(option("DB 5mm,POINT_LOGIC")).isEqualTo(new Motion.RawOption("DB 5mm,POINT_LOGIC", "DISTANCE BEFORE (DB)"));
  }

  @Test
  void aKeptOptionIsRebuiltFromItsTokensWhenTheLineTextIsNotAtHand() {
    // parse(tokens) without the line: the option is rebuilt, words one space apart, strings quoted
    Instruction in = TpStatementParser.parse(TpLexer.tokenize("L P[1] 100mm/sec FINE COORD  X 'a'[1]", 1, 1, true)).instruction();
    assertThat(((Instruction.Move) in).options()).containsExactly(new Motion.RawOption("COORD X 'a'[1]", "coordinated motion COORD"));
    Instruction spaced = TpStatementParser.parse(TpLexer.tokenize("L P[1] 100mm/sec FINE COORD 'a' [1]", 1, 1, true)).instruction();
    assertThat(((Instruction.Move) spaced).options()).containsExactly(new Motion.RawOption("COORD 'a' [1]", "coordinated motion COORD"));
    // with the line, exactly as written
    String line = "L P[1] 100mm/sec FINE COORD  X 'a'[1]";
    Instruction withLine = TpStatementParser.parse(TpLexer.tokenize(line, 1, 1, true), l -> l == 1 ? line : null).instruction();
    assertThat(((Instruction.Move) withLine).options()).containsExactly(new Motion.RawOption("COORD  X 'a'[1]", "coordinated motion COORD"));
  }

  @Test
  void viaPointOffsetsOfACircularMotion() {
    Instruction.Move m = (Instruction.Move) parsed("C P[1] Offset,PR[2] Tool_Offset" + TpText.CONTINUATION + "P[2] 100mm/sec FINE Offset");
    assertThat(m.viaOptions()).containsExactly(new Motion.OffsetPr(r(2)), new Motion.ToolOffset());
    assertThat(m.options()).containsExactly(new Motion.Offset());
    assertThat(TpText.statement(m)).isEqualTo("C P[1] Offset,PR[2] Tool_Offset" + TpText.CONTINUATION + "P[2] 100mm/sec FINE Offset");
  }

  @Test
  void motionsToGroupOneRun() {
    assertThat(parsed("J PR[GP1:5] 100% FINE")).isEqualTo(parsed("J PR[5] 100% FINE"));
    assertThat(parsed("J PR[GP1:R[2]] 100% FINE")).isEqualTo(parsed("J PR[R[2]] 100% FINE"));
    assertThat(parsed("J PR[GP1:R[2]:X] 100% FINE")).isInstanceOf(Instruction.Unsupported.class);
  }

  // ---- hand-edited files (docs/tp-language.md, "Program lines") ----------------------------------

  private static TpStatementParser.Parsed mended(String text) {
    return TpStatementParser.parseMendingHandEdits(TpLexer.tokenize(text, 1, 1, true), l -> text);
  }

  @Test
  void aFileMotionWithoutSpeedOrTerminationIsCompletedFromTheDefaultMotionTable() {
    Motion.Speed pct100 = new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.PERCENT);
    TpStatementParser.Parsed j = mended("J PR[96]");
    assertThat(j.instruction()).isEqualTo(Instruction.Move.of(Motion.Type.J, new Motion.Register(r(96)), pct100, new Motion.Fine(), List.of()));
    assertThat(j.warnings()).containsExactly("mended: a J motion without speed and termination: completed with 100% FINE "
        + "from the pendant's first default J motion (J P[] 100% FINE)");
    TpStatementParser.Parsed l = mended("L P[1] CNT50");
    assertThat(l.instruction()).isEqualTo(Instruction.Move.of(Motion.Type.L, new Motion.Local(1, ""), mmPerSec(100), new Motion.Cnt(50), List.of()));
    assertThat(l.warnings()).containsExactly("mended: a L motion without speed: completed with 100mm/sec "
        + "from the pendant's first default L motion (L P[] 100mm/sec FINE)");
    TpStatementParser.Parsed t = mended("J P[1] 30%");
    assertThat(t.instruction()).isEqualTo(Instruction.Move.of(Motion.Type.J, new Motion.Local(1, ""),
        new Motion.Speed(new Motion.SpeedConst(30), Motion.SpeedUnit.PERCENT), new Motion.Fine(), List.of()));
    assertThat(t.warnings()).containsExactly("mended: a J motion without termination: completed with FINE "
        + "from the pendant's first default J motion (J P[] 100% FINE)");
    TpStatementParser.Parsed a = mended("A P[1] Offset");
    assertThat(a.instruction()).isEqualTo(Instruction.Move.of(Motion.Type.A, new Motion.Local(1, ""), mmPerSec(100), new Motion.Fine(),
        List.of(new Motion.Offset())));
    assertThat(a.warnings()).containsExactly("mended: a A motion without speed and termination: completed with 100mm/sec FINE "
        + "from the pendant's first default L motion (L P[] 100mm/sec FINE; its table has no A row)");
    assertThat(mended("L P[1] FINE").warnings()).containsExactly("mended: a L motion without speed: completed with 100mm/sec "
        + "from the pendant's first default L motion (L P[] 100mm/sec FINE)");
    assertThat(mended("L P[1] CNT 5").warnings()).hasSize(1);
    assertThat(mended("L P[1] 50mm/sec INC").warnings()).containsExactly("mended: a L motion without termination: completed with FINE "
        + "from the pendant's first default L motion (L P[] 100mm/sec FINE)");
    // C takes the L row too, its end point on the continuation line
    List<TpToken> c = new java.util.ArrayList<>(TpLexer.tokenize("C P[1]", 1, 1, true));
    c.remove(c.size() - 1);
    c.addAll(TpLexer.tokenize("P[2]", 2, 8, false));
    TpStatementParser.Parsed cm = TpStatementParser.parseMendingHandEdits(c, ln -> null);
    assertThat(cm.instruction()).isEqualTo(Instruction.Move.circular(new Motion.Local(1, ""), new Motion.Local(2, ""), mmPerSec(100),
        new Motion.Fine(), List.of()));
    assertThat(cm.warnings()).containsExactly("mended: a C motion without speed and termination: completed with 100mm/sec FINE "
        + "from the pendant's first default L motion (L P[] 100mm/sec FINE; its table has no C row)");
    assertThat(DefaultMotions.first(Motion.Type.J)).isEqualTo(DefaultMotions.STANDARD.get(0));
    assertThat(DefaultMotions.first(Motion.Type.L)).isEqualTo(DefaultMotions.STANDARD.get(2));
    // a complete motion is not touched, and the pendant (statementText) still needs both parts
    assertThat(mended("L P[1] 50mm/sec CNT5").warnings()).isEmpty();
    assertThatThrownBy(() -> mended("L P[1] 50mm/sec CNTX")).isInstanceOf(TpSyntaxError.class)
        .hasMessage("expected a termination (FINE, CNTn or CNT R[i]), found 'CNTX'");
    assertThatThrownBy(() -> parsed("J PR[96]")).isInstanceOf(TpSyntaxError.class);
    assertThatThrownBy(() -> parsed("J P[1] 30%")).isInstanceOf(TpSyntaxError.class);
  }

  /** The kind a file's statement is kept as (not run): the reader keeps such a line as written. */
  private static String keptFromFile(String text) {
    try {
      mended(text);
    } catch (TpSyntaxError e) {
      assertThat(e.unsupported()).as(text + ": " + e.getMessage()).isPresent();
      assertThat(e.runnable()).isFalse();
      return e.unsupported().get();
    }
    throw new AssertionError(text + " was read as a statement that runs");
  }

  /** The message of a file's statement that is a syntax error (not a kept form). */
  private static String syntaxErrorFromFile(String text) {
    try {
      mended(text);
    } catch (TpSyntaxError e) {
      assertThat(e.unsupported()).as(text + ": " + e.getMessage()).isEmpty();
      return e.getMessage();
    }
    throw new AssertionError(text + " was read");
  }

  @Test
  void aRegisterKindRobotRunDoesNotKnowIsKeptInAFileAndRefusedWhenTyped() {
    assertThat(keptFromFile("IF M[1]=ON,JMP LBL[1]")).isEqualTo("M[] in an expression");
    assertThatThrownBy(() -> parsed("IF M[1]=ON,JMP LBL[1]")).isInstanceOf(TpSyntaxError.class)
        .hasMessage("expected a value (number, R[i], PR[i,j], DI[i], F[i], TIMER[i], AR[i], ON, OFF or '('), found 'M'");
    // only a kind's name before '[': letters, digits and '_', starting with a letter, at most 24 characters
    assertThat(syntaxErrorFromFile("R[1]=M")).startsWith("expected a value");
    assertThat(syntaxErrorFromFile("R[1]=_M[1]")).startsWith("expected a value");
    assertThat(syntaxErrorFromFile("R[1]=A$B[1]")).startsWith("expected a value");
    assertThat(keptFromFile("R[1]=" + "W".repeat(24) + "[1]")).isEqualTo("W".repeat(24) + "[] in an expression");
    assertThat(syntaxErrorFromFile("R[1]=" + "W".repeat(25) + "[1]")).startsWith("expected a value");
    assertThat(keptFromFile("R[1]=W2_O[1]")).isEqualTo("W2_O[] in an expression");
  }

  // ---- expressions ------------------------------------------------------------------------------

  @Test
  void operandsOfExpressions() {
    assertThat(TpStatementParser.expressionText("-7")).isEqualTo(n(-7));
    assertThat(TpStatementParser.expressionText("-2.5")).isEqualTo(new Expr.RealConst(-2.5));
    assertThat(TpStatementParser.expressionText("-R[1]")).isEqualTo(new Expr.Unary(Expr.UnaryOp.MINUS, reg(1)));
    assertThat(TpStatementParser.expressionText("!DI[1]")).isEqualTo(new Expr.Unary(Expr.UnaryOp.NOT, new Expr.Io(IoKind.DI, r(1))));
    assertThat(TpStatementParser.expressionText(".20")).isEqualTo(new Expr.RealConst(0.2));
    assertThat(TpStatementParser.expressionText("3.0")).isEqualTo(new Expr.RealConst(3));
    assertThat(TpStatementParser.expressionText("2147483647")).isEqualTo(n(Integer.MAX_VALUE));
    assertThat(TpStatementParser.expressionText("'PART'")).isEqualTo(new Expr.StringConst("PART"));
    assertThat(TpStatementParser.expressionText("SR[1]+'_A'")).isEqualTo(new Expr.Binary(Expr.BinaryOp.ADD,
        new Expr.StringReg(r(1)), new Expr.StringConst("_A")));
    assertThat(TpStatementParser.expressionText("TIMER[2]")).isEqualTo(new Expr.Timer(r(2)));
    assertThat(TpStatementParser.expressionText("AR[R[1]]")).isEqualTo(new Expr.Arg(new Index.Indirect(1, "")));
    assertThat(TpStatementParser.expressionText("UI[3]")).isEqualTo(new Expr.Io(IoKind.UI, r(3)));
    assertThat(TpStatementParser.expressionText("ABS[R[1]]")).isEqualTo(new Expr.MathFunc(Expr.MathFn.ABS, reg(1)));
    assertThat(TpStatementParser.expressionText("sqrt[2]")).isEqualTo(new Expr.MathFunc(Expr.MathFn.SQRT, n(2)));
    for (Expr.MathFn f : Expr.MathFn.values()) {
      assertThat(TpStatementParser.expressionText(f.name() + "[1]")).isEqualTo(new Expr.MathFunc(f, n(1)));
    }
    assertThat(TpText.expr(TpStatementParser.expressionText("ROUND[R[1]*2]+1"))).isEqualTo("ROUND[R[1]*2]+1");
    // ATAN2's argument order is not confirmed: kept, not run; a function name without '[' is no value
    assertThat(parsed("R[1]=ATAN2[1,2]")).isEqualTo(new Instruction.Unsupported("R[1]=ATAN2[1,2]", "arithmetic function ATAN2[]", false));
    assertThatThrownBy(() -> TpStatementParser.expressionText("ABS")).isInstanceOf(TpSyntaxError.class);
    assertThat(parsed("R[1]=ERR_NUM")).isEqualTo(new Instruction.Unsupported("R[1]=ERR_NUM",
        "ERR_NUM (the error-recovery option's alarm number)", false));
    assertThat(parsed("R[1]=$SGSCH1[90].$WELD_PRESS")).isEqualTo(new Instruction.Unsupported("R[1]=$SGSCH1[90].$WELD_PRESS",
        "system variable $SGSCH1[90].$WELD_PRESS in an expression", false));
    assertThat(parsed("R[1]=1+VR[1]")).isEqualTo(new Instruction.Unsupported("R[1]=1+VR[1]",
        "vision registers VR[] in an expression", false));
    assertThat(parsed("R[1]=DIAGNOSTIC")).isEqualTo(new Instruction.Unsupported("R[1]=DIAGNOSTIC", "DIAGNOSTIC in an expression", false));
  }

  @Test
  void precedenceFromLoosestToTightestAllLeftAssociative() {
    // OR; AND; comparisons; + -; * / DIV MOD; unary (docs/tp-language.md, "Expressions")
    Expr e = TpStatementParser.expressionText("R[1]=1 OR R[2]+3*4>5 AND !DI[1]");
    Expr expected = new Expr.Binary(Expr.BinaryOp.OR, new Expr.Binary(Expr.BinaryOp.EQ, reg(1), n(1)),
        new Expr.Binary(Expr.BinaryOp.AND,
            new Expr.Binary(Expr.BinaryOp.GT, new Expr.Binary(Expr.BinaryOp.ADD, reg(2), new Expr.Binary(Expr.BinaryOp.MUL, n(3), n(4))), n(5)),
            new Expr.Unary(Expr.UnaryOp.NOT, new Expr.Io(IoKind.DI, r(1)))));
    assertThat(e).isEqualTo(expected);
    assertThat(TpStatementParser.expressionText("8-2-1")).isEqualTo(new Expr.Binary(Expr.BinaryOp.SUB,
        new Expr.Binary(Expr.BinaryOp.SUB, n(8), n(2)), n(1)));
    assertThat(TpStatementParser.expressionText("8 DIV 2 MOD 3/4")).isEqualTo(new Expr.Binary(Expr.BinaryOp.DIVIDE,
        new Expr.Binary(Expr.BinaryOp.MOD, new Expr.Binary(Expr.BinaryOp.DIV, n(8), n(2)), n(3)), n(4)));
    assertThat(TpStatementParser.expressionText("1<>2")).isEqualTo(new Expr.Binary(Expr.BinaryOp.NE, n(1), n(2)));
    assertThat(TpStatementParser.expressionText("1<2")).isEqualTo(new Expr.Binary(Expr.BinaryOp.LT, n(1), n(2)));
    assertThat(TpStatementParser.expressionText("1<=2")).isEqualTo(new Expr.Binary(Expr.BinaryOp.LE, n(1), n(2)));
    assertThat(TpStatementParser.expressionText("1 and 2 or 3")).isEqualTo(new Expr.Binary(Expr.BinaryOp.OR,
        new Expr.Binary(Expr.BinaryOp.AND, n(1), n(2)), n(3)));
    // the printer adds the parentheses the tree needs, and only those
    assertThat(TpText.expr(new Expr.Binary(Expr.BinaryOp.SUB, n(8), new Expr.Binary(Expr.BinaryOp.SUB, n(2), n(1))))).isEqualTo("8-(2-1)");
    assertThat(TpText.expr(new Expr.Binary(Expr.BinaryOp.MUL, new Expr.Binary(Expr.BinaryOp.ADD, n(1), n(2)), n(3)))).isEqualTo("(1+2)*3");
    assertThat(TpText.expr(new Expr.Binary(Expr.BinaryOp.ADD, n(1), new Expr.Binary(Expr.BinaryOp.MUL, n(2), n(3))))).isEqualTo("1+2*3");
    assertThat(TpText.expr(new Expr.Unary(Expr.UnaryOp.MINUS, new Expr.Binary(Expr.BinaryOp.ADD, n(1), n(2))))).isEqualTo("-(1+2)");
    assertThat(TpText.expr(new Expr.Unary(Expr.UnaryOp.NOT, new Expr.Unary(Expr.UnaryOp.NOT, new Expr.OnOff(true))))).isEqualTo("!!ON");
    assertThat(TpText.expr(new Expr.Binary(Expr.BinaryOp.DIV, n(7), n(2)))).isEqualTo("7 DIV 2");
    assertThat(TpText.expr(new Expr.StringFunc(Expr.StringFn.SUBSTR, List.of(new Expr.Binary(Expr.BinaryOp.ADD,
        new Expr.StringReg(r(1)), new Expr.StringConst("A")), n(1), new Expr.Unary(Expr.UnaryOp.MINUS, reg(2))))))
        .isEqualTo("SUBSTR (SR[1]+'A'),1,-R[2]");
    assertThat(TpText.expr(new Expr.StringConst("it's"))).isEqualTo("\"it's\"");
  }

  @Test
  void entryRulesOfTheControllerAreWarningsOnAStatement() {
    String mixed = "the controller does not mix + or - with *, /, DIV or MOD on a line without parentheses: "
        + "put the expression in parentheses (mixed logic) (a pendant refuses this entry)";
    String andOr = "the controller does not mix AND with OR on a line without parentheses: "
        + "put the condition in parentheses (mixed logic) (a pendant refuses this entry)";
    assertThat(warnings("R[1]=R[2]+R[3]*2")).containsExactly(mixed);
    assertThat(warnings("R[1]=(R[2]+R[3]*2)")).isEmpty();
    assertThat(warnings("R[1]=R[2]+R[3]-1")).isEmpty();
    assertThat(warnings("R[1]=R[2]*R[3] DIV 2 MOD 3/4")).isEmpty();
    assertThat(warnings("R[1]=-R[2]+R[3]*2")).containsExactly(mixed);
    assertThat(warnings("IF DI[1] AND DI[2] OR DI[3],JMP LBL[1]")).containsExactly(andOr);
    assertThat(warnings("IF (DI[1] AND DI[2] OR DI[3]),JMP LBL[1]")).isEmpty();
    assertThat(warnings("IF !(DI[1]) AND DI[2] OR DI[3],JMP LBL[1]")).isEmpty();
    // every statement that holds an expression is checked
    for (String t : List.of("PR[1,2]=R[2]+R[3]*2", "IF DI[1] AND DI[2] OR DI[3] THEN", "IF DI[1] AND DI[2] OR DI[3],R[1]=1",
        "WAIT DI[1] AND DI[2] OR DI[3]", "DO[1]=DI[1] AND DI[2] OR DI[3]", "$WAITTMOUT=R[2]+R[3]*2", "SR[1]=R[2]+R[3]*2",
        "SKIP CONDITION DI[1] AND DI[2] OR DI[3]")) {
      assertThat(warnings(t)).as(t).hasSize(1);
    }
    assertThat(TpStatementParser.parseMendingHandEdits(TpLexer.tokenize("WHEN DI[1] AND DI[2] OR DI[3],CALL X", 1, 1, true), l -> null)
        .warnings()).hasSize(1);
    // parentheses anywhere make the line mixed logic: left or right of an operator, under a sign
    assertThat(warnings("R[1]=(1)+R[2]*3")).isEmpty();
    assertThat(warnings("R[1]=R[2]*3+(1)")).isEmpty();
    assertThat(warnings("R[1]=-(R[2]+R[3]*2)")).isEmpty();
    assertThat(warnings("R[1]=R[2]*-R[3]+1")).containsExactly(mixed);
    assertThat(warnings("R[1]=ABS[R[2]+R[3]*2]")).isEmpty();
    assertThat(warnings("R[1]=R[2] MOD 3-1")).containsExactly(mixed);
    assertThat(warnings("R[1]=R[2] DIV 3+1")).containsExactly(mixed);
    assertThat(warnings("R[1]=R[2]/3-1")).containsExactly(mixed);
    assertThat(EntryRules.refusal(new Expr.Binary(Expr.BinaryOp.OR, new Expr.Binary(Expr.BinaryOp.AND, new Expr.OnOff(true),
        new Expr.OnOff(true)), new Expr.OnOff(false)))).isPresent();
    assertThat(EntryRules.refusal(new Expr.Binary(Expr.BinaryOp.AND, new Expr.OnOff(true), new Expr.OnOff(false)))).isEmpty();
    // five conditions in a standard line, twenty in a mixed-logic one
    String five = String.join(" AND ", java.util.Collections.nCopies(5, "DI[1]"));
    assertThat(warnings("IF " + five + ",JMP LBL[1]")).isEmpty();
    assertThat(warnings("IF " + five + " AND DI[2],JMP LBL[1]")).containsExactly("the controller takes at most 5 conditions "
        + "joined by AND/OR on a line without parentheses, this one has 6: put the condition in parentheses (mixed logic) "
        + "or split it (a pendant refuses this entry)");
    assertThat(warnings("IF " + String.join(" OR ", java.util.Collections.nCopies(5, "!DI[1]")) + " OR DI[2],JMP LBL[1]"))
        .hasSize(1);
    String twenty = String.join(" OR ", java.util.Collections.nCopies(20, "DI[1]"));
    assertThat(warnings("IF (" + String.join(" OR ", java.util.Collections.nCopies(10, "DI[1]")) + ") AND !("
        + String.join(" AND ", java.util.Collections.nCopies(11, "DI[2]")) + "),JMP LBL[1]")).hasSize(1);
    assertThat(warnings("IF (" + String.join(" OR ", java.util.Collections.nCopies(10, "DI[1]")) + ") AND !("
        + String.join(" AND ", java.util.Collections.nCopies(10, "DI[2]")) + "),JMP LBL[1]")).isEmpty();
    assertThat(warnings("IF (" + twenty + "),JMP LBL[1]")).isEmpty();
    assertThat(warnings("IF (" + twenty + " OR !DI[2]),JMP LBL[1]")).containsExactly("the controller takes at most 20 conditions "
        + "in one mixed-logic instruction, this one has 21: split it over several lines (a pendant refuses this entry)");
  }

  // ---- the pendant's fields -----------------------------------------------------------------

  @Test
  void fragmentsTypedInThePendantsFields() {
    assertThat(TpStatementParser.callText("SUB(1,'A,B',R[2])")).isEqualTo(new Instruction.Call("SUB",
        List.of(n(1), new Expr.StringConst("A,B"), reg(2))));
    assertThat(TpStatementParser.callText("sub")).isEqualTo(new Instruction.Call("SUB", List.of()));
    assertThatThrownBy(() -> TpStatementParser.callText("SUB X")).isInstanceOf(TpSyntaxError.class)
        .hasMessage("expected the end of the CALL, found 'X'");
    assertThat(TpStatementParser.posSourceText("LPOS-PR[4]")).isEqualTo(new Instruction.PosSum(new Instruction.CurrentLpos(),
        List.of(new Instruction.PosTerm(false, new Instruction.FromPosReg(r(4))))));
    assertThat(TpStatementParser.posSourceText("UFRAME[1]")).isEqualTo(new Instruction.FromFrame(Instruction.FrameKind.USER,
        new Index.Direct(1), ""));
    assertThatThrownBy(() -> TpStatementParser.posSourceText("PR[1] PR[2]")).isInstanceOf(TpSyntaxError.class)
        .hasMessage("expected the end of the position, found 'PR'");
    assertThat(TpStatementParser.indexText("5")).isEqualTo(new Index.Direct(5));
    assertThat(TpStatementParser.indexText("R[2:PTR]")).isEqualTo(new Index.Indirect(2, "PTR"));
    assertThatThrownBy(() -> TpStatementParser.indexText("5 6")).isInstanceOf(TpSyntaxError.class)
        .hasMessage("expected the end of the index, found '6'");
    assertThat(TpStatementParser.itemText("R", "R[3:COUNT]")).isEqualTo(new Item(new Index.Direct(3), "COUNT"));
    assertThat(TpStatementParser.itemText("DO", "do[3]")).isEqualTo(r(3));
    assertThatThrownBy(() -> TpStatementParser.itemText("R", "DO[3]")).isInstanceOf(TpSyntaxError.class)
        .hasMessage("expected R[i], found 'DO'");
    assertThatThrownBy(() -> TpStatementParser.itemText("R", "R[3] 4")).isInstanceOf(TpSyntaxError.class)
        .hasMessage("expected the end of the item, found '4'");
    assertThat(TpStatementParser.expressionText("'A B'")).isEqualTo(new Expr.StringConst("A B"));
    assertThatThrownBy(() -> TpStatementParser.expressionText("1 2")).isInstanceOf(TpSyntaxError.class)
        .hasMessage("expected the end of the expression, found '2'");
    // a typed error names its column on line 1
    assertThatThrownBy(() -> TpStatementParser.expressionText("R[1]+")).isInstanceOfSatisfying(TpSyntaxError.class, e -> {
      assertThat(e.line()).isEqualTo(1);
      assertThat(e.column()).isEqualTo(6);
    });
  }

  // ---- the printer's pieces (the pendant builds its fields from them) ----------------------------

  @Test
  void thePrintersPiecesAreTheControllersSpelling() {
    assertThat(TpText.target(new Motion.Local(2, "PICK"))).isEqualTo("P[2:PICK]");
    assertThat(TpText.target(new Motion.Register(new Item(new Index.Indirect(1, ""), "")))).isEqualTo("PR[R[1]]");
    assertThat(TpText.speed(mmPerSec(400))).isEqualTo("400mm/sec");
    assertThat(TpText.speed(new Motion.Speed(new Motion.SpeedRegister(r(3)), Motion.SpeedUnit.PERCENT))).isEqualTo("R[3]%");
    assertThat(TpText.speedValue(new Motion.SpeedConst(0.5))).isEqualTo("0.5");
    assertThat(TpText.termination(new Motion.CntRegister(r(2)))).isEqualTo("CNT R[2]");
    assertThat(TpText.termination(new Motion.Cnt(50))).isEqualTo("CNT50");
    assertThat(TpText.branch(new Instruction.Jump(new LabelRef(new Index.Direct(3), "X")))).isEqualTo("JMP LBL[3:X]");
    assertThat(TpText.branch(new Instruction.Call("NAME", List.of(n(1), new Expr.StringConst("A"), reg(2)))))
        .isEqualTo("CALL NAME(1,'A',R[2])");
    assertThat(TpText.call("", List.of(n(1)))).isEqualTo("(1)");
    assertThat(TpText.call("SUB", List.of())).isEqualTo("SUB");
    assertThat(TpText.waitTime(new Expr.RealConst(0.2))).isEqualTo("   .20(sec)");
    assertThat(TpText.waitTime(new Expr.IntConst(3))).isEqualTo("  3.00(sec)");
    assertThat(TpText.waitTime(reg(2))).isEqualTo("R[2]");
    assertThat(TpText.waitTime(new Expr.Group(reg(2)))).isEqualTo("(R[2])(sec)");
    assertThat(TpText.label(new LabelRef(new Index.Indirect(1, "PTR"), "L"))).isEqualTo("LBL[R[1:PTR]:L]");
    assertThat(TpText.index(new Index.Direct(5))).isEqualTo("5");
    assertThat(TpText.index(new Index.Indirect(2, "PTR"))).isEqualTo("R[2:PTR]");
    assertThat(TpText.index(new Index.ViaArg(1))).isEqualTo("AR[1]");
    assertThat(TpText.item("DO", new Item(new Index.Direct(3), "LAMP"))).isEqualTo("DO[3:LAMP]");
    assertThat(TpText.posSource(new Instruction.CurrentJpos())).isEqualTo("JPOS");
    assertThat(TpText.posSource(new Instruction.FromFrame(Instruction.FrameKind.USER, new Index.Direct(1), "T"))).isEqualTo("UFRAME[1:T]");
    assertThat(TpText.frameWord(Instruction.FrameKind.USER)).isEqualTo("UFRAME");
    assertThat(TpText.frameWord(Instruction.FrameKind.TOOL)).isEqualTo("UTOOL");
    assertThat(TpText.option(new Motion.RawOption("TB .5sec,POINT_LOGIC\n  1:  DO[1]=ON ;", "x"))).isEqualTo("TB .5sec,POINT_LOGIC");
    assertThat(TpText.option(new Motion.RawOption("COORD", "x"))).isEqualTo("COORD");
    StringBuilder sb = new StringBuilder();
    TpText.move((Instruction.Move) parsed("C P[1]" + TpText.CONTINUATION + "P[2] 100mm/sec FINE"), " : ", sb);
    assertThat(sb).hasToString("C P[1] : P[2] 100mm/sec FINE");
  }

  @Test
  void thePrinterRefusesAModelNestedDeeperThanAControllerReads() {
    Expr e = n(1);
    for (int i = 0; i < TpLimits.MAX_NESTING; i++) {
      e = new Expr.Group(e);
    }
    assertThat(TpText.expr(e)).isEqualTo("(".repeat(64) + "1" + ")".repeat(64));
    Expr deeper = new Expr.Group(e);
    assertThatThrownBy(() -> TpText.expr(deeper)).isInstanceOf(IllegalArgumentException.class)
        .hasMessage("expression nested deeper than 64 levels of parentheses and signs: a controller would not read it");
    assertThatThrownBy(() -> TpText.statement(new Instruction.AssignRegister(r(1), deeper))).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> TpText.statement(new Instruction.WaitCondition(deeper, Optional.empty())))
        .isInstanceOf(IllegalArgumentException.class);
  }

  @Test
  void nestingCountsParenthesesSignsAndFunctionBracketsButNotWidth() {
    Expr one = n(1);
    assertThat(TpLimits.nesting(one, 64)).isZero();
    assertThat(TpLimits.nesting(new Expr.Group(one), 64)).isEqualTo(1);
    assertThat(TpLimits.nesting(new Expr.Unary(Expr.UnaryOp.MINUS, new Expr.Group(one)), 64)).isEqualTo(2);
    assertThat(TpLimits.nesting(new Expr.MathFunc(Expr.MathFn.ABS, new Expr.Group(one)), 64)).isEqualTo(2);
    // a function's arguments and a binary operator's operands are side by side: the deepest counts
    assertThat(TpLimits.nesting(new Expr.StringFunc(Expr.StringFn.SUBSTR, List.of(new Expr.StringReg(r(1)),
        new Expr.Group(new Expr.Group(one)), new Expr.Group(one))), 64)).isEqualTo(2);
    assertThat(TpLimits.nesting(new Expr.StringFunc(Expr.StringFn.SUBSTR, List.of(new Expr.Group(one), one,
        new Expr.Group(new Expr.Group(new Expr.Group(one))))), 64)).isEqualTo(3);
    Expr wide = one;
    for (int i = 0; i < 500; i++) {
      wide = new Expr.Binary(Expr.BinaryOp.ADD, wide, new Expr.Group(one));
    }
    assertThat(TpLimits.nesting(wide, 64)).isEqualTo(1);
    assertThat(TpLimits.nesting(new Expr.Binary(Expr.BinaryOp.ADD, new Expr.Group(new Expr.Group(one)), one), 64)).isEqualTo(2);
    assertThat(TpLimits.nesting(new Expr.Binary(Expr.BinaryOp.ADD, one, new Expr.Group(new Expr.Group(one))), 64)).isEqualTo(2);
    assertThat(TpLimits.nesting(new Expr.Binary(Expr.BinaryOp.ADD,
        new Expr.Binary(Expr.BinaryOp.ADD, one, new Expr.Group(new Expr.Group(new Expr.Group(one)))), one), 64)).isEqualTo(3);
    // counting stops one past the limit, however deep the model
    Expr deep = one;
    for (int i = 0; i < 5000; i++) {
      deep = new Expr.Group(deep);
    }
    assertThat(TpLimits.nesting(deep, 64)).isEqualTo(65);
    assertThat(TpLimits.nesting(deep, 3)).isEqualTo(4);
  }

  @Test
  void aProgramsSourceHoldsTheTextOfEachOfItsLines() {
    Program p = Program.of("A", List.of(new Instruction.End(), new Instruction.Pause()));
    byte[] file = "/PROG A\n".getBytes(java.nio.charset.StandardCharsets.UTF_8);
    List<List<String>> two = List.of(List.of("   1:  END ;\n"), List.of("   2:  PAUSE ;\n"));
    ProgramSource s = new ProgramSource(file, java.nio.charset.StandardCharsets.UTF_8, "\n", p, List.of("/PROG A\n"), List.of(),
        two, List.of("/END\n"));
    assertThat(s.statements()).isEqualTo(two);
    byte[] copy = s.bytes();
    copy[0] = 'x';
    assertThat(s.bytes()).isEqualTo(file);
    assertThatThrownBy(() -> new ProgramSource(file, java.nio.charset.StandardCharsets.UTF_8, "\n", p, List.of(), List.of(),
        List.of(List.of("   1:  END ;\n")), List.of())).isInstanceOf(IllegalArgumentException.class)
        .hasMessage("1 statement texts for 2 lines");
  }
}
