package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class BenchVisionCommandTest {
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
  void printsTheCostOfOneRunFindWithEveryPartInView() {
    Run r = run("bench", "vision", "--parts", "50", "--repeat", "5");
    assertThat(r.exit()).as(r.err()).isZero();
    Matcher m = Pattern.compile("parts=50 found=(\\d+) run_find_us=[0-9.]+ p90_us=[0-9.]+\\n").matcher(r.out());
    assertThat(m.matches()).as(r.out()).isTrue();
    // 1 % misses: nearly all 50 are found in one RUN_FIND
    assertThat(Integer.parseInt(m.group(1))).isBetween(45, 50);
  }

  @Test
  void aPartCountOutOfRangeIsBadInput() {
    Run r = run("bench", "vision", "--parts", "0");
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).contains("--parts must be 1..100");
  }
}
