package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.render.GlTestSupport;
import picocli.CommandLine;

/** run --seed, render --vision-camera / --vision-find on the vision lab. */
class VisionCommandsTest {
  static final String LAB = "scenarios/vision-pick.json";

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

  static JsonNode report(Path dir, String seed) throws Exception {
    Path r = dir.resolve("r" + seed + ".json");
    assertThat(Main.execute("run", "--scenario", LAB, "--seed", seed, "--report", r.toString())).isZero();
    return new ObjectMapper().readTree(r.toFile());
  }

  @Test
  void theSeedChangesTheRunAndTheSameSeedRepeatsIt(@TempDir Path dir) throws Exception {
    JsonNode a = report(dir, "11");
    JsonNode b = report(dir, "11");
    JsonNode c = report(dir, "12");
    assertThat(a.get("status").asText()).isEqualTo("finished");
    for (JsonNode p : a.get("parts")) {
      assertThat(p.get("parent").asText()).isEqualTo("tray");
    }
    // the same seed: the same run to the last register and time; another seed: another path
    assertThat(a.get("robots")).isEqualTo(b.get("robots"));
    assertThat(a.get("simTimeSec")).isEqualTo(b.get("simTimeSec"));
    assertThat(a.get("robots").get(0).get("registers").get("PR").get("7"))
        .isNotEqualTo(c.get("robots").get(0).get("registers").get("PR").get("7"));
  }

  @Test
  void aSeedForAScenarioWithoutVisionWarns(@TempDir Path dir) {
    // run prints its warnings on the process's stderr, as its other warnings
    java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
    java.io.PrintStream was = System.err;
    System.setErr(new java.io.PrintStream(bytes, true, java.nio.charset.StandardCharsets.UTF_8));
    Run r;
    try {
      r = run("run", "--scenario", "scenarios/pick-and-place.json", "--seed", "3", "--report",
          dir.resolve("r.json").toString());
    } finally {
      System.setErr(was);
    }
    assertThat(r.exitCode()).isZero();
    assertThat(bytes.toString(java.nio.charset.StandardCharsets.UTF_8)).contains("--seed").contains("has no vision section");
  }

  @Test
  void renderingAVisionCameraNeedsAScenarioAndAKnownCamera(@TempDir Path dir) {
    String out = dir.resolve("cam.png").toString();
    Run none = run("render", "--out", out, "--vision-camera", "CAM1");
    assertThat(none.exitCode()).isEqualTo(2);
    assertThat(none.err()).contains("--vision-camera: needs --scenario");
    Run unknown = run("render", "--out", out, "--scenario", LAB, "--vision-camera", "CAM9");
    assertThat(unknown.exitCode()).isEqualTo(2);
    assertThat(unknown.err()).contains("no camera named 'CAM9'").contains("cameras: CAM1");
    Run process = run("render", "--out", out, "--scenario", LAB, "--vision-camera", "CAM1", "--vision-find", "NOPE");
    assertThat(process.exitCode()).isEqualTo(2);
    assertThat(process.err()).contains("--vision-find: no vision process named 'NOPE'");
  }

  @Test
  void renderingAVisionCameraWritesItsImageAndPrintsWhatWasFound(@TempDir Path dir) throws Exception {
    GlTestSupport.rendererOrSkip(16, 16).close();
    Path out = dir.resolve("cam.png");
    Run r = run("render", "--out", out.toString(), "--scenario", LAB, "--vision-camera", "CAM1", "--vision-find",
        "find_blocks", "--seed", "4");
    assertThat(r.exitCode()).as(r.err()).isZero();
    assertThat(r.out()).startsWith("FIND_BLOCKS found ");
    assertThat(r.out().lines().filter(l -> l.startsWith("  block"))).isNotEmpty().allMatch(l -> l.contains("found UF[1]"));
    var img = javax.imageio.ImageIO.read(out.toFile());
    // the camera's image size
    assertThat(img.getWidth()).isEqualTo(640);
    assertThat(img.getHeight()).isEqualTo(480);
    // the found blocks are outlined in bright green
    int green = 0;
    for (int y = 0; y < img.getHeight(); y++) {
      for (int x = 0; x < img.getWidth(); x++) {
        int rgb = img.getRGB(x, y);
        int rr = rgb >> 16 & 0xFF;
        int g = rgb >> 8 & 0xFF;
        int b = rgb & 0xFF;
        if (g > 180 && rr < 120 && b < 120) {
          green++;
        }
      }
    }
    assertThat(green).isGreaterThan(50);
  }
}
