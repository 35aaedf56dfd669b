package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

class CheckCommandTest {

  private static final String PROGRAMS = "tests/resources/programs/";
  private static final String PAYLOAD_WARNING =
      "PAYLOAD has no effect in the simulator: motion is planned without payload dynamics";

  /** Exit code, stdout and stderr of one command line. */
  private record Run(int exit, String out, String err) {}

  private static Run run(String... args) {
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    CommandLine cl = Main.commandLine();
    cl.setOut(new PrintWriter(out, true));
    cl.setErr(new PrintWriter(err, true));
    int exit = cl.execute(args);
    return new Run(exit, out.toString(), err.toString());
  }

  @Test
  void pick3AloneReportsItsUnknownCallAndExitsOne() {
    Run r = run("check", PROGRAMS + "PICK3.LS");
    assertThat(r.exit()).isEqualTo(1);
    assertThat(r.out()).isEqualTo(PROGRAMS + "PICK3.LS:25: warning: " + PAYLOAD_WARNING + "\n"
        + PROGRAMS + "PICK3.LS:44: CALL BEEP: no program named BEEP is known\n");
    assertThat(r.err()).isEmpty();
  }

  @Test
  void pick3WithTheProgramItCallsIsCleanButForItsPayloadWarning() {
    Run r = run("check", PROGRAMS + "PICK3.LS", PROGRAMS + "BEEP.LS");
    assertThat(r.out()).isEqualTo(PROGRAMS + "PICK3.LS:25: warning: " + PAYLOAD_WARNING + "\n");
    assertThat(run("check", "--quiet", PROGRAMS + "PICK3.LS", PROGRAMS + "BEEP.LS").out()).isEmpty();
    assertThat(r.exit()).isEqualTo(0);
    assertThat(run("check", "--known", "BEEP,OTHER", PROGRAMS + "PICK3.LS").exit()).isEqualTo(0);
  }

  @Test
  void everyProblemIsOneLineFileColonLine(@TempDir Path dir) throws IOException {
    Path bad = dir.resolve("BAD.LS");
    Files.writeString(bad, "/PROG  BAD\n/ATTR\nLINE_COUNT\t= 7;\n/MN\n   1:  R[1]=(1+ ;\n   2:J P[1] 100mm/sec FINE    ;\n"
        + "   3:  JMP LBL[4] ;\n/POS\n/END\n");
    Run r = run("check", bad.toString());
    assertThat(r.exit()).isEqualTo(1);
    assertThat(r.out().lines().toList()).containsExactly(
        bad + ":3: warning: LINE_COUNT = 7 but /MN has 3 lines; using 3",
        bad + ":5: expected a value (number, R[i], PR[i,j], DI[i], F[i], TIMER[i], AR[i], ON, OFF or '('), found end of line",
        bad + ":6: speed unit mm/sec does not fit a J motion: expected %, sec or msec",
        bad + ":7: warning: LBL[4] is not defined in this program: the jump alarms when it runs");
    assertThat(run("check", "--quiet", bad.toString()).out()).doesNotContain("warning");
  }

