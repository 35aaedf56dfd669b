package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.render.GlTestSupport;
import picocli.CommandLine;

class RenderCommandTest {

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
  void missingOutputDirectoryIsAOneLineErrorWithExitCode2(@TempDir Path dir) {
    Run r = run("render", "--out", dir.resolve("no/such/dir/shot.png").toString());
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.err().strip().lines()).hasSize(1);
    assertThat(r.err()).contains("--out").contains("does not exist").doesNotContain("Exception").doesNotContain("\tat ");
  }

  @Test
  void badJointValuesAreOneLineErrorsWithExitCode2(@TempDir Path dir) {
    String out = dir.resolve("shot.png").toString();
    for (String joints : new String[] {"1,2,3", "0,0,0,0,0,x", "0,0,0,0,0,NaN", "0,0,0,0,0,0,0", "400,0,0,0,0,0"}) {
      Run r = run("render", "--out", out, "--joints", joints);
      assertThat(r.exitCode()).as(joints).isEqualTo(2);
      assertThat(r.err().strip().lines()).as(joints).hasSize(1);
      assertThat(r.err()).as(joints).startsWith("robotrun: --joints").doesNotContain("\tat ");
    }
    assertThat(Files.exists(Path.of(out))).isFalse();
  }

  @Test
  void unknownOptionExitsWith2AndPointsToHelp() {
    Run r = run("render", "--out", "x.png", "--bogus");
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.err()).contains("--bogus").contains("--help");
  }

  @Test
  void rendersThePngAtTheRequestedSize(@TempDir Path dir) throws Exception {
    // Probe first so a machine without OpenGL skips (outside CI) rather than fails.
    GlTestSupport.rendererOrSkip(16, 16).close();
    Path out = dir.resolve("arm.png");
    Run r = run("render", "--out", out.toString(), "--width", "200", "--height", "120", "--joints", "90,10,-10,0,-30,0");
    assertThat(r.exitCode()).as(r.err()).isZero();
    var img = javax.imageio.ImageIO.read(out.toFile());
    assertThat(img.getWidth()).isEqualTo(200);
    assertThat(img.getHeight()).isEqualTo(120);
  }

  @Test
  void showBoxesTurnsTouchingBoxesRed(@TempDir Path dir) throws Exception {
    GlTestSupport.rendererOrSkip(16, 16).close();
    Path free = dir.resolve("free.png");
    Path hit = dir.resolve("hit.png");
    Run a = run("render", "--scenario", "scenarios/pick-and-place.json", "--show-boxes", "--out", free.toString(),
        "--width", "300", "--height", "200");
    // The gripper pushed down into the table.
    Run b = run("render", "--scenario", "scenarios/pick-and-place.json", "--show-boxes", "--joints", "0,50,-50,0,-80,0",
        "--out", hit.toString(), "--width", "300", "--height", "200");
    assertThat(a.exitCode()).as(a.err()).isZero();
    assertThat(b.exitCode()).as(b.err()).isZero();
    // Strong red pixels: the small red part only when free; the table and gripper when touching.
    assertThat(redPixels(hit)).isGreaterThan(10 * Math.max(1, redPixels(free)));
  }

  @Test
  void showBoxesNeedsAScenario(@TempDir Path dir) {
    Run r = run("render", "--show-boxes", "--out", dir.resolve("x.png").toString());
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.err()).contains("--show-boxes").contains("--scenario");
  }

  private static int redPixels(Path png) throws Exception {
    var img = javax.imageio.ImageIO.read(png.toFile());
    int n = 0;
    for (int y = 0; y < img.getHeight(); y++) {
      for (int x = 0; x < img.getWidth(); x++) {
        int rgb = img.getRGB(x, y);
        int r = rgb >> 16 & 0xFF, g = rgb >> 8 & 0xFF, bl = rgb & 0xFF;
        n += r > 180 && g < 70 && bl < 70 ? 1 : 0;
      }
    }
    return n;
  }

  @Test
  void rendersEveryExampleScenario(@TempDir Path dir) throws Exception {
    GlTestSupport.rendererOrSkip(16, 16).close();
    try (var files = Files.list(Path.of("scenarios"))) {
      for (Path sc : files.filter(p -> p.toString().endsWith(".json")).toList()) {
        Path out = dir.resolve(sc.getFileName() + ".png");
        Run r = run("render", "--scenario", sc.toString(), "--out", out.toString(), "--width", "160", "--height", "100");
        assertThat(r.exitCode()).as(sc + ": " + r.err()).isZero();
        assertThat(Files.size(out)).isPositive();
      }
    }
  }

  @Test
  void brokenScenarioIsAnErrorNamingFileLineAndField(@TempDir Path dir) throws Exception {
    Path bad = dir.resolve("bad.json");
    Files.writeString(bad, "{\n  \"format\": 1,\n  \"robots\": \"nope\"\n}\n");
    Run r = run("render", "--scenario", bad.toString(), "--out", dir.resolve("x.png").toString());
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.err()).contains("bad.json").contains("robots").doesNotContain("\tat ");
    assertThat(Files.exists(dir.resolve("x.png"))).isFalse();
  }
}
