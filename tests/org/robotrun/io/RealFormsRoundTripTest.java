package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robotrun.program.Config;
import org.robotrun.program.Instruction;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/**
 * The golden files of real-file forms (tests/resources/corpus/REAL_*.LS, written for this project
 * as controllers list programs): an edit keeps what RobotRun reads but cannot hold (SCARA, rail
 * and never-taught positions, a repeated /APPL), and hand-edited files load mended, each mend a
 * warning with its line.
 */
class RealFormsRoundTripTest {
  private static final Path FORMS = Path.of("tests/resources/corpus/REAL_FORMS.LS");

  @Test
  void reTeachingOnePositionKeepsTheBlocksTheModelCannotHold() throws IOException {
    LsReadResult r = LsReader.read(FORMS);
    Program p = r.program();
    assertThat(p.positions().keySet()).containsExactly(1);
    Map<Integer, LocalPosition> moved = new LinkedHashMap<>(p.positions());
    moved.put(1, new LocalPosition(1, "", 3, 1, new Position.Cartesian(410, 10, 250, 180, 0, 0, Config.DEFAULT)));
    moved.put(6, new LocalPosition(6, "NEW", 3, 1, new Position.Cartesian(300, 0, 200, 180, 0, 0, Config.DEFAULT)));
    String text = new String(LsWriter.bytes(p.withBody(p.lines(), moved)), StandardCharsets.UTF_8);
    String original = Files.readString(FORMS);
    // the SCARA, rail and never-taught blocks as read, in their place
    assertThat(text).contains(block(original, "P[2]{")).contains(block(original, "P[3]{")).contains(block(original, "P[4]{"));
    assertThat(text).contains("X =   410.000  mm").contains("P[6:\"NEW\"]{").contains("/APPL\n/APPL\n/MN\n");
    assertThat(text.indexOf("P[2]{")).isLessThan(text.indexOf("P[6:"));
    LsReadResult again = LsReader.parse("again.LS", text);
    assertThat(again.program().positions()).isEqualTo(moved);
    assertThat(again.program().lines()).isEqualTo(p.lines());
  }

  @Test
  void anEditedLineIsLaidOutAfreshAndTheOthersKeepTheirText() throws IOException {
    LsReadResult r = LsReader.read(FORMS);
    Program p = r.program();
    java.util.List<Instruction> lines = new java.util.ArrayList<>(p.lines());
    lines.set(1, new Instruction.Comment(" edited"));
    String text = new String(LsWriter.bytes(p.withBody(lines, p.positions())), StandardCharsets.UTF_8);
    assertThat(text).contains("   2:  ! edited ;\n").contains("  10:  MESSAGE[R[6] > 50 mm <check> + [ok]] ;\n")
        .contains("  22:  Program Status(13) ;\n").contains("  37:  R[11]=R[12]+\n    :  R[13]    ;\n");
  }

  @Test
  void handEditedLinesAreMendedAsTheOfflineConverterTakesThem() {
    String file = "/PROG  HAND\n/ATTR\n/MN\n   1:  R[1]=1 ;\n   1:  R[2]=2 ; ! set two\n    : ! a remark line ;\n"
        + "   7:  R[3]=3\n   3:  CALL GRIP \n    :  !close it ;\n/POS\n/END\n";
    LsReadResult r = LsReader.parse("HAND.LS", file);
    assertThat(r.hasErrors()).isFalse();
    assertThat(r.diagnostics()).extracting(Diagnostic::toString).containsExactly(
        "HAND.LS:5: warning: mended: line number 1 out of order or repeated: read as line 2",
        "HAND.LS:5: warning: mended: a remark after ';': kept as remark line 3",
        "HAND.LS:6: warning: mended: a line with ':' and no number after a finished statement: read as line 4",
        "HAND.LS:7: warning: mended: line number 7 out of order or repeated: read as line 5",
        "HAND.LS:7: warning: mended: no ';' at the end of the line: read as if it were there",
        "HAND.LS:8: warning: mended: line number 3 out of order or repeated: read as line 6",
        "HAND.LS:8: warning: mended: no ';' at the end of the line: read as if it were there",
        "HAND.LS:9: warning: mended: a line with ':' and no number after a finished statement: read as line 7");
    assertThat(r.program().lines()).containsExactly(
        new Instruction.AssignRegister(org.robotrun.program.Item.of(1), new org.robotrun.program.Expr.IntConst(1)),
        new Instruction.AssignRegister(org.robotrun.program.Item.of(2), new org.robotrun.program.Expr.IntConst(2)),
        new Instruction.Comment(" set two"),
        new Instruction.Comment(" a remark line"),
        new Instruction.AssignRegister(org.robotrun.program.Item.of(3), new org.robotrun.program.Expr.IntConst(3)),
        new Instruction.Call("GRIP", java.util.List.of()),
        new Instruction.Comment("close it"));
    // saved unedited it comes back as read; written afresh it is in the controller's layout
    assertThat(LsWriter.bytes(r.program())).isEqualTo(file.getBytes(StandardCharsets.UTF_8));
    assertThat(LsWriter.write(r.program().withoutSource())).contains("   7:  !close it ;\n");
  }

  private static String block(String text, String start) {
    int from = text.indexOf(start);
    return text.substring(from, text.indexOf("};", from) + 2);
  }
}
