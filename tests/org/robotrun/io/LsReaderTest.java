package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.robotrun.program.Config;
import org.robotrun.program.Expr;
import org.robotrun.program.Expr.BinaryOp;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;
import org.robotrun.program.LabelRef;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Motion;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.ProgramStore;

class LsReaderTest {

  private static final String HEAD = "/PROG  T\n/ATTR\n/MN\n";
  private static final String TAIL = "/POS\n/END\n";

  /** A program whose /MN holds {@code mn} (lines start at file line 4). */
  private static LsReadResult mn(String mn) {
    return LsReader.parse("t.ls", HEAD + mn + TAIL);
  }

  private static List<String> messages(LsReadResult r) {
    return r.diagnostics().stream().map(Diagnostic::toString).toList();
  }

  private static Instruction only(String statementLine) {
    LsReadResult r = mn("   1:" + statementLine + "\n");
    assertThat(messages(r)).isEmpty();
    return r.program().line(1);
  }

  @Test
  void readsPick3AsTheControllerWroteIt() throws IOException {
    LsReadResult r = LsReader.read(Path.of("tests/resources/programs/PICK3.LS"));
    assertThat(r.diagnostics()).isEmpty();
    Program p = r.program();
    assertThat(p.name()).isEqualTo("PICK3");
    assertThat(p.comment()).isEqualTo("3 picks demo");
    assertThat(p.lineCount()).isEqualTo(29);
    assertThat(p.attributes()).containsEntry("OWNER", "MNEDITOR").containsEntry("LINE_COUNT", "29")
        .containsEntry("CREATE", "DATE 25-01-10  TIME 09:00:00");
    assertThat(List.copyOf(p.attributes().keySet())).startsWith("OWNER", "PROG_SIZE", "CREATE", "MODIFIED");
    assertThat(p.line(7)).isEqualTo(Instruction.Move.of(Motion.Type.J, new Motion.Local(1, "HOME"),
        new Motion.Speed(new Motion.SpeedConst(30), Motion.SpeedUnit.PERCENT), new Motion.Fine(), List.of()));
    assertThat(p.line(15)).isEqualTo(new Instruction.AssignPosElement(Item.of(10, "STACK"), 3,
        new Expr.Binary(BinaryOp.MUL,
            new Expr.Group(new Expr.Binary(BinaryOp.SUB, new Expr.Register(Item.of(1, "I")), new Expr.IntConst(1))),
            new Expr.IntConst(20))));
    assertThat(p.line(13)).isEqualTo(new Instruction.WaitCondition(
        new Expr.Binary(BinaryOp.EQ, new Expr.Io(IoKind.RI, Item.of(1, "CLOSED")), new Expr.OnOff(true)),
        java.util.Optional.of(LabelRef.of(99))));
    assertThat(p.line(18)).isEqualTo(new Instruction.WaitTime(new Expr.RealConst(0.2)));
    assertThat(p.line(23)).isEqualTo(new Instruction.SelectElse(new Instruction.Call("BEEP", List.of())));
    assertThat(p.line(27)).isEqualTo(new Instruction.Label(99, "NO GRIP"));
    assertThat(p.position(1)).contains(new LocalPosition(1, "HOME", 1, 1, new Position.Joint(0, 0, 0, 0, -90, 0)));
    assertThat(p.position(2)).contains(new LocalPosition(2, "PICK", 1, 1,
        new Position.Cartesian(350, -120, 40, 180, 0, 0, Config.DEFAULT)));
    assertThat(r.sourceLine(1)).isEqualTo(22);
  }

  @Test
  void precedenceInsideParenthesesIsTheUsualOne() {
    Instruction in = only("  R[1]=(2+3*4)    ;");
    assertThat(in).isEqualTo(new Instruction.AssignRegister(Item.of(1), new Expr.Group(
        new Expr.Binary(BinaryOp.ADD, new Expr.IntConst(2),
            new Expr.Binary(BinaryOp.MUL, new Expr.IntConst(3), new Expr.IntConst(4))))));
    Instruction logic = only("  IF (R[1]=1 OR R[2]>2 AND DI[1]=ON),JMP LBL[1] ;\n   2:  LBL[1]  ;");
    Expr cond = ((Expr.Group) ((Instruction.If) logic).condition()).inner();
    assertThat(cond).isInstanceOfSatisfying(Expr.Binary.class, b -> {
      assertThat(b.op()).isEqualTo(BinaryOp.OR);
      assertThat(((Expr.Binary) b.right()).op()).isEqualTo(BinaryOp.AND);
    });
  }

