package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.program.Instruction;
import org.robotrun.program.Motion;
import org.robotrun.program.Program;
import org.robotrun.program.TpLexer;
import org.robotrun.program.TpStatementParser;
import org.robotrun.program.TpSyntaxError;

/**
 * Slips of hand-edited .LS files (docs/tp-language.md, "Program lines"): each either loads with a
 * {@code mended:} warning naming its line, the meaning kept and the file written back as read, or
 * is one error naming its line and column. The texts are this project's own.
 */
class HandEditMendsTest {

  private static final String HEAD = "/PROG  HANDED\n/ATTR\nCOMMENT\t\t= \"by hand\";\n/MN\n";
  private static final String POS = "/POS\nP[1]{\n   GP1:\n\tUF : 0, UT : 1,\t\tCONFIG : 'N U T, 0, 0, 0',\n"
      + "\tX =   450.000  mm,\tY =    10.000  mm,\tZ =   320.000  mm,\n"
      + "\tW =   180.000 deg,\tP =     0.000 deg,\tR =     0.000 deg\n};\n/END\n";

  /** A program whose /MN holds {@code mn}: its first line is file line 5. */
  private static LsReadResult mn(String mn) {
    return LsReader.parse("HANDED.LS", HEAD + mn + POS);
  }

  private static List<String> messages(LsReadResult r) {
    return r.diagnostics().stream().map(Diagnostic::toString).toList();
  }

  /** The program a controller-written /MN reads as (no diagnostics at all). */
  private static Program clean(String mn) {
    LsReadResult r = mn(mn);
    assertThat(messages(r)).isEmpty();
    return r.program();
  }

  private static void assertLoadsAsReadBack(LsReadResult r, String text) {
    assertThat(r.hasErrors()).as(messages(r).toString()).isFalse();
    assertThat(new String(LsWriter.bytes(r.program()), StandardCharsets.UTF_8)).isEqualTo(text);
  }

  @Test
  void registerWrittenInsideTheBracketsIsReadAsThatRegister() {
    LsReadResult r = mn("   1:  R[7:half]=[R80]/2 ;\n   2:  IF [R3]>1,JMP LBL[1] ;\n   3:  LBL[1] ;\n"
        + "   4:  PR[2]=[PR5] ;\n   5:  R[1]=[AR1]+R[2] ;\n   6:  SR[1]=[SR2] ;\n");
    assertThat(r.hasErrors()).as(messages(r).toString()).isFalse();
    assertThat(messages(r)).contains(
        "HANDED.LS:5: warning: mended: read [R80] as R[80] (a register written inside the brackets)",
        "HANDED.LS:6: warning: mended: read [R3] as R[3] (a register written inside the brackets)",
        "HANDED.LS:8: warning: mended: read [PR5] as PR[5] (a register written inside the brackets)",
        "HANDED.LS:9: warning: mended: read [AR1] as AR[1] (a register written inside the brackets)",
        "HANDED.LS:10: warning: mended: read [SR2] as SR[2] (a register written inside the brackets)");
    assertThat(r.program().lines()).isEqualTo(clean("   1:  R[7:half]=R[80]/2 ;\n   2:  IF R[3]>1,JMP LBL[1] ;\n"
        + "   3:  LBL[1] ;\n   4:  PR[2]=PR[5] ;\n   5:  R[1]=AR[1]+R[2] ;\n   6:  SR[1]=SR[2] ;\n").lines());
  }

  @Test
  void remarksMessagesAndIndexesAreNotTouched() {
    LsReadResult r = mn("   1:  ! see [R80] ;\n   2:  MESSAGE[set [R80] first] ;\n   3:  R[2]=R[R[4]] ;\n");
    assertThat(messages(r)).isEmpty();
    assertThat(r.program().line(1)).isEqualTo(new Instruction.Comment(" see [R80]"));
    assertThat(r.program().line(2)).isEqualTo(new Instruction.Message("set [R80] first"));
  }

  @Test
  void otherBracketedWordsStayErrorsNamingTheColumn() {
    // only R, PR, AR and SR are mended: [DI1] is not a register, and a guess would change meaning
    LsReadResult r = mn("   1:  R[1]=[DI1] ;\n");
    assertThat(r.hasErrors()).isTrue();
    Diagnostic d = r.diagnostics().get(0);
    assertThat(d.line()).isEqualTo(5);
    assertThat(d.column()).isEqualTo(13);
  }