  @Test
  void macrosAreCheckedAgainstTheTableAnInstructorPasses(@TempDir Path dir) throws IOException {
    Path prog = dir.resolve("CELL.LS");
    Files.writeString(prog, "/PROG  CELL\n/ATTR\n/MN\n   1:  Open hand 1 ;\n   2:  Close hand(2) ;\n"
        + "   3:  HOME_IT ;\n/POS\n/END\n");
    Path opener = dir.resolve("HOPEN.LS");
    Files.writeString(opener, "/PROG  HOPEN\n/ATTR\n/MN\n   1:  R[1]=AR[1] ;\n/POS\n/END\n");
    // Without a table: a macro of several words cannot be known, and says so by name.
    Run none = run("check", prog.toString(), opener.toString());
    assertThat(none.out()).contains(prog + ":4: macro Open hand 1: not in the macro table")
        .contains(prog + ":5: macro Close hand: not in the macro table")
        .contains(prog + ":6: macro HOME_IT: no program named HOME_IT is known");
    Path table = dir.resolve("macros.txt");
    Files.writeString(table, "# the cell's MACRO screen\nOpen hand 1 = HOPEN\nCLOSE HAND = HCLOSE\nHOME_IT=HOPEN\n");
    Run with = run("check", "--macros", table.toString(), prog.toString(), opener.toString());
    assertThat(with.out().lines().toList()).containsExactly(
        prog + ":5: macro Close hand runs HCLOSE (macro table): no program named HCLOSE is known");
    // a scenario's robots' "macros" are the same table
    Path scenario = dir.resolve("cell.json");
    Files.writeString(scenario, "{\"format\": 1, \"name\": \"m\", \"robots\": [{\"name\": \"r1\", \"model\": \"lrmate200id\","
        + " \"macros\": [{\"name\": \"OPEN HAND 1\", \"program\": \"HOPEN\"}, {\"name\": \"Close hand\", \"program\": \"HOPEN\"},"
        + " {\"name\": \"HOME_IT\", \"program\": \"HOPEN\"}]}]}");
    Run fromScenario = run("check", "--macros", scenario.toString(), prog.toString(), opener.toString());
    assertThat(fromScenario.err()).isEmpty();
    assertThat(fromScenario.out()).isEmpty();
    assertThat(fromScenario.exit()).isEqualTo(0);
    Files.writeString(table, "Open hand 1 = HOPEN\nno equals sign here\n");
    Run bad = run("check", "--macros", table.toString(), prog.toString());
    assertThat(bad.exit()).isEqualTo(2);
    assertThat(bad.err()).contains(table + ":2: expected 'MACRO NAME = PROGRAM'");
  }

  @Test
  void controllerOptionSaysWhatTheLabsControllerWouldRefuseOrTreatDifferently(@TempDir Path dir) throws IOException {
    Path prog = dir.resolve("LAB.LS");
    Files.writeString(prog, "/PROG  LAB\n/ATTR\nCOMMENT\t\t= \"pick and place for lab 3\";\n/MN\n"
        + "   1:  R[1:A COMMENT FAR TOO LONG]=1 ;\n   2:  VISION RUN_FIND 'FIND1' ;\n   3:  SR[1]=SR[2] ;\n"
        + "   4:  CALL SUB(SPEED=5) ;\n   5:  R[2]=2 ;\n/POS\n/END\n");
    Run b = run("check", "--quiet", "--controller", "R-30iB", prog.toString());
    assertThat(b.out()).contains(prog + ":6: R-30iB: needs the iRVision option")
        .contains(prog + ":8: R-30iB: named CALL arguments (NAME=value) is a statement of a newer system than R-30iB")
        .doesNotContain(":7: R-30iB");
    Run a = run("check", "--controller", "r-30ia", prog.toString());
    assertThat(a.out()).contains(prog + ":7: R-30iA: a string register SR[] or string function is a statement of a newer system")
        .contains(prog + ":5: warning: R-30iA: the comment 'A COMMENT FAR TOO LONG' is 22 characters; the controller keeps 16")
        .contains(prog + ":1: warning: R-30iA: the program comment is 24 characters; the pendant keeps 16")
        .doesNotContain(":9:");
    Run plus = run("check", "--quiet", "--controller", "R-30iB-Plus", prog.toString());
    assertThat(plus.out()).doesNotContain("newer system");
    Run bad = run("check", "--controller", "R-2000", prog.toString());
    assertThat(bad.exit()).isEqualTo(2);
    assertThat(bad.err()).contains("expected R-30iA, R-30iB or R-30iB-Plus");
  }