  @Test
  void indirectRegistersAndItemComments() {
    assertThat(only("  R[R[2:PTR]:X]=R[R[3]]    ;")).isEqualTo(new Instruction.AssignRegister(
        new Item(new Index.Indirect(2, "PTR"), "X"), new Expr.Register(new Item(new Index.Indirect(3, ""), ""))));
    assertThat(only("  JMP LBL[R[4]] ;")).isEqualTo(new Instruction.Jump(new LabelRef(new Index.Indirect(4, ""), "")));
  }

  @Test
  void indexesOutsideTheControllersTablesAreWarnings() {
    LsReadResult r = mn("   1:  R[201]=TIMER[11]+DI[0]+R[R[300]]    ;\n   2:  PR[101,1]=F[200]    ;\n");
    assertThat(messages(r)).containsExactly(
        "t.ls:4: warning: R[201]: index out of range (expected 1..200); running this line raises an alarm",
        "t.ls:4: warning: TIMER[11]: index out of range (expected 1..10); running this line raises an alarm",
        "t.ls:4: warning: DI[0]: index out of range (expected 1..512); running this line raises an alarm",
        "t.ls:4: warning: R[300]: index out of range (expected 1..200); running this line raises an alarm",
        "t.ls:5: warning: PR[101]: index out of range (expected 1..100); running this line raises an alarm");
    assertThat(r.hasAnyError()).isFalse();
  }

  @Test
  void constantsKeepIntegerAndRealApart() {
    assertThat(only("  R[1]=.5    ;")).isEqualTo(new Instruction.AssignRegister(Item.of(1), new Expr.RealConst(0.5)));
    assertThat(only("  R[1]=-3    ;")).isEqualTo(new Instruction.AssignRegister(Item.of(1), new Expr.IntConst(-3)));
    assertThat(only("  R[1]=3.0    ;")).isEqualTo(new Instruction.AssignRegister(Item.of(1), new Expr.RealConst(3)));
  }

  @Test
  void waitTakesATimeOrACondition() {
    assertThat(only("  WAIT 1(sec) ;")).isEqualTo(new Instruction.WaitTime(new Expr.RealConst(1)));
    assertThat(only("  WAIT R[3] ;")).isEqualTo(new Instruction.WaitTime(new Expr.Register(Item.of(3))));
    assertThat(only("  WAIT R[3]>2 ;")).isEqualTo(new Instruction.WaitCondition(
        new Expr.Binary(BinaryOp.GT, new Expr.Register(Item.of(3)), new Expr.IntConst(2)), java.util.Optional.empty()));
    assertThat(messages(mn("   1:  WAIT 5 ;\n"))).containsExactly("t.ls:4: expected '(sec)' after the wait time, found end of line");
  }

  @Test
  void lowerCaseIsReadAndWrittenInUpperCase() {
    LsReadResult r = LsReader.parse("low.ls", "/prog  low\n/mn\n   1:j pr[1] 30% fine    ;\n   2:  call beep ;\n"
        + "   3:  wait di[1]=on timeout,lbl[1] ;\n   4:  lbl[1] ;\n/pos\n/end\n");
    assertThat(messages(r)).isEmpty();
    assertThat(LsWriter.write(r.program())).startsWith("/PROG  LOW\n").contains(
        "   1:J PR[1] 30% FINE    ;\n   2:  CALL BEEP ;\n   3:  WAIT DI[1]=ON TIMEOUT,LBL[1] ;\n   4:  LBL[1] ;\n");
  }

