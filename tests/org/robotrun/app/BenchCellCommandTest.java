package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class BenchCellCommandTest {
  private record Run(int exit, String out, String err) {}

  private static Run run(String... args) {
    CommandLine cl = Main.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(err));
    int exit = cl.execute(args);
    return new Run(exit, out.toString(), err.toString());
  }

  @Test
  void printsCycleTimeAndCollisionCostPerTick() {
    Run r = run("bench", "cell", "--scenario", "scenarios/pick-and-place.json", "--repeats", "1");
    assertThat(r.exit()).as(r.err()).isZero();
    assertThat(r.out()).startsWith("scenario=pick-and-place.json program=PICKPLACE cycle_s=")
        .contains("ticks=").contains("collision_us_per_tick=");
  }

  @Test
  void aCellOfTwoRobotsRunsBothMainPrograms() {
    Run r = run("bench", "cell", "--scenario", "scenarios/two-robot-handshake.json", "--repeats", "1");
    assertThat(r.exit()).as(r.err()).isZero();
    assertThat(r.out()).startsWith("scenario=two-robot-handshake.json program=LOADER+UNLOADER cycle_s=");
    // The bench's cycle is the cell's cycle as `robotrun run` reports it for the same scenario (not a figure
    // copied from an earlier run): both commands must agree to the millisecond.
    java.util.regex.Matcher m = java.util.regex.Pattern.compile("cycle_s=([0-9.]+) ").matcher(r.out());
    assertThat(m.find()).as(r.out()).isTrue();
    assertThat(Double.parseDouble(m.group(1))).isEqualTo(runCycleSec("scenarios/two-robot-handshake.json"), org.assertj.core.data.Offset.offset(0.0005));
  }

  /** The cell cycle time `robotrun run --scenario FILE --report` reports. */
  private static double runCycleSec(String scenario) {
    try {
      java.nio.file.Path dir = java.nio.file.Files.createTempDirectory("bench-cell");
      java.nio.file.Path report = dir.resolve("r.json");
      assertThat(Main.execute("run", "--scenario", scenario, "--report", report.toString())).isZero();
      double t = new com.fasterxml.jackson.databind.ObjectMapper().readTree(report.toFile()).get("cycleTimeSec").asDouble();
      java.nio.file.Files.delete(report);
      java.nio.file.Files.delete(dir);
      return t;
    } catch (java.io.IOException e) {
      throw new java.io.UncheckedIOException(e);
    }
  }

  @Test
  void aCellThePlcStartsRunsAsRunDoesIt() {
    // plc-cell's PLC selects and starts PNS0001 (runStartsFromPlc): bench cell starting it too failed with INTP-105
    Run r = run("bench", "cell", "--scenario", "scenarios/plc-cell.json", "--repeats", "1");
    assertThat(r.exit()).as(r.err()).isZero();
    assertThat(r.out()).startsWith("scenario=plc-cell.json program=PLC cycle_s=");
  }

  @Test
  void scenarioWithoutMainProgramIsBadInput() {
    Run r = run("bench", "cell", "--scenario", "scenarios/empty-cell.json", "--repeats", "1");
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).contains("mainProgram");
  }
}
