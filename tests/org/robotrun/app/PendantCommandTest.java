package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

class PendantCommandTest {
  record Run(int exitCode, String out, String err) {}

  static Run run(String... args) {
    CommandLine cl = Main.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(err));
    int code = cl.execute(args);
    return new Run(code, out.toString(), err.toString());
  }

  @Test
  void scriptRunsAndEveryShowPrintsTheLcd(@TempDir Path dir) throws Exception {
    Path keys = dir.resolve("demo.keys");
    Files.writeString(keys, """
        HOLD DEADMAN
        # make a program with one point and run it
        SELECT
        F1
        TYPE DEMO
        ENTER
        SHIFT+F1
        SHOW
        HOLD SHIFT
        FWD
        WAIT 1
        RELEASE SHIFT
        SHOW
        """);
    Run r = run("pendant", "--keys", keys.toString());
    assertThat(r.exitCode()).isEqualTo(0);
    assertThat(r.err()).isEmpty();
    assertThat(r.out()).contains("-- SHOW (line 8, t=0.000 s) --").contains("-- SHOW (line 13, t=1.000 s) --")
        .contains("J P[1] 100% FINE").contains("EDIT DEMO");
  }

  @Test
  void theDocumentedTourRuns() {
    Run r = run("pendant", "--keys", "docs/examples/pendant-tour.keys");
    assertThat(r.exitCode()).isEqualTo(0);
    assertThat(r.out()).contains("L P[2] 200mm/sec {CNT50}").contains("IF {R[1]<3},JMP LBL[1]")
        .contains("T1   RUNNING").contains("LINE 6    T1   ABORTED").contains("R[  1:            ]  = {3}");
  }

  @Test
  void saveWritesTheProgramsTheScriptBuiltAsLsFiles(@TempDir Path dir) throws Exception {
    Run r = run("pendant", "--keys", "docs/examples/pendant-tour.keys", "--save", dir.toString());
    assertThat(r.exitCode()).isEqualTo(0);
    org.robotrun.io.LsReadResult back = org.robotrun.io.LsReader.read(dir.resolve("PICK1.LS"));
    assertThat(back.hasAnyError()).as(back.diagnostics().toString()).isFalse();
    assertThat(back.program().lineCount()).isEqualTo(6);
    assertThat(back.program().positions()).containsKeys(1, 2, 3);
    assertThat(Files.readString(dir.resolve("PICK1.LS"))).contains("L P[2] 200mm/sec CNT50");
    Run bad = run("pendant", "--keys", "docs/examples/pendant-tour.keys", "--save", dir.resolve("nope").toString());
    assertThat(bad.exitCode()).isEqualTo(2);
    assertThat(bad.err()).contains("--save: the directory");
  }

  @Test
  void malformedScriptIsExit2WithFileAndLine(@TempDir Path dir) throws Exception {
    Path keys = dir.resolve("bad.keys");
    Files.writeString(keys, "SELECT\nWAIT later\n");
    Run r = run("pendant", "--keys", keys.toString());
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.out()).isEmpty();
    assertThat(r.err().strip()).isEqualTo("robotrun: " + keys + ":2: WAIT needs seconds (e.g. WAIT 2.5), got 'later'");
  }

  @Test
  void missingFilesAreExit2(@TempDir Path dir) {
    Run r = run("pendant", "--keys", dir.resolve("none.keys").toString());
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.err()).contains("--keys: no such file");
  }

  @Test
  void anInputLineBeyondTheRobotsIoIsExit2BeforeAnyKey(@TempDir Path dir) throws Exception {
    // DI[20] passes the default sizes (512) but this robot has 16 DI: it threw inside the run.
    Path sc = dir.resolve("small.json");
    Files.writeString(sc, "{\"format\": 1, \"robots\": [{\"name\": \"robot1\", \"model\": \"lrmate200id\", "
        + "\"io\": {\"DI\": 16}}]}");
    Path keys = dir.resolve("k.keys");
    Files.writeString(keys, "SHOW\nDI[16] ON\nDI[20] ON\nSHOW\n");
    Run r = run("pendant", "--scenario", sc.toString(), "--keys", keys.toString());
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.err()).contains("k.keys:3").contains("DI[20]").contains("1..16");
    assertThat(r.out()).doesNotContain("SHOW");
  }

  @Test
  void scenarioCellsLoad(@TempDir Path dir) throws Exception {
    Path keys = dir.resolve("k.keys");
    Files.writeString(keys, "POSN\nSHOW\nMENU\n5\nSHOW\n");
    Run r = run("pendant", "--scenario", "scenarios/frame-teaching.json", "--keys", keys.toString());
    assertThat(r.exitCode()).as(r.err()).isEqualTo(0);
    assertThat(r.out()).contains("POSITION  (live)").contains("J5   -90.000").contains("SETUP Frames");
    Run s = run("pendant", "--keys", keys.toString(), "--scenario", dir.resolve("x.json").toString());
    assertThat(s.exitCode()).isEqualTo(2);
    assertThat(s.err()).contains("--scenario: no such file");
  }

  @Test
  void programsLoadFromLsFiles(@TempDir Path dir) throws Exception {
    Path ls = dir.resolve("HELLO.LS");
    Files.writeString(ls, """
        /PROG  HELLO
        /ATTR
        COMMENT = "from a file";
        /MN
           1:  R[1]=7 ;
        /POS
        /END
        """);
    Path keys = dir.resolve("k.keys");
    Files.writeString(keys, "HOLD DEADMAN\nSELECT\nSHOW\nENTER\nHOLD SHIFT\nFWD\nWAIT 0.1\nRELEASE SHIFT\nDATA\nSHOW\n");
    Run r = run("pendant", "--program", ls.toString(), "--keys", keys.toString());
    assertThat(r.exitCode()).isEqualTo(0);
    assertThat(r.out()).contains("HELLO").contains("from a file").contains("R[  1:            ]  = {7}");
    Path broken = dir.resolve("BROKEN.LS");
    Files.writeString(broken, "/PROG  BROKEN\n/MN\n   1:  R[1]= ;\n/END\n");
    Run b = run("pendant", "--program", broken.toString(), "--keys", keys.toString());
    assertThat(b.exitCode()).isEqualTo(2);
    assertThat(b.err()).contains("--program: ").contains("BROKEN.LS:");
  }

  @Test
  void helpSaysWhichControllerItRunsAndHowTheScriptStarts() {
    Run r = run("pendant", "--help");
    assertThat(r.exitCode()).isEqualTo(0);
    assertThat(r.out()).contains("--keys").contains("--scenario").contains("--program").contains("--mode")
        .contains("--override").contains("--trace").contains("simulation's controller").contains("cold-started")
        .doesNotContain("--controller").doesNotContain("stand-in").contains("override 10%");
    assertThat(r.err()).isEmpty();
  }

  @Test
  void modeAndOverrideOptionsSetTheStartAndBadOnesAreExit2(@TempDir Path dir) throws Exception {
    Path keys = dir.resolve("k.keys");
    Files.writeString(keys, "SHOW\n");
    Run cold = run("pendant", "--keys", keys.toString());
    assertThat(cold.out()).contains("T1   ABORTED JOINT  10%");
    Run r = run("pendant", "--keys", keys.toString(), "--mode", "auto", "--override", "40");
    assertThat(r.exitCode()).as(r.err()).isEqualTo(0);
    assertThat(r.out()).contains("AUTO ABORTED JOINT  40%");
    // a scenario's "mode" sets the start unless --mode is given
    Path sc = dir.resolve("t2.json");
    Files.writeString(sc, Files.readString(Path.of("scenarios/empty-cell.json")).replaceFirst("\\{", "{\n  \"mode\": \"T2\","));
    assertThat(run("pendant", "--keys", keys.toString(), "--scenario", sc.toString()).out()).contains("T2   ABORTED");
    assertThat(run("pendant", "--keys", keys.toString(), "--scenario", sc.toString(), "--mode", "T1").out())
        .contains("T1   ABORTED");
    Run badMode = run("pendant", "--keys", keys.toString(), "--mode", "T3");
    assertThat(badMode.exitCode()).isEqualTo(2);
    assertThat(badMode.err()).contains("--mode: expected T1, T2 or AUTO, got 'T3'");
    Run badOverride = run("pendant", "--keys", keys.toString(), "--override", "0");
    assertThat(badOverride.exitCode()).isEqualTo(2);
    assertThat(badOverride.err()).contains("--override: expected 1..100, got 0");
  }
}
