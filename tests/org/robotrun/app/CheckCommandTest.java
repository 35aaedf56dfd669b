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
    assertThat(r.out()).isEqualTo(PROGRAMS + "PICK3.LS:44: CALL BEEP: no program named BEEP is known\n");
    assertThat(r.err()).isEmpty();
  }

  @Test
  void pick3WithTheProgramItCallsIsClean() {
    Run r = run("check", PROGRAMS + "PICK3.LS", PROGRAMS + "BEEP.LS");
    assertThat(r.out()).isEmpty();
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
        bad + ":7: LBL[4] is not defined in this program");
    assertThat(run("check", "--quiet", bad.toString()).out()).doesNotContain("warning");
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
    assertThat(directory.err()).contains(dir + ": cannot read: is a directory");

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
    assertThat(r.out()).contains("file:line: message", "--known", "--quiet", "Exit codes:", "2   a file could not be read");
  }

  @Test
  void benchParsePrintsLinesPerSecond() {
    Run r = run("bench", "parse", "--lines", "200", "--rounds", "2", "--warmup", "1");
    assertThat(r.exit()).isEqualTo(0);
    assertThat(r.out()).matches("lines_per_sec=\\d+ lines_per_cpu_sec=\\d+ lines=200 rounds=2 best_ms=\\S+ mean_ms=\\S+ best_cpu_ms=\\S+\\n");
  }
}
