package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * What the one statement parser says about text it cannot take (issue 31): the exact message, on
 * the line and at the column of the token it stopped at (docs/tp-language.md, "What reading
 * reports": "the message says what was expected"; `check --format json` gives the column). Each
 * case names the offending token by the rest of the text from it ({@code ""}: the end of the
 * line, which stands one column after the last character). Forms a controller has and RobotRun
 * does not run are not errors: they come back as {@link Instruction.Unsupported} naming their kind,
 * a warning when the program can run on without them (docs/tp-language.md, "What is not supported").
 */
class TpStatementErrorsTest {

  /** {@code text} is refused, at the column where {@code from} starts, with {@code message}. */
  private static void refused(String text, String from, String message) {
    assertThat(text).as("the case names its offending token").endsWith(from);
    int column = text.length() - from.length() + 1;
    assertThatThrownBy(() -> TpStatementParser.statementText(text)).as(text)
        .isInstanceOfSatisfying(TpSyntaxError.class, e -> {
          assertThat(e.getMessage()).as(text).isEqualTo(message);
          assertThat(e.unsupported()).as(text).isEmpty();
          assertThat(e.line()).as(text).isEqualTo(1);
          assertThat(e.column()).as(text + ": column").isEqualTo(column);
        });
  }

  /** {@code text} is kept as written, not run: an error when it runs ({@code runnable} false) or skipped. */
  private static void kept(String text, String what, boolean runnable) {
    assertThat(TpStatementParser.statementText(text).instruction()).as(text)
        .isEqualTo(new Instruction.Unsupported(text, what, runnable));
  }

  private static void keptAlarming(String text, String what) {
    kept(text, what, false);
  }

  // ---- the statement as a whole -----------------------------------------------------------

  @Test
  void aLineHoldsOneStatementAndNothingAfterIt() {
    refused("R[1]=1 ;R[2]=2", ";R[2]=2", "text after ';': a line holds one statement (put a remark on its own '!' line)");
    refused("PAUSE 5", "5", "expected the end of the statement, found '5'");
    refused("END END", "END", "expected the end of the statement, found 'END'");
    refused("WAIT DI[1]=ON X", "X", "expected the end of the statement, found 'X'");
  }

  @Test
  void aStatementStartsWithAWordARemarkOrASelectCase() {
    refused("/R[1]=1", "/R[1]=1", "expected a statement, found '/' (a commented-out line starts with '//')");
    refused("-R[1]", "-R[1]", "expected a statement, found '-'");
    refused("(R[1])", "(R[1])", "expected a statement, found '('");
    refused("'abc'", "'abc'", "expected a statement, found 'abc'");
    refused("5", "5", "expected a statement, found '5'");
    refused("FROBNICATE=3", "FROBNICATE=3", "unknown statement 'FROBNICATE': expected a motion (J/L/C/A), an assignment, IF, "
        + "SELECT, FOR, WAIT, JMP, CALL, LBL or another TP statement");
    kept("--eg:ARC", "remark (--eg:)", true);
  }

  // ---- registers, frames, I/O -------------------------------------------------------------

  @Test
  void registersTakeAnEqualsSignAndTheRightKindOfValue() {
    refused("R[1] 5", "5", "expected '=' after R[...], found '5'");
    refused("R[1]='A'", "'A'", "R[] holds a number, not a string constant: put the text in a string register SR[i]");
    refused("SR[1] 5", "5", "expected '=' after SR[...], found '5'");
    refused("AR[1]=5", "AR[1]=5", "AR[] holds the CALL arguments: a program can read it but not set it");
    refused("R[1]=", "", "expected a value (number, R[i], PR[i,j], DI[i], F[i], TIMER[i], AR[i], ON, OFF or '('), found end of line");
    refused("R[1]=)", ")", "expected a value (number, R[i], PR[i,j], DI[i], F[i], TIMER[i], AR[i], ON, OFF or '('), found ')'");
    refused("R[1]=FOO", "FOO", "expected a value (number, R[i], PR[i,j], DI[i], F[i], TIMER[i], AR[i], ON, OFF or '('), found 'FOO'");
    refused("R[1]=(1", "", "expected ')' closing the '(' of column 6, found end of line");
    refused("R[1]=PR[1]", "]", "PR[i] is a whole position: in an expression use one element, PR[i,j]");
    refused("R[1]=AR[1:N]", "AR[1:N]", "AR[i] takes no comment");
    refused("R[1]=99999999999", "99999999999", "integer 99999999999 is too large: expected at most 2147483647");
    refused("R[1]=1" + "0".repeat(400) + ".5", "1" + "0".repeat(400) + ".5",
        "number 1" + "0".repeat(39) + "... is too large");
    refused("SR[1]=SUBSTR SR[2],1", "", "expected ',' (SUBSTR takes 3 arguments), found end of line");
    refused("R[1]=SQRT[4", "", "expected ']' closing SQRT[...], found end of line");
  }

  @Test
  void inputsAreReadNotSet() {
    for (String in : List.of("DI", "RI", "GI", "SI", "AI")) {
      refused(in + "[1]=ON", in + "[1]=ON", in + "[] is an input: a program cannot set it (expected DO, RO, GO, AO or F)");
    }
    keptAlarming("SO[1]=ON", "assigning SO[] (the controller sets it)");
    keptAlarming("UO[1]=ON", "assigning UO[] (the controller sets it)");
    keptAlarming("UI[1]=ON", "assigning UI[] (the controller sets it)");
  }

  @Test
  void outputsAndPulses() {
    refused("DO[1] ON", "ON", "expected '=' after DO[...], found 'ON'");
    refused("GO[1]=PULSE", "PULSE", "PULSE works on DO[] and RO[] only, not GO[]");
    refused("F[1]=PULSE", "PULSE", "PULSE works on DO[] and RO[] only, not F[]");
    refused("DO[1]=PULSE,x", "x", "expected a number (pulse width in seconds), found 'x'");
    refused("DO[1]=PULSE,0.5", "", "expected 'sec' after the pulse width, found end of line");
    refused("RO[1]=PULSE,0.5msec", "msec", "expected 'sec' after the pulse width, found 'msec'");
  }

  @Test
  void timers() {
    refused("TIMER[1] START", "START", "expected '=' after TIMER[...], found 'START'");
    refused("TIMER[1]=GO", "GO", "expected START, STOP or RESET after TIMER[...]=, found 'GO'");
    keptAlarming("TIMER[1]=5", "TIMER[i] set to a value");
    keptAlarming("TIMER[1]=((-3))", "TIMER[i] set to a value");
  }

  @Test
  void frameNumbersAndFrames() {
    refused("UFRAME_NUM[5]=1", "5]=1", "expected a motion group GPn in UFRAME_NUM[GPn], found '5'");
    refused("UFRAME_NUM[GPX]=1", "GPX]=1", "expected a motion group GP1..GP9 in UFRAME_NUM[...], found 'GPX'");
    refused("UFRAME_NUM[GP10]=1", "GP10]=1", "expected a motion group GP1..GP9 in UFRAME_NUM[...], found 'GP10'");
    refused("UTOOL_NUM[GP1=1", "=1", "expected ']' closing UTOOL_NUM[GPn], found '='");
    keptAlarming("UTOOL_NUM[GP2]=1", "UTOOL_NUM of motion group GP2 (RobotRun moves group 1)");
    keptAlarming("UFRAME_NUM[gp9]=1", "UFRAME_NUM of motion group GP9 (RobotRun moves group 1)");
    refused("UFRAME_NUM 1", "1", "expected '=' after UFRAME_NUM, found '1'");
    keptAlarming("UFRAME_NUM=Constant", "UFRAME_NUM=Constant");
    refused("UFRAME_NUM=R[R[1]]", "", "UFRAME_NUM=R[R[i]] is not allowed: expected a number or R[i]");
    refused("UTOOL_NUM='x'", "'x'", "expected a number or R[i] after UTOOL_NUM=, found 'x'");
    refused("UFRAME[1]=P[1]", "P[1]", "expected PR[i] (UFRAME[n] is set from a position register), found 'P'");
    refused("UTOOL[1] PR[1]", "PR[1]", "expected '=' after UTOOL[...], found 'PR'");
    refused("OFFSET CONDITION PR[1],UFRAME[2:T]", "", "UFRAME[...] takes no comment");
    keptAlarming("OFFSET CONDITION PR[1],UTOOL[2]", "OFFSET CONDITION with UTOOL");
    keptAlarming("OFFSET PR[1]", "OFFSET CONDITION");
    keptAlarming("OFFSET CONDITION R[1]", "OFFSET CONDITION");
    keptAlarming("TOOL_OFFSET CONDITION PR[2],UTOOL[3]", "TOOL_OFFSET CONDITION with UTOOL");
    keptAlarming("TOOL_OFFSET PR[2]", "TOOL_OFFSET CONDITION");
    keptAlarming("TOOL_OFFSET CONDITION R[2]", "TOOL_OFFSET CONDITION");
    keptAlarming("SKIP R[1]", "SKIP CONDITION");
  }

  @Test
  void positionRegisterAssignments() {
    refused("PR[1,2] 5", "5", "expected '=' after PR[i,j], found '5'");
    refused("PR[1] P[1]", "P[1]", "expected '=' after PR[...], found 'P'");
    refused("PR[1]=5", "5", "expected PR[j], P[j], LPOS, JPOS, UFRAME[n] or UTOOL[n], found '5'");
    refused("PR[1]=FOO", "FOO", "expected PR[j], P[j], LPOS, JPOS, UFRAME[n] or UTOOL[n] after PR[i]=, found 'FOO'");
    refused("PR[1]=P[R[1]]", "", "P[...] needs a constant number (P[R[i]] does not exist; use PR[R[i]])");
    refused("PR[1]=P[0]", "", "P[0]: numbers start at 1");
    refused("PR[1]=UFRAME[1]+PR[2]", "+PR[2]",
        "UFRAME[n] and UTOOL[n] cannot be added to: position arithmetic takes PR[], P[], LPOS and JPOS");
    refused("PR[1]=PR[2]+UFRAME[1]", "", "expected PR[], P[], LPOS or JPOS after '+' in position arithmetic");
    refused("PR[1]=LPOS-UTOOL[1]", "", "expected PR[], P[], LPOS or JPOS after '-' in position arithmetic");
    refused("PR[1]=PR[2]+PR[3]-UTOOL[1]", "", "expected PR[], P[], LPOS or JPOS after '-' in position arithmetic");
    keptAlarming("PR[1]=VR[1].OFFSET+PR[2]", "PR[i]=vision registers VR[] in position arithmetic");
    keptAlarming("PR[1]=PR[2]+VR[1].OFFSET", "PR[i]=vision registers VR[] in position arithmetic");
    keptAlarming("PR[1]=VR[2].FOUND_POS[1]+PR[3]", "PR[i]=vision registers VR[] in position arithmetic");
    keptAlarming("PR[1]=$POS", "PR[i]=system variable");
    keptAlarming("PR[1]=PL[1]", "PR[i]=palletizing register PL[]");
    keptAlarming("PR[1]=VR[1].FOUND_POS[2]", "PR[i]=vision registers VR[]");
    keptAlarming("PR[1]=VR[1].MODELID", "PR[i]=vision registers VR[]");
    keptAlarming("PR[1]=VR[1]", "PR[i]=vision registers VR[]");
  }

  // ---- flow -------------------------------------------------------------------------------

  @Test
  void labelsAndJumps() {
    refused("LBL[R[1]]", "", "a label number must be a constant: LBL[n]");
    refused("LBL[AR[1]]", "", "a label number must be a constant: LBL[n]");
    refused("LBL[0]", "", "label numbers start at 1, found LBL[0]");
    refused("LBL 1", "1", "expected '[' after LBL, found '1'");
    refused("JMP 5", "5", "expected LBL[n] after JMP, found '5'");
    refused("JMP LBL[1", "", "expected ']' closing LBL[...], found end of line");
  }

  @Test
  void callsAndRuns() {
    refused("CALL 5", "5", "expected a program name after CALL, found '5'");
    refused("CALL - KEPT", "- KEPT", "expected a program name after CALL, found '-'");
    String long37 = "A".repeat(37);
    refused("CALL " + long37, long37, "'" + "A".repeat(37)
        + "' is not a program name: expected letters, digits and '_', starting with a letter");
    refused("CALL SUB(1", "", "expected ')' closing the CALL arguments, found end of line");
    refused("CALL SUB(1 2)", "2)", "expected ')' closing the CALL arguments, found '2'");
    keptAlarming("CALL SUB(SPEED=5)", "named CALL arguments (NAME=value)");
    // a name after '-' is checked whole, and the message points at the '-'
    String long36 = "K".repeat(36);
    refused("CALL -" + long36, "-" + long36, "'-" + long36 + "' is not a program name: expected letters, digits and '_', starting with a letter");
    keptAlarming("CALL ...", "CALL with no program chosen (...)");
    keptAlarming("RUN SR[1]", "RUN through a string register SR[]");
    refused("RUN 5", "5", "expected a program name after CALL, found '5'");
  }

  @Test
  void ifSelectForAndWait() {
    refused("IF R[1]=1 JMP LBL[1]", "JMP LBL[1]", "expected ',' then JMP or CALL (or THEN) after the IF condition, found 'JMP'");
    refused("IF R[1]=1,", "", "expected JMP LBL[n] or CALL NAME, found end of line");
    keptAlarming("IF R[1]=1,PAUSE", "IF with an action other than an assignment, output or pulse");
    keptAlarming("IF R[1]=1,TIMER[1]=START", "IF with an action other than an assignment, output or pulse");
    refused("SELECT DI[1]=1,JMP LBL[1]", "DI[1]=1,JMP LBL[1]", "expected R[i] after SELECT (SELECT R[i]=value,JMP LBL[n]), found 'DI'");
    refused("SELECT R[1] 1", "1", "expected '=' after SELECT R[...], found '1'");
    refused("SELECT R[1]=1 JMP LBL[1]", "JMP LBL[1]", "expected ',' after the SELECT value, found 'JMP'");
    refused("SELECT R[1]=1,PAUSE", "PAUSE", "expected JMP LBL[n] or CALL NAME, found 'PAUSE'");
    refused("SELECT R[1]=1,5", "5", "expected JMP LBL[n] or CALL NAME, found '5'");
    refused("=1 JMP LBL[1]", "JMP LBL[1]", "expected ',' after the SELECT value, found 'JMP'");
    refused("ELSE,5", "5", "expected JMP LBL[n] or CALL NAME, found '5'");
    refused("FOR I=1 TO 5", "I=1 TO 5", "expected R[i] after FOR (FOR R[i]=start TO end), found 'I'");
    refused("FOR R[1] 1 TO 5", "1 TO 5", "expected '=' after FOR R[...], found '1'");
    refused("FOR R[1]=1 UNTIL 5", "UNTIL 5", "expected TO or DOWNTO in FOR, found 'UNTIL'");
    refused("FOR R[1]=1 5", "5", "expected TO or DOWNTO, found '5'");
    refused("FOR R[1]=1.5 TO 5", "TO 5", "a FOR bound must be an integer constant, R[i] or AR[i]");
    refused("FOR R[1]=1 TO DI[1]", "", "a FOR bound must be an integer constant, R[i] or AR[i]");
    refused("FOR R[1]=1 TO R[2]+1", "+1", "expected the end of the statement, found '+'");
    refused("WAIT -1(sec)", "(sec)", "WAIT time must be 0 or more seconds, found a negative constant");
    refused("WAIT -.5(sec)", "(sec)", "WAIT time must be 0 or more seconds, found a negative constant");
    refused("WAIT 1", "", "expected '(sec)' after the wait time, found end of line");
    refused("WAIT 1.5(s)", "(s)", "expected '(sec)' after the wait time, found '('");
    refused("WAIT 1(sec", "", "expected ')' closing '(sec)', found end of line");
    refused("WAIT DI[1]=ON TIMEOUT LBL[1]", "LBL[1]", "expected ',' after TIMEOUT, found 'LBL'");
    refused("WAIT DI[1]=ON TIMEOUT,5", "5", "expected LBL[n] after TIMEOUT,, found '5'");
    refused("MESSAGE x", "x", "expected '[' after MESSAGE, found 'x'");
    refused("OVERRIDE 50%", "50%", "expected '=' after OVERRIDE, found '50'");
    refused("OVERRIDE=ON", "", "expected a percentage (n% or R[i]) after OVERRIDE=");
    refused("OVERRIDE=DO[1]", "", "expected a percentage (n% or R[i]) after OVERRIDE=");
  }

  @Test
  void monitorsAndConditionPrograms() {
    refused("MONITOR 5", "5", "expected a condition program name after MONITOR, found '5'");
    String long37 = "B".repeat(37);
    refused("MONITOR " + long37, long37, "'" + long37 + "' is not a program name");
    refused("WHEN DI[1]=ON JMP", "JMP", "expected ',' then CALL after the WHEN condition, found 'JMP'");
    keptAlarming("WHEN DI[1]=ON,JMP LBL[1]", "WHEN with an action other than CALL");
    keptAlarming("WHEN DI[1]=ON,CALL SR[1]", "WHEN ...,CALL through a string register SR[]");
  }

  @Test
  void macros() {
    refused("Program Status(13", "", "expected ')' closing the macro's arguments, found end of line");
    refused("OPEN HAND(1) X", "X", "expected the end of the macro call, found 'X'");
    keptAlarming("Frob Start[1,2]", "instruction Frob Start");
    keptAlarming("HOLD[1]", "HOLD[]");
    keptAlarming("PALLETIZING_X", "palletizing");
    keptAlarming("PAL_1[1]=1", "palletizing");
    refused("FOO=1", "FOO=1", "unknown statement 'FOO': expected a motion (J/L/C/A), an assignment, IF, "
        + "SELECT, FOR, WAIT, JMP, CALL, LBL or another TP statement");
  }

  // ---- motion -----------------------------------------------------------------------------

  @Test
  void speeds() {
    refused("J P[1] x% FINE", "x% FINE", "expected a speed (30%, 400mm/sec, 2sec, R[i]%...), found 'x'");
    refused("J P[1] 100mm/sec FINE", "FINE", "speed unit mm/sec does not fit a J motion: expected %, sec or msec");
    refused("L P[1] 50% FINE", "FINE", "speed unit % does not fit a L motion: expected mm/sec, cm/min, inch/min, deg/sec, sec or msec");
    refused("J P[1] 0% FINE", "FINE", "speed 0%: expected a speed greater than 0");
    refused("L P[1] 0mm/sec FINE", "FINE", "speed 0mm/sec: expected a speed greater than 0");
    refused("J P[1] 300% FINE", "FINE", "speed 300%: expected 1..100%");
    refused("J P[1] 100.5% FINE", "FINE", "speed 100.5%: expected 1..100%");
    refused("J P[1] 100 FINE", "FINE", "expected a speed unit (%, mm/sec, cm/min, inch/min, deg/sec, sec, msec), found 'FINE'");
    refused("J P[1] 100, FINE", ", FINE", "expected a speed unit (%, mm/sec, cm/min, inch/min, deg/sec, sec, msec), found ','");
    refused("L P[1] 100mm/hour FINE", "mm/hour FINE", "unknown speed unit 'mm/hour': expected mm/sec, cm/min, inch/min or deg/sec");
    refused("L P[1] 100mm/5 FINE", "5 FINE", "expected sec or min after '/', found '5'");
    keptAlarming("L P[1] WELD_SPEED FINE", "arc welding speed WELD_SPEED");
  }

  @Test
  void terminations() {
    refused("J P[1] 100% X", "X", "expected a termination (FINE, CNTn or CNT R[i]), found 'X'");
    refused("J P[1] 100%", "", "expected a termination (FINE, CNTn or CNT R[i]), found end of line");
    refused("J P[1] 100% CNT101", "", "CNT101: expected 0..100");
    refused("J P[1] 100% CNT 101", "", "CNT101: expected 0..100");
    refused("J P[1] 100% CNT x", "x", "expected a number or R[i] after CNT, found 'x'");
    refused("J P[1] 100% CNT 1.5", "1.5", "expected an integer (CNT value), found '1.5'");
    refused("J P[1] 100% CNT99999999999", "CNT99999999999", "number 99999999999 is too large");
  }

  @Test
  void targetsAndCircularMotions() {
    refused("J P[R[1]] 100% FINE", "100% FINE", "P[...] needs a constant number (P[R[i]] does not exist; use PR[R[i]])");
    refused("J P[0] 100% FINE", "100% FINE", "P[0]: numbers start at 1");
    keptAlarming("J PR[GP2:1] 100% FINE", "a group in PR[GPn:...] (multi-group)");
    keptAlarming("J PR[GP1:1,7] 100% FINE", "a group in PR[GPn:...] (multi-group)");
    keptAlarming("J PAL_1[A_1] 100% CNT100", "motion to a palletizing point (PAL_n)");
    keptAlarming("L VR[1] 100mm/sec FINE", "motion to VR[]");
    refused("C P[1] 100mm/sec FINE", "100mm/sec FINE",
        "a C motion needs its end point on a continuation line ':  P[j] speed termination ;', found '100'");
    refused("C P[1] FINE", "FINE", "a C motion needs its end point on a continuation line ':  P[j] speed termination ;', found 'FINE'");
    refused("C P[1] CNT 50", "CNT 50", "a C motion needs its end point on a continuation line ':  P[j] speed termination ;', found 'CNT'");
    keptAlarming("C P[1] Weave\n    :  P[2] 100mm/sec FINE", "motion option Weave on the via point of a C motion");
  }

  @Test
  void continuationLinesStartWithAColon() {
    assertThat(TpStatementParser.statementText("C P[1]\n:  P[2] 100mm/sec FINE").instruction()).isInstanceOf(Instruction.Move.class);
    assertThatThrownBy(() -> TpStatementParser.statementText("C P[1]\n  P[2] 100mm/sec FINE"))
        .isInstanceOfSatisfying(TpSyntaxError.class, e -> {
          assertThat(e.getMessage()).isEqualTo("expected a continuation line ':  ...', found 'P[2] 100mm/sec FINE'");
          assertThat(e.line()).isEqualTo(2);
        });
    assertThatThrownBy(() -> TpStatementParser.statementText("C P[1]\n x:  P[2] 100mm/sec FINE"))
        .isInstanceOf(TpSyntaxError.class).hasMessage("expected a continuation line ':  ...', found 'x:  P[2] 100mm/sec FINE'");
    // the error on a continuation line names that line and the column in it
    assertThatThrownBy(() -> TpStatementParser.statementText("C P[1]\n    :  P[2] 100mm/sec X"))
        .isInstanceOfSatisfying(TpSyntaxError.class, e -> {
          assertThat(e.getMessage()).isEqualTo("expected a termination (FINE, CNTn or CNT R[i]), found 'X'");
          assertThat(e.line()).isEqualTo(2);
          assertThat(e.column()).isEqualTo(23);
        });
  }

  @Test
  void motionOptions() {
    refused("J P[1] 100% FINE 5", "5", "expected a motion option or the end of the statement, found '5'");
    refused("L P[1] 100mm/sec FINE Offset,P[1]", "P[1]", "expected PR[i] after Offset,, found 'P'");
    refused("L P[1] 100mm/sec FINE Tool_Offset,P[1]", "P[1]", "expected PR[i] after Tool_Offset,, found 'P'");
    refused("L P[1] 100mm/sec FINE Skip LBL[1]", "LBL[1]", "expected ',LBL[n]' after Skip, found 'LBL'");
    refused("L P[1] 100mm/sec FINE Skip,PR[1]", "PR[1]", "expected LBL[n] after Skip,, found 'PR'");
    refused("L P[1] 100mm/sec FINE Skip,LBL[1],PR[2] LPOS", "LPOS", "expected '=' then LPOS or JPOS after Skip,LBL[n],PR[i], found 'LPOS'");
    refused("L P[1] 100mm/sec FINE Skip,LBL[1],PR[2]=P", "P", "expected LPOS or JPOS after Skip,LBL[n],PR[i]=, found 'P'");
    refused("L P[1] 100mm/sec FINE ACC501", "ACC501", "ACC501: expected 0..150 (0..500 where the controller's limit is raised)");
    refused("L P[1] 100mm/sec FINE ACC99999999999", "ACC99999999999", "number 99999999999 is too large");
  }

  // ---- items and indexes ------------------------------------------------------------------

  @Test
  void itemsAndIndexes() {
    refused("R 1", "1", "expected '[' after R (R[i]), found '1'");
    refused("R[1", "", "expected ']' closing R[...], found end of line");
    refused("R[X]=1", "X]=1", "expected an index (a number or R[i]) inside R[...], found 'X'");
    refused("R[R 1]=1", "1]=1", "expected '[' after R, found '1'");
    refused("R[R[1]=1", "=1", "expected ']' closing R[...], found '='");
    refused("R[AR 1]=1", "1]=1", "expected '[' after AR, found '1'");
    refused("R[AR[1]=1", "=1", "expected ']' closing R[...], found '='");
    refused("R[AR[1 2]]=1", "2]]=1", "expected ']' closing AR[...], found '2'");
    refused("R[AR[0]]=1", "]]=1", "AR[0]: argument numbers start at 1");
    refused("R[.5]=1", ".5]=1", "expected an integer (index of R[...]), found '.5'");
    keptAlarming("R[GP2:1]=1", "a group in R[GPn:...] (multi-group)");
    refused("R[1:X=1", "", "expected ']' closing R[...], found end of line");
    refused("PAYLOAD 1", "1", "expected '[' after PAYLOAD (PAYLOAD[i]), found '1'");
  }
}