  @Test
  void motionWithoutSpeedOrTerminationTakesThePendantsFirstDefaultOfItsType() {
    LsReadResult r = mn("   1:J P[1] ;\n   2:L P[1] ;\n   3:L P[1] CNT50 ;\n   4:J P[1] 30% ;\n"
        + "   5:J PR[96] Offset,PR[2] ;\n   6:C P[1]\n    :  P[1] ;\n");
    assertThat(r.hasErrors()).as(messages(r).toString()).isFalse();
    assertThat(r.program().lines()).isEqualTo(clean("   1:J P[1] 100% FINE ;\n   2:L P[1] 100mm/sec FINE ;\n"
        + "   3:L P[1] 100mm/sec CNT50 ;\n   4:J P[1] 30% FINE ;\n   5:J PR[96] 100% FINE Offset,PR[2] ;\n"
        + "   6:C P[1]\n    :  P[1] 100mm/sec FINE ;\n").lines());
    assertThat(messages(r)).contains(
        "HANDED.LS:5: warning: mended: a J motion without speed and termination: completed with 100% FINE"
            + " from the pendant's first default J motion (J P[] 100% FINE)",
        "HANDED.LS:7: warning: mended: a L motion without speed: completed with 100mm/sec"
            + " from the pendant's first default L motion (L P[] 100mm/sec FINE)",
        "HANDED.LS:8: warning: mended: a J motion without termination: completed with FINE"
            + " from the pendant's first default J motion (J P[] 100% FINE)",
        "HANDED.LS:10: warning: mended: a C motion without speed and termination: completed with 100mm/sec FINE"
            + " from the pendant's first default L motion (L P[] 100mm/sec FINE; its table has no C row)");
  }

  @Test
  void thePendantsOwnEntryDoesNotMend() {
    // typed on the pendant (or given to the parser outside a file) a motion still needs its speed
    assertThatThrownBy(() -> TpStatementParser.parse(TpLexer.tokenize("J P[1]", 1, 1, true)))
        .isInstanceOf(TpSyntaxError.class).hasMessageContaining("expected a speed");
  }

  @Test
  void unchangedFileIsWrittenAsReadAndAnEditWritesTheMendedForm() {
    String text = HEAD + "   1:  R[1]=[R80]/2 ;\n   2:J P[1] ;\n   3:  WAIT 1.00(sec) ;\n" + POS;
    LsReadResult r = LsReader.parse("HANDED.LS", text);
    assertLoadsAsReadBack(r, text);
    List<Instruction> lines = new ArrayList<>(r.program().lines());
    lines.add(new Instruction.End());
    Program edited = r.program().withBody(lines, r.program().positions());
    String written = new String(LsWriter.bytes(edited), StandardCharsets.UTF_8);
    assertThat(written).contains("   1:  R[1]=R[80]/2    ;\n", "   2:J P[1] 100% FINE    ;\n",
        "   3:  WAIT 1.00(sec) ;\n", "   4:  END ;\n");
    assertThat(written).doesNotContain("[R80]");
    LsReadResult again = LsReader.parse("HANDED.LS", written);
    assertThat(again.diagnostics().stream().filter(d -> d.message().startsWith("mended")).toList()).isEmpty();
    assertThat(again.program().lines()).isEqualTo(lines);
  }

  @Test
  void lineWithoutItsNumberIsNumberedInFileOrder() {
    LsReadResult r = mn("  R[1]=5 ;\nJ P[1] 50% FINE ;\n  ! a remark ;\n  // R[2]=1 ;\n");
    assertThat(messages(r)).containsExactly(
        "HANDED.LS:5: warning: mended: a line without its number: read as line 1",
        "HANDED.LS:6: warning: mended: a line without its number: read as line 2",
        "HANDED.LS:7: warning: mended: a line without its number: read as line 3",
        "HANDED.LS:8: warning: mended: a line without its number: read as line 4");
    assertThat(r.program().lines()).isEqualTo(
        clean("   1:  R[1]=5 ;\n   2:J P[1] 50% FINE ;\n   3:  ! a remark ;\n   4:  // R[2]=1 ;\n").lines());
  }

