package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** What {@code bench window} decides before any window opens, and how it reads /proc. */
class BenchWindowCommandTest {
  private static String[] run(String... args) {
    CommandLine cl = Main.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(err));
    int code = cl.execute(args);
    return new String[] {String.valueOf(code), out.toString(), err.toString()};
  }

  @Test
  void theWindowsJvmGetsTheseOptionsButNotTheSharedArchiveOrARecordingOrADebugger() {
    List<String> mine = List.of("--enable-native-access=ALL-UNNAMED", "-XX:+AutoCreateSharedArchive",
        "-XX:SharedArchiveFile=target/robotrun-jdk25.jsa", "-Xlog:cds*=off", "-Xlog:aot*=off",
        "-XX:StartFlightRecording=filename=a.jfr", "-agentlib:jdwp=transport=dt_socket", "-Xmx2g");
    assertThat(BenchWindowCommand.childJvmOptions(mine, null))
        .containsExactly("--enable-native-access=ALL-UNNAMED", "-Xmx2g");
    assertThat(BenchWindowCommand.childJvmOptions(List.of("-Xmx2g"), "  -XX:+FlightRecorder  -Dx=1 "))
        .containsExactly("-Xmx2g", "-XX:+FlightRecorder", "-Dx=1");
  }

  @Test
  void readsUserAndSystemTicksEvenWhenTheThreadNameHoldsSpacesAndParentheses() {
    String stat = "4242 (llvm pipe) (0) S 1 4242 4242 0 -1 4194368 100 0 0 0 17 5 0 0 20 0 3 0 100 0 0";
    assertThat(ProcessCpu.userAndSystemTicks(stat)).isEqualTo(22);
  }

  @Test
  void refusesBadSizesAndTimesBeforeOpeningAWindow() {
    String[] r = run("bench", "window", "--seconds", "0");
    assertThat(r[0]).isEqualTo("2");
    assertThat(r[2]).contains("--seconds: expected more than 0 and at most 600, got 0");
    r = run("bench", "window", "--width", "5");
    assertThat(r[0]).isEqualTo("2");
    assertThat(r[2]).contains("--width");
    r = run("bench", "window", "--scenario", "no/such/file.json");
    assertThat(r[0]).isEqualTo("2");
    assertThat(r[2]).contains("no such file");
    r = run("bench", "window", "--scenario", "scenarios/pick-and-place.json", "--program", "nosuch");
    assertThat(r[0]).isEqualTo("2");
    assertThat(r[2]).contains("--program: ").contains("has no program NOSUCH (it has PICKPLACE)");
  }
}
