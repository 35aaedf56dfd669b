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
    assertThat(r.out()).startsWith("scenario=two-robot-handshake.json program=LOADER+UNLOADER cycle_s=10.304 ");
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