  @Test
  void spacesBeforeTheColonAndAttrEntryWithoutSemicolonAreMended() {
    String text = "/PROG  HANDED\n/ATTR\nCOMMENT\t\t= \"by hand\"\nPROTECT\t\t= READ_WRITE;\n/MN\n"
        + " 1 :  R[1]=5 ;\n   2:  R[2]=1 ;\n" + POS;
    LsReadResult r = LsReader.parse("HANDED.LS", text);
    assertThat(messages(r)).containsExactly(
        "HANDED.LS:3: warning: mended: no ';' at the end of the /ATTR entry: read as if it were there",
        "HANDED.LS:6: warning: mended: spaces between the line number and ':': read as '1:'");
    assertThat(r.program().comment()).isEqualTo("by hand");
    assertLoadsAsReadBack(r, text);
  }

  @Test
  void layoutSlipsLoadWithoutAWordAndComeBackByteForByte() {
    String[] texts = {
      // lower case keywords and section names
      "/PROG  HANDED\n/ATTR\n/mn\n   1:  r[1]=r[1]+1 ;\n   2:j p[1] 50% fine ;\n   3:  if r[1]>3,jmp lbl[1] ;\n"
          + "   4:  lbl[1] ;\n" + POS.replace("/END", "/end"),
      // tabs instead of spaces, trailing blanks
      HEAD + "\t1:\tR[1]=5\t;\n\t2:J\tP[1]\t50%\tFINE\t;  \n" + POS,
      // blank lines without numbers
      HEAD + "   1:  R[1]=5 ;\n\n   2:J P[1] 50% FINE ;\n   \n   3:  R[2]=1 ;\n" + POS,
      // CRLF and LF mixed
      HEAD + "   1:  R[1]=5 ;\r\n   2:J P[1] 50% FINE ;\n   3:  R[2]=1 ;\r\n" + POS,
      // no /ATTR, no /POS
      "/PROG  HANDED\n/MN\n   1:  R[1]=5 ;\n/END\n",
    };
    for (String text : texts) {
      LsReadResult r = LsReader.parse("HANDED.LS", text);
      assertThat(messages(r)).as(text).allMatch(m -> !m.contains(" error") && m.contains("warning: "));
      assertLoadsAsReadBack(r, text);
    }
  }

  @Test
  void oldMacLineEndsAreLinesWithAWarning() {
    String text = (HEAD + "   1:  R[1]=5 ;\n   2:J P[1] 50% FINE ;\n" + POS).replace('\n', '\r');
    LsReadResult r = LsReader.parse("HANDED.LS", text);
    assertThat(messages(r)).containsExactly(
        "HANDED.LS:1: warning: mended: a line ending in a lone CR (an old Mac editor's line end): read as a line break");
    assertThat(r.program().lines()).isEqualTo(clean("   1:  R[1]=5 ;\n   2:J P[1] 50% FINE ;\n").lines());
    assertLoadsAsReadBack(r, text);
  }

  @Test
  void whatCannotBeMendedIsOneErrorNamingLineAndColumn() {
    LsReadResult garbled = mn("   1:  R[1]=5 ;\n  1.5 R[2]=1 ;\n");
    assertThat(garbled.hasErrors()).isTrue();
    assertThat(garbled.diagnostics()).hasSize(1);
    Diagnostic d = garbled.diagnostics().get(0);
    assertThat(List.of(d.line(), d.column())).containsExactly(6, 3);
    assertThat(d.message()).startsWith("expected a numbered line 'N:  instruction ;', found '1.5 R[2]=1 ;'");

    LsReadResult truncated = LsReader.parse("HANDED.LS", HEAD + "   1:  R[1]=5 ;\n");
    assertThat(messages(truncated)).containsExactly("HANDED.LS:5: file ends without /END (truncated?)");
  }

  @Test
  void theDefaultTableIsThePendantsStandardFour() {
    assertThat(org.robotrun.program.DefaultMotions.first(Motion.Type.J).termination()).isEqualTo(new Motion.Fine());
    assertThat(org.robotrun.program.DefaultMotions.first(Motion.Type.A).speed())
        .isEqualTo(new Motion.Speed(new Motion.SpeedConst(100), Motion.SpeedUnit.MM_PER_SEC));
  }
}
