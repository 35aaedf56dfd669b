package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import org.robotrun.render.GlTestSupport;
import picocli.CommandLine;

class BenchRenderCommandTest {
  private record Run(int code, String out, String err) {}

  private static Run run(String... args) {
    CommandLine cl = Main.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(err));
    int code = cl.execute(args);
    return new Run(code, out.toString(), err.toString());
  }

  @Test
  void printsOneLineOfFiguresForEachSmoothingMode() {
    GlTestSupport.rendererOrSkip(16, 16).close();
    for (String mode : new String[] {"NONE", "FXAA", "MSAA4"}) {
      Run r = run("bench", "render", "--width", "64", "--height", "48", "--seconds", "0.05", "--antialias", mode);
      assertThat(r.code()).as(mode + ": " + r.err()).isZero();
      assertThat(r.out()).as(mode).matches("fps=[0-9.]+ frames=[1-9][0-9]* seconds=[0-9.]+ width=64 height=48 antialias="
          + mode.toLowerCase() + " median_frame_ms=[0-9.]+ cpu_ms_per_frame=[0-9.]+\\R");
    }
  }

  @Test
  void defaultsToTheSmoothingRobotrunRenderUses() {
    GlTestSupport.rendererOrSkip(16, 16).close();
    Run r = run("bench", "render", "--width", "64", "--height", "48", "--seconds", "0.05");
    assertThat(r.code()).as(r.err()).isZero();
    assertThat(r.out()).contains("antialias=fxaa");
  }

  @Test
  void unknownSmoothingModeIsExit2NamingTheChoices() {
    Run r = run("bench", "render", "--antialias", "SSAA");
    assertThat(r.code()).isEqualTo(2);
    assertThat(r.err()).contains("--antialias").contains("NONE").contains("FXAA").contains("MSAA4").doesNotContain("\tat ");
  }
}
