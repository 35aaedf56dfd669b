package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code robotrun bench interp} prints its figure and refuses bad options with exit 2. */
class BenchInterpCommandTest {

  private static String[] run(String... args) {
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    CommandLine cl = Main.commandLine();
    cl.setOut(new PrintWriter(out, true));
    cl.setErr(new PrintWriter(err, true));
    int exit = cl.execute(args);
    return new String[] {Integer.toString(exit), out.toString(), err.toString()};
  }

  @Test
  void printsInstructionsPerSecond() {
    String[] r = run("bench", "interp", "--seconds", "0.05", "--warmup-seconds", "0", "--loops", "100");
    assertThat(r[0]).isEqualTo("0");
    assertThat(r[1]).startsWith("instructions_per_sec=").contains(" loops_per_run=100 ");
    assertThat(r[2]).isEmpty();
  }

  @Test
  void badOptionsExitWithTwo() {
    String[] r = run("bench", "interp", "--seconds", "0");
    assertThat(r[0]).isEqualTo("2");
    assertThat(r[2]).startsWith("robotrun: --seconds must be > 0");
    assertThat(run("bench", "interp", "--loops", "many")[0]).isEqualTo("2");
  }
}