  @Test
  void circularMotionTakesItsContinuationLine() {
    LsReadResult r = LsReader.parse("c.ls", HEAD
        + "   1:C P[1]    \n    :  P[2] 100mm/sec FINE    ;\n   2:  END ;\n"
        + "/POS\nP[1]{\n   GP1:\n\tUF : 0, UT : 1,\n\tJ1= 0 deg, J2= 0 deg, J3= 0 deg, J4= 0 deg, J5= 0 deg, J6= 0 deg\n};\n"
        + "P[2]{\n   GP1:\n\tUF : 0, UT : 1,\n\tJ1= 1 deg, J2= 0 deg, J3= 0 deg, J4= 0 deg, J5= 0 deg, J6= 0 deg\n};\n/END\n");
    assertThat(messages(r)).isEmpty();
    assertThat(r.program().line(1)).isEqualTo(Instruction.Move.circular(new Motion.Local(1, ""), new Motion.Local(2, ""),
        new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.MM_PER_SEC), new Motion.Fine(), List.of()));
    assertThat(r.sourceLine(2)).isEqualTo(6);

    LsReadResult missing = mn("   1:C P[1]\n   2:  END ;\n");
    assertThat(messages(missing)).anyMatch(m -> m.startsWith("t.ls:4: a C motion needs its end point on a continuation line"));
  }

  @Test
  void everyBadLineIsReportedInOnePassWithWhatWasExpected() {
    LsReadResult r = mn(String.join("\n",
        "   1:  R[1]=1    ;",
        "   2:  R[1]=    ;",
        "   3:  JMP LBL[ ;",
        "   4:J P[1] 100mm/sec FINE    ;",
        "   5:L PR[1] 30% FINE    ;",
        "   6:  FOR R[1]=1 UNTIL 3 ;",
        "   7:  RUN SUB1 ;",
        "   8:  R[2]=3 ;",
        "   9:  WAIT 2 ;",
        "  10:  DI[1]=ON ;",
        "  11:  CALL _HIDDEN ;",
        "  12:  R[1]=1",
        "  13:L PR[1] 100mm/sec FINE Frobnicate    ;",
        "  14:J PR[1] 20% CNT120    ;",
        "  15:J PR[1] 300% FINE    ;",
        "  16:L PR[1] 0mm/sec FINE    ;",
        "  17:  WAIT -5(sec) ;",
        "")) ;
    assertThat(messages(r)).containsExactly(
        "t.ls:5: expected a value (number, R[i], PR[i,j], DI[i], F[i], TIMER[i], AR[i], ON, OFF or '('), found end of line",
        "t.ls:6: expected an index (a number or R[i]) inside LBL[...], found end of line",
        "t.ls:7: speed unit mm/sec does not fit a J motion: expected %, sec or msec",
        "t.ls:8: speed unit % does not fit a L motion: expected mm/sec, cm/min, inch/min, deg/sec, sec or msec",
        "t.ls:9: expected TO or DOWNTO in FOR, found 'UNTIL'",
        "t.ls:12: expected '(sec)' after the wait time, found end of line",
        "t.ls:13: DI[] is an input: a program cannot set it (expected DO, RO, GO, AO or F)",
        "t.ls:15: warning: mended: no ';' at the end of the line: read as if it were there",
        "t.ls:16: warning: not supported: motion option FROBNICATE (the motion runs without it)",
        "t.ls:17: CNT120: expected 0..100",
        "t.ls:18: speed 300%: expected 1..100%",
        "t.ls:19: speed 0mm/sec: expected a speed greater than 0",
        "t.ls:20: WAIT time must be 0 or more seconds, found a negative constant");
    // Bad lines keep their place, so line numbering of the rest holds.
    assertThat(r.program().lineCount()).isEqualTo(17);
    assertThat(r.program().line(8)).isInstanceOf(Instruction.AssignRegister.class);
    assertThat(r.program().line(2)).isEqualTo(new Instruction.CommentedOut("R[1]="));
  }

  @Test
  void aMacroOfSeveralWordsIsReadAndCheckedAgainstTheMacroTable() {
    String text = "   1:  HAND1 OPEN ;\n   2:  Grip  Close    ;\n";
    LsReadResult r = mn(text);
    assertThat(r.program().line(1)).isEqualTo(new Instruction.MacroCall("HAND1 OPEN"));
    assertThat(r.program().line(2)).isEqualTo(new Instruction.MacroCall("Grip Close"));
    // Not a syntax error: check has no macro table, so it names the macro as unresolved.
    assertThat(messages(r.withCallTargetsChecked(java.util.Set.of()))).contains(
        "t.ls:4: macro HAND1 OPEN: not in the macro table (a robot's \"macros\" in the scenario define it; the line alarms when it runs without one)");
    assertThat(r.withCallTargetsChecked(java.util.Set.of()).diagnostics()).extracting(Diagnostic::kind)
        .containsOnly(Diagnostic.Kind.REFERENCE);
    assertThat(r.diagnostics()).isEmpty();
    // kept as written, and written in the controller's layout when fresh
    assertThat(new String(LsWriter.bytes(r.program()), java.nio.charset.StandardCharsets.UTF_8))
        .isEqualTo(HEAD + text + TAIL);
    assertThat(LsWriter.write(r.program().withoutSource())).contains("   1:  HAND1 OPEN ;").contains("   2:  Grip Close ;");
  }

  @Test
  void aOneWordMacroIsACallOfTheProgramOfThatName() {
    LsReadResult r = mn("   1:  open_hand ;\n");
    assertThat(r.diagnostics()).isEmpty();
    assertThat(r.program().line(1)).isEqualTo(new Instruction.MacroCall("OPEN_HAND"));
  }

  @Test
  void systemVariablesRobotRunRunsAreReadIntoTheModel() {
    LsReadResult r = mn("   1:  $WAITTMOUT=500 ;\n   2:  R[1]=$mcr.$genoverride+$WAITTMOUT    ;\n");
    assertThat(r.diagnostics()).isEmpty();
    assertThat(r.program().line(1)).isEqualTo(new Instruction.SetSysVar("$WAITTMOUT", new Expr.IntConst(500)));
    assertThat(r.program().line(2)).isEqualTo(new Instruction.AssignRegister(org.robotrun.program.Item.of(1),
        new Expr.Binary(Expr.BinaryOp.ADD, new Expr.SysVar("$MCR.$GENOVERRIDE"), new Expr.SysVar("$WAITTMOUT"))));
  }

  @Test
  void timeBeforeAndAfterWithAnOutputAreRunOthersAreKept() {
    LsReadResult r = mn(String.join("\n",
        "   1:L P[1] 100mm/sec CNT100 TB    .20sec,DO[3:VAC]=ON    ;",
        "   2:L P[1] 100mm/sec FINE TA   0.50sec,RO[1]=PULSE,0.3sec    ;",
        "   3:L P[1] 100mm/sec FINE TB   0.50sec,CALL X    ;",
        "   4:L P[1] 100mm/sec FINE TIME AFTER 1.0sec,GO[2]=R[4]    ;",
        "   5:L P[1] 100mm/sec CNT50 DB   10.0mm,DO[5]=OFF    ;",
        "   6:L P[1] 100mm/sec CNT50 DB   10.0mm,CALL X    ;",
        "   7:L P[1] 100mm/sec CNT50 DB   10.0mm,CALL X(1)    ;",
        ""));
    assertThat(((Motion.TimedAction) ((Instruction.Move) r.program().line(5)).options().get(0)).when())
        .isEqualTo(Motion.When.DISTANCE_BEFORE);
    // A CALL runs (its program beside the motion), with its arguments too (issue 25).
    assertThat(((Instruction.Move) r.program().line(6)).options().get(0)).isEqualTo(new Motion.TimedAction(
        Motion.When.DISTANCE_BEFORE, 10, new Instruction.Call("X", java.util.List.of()), "DB   10.0mm,CALL X"));
    assertThat(((Instruction.Move) r.program().line(7)).options().get(0)).isEqualTo(new Motion.TimedAction(
        Motion.When.DISTANCE_BEFORE, 10, new Instruction.Call("X", java.util.List.of(new Expr.IntConst(1))),
        "DB   10.0mm,CALL X(1)"));
    Instruction.Move m1 = (Instruction.Move) r.program().line(1);
    assertThat(m1.options()).containsExactly(new Motion.TimedAction(Motion.When.TIME_BEFORE, 0.2,
        new Instruction.SetIo(org.robotrun.program.IoKind.DO, org.robotrun.program.Item.of(3, "VAC"), new Expr.OnOff(true)),
        "TB    .20sec,DO[3:VAC]=ON"));
    Motion.TimedAction ta = (Motion.TimedAction) ((Instruction.Move) r.program().line(2)).options().get(0);
    assertThat(ta.when()).isEqualTo(Motion.When.TIME_AFTER);
    assertThat(ta.action()).isInstanceOf(Instruction.Pulse.class);
    assertThat(((Instruction.Move) r.program().line(3)).options().get(0)).isInstanceOf(Motion.TimedAction.class);
    assertThat(((Instruction.Move) r.program().line(4)).options().get(0)).isInstanceOf(Motion.TimedAction.class);
    // every one of them runs: nothing is reported; the line comes back as written
    assertThat(messages(r)).filteredOn(m -> m.contains("not supported")).isEmpty();
    assertThat(LsWriter.write(r.program().withoutSource())).contains("   1:L P[1] 100mm/sec CNT100 TB    .20sec,DO[3:VAC]=ON    ;");
  }

  @Test
  void offsetConditionWithAUserFrameIsReadAndWrittenBack() {
    LsReadResult r = mn("   1:  OFFSET CONDITION PR[3:SHIFT],UFRAME[2] ;\n   2:  OFFSET CONDITION PR[3],UFRAME[R[4]] ;\n");
    assertThat(r.diagnostics()).isEmpty();
    assertThat(r.program().line(1)).isEqualTo(new Instruction.OffsetCondition(org.robotrun.program.Item.of(3, "SHIFT"),
        java.util.Optional.of(org.robotrun.program.Index.of(2))));
    String fresh = LsWriter.write(r.program().withoutSource());
    assertThat(fresh).contains("   1:  OFFSET CONDITION PR[3:SHIFT],UFRAME[2] ;").contains("OFFSET CONDITION PR[3],UFRAME[R[4]] ;");
  }

  @Test
  void unsupportedStatementsAreNamedNotDropped() {
    for (String[] c : new String[][] {
        {"UO[1]=ON", "not supported: assigning UO[] (the controller sets it) (the line alarms when it runs)"},
        {"$SCR.$ITP_SPEED=100", "warning: not supported: system variable assignment (the line is skipped when it runs)"},
        {"$WAITTMOUT[1]=100", "warning: not supported: system variable assignment (the line is skipped when it runs)"},
        {"R[1]=$SCR.$ITP_SPEED", "not supported: system variable $SCR.$ITP_SPEED in an expression (the line alarms when it runs)"},
        {"LOCK PREG", "warning: not supported: LOCK PREG (the line is skipped when it runs)"},
        {"SO[1]=ON", "not supported: assigning SO[] (the controller sets it) (the line alarms when it runs)"},
        {"TOOL_OFFSET CONDITION PR[2],UTOOL[3]", "not supported: TOOL_OFFSET CONDITION with UTOOL (the line alarms when it runs)"},
        {"L P[1] max_speed FINE", "not supported: max_speed (the line alarms when it runs)"},
        {"L P[1] 100mm/sec FINE TB .50sec,POINT_LOGIC", "warning: not supported: TIME BEFORE/AFTER (TB/TA) (the motion runs without it)"},
        {"R[1]=1 ; ! trailing remark", "text after ';': a line holds one statement (put a remark on its own '!' line)"},
        {"AR[1]=5", "AR[] holds the CALL arguments: a program can read it but not set it"},
        {"/L P[1] 10% FINE", "expected a statement, found '/' (a commented-out line starts with '//')"},
        {"FROBNICATE=3", "unknown statement 'FROBNICATE': expected a motion (J/L/C/A), an assignment, IF, SELECT, FOR, WAIT, JMP, CALL, LBL or another TP statement"}}) {
      LsReadResult r = mn("   1:  " + c[0] + " ;\n");
      assertThat(messages(r)).as(c[0]).contains("t.ls:4: " + c[1]);
    }
  }

  @Test
  void applicationMotionFormsAreNamed() {
    LsReadResult r = mn(String.join("\n",
        "   1:L P[1] WELD_SPEED FINE    ;",
        "   2:J PR[2] 40% FINE",
        "    :  Arc Start[1]    ;",
        "   3:C P[2] VOFFSET,VR[2]",
        "    :  P[3] R[23]mm/sec CNT100    ;",
        "   4:L PR[1] 500mm/sec CNT50 VOFFSET,VR[1]    ;",
        ""));
    assertThat(messages(r)).containsExactly(
        "t.ls:4: not supported: arc welding speed WELD_SPEED (the line alarms when it runs)",
        "t.ls:5: warning: not supported: arc welding (as a motion option) (the motion runs without it)",
        "t.ls:7: not supported: motion option VOFFSET on the via point of a C motion (the line alarms when it runs)");
    // VOFFSET,VR[i] runs since issue 16 (line 9): no warning.
  }

  @Test
  void lineNumbersOutOfOrderAreMendedWithAWarningEach() {
    // As the offline converter takes a hand-edited file: numbered in file order, each mend said.
    LsReadResult r = mn("   1:  R[1]=1 ;\n   3:  R[1]=2 ;\n   2:  R[1]=3 ;\n");
    assertThat(messages(r)).containsExactly(
        "t.ls:5: warning: mended: line number 3 out of order or repeated: read as line 2",
        "t.ls:6: warning: mended: line number 2 out of order or repeated: read as line 3");
    assertThat(r.hasErrors()).isFalse();
    assertThat(r.program().lineCount()).isEqualTo(3);
    assertThat(r.program().line(2)).isEqualTo(new Instruction.AssignRegister(new Item(Index.of(1), ""), new Expr.IntConst(2)));
  }

  @Test
  void programLevelChecks() {
    LsReadResult r = mn(String.join("\n",
        "   1:  LBL[1] ;",
        "   2:J P[7] 10% FINE    ;",
        "   3:  LBL[1:AGAIN] ;",
        "   4:  JMP LBL[5] ;",
        "   5:  IF R[1]=1,JMP LBL[6] ;",
        "   6:  WAIT DI[1]=ON TIMEOUT,LBL[7] ;",
        "   7:  JMP LBL[R[1]] ;",
        "   8:  CALL NOWHERE ;",
        ""));
    assertThat(messages(r)).containsExactly(
        // the controller loads these; the line alarms when it runs
        "t.ls:5: warning: P[7] is used but /POS has no P[7]: the position is uninitialised and the line alarms when it runs",
        "t.ls:6: LBL[1] is defined twice (first on line 4)",
        "t.ls:7: warning: LBL[5] is not defined in this program: the jump alarms when it runs",
        "t.ls:8: warning: LBL[6] is not defined in this program: the jump alarms when it runs",
        "t.ls:9: warning: LBL[7] is not defined in this program: the jump alarms when it runs");
    LsReadResult known = r.withCallTargetsChecked(Set.of("OTHER"));
    assertThat(messages(known)).contains("t.ls:11: CALL NOWHERE: no program named NOWHERE is known");
    assertThat(messages(mn("   1:  CALL T ;\n").withCallTargetsChecked(Set.of()))).isEmpty();
    assertThat(messages(r.withCallTargetsChecked(Set.of("nowhere")))).doesNotContain(
        "t.ls:11: CALL NOWHERE: no program named NOWHERE is known");
    assertThat(messages(r.withCallTargetsChecked(ProgramStore.of(Program.of("NOWHERE", List.of()))))).doesNotContain(
        "t.ls:11: CALL NOWHERE: no program named NOWHERE is known");
  }

  @Test
  void blocksMustMatchUp() {
    LsReadResult r = mn(String.join("\n",
        "   1:  ENDFOR ;",
        "   2:  IF (R[1]=1) THEN ;",
        "   3:  FOR R[2]=1 TO 2 ;",
        "   4:  ENDIF ;",
        "   5:  ELSE ;",
        "   6:         =2,JMP LBL[1] ;",
        "   7:  LBL[1] ;",
        ""));
    assertThat(messages(r)).containsExactly(
        "t.ls:4: ENDFOR without an open FOR",
        "t.ls:5: IF ... THEN has no ENDIF",
        "t.ls:6: FOR has no ENDFOR",
        "t.ls:7: ENDIF without an open IF ... THEN (the innermost open block is the FOR on line 6)",
        "t.ls:8: ELSE without an open IF ... THEN (the innermost open block is the FOR on line 6)",
        "t.ls:9: SELECT case '=value' must follow a SELECT line or another case");
  }

  @Test
  void positionBlocksReportBadFieldsAndKeepTheGoodOnes() {
    String pos = String.join("\n",
        "/POS",
        "P[1:\"A\"]{",
        "   GP1:",
        "\tUF : 1, UT : 1,\t\tCONFIG : 'N U X, 0, 0, 0',",
        "\tX =   1.000  mm,\tY =   2.000  mm,\tZ =   3.000  mm,",
        "\tW =   0.000 deg,\tP =   0.000 deg,\tR =   0.000 deg",
        "};",
        "P[2]{",
        "   GP1:",
        "\tUF : 1, UT : 1,",
        "\tJ1=   0.000 deg,\tJ2=   0.000 deg,\tJ3=   0.000 deg,",
        "\tJ4=   0.000 deg,\tJ5=   0.000 deg,\tJ6=   0.000 mm",
        "};",
        "P[3]{",
        "   GP2:",
        "};",
        "P[4]{",
        "   GP1:",
        "\tUF : 0, UT : 2,",
        "\tX =   1.000  mm,\tY =   2.000  mm,\tZ =   3.000  mm,",
        "\tW =   0.000 deg,\tP =   0.000 deg",
        "};",
        "P[5]{",
        "   GP1:",
        "\tUF : 0, UT : 2,",
        "\tJ1=   1.000 deg,\tJ2=   0.000 deg,\tJ3=   0.000 deg,",
        "\tJ4=   0.000 deg,\tJ5=   0.000 deg,\tJ6=   0.000 deg",
        "};",
        "P[6]{",
        "   GP1:",
        "\tUF : 0, UT : 2,",
        "/END",
        "");
    LsReadResult r = LsReader.parse("p.ls", HEAD + "   1:  END ;\n" + pos);
    assertThat(messages(r)).containsExactly(
        "p.ls:8: P[1]: CONFIG 'N U X, 0, 0, 0': expected 'F|N U|D T|B, t1, t2, t3' like 'N U T, 0, 0, 0'",
        "p.ls:16: P[2]: expected 'deg' after the value of J6, found 'mm'",
        "p.ls:19: warning: not supported: motion group GP2 (RobotRun moves group 1; the others are kept, not moved)",
        "p.ls:21: P[4]: R is missing: expected all of X, Y, Z, W, P, R",
        "p.ls:33: P[6] is not closed: expected '};' before the end of the /POS section");
    assertThat(r.program().positions().keySet()).containsExactly(5);
  }

  @Test
  void absurdPositionValuesAreRefusedWithTheSharedBound() {
    String pos = String.join("\n",
        "/POS",
        "P[1]{",
        "   GP1:",
        "\tUF : 0, UT : 1,\t\tCONFIG : 'N U T, 0, 0, 0',",
        "\tX =  99999999.000  mm,\tY =   0.000  mm,\tZ =   0.000  mm,",
        "\tW =   0.000 deg,\tP =   0.000 deg,\tR =   0.000 deg",
        "};",
        "P[2]{",
        "   GP1:",
        "\tUF : 0, UT : 1,",
        "\tJ1=   0.000 deg,\tJ2=   0.000 deg,\tJ3=   0.000 deg,",
        "\tJ4=   0.000 deg,\tJ5=   -36000.001 deg,\tJ6=   0.000 deg",
        "};",
        "P[3]{",
        "   GP1:",
        "\tUF : 0, UT : 1,\t\tCONFIG : 'N U T, 0, 0, 0',",
        "\tX =  -100000.000  mm,\tY =   100000.000  mm,\tZ =   0.000  mm,",
        "\tW =   36000.000 deg,\tP =   0.000 deg,\tR =   -36000.000 deg",
        "};",
        "/END",
        "");
    LsReadResult r = LsReader.parse("p.ls", HEAD + "   1:  END ;\n" + pos);
    assertThat(messages(r)).containsExactly(
        "p.ls:9: P[1]: X = 99999999.000 mm is out of range: expected -100000..100000 mm",
        "p.ls:16: P[2]: J5 = -36000.001 deg is out of range: expected -36000..36000 deg");
    // the bounds themselves are fine
    assertThat(r.program().positions().keySet()).containsExactly(3);
  }

  @Test
  void aNumberTooLargeForADoubleIsAnErrorNotInfinity() {
    String huge = "1" + "0".repeat(400) + ".0";
    assertThat(messages(mn("   1:  R[1]=" + huge + " ;\n"))).singleElement().asString()
        .startsWith("t.ls:4: number 1000").endsWith("is too large");
    assertThat(messages(mn("   1:  DO[1]=PULSE," + huge + "sec ;\n"))).singleElement().asString()
        .endsWith("is too large");
  }

  @Test
  void attributesAreKeptInOrderWithDefaultsAddedAndLineCountCorrected() {
    LsReadResult r = LsReader.parse("a.ls", "/PROG  A\n/ATTR\nZETA\t= 1;\nOWNER\t= ME;\nLINE_COUNT\t= 9;\n"
        + "COMMENT\t= \"hi\";\n/MN\n   1:  END ;\n/POS\n/END\n");
    assertThat(messages(r)).containsExactly("a.ls:5: warning: LINE_COUNT = 9 but /MN has 1 lines; using 1");
    assertThat(r.hasAnyError()).isFalse();
    assertThat(List.copyOf(r.program().attributes().keySet())).startsWith("ZETA", "OWNER", "LINE_COUNT", "PROG_SIZE");
    assertThat(r.program().attributes()).containsEntry("OWNER", "ME").containsEntry("LINE_COUNT", "1")
        .containsEntry("PROTECT", "READ_WRITE");
    assertThat(r.program().comment()).isEqualTo("hi");
    String written = LsWriter.write(r.program());
    assertThat(written).contains("OWNER\t\t= ME;\nCOMMENT\t\t= \"hi\";\n").contains("LINE_COUNT\t= 1;\n").contains("ZETA\t\t= 1;\n");
  }

  @Test
  void aBadAttributeLineIsReportedAloneAndTheOthersKept() {
    LsReadResult r = LsReader.parse("a.ls", "/PROG  A\n/ATTR\nOWNER\t= MNEDITOR\nCOMMENT\t= \"kept\";\nJUNK;\n"
        + "TCD:  STACK_SIZE\t= 0,\n      TASK_PRIORITY\t= 40;\n/MN\n   1:  END ;\n/POS\n/END\n");
    assertThat(messages(r)).containsExactly(
        "a.ls:3: warning: mended: no ';' at the end of the /ATTR entry: read as if it were there",
        "a.ls:5: expected 'KEY = value;' in /ATTR, found 'JUNK;'");
    assertThat(r.program().comment()).isEqualTo("kept");
    assertThat(r.program().attributes()).containsEntry("TCD", "STACK_SIZE = 0, TASK_PRIORITY = 40")
        .containsEntry("OWNER", "MNEDITOR");
    assertThat(LsWriter.write(r.program())).contains("TCD:  STACK_SIZE\t= 0,\n      TASK_PRIORITY\t= 40;\n");
  }

  @Test
  void sectionsAreCheckedAndExtraSectionsFlagged() {
    assertThat(messages(LsReader.parse("s.ls", "/PROG  S  Macro\n/ATTR\n/APPL\n/APPL\nFOO : 1;\n/MN\n   1:  END ;\n/POS\n/END\nextra\n")))
        .containsExactly(
                "s.ls:4: warning: not supported: section /APPL (its 1 lines are kept, not used)",
            "s.ls:10: warning: text after /END is ignored");
    assertThat(messages(LsReader.parse("n.ls", "/PROG  1BAD\n/MN\n/POS\n/END\n")))
        .containsExactly("n.ls:1: '1BAD' is not a program name: expected letters, digits and '_', not starting with a digit, at most 36 characters");
  }
}