  @Test
  void ioSizesReportIoBeyondTheLabsConfiguredRange(@TempDir Path dir) throws IOException {
    Path prog = dir.resolve("CELL.LS");
    Files.writeString(prog, "/PROG  CELL\n/ATTR\n/MN\n   1:  DO[64:LAST]=ON ;\n   2:  WAIT DI[65]=ON ;\n"
        + "   3:  ! DO[500] in a remark ;\n   4:  MESSAGE[GO[9] text] ;\n   5:  IF (GI[5:COUNT]>2 AND F[3]),DO[120]=(ON) ;\n"
        + "/POS\n/END\n");
    Run plain = run("check", prog.toString());
    assertThat(plain.exit()).isZero();
    Run lab = run("check", "--io-sizes", "DI=64,do=64,GI=4", prog.toString());
    assertThat(lab.exit()).isEqualTo(1);
    assertThat(lab.out()).contains(prog + ":5: lab I/O: DI[65] is outside the configured DI[1..64]")
        .contains(prog + ":8: lab I/O: GI[5] is outside the configured GI[1..4]")
        .contains(prog + ":8: lab I/O: DO[120] is outside the configured DO[1..64]")
        .doesNotContain(":4: lab").doesNotContain(":6: lab").doesNotContain(":7: lab").doesNotContain("F[3]");
    Run bad = run("check", "--io-sizes", "XX=3", prog.toString());
    assertThat(bad.exit()).isEqualTo(2);
    assertThat(bad.err()).contains("--io-sizes:");
  }

  @Test
  void payloadAndWjntWarnThatTheyHaveNoEffectInTheSimulator(@TempDir Path dir) throws IOException {
    Path w = dir.resolve("PAY.LS");
    Files.writeString(w, "/PROG  PAY\n/ATTR\n/MN\n   1:  PAYLOAD[2] ;\n   2:L P[1] 100mm/sec FINE Wjnt ;\n"
        + "   3:L P[1] 100mm/sec FINE ;\n/POS\nP[1]{\n   GP1:\n\tUF : 0, UT : 1,\t\tCONFIG : 'N U T, 0, 0, 0',\n"
        + "\tX = 400.000 mm,\tY = 0.000 mm,\tZ = 300.000 mm,\n\tW = 180.000 deg,\tP = 0.000 deg,\tR = 0.000 deg\n};\n/END\n");
    Run r = run("check", w.toString());
    assertThat(r.out().lines().toList()).containsExactly(
        w + ":4: warning: PAYLOAD has no effect in the simulator: motion is planned without payload dynamics",
        w + ":5: warning: Wjnt has no effect in the simulator: the tool orientation is interpolated as without it");
    assertThat(r.exit()).isEqualTo(0);
  }

  @Test
  void warningsAloneExitZero(@TempDir Path dir) throws IOException {
    Path w = dir.resolve("W.LS");
    Files.writeString(w, "/PROG  W\n/ATTR\nLINE_COUNT\t= 2;\n/MN\n   1:  END ;\n/POS\n/END\n");
    Run r = run("check", w.toString());
    assertThat(r.out()).isEqualTo(w + ":3: warning: LINE_COUNT = 2 but /MN has 1 lines; using 1\n");
    assertThat(r.exit()).isEqualTo(0);
  }

  @Test
  void unreadableInputExitsTwo(@TempDir Path dir) {
    Run missing = run("check", dir.resolve("NOPE.LS").toString(), PROGRAMS + "BEEP.LS");
    assertThat(missing.exit()).isEqualTo(2);
    assertThat(missing.err()).isEqualTo(dir.resolve("NOPE.LS") + ": cannot read: no such file\n");

    Run directory = run("check", dir.toString());
    assertThat(directory.exit()).isEqualTo(2);
    assertThat(directory.err()).isEqualTo(dir + ": no .LS files in this directory\n");

    Run none = run("check");
    assertThat(none.exit()).isEqualTo(2);
    assertThat(none.err()).contains("Missing required parameter");
  }

  @Test
  void theSameProgramTwiceIsAnError() {
    Run r = run("check", PROGRAMS + "BEEP.LS", "./" + PROGRAMS + "BEEP.LS");
    assertThat(r.exit()).isEqualTo(1);
    assertThat(r.out()).isEqualTo("./" + PROGRAMS + "BEEP.LS:1: program BEEP is also defined in " + PROGRAMS + "BEEP.LS\n");
  }

  @Test
  void helpDocumentsTheCommandAndItsExitCodes() {
    Run top = run("--help");
    assertThat(top.out()).contains("check");
    Run r = run("check", "--help");
    assertThat(r.exit()).isEqualTo(0);
    assertThat(r.out()).contains("file:line: message", "--known", "--quiet", "Exit codes:", "2   a file or directory could not be read",
        "FILE.ls|DIR", "every *.LS file in it", "/PROG name");
  }

  /** A program with one error on file line 5: a jump to a label it does not define. */
  private static String badProgram(String name) {
    return "/PROG  " + name + "\n/ATTR\n/MN\n   1:  END ;\n   2:  JMP LBL[4] ;\n/POS\n/END\n";
  }

  @Test
  void aDirectoryIsEveryLsFileInItInOrderOfNameWithCallsResolvedAmongThem(@TempDir Path dir) throws IOException {
    Files.copy(Path.of(PROGRAMS, "PICK3.LS"), dir.resolve("PICK3.LS"));
    Files.copy(Path.of(PROGRAMS, "BEEP.LS"), dir.resolve("BEEP.LS"));
    Files.writeString(dir.resolve("ZED.ls"), badProgram("ZED"));
    Files.writeString(dir.resolve("ALPHA.LS"), badProgram("ALPHA"));
    // neither a subdirectory (even one named like a program) nor another file is checked
    Files.createDirectories(dir.resolve("OLD.LS"));
    Files.writeString(dir.resolve("OLD.LS").resolve("GONE.LS"), badProgram("GONE"));
    Files.writeString(dir.resolve("notes.txt"), "not a program");

    Run r = run("check", dir.toString());
    // PICK3's CALL BEEP is resolved by BEEP.LS in the same directory; errors come in order of file name
    assertThat(r.out().lines().toList()).containsExactly(
        dir.resolve("ALPHA.LS") + ":5: warning: LBL[4] is not defined in this program: the jump alarms when it runs",
        dir.resolve("PICK3.LS") + ":25: warning: " + PAYLOAD_WARNING,
        dir.resolve("ZED.ls") + ":5: warning: LBL[4] is not defined in this program: the jump alarms when it runs");
    // a controller loads a jump to a missing label (it alarms when it runs): a warning, exit 0
    assertThat(r.exit()).isEqualTo(0);
    assertThat(r.err()).isEmpty();

    // the worst code wins: a missing file next to the directory makes it 2
    Run worse = run("check", dir.toString(), dir.resolve("NOPE.LS").toString());
    assertThat(worse.exit()).isEqualTo(2);
    assertThat(worse.out().lines()).hasSize(3);

    Files.delete(dir.resolve("ALPHA.LS"));
    Files.delete(dir.resolve("ZED.ls"));
    assertThat(run("check", "--quiet", dir.toString())).isEqualTo(new Run(0, "", ""));
  }

  @Test
  void aFileNamedOtherThanItsProgramGetsAWarning(@TempDir Path dir) throws IOException {
    Files.copy(Path.of(PROGRAMS, "PICK3.LS"), dir.resolve("PICK.LS"));
    Files.copy(Path.of(PROGRAMS, "BEEP.LS"), dir.resolve("beep.ls"));
    Run r = run("check", dir.toString());
    assertThat(r.out()).isEqualTo(dir.resolve("PICK.LS")
        + ":1: warning: the program is named PICK3 (/PROG) but the file is PICK.LS: a controller loads it as PICK3, not PICK\n"
        + dir.resolve("PICK.LS") + ":25: warning: " + PAYLOAD_WARNING + "\n");
    assertThat(r.exit()).isEqualTo(0);
    assertThat(run("check", "-q", dir.resolve("PICK.LS").toString(), dir.resolve("beep.ls").toString()))
        .isEqualTo(new Run(0, "", ""));
  }

  @Test
  void benchParsePrintsLinesPerSecond() {
    Run r = run("bench", "parse", "--lines", "200", "--rounds", "2", "--warmup", "1");
    assertThat(r.exit()).isEqualTo(0);
    assertThat(r.out()).matches("lines_per_sec=\\d+ lines_per_cpu_sec=\\d+ lines=200 rounds=2 best_ms=\\S+ mean_ms=\\S+ best_cpu_ms=\\S+\\n");
  }
}
