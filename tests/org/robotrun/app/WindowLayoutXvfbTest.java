package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The real window on a virtual X display (xvfb-run), in a child JVM ({@link WindowProbe}): at
 * 1024×640, 1366×768 and 1920×1080, and after shrinking and growing again, every pendant key lies
 * inside the window and inside the pendant's column, and no panel covers the robot's projected
 * bounding box at start; and a box added by clicking "Add box" is in the scenario saved by clicking
 * "Save". Outside CI the test skips, saying so, when xvfb-run or xdotool is missing; in CI
 * ({@code CI=true}) it never skips.
 */
class WindowLayoutXvfbTest {
  private static final double TOLERANCE_PX = 0.5;

  /** One window run serves both tests: starting a JVM on an X server is the slow part. */
  private static List<String> lines;
  /** The same at a UI scale of 2 (ROBOTRUN_UI_SCALE, as a HiDPI screen's content scale would give). */
  private static List<String> scaled;
  private static Path dir;

  @BeforeAll
  static void runTheWindowOnce(@TempDir Path tmp) throws Exception {
    needsXvfb();
    dir = tmp;
    lines = probe(tmp.resolve("1"), Map.of(), "1920x1080", "1024x640", "1366x768", "1920x1080", "1024x640", "1920x1080",
        "--add-box");
    scaled = probe(tmp.resolve("2"), Map.of("ROBOTRUN_UI_SCALE", "2"), "2800x1600", "2048x1280", "2732x1536");
  }

  static void needsXvfb() {
    boolean have = onPath("xvfb-run") && onPath("xdotool") && onPath("xauth");
    if (!have) {
      if ("true".equals(System.getenv("CI"))) {
        throw new AssertionError("CI must run the window tests, but xvfb-run, xauth or xdotool is missing (.ci/run installs them)");
      }
      Assumptions.abort("skipped: xvfb-run, xauth or xdotool is not installed (apt-get install xvfb xauth xdotool)");
    }
  }

  private static boolean onPath(String tool) {
    for (String dir : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
      if (Files.isExecutable(Path.of(dir, tool))) {
        return true;
      }
    }
    return false;
  }

  private static List<String> probe(Path tmp, Map<String, String> env, String screen, String... args)
      throws IOException, InterruptedException {
    Files.createDirectories(tmp);
    Path out = tmp.resolve("probe.txt");
    Path scenario = Path.of("scenarios/pick-and-place.json").toAbsolutePath();
    Path copy = tmp.resolve("pick-and-place.json");
    Files.copy(scenario, copy);
    Files.createDirectories(tmp.resolve("programs"));
    try (var ls = Files.list(scenario.getParent().resolve("programs"))) {
      for (Path p : ls.toList()) {
        Files.copy(p, tmp.resolve("programs").resolve(p.getFileName()));
      }
    }
    List<String> cmd = new ArrayList<>(List.of("xvfb-run", "-a", "-s", "-screen 0 " + screen + "x24",
        Path.of(System.getProperty("java.home"), "bin", "java").toString(), "--enable-native-access=ALL-UNNAMED",
        "-cp", System.getProperty("java.class.path"), WindowProbe.class.getName(),
        out.toString(), copy.toString(), tmp.resolve("config").toString()));
    cmd.addAll(List.of(args));
    ProcessBuilder pb = new ProcessBuilder(cmd);
    pb.environment().remove("ROBOTRUN_UI_SCALE");
    pb.environment().putAll(env);
    Process p = pb.redirectErrorStream(true).redirectOutput(tmp.resolve("log.txt").toFile()).start();
    if (!p.waitFor(120, TimeUnit.SECONDS)) {
      p.destroyForcibly();
      throw new AssertionError("the window probe did not finish in 120 s: " + Files.readString(tmp.resolve("log.txt")));
    }
    assertThat(p.exitValue()).as(Files.readString(tmp.resolve("log.txt"))).isZero();
    List<String> lines = Files.readAllLines(out, StandardCharsets.UTF_8);
    if (System.getenv("ROBOTRUN_PROBE_PRINT") != null) {
      lines.forEach(System.out::println);
    }
    return lines;
  }

  /** One recorded size: name → numbers. */
  private static List<Map<String, double[]>> sizes(List<String> lines) {
    List<Map<String, double[]>> out = new ArrayList<>();
    Map<String, double[]> cur = null;
    for (String l : lines) {
      String[] f = l.split(" ");
      if (f[0].equals("size")) {
        cur = new LinkedHashMap<>();
        out.add(cur);
      }
      if (cur == null || f[0].equals("objects") || f[0].equals("message")) {
        continue;
      }
      String key = f[0].equals("key") ? "key " + f[1] + " " + cur.size() : f[0];
      int from = f[0].equals("key") ? 2 : 1;
      double[] v = new double[f.length - from];
      for (int i = from; i < f.length; i++) {
        v[i - from] = f[i].matches("-?[0-9.]+") ? Double.parseDouble(f[i]) : Double.NaN;
      }
      cur.put(key, v);
    }
    return out;
  }

  @Test
  void atEverySizeThePendantFitsAndNoPanelCoversTheRobot() {
    var recorded = sizes(lines);
    assertThat(recorded).hasSize(5);
    checkLayouts(recorded);
    // the first-start card is open at start (a fresh settings folder), docked under the view
    double[] card = recorded.get(0).get("card");
    double[] view = recorded.get(0).get("view");
    assertThat(card[2]).as("first-start card width").isPositive();
    assertThat(card[1]).as("card starts where the view ends").isGreaterThanOrEqualTo(view[1] + view[3] - TOLERANCE_PX);
  }

  @Test
  void atUiScaleTwoEverythingFitsAndIsTwiceAsLarge() {
    var recorded = sizes(scaled);
    assertThat(recorded).hasSize(2);
    checkLayouts(recorded);
    // same window in half the pixels per unit: the pendant's natural width doubles with the font
    double one = sizes(lines).get(2).get("pendant")[2];
    double two = recorded.get(1).get("pendant")[2];
    assertThat(two).as("pendant width at scale 2 vs 1").isBetween(1.8 * one, 2.2 * one);
  }

  private static void checkLayouts(List<Map<String, double[]>> recorded) {
    for (Map<String, double[]> s : recorded) {
      double[] size = s.get("size");
      double w = size[0], h = size[1];
      assertThat(new double[] {w, h}).as("window size").containsExactly(size[3], size[4]);
      double[] pendant = s.get("pendant");
      double[] robot = s.get("robot");
      double[] view = s.get("view");
      long keys = s.keySet().stream().filter(k -> k.startsWith("key ")).count();
      assertThat(keys).as("pendant keys drawn at %sx%s", w, h).isGreaterThanOrEqualTo(60);
      for (var e : s.entrySet()) {
        if (!e.getKey().startsWith("key ")) {
          continue;
        }
        double[] k = e.getValue();
        String what = e.getKey() + " at " + w + "x" + h;
        assertThat(k[0]).as(what + " left").isGreaterThanOrEqualTo(pendant[0] - TOLERANCE_PX);
        assertThat(k[1]).as(what + " top").isGreaterThanOrEqualTo(pendant[1] - TOLERANCE_PX);
        assertThat(k[0] + k[2]).as(what + " right").isLessThanOrEqualTo(Math.min(w, pendant[0] + pendant[2]) + TOLERANCE_PX);
        assertThat(k[1] + k[3]).as(what + " bottom").isLessThanOrEqualTo(Math.min(h, pendant[1] + pendant[3]) + TOLERANCE_PX);
      }
      // the robot's projected box lies in the 3D view, which no panel overlaps
      String at = " at " + w + "x" + h + ": robot " + java.util.Arrays.toString(robot) + " view " + java.util.Arrays.toString(view);
      assertThat(robot[0]).as("robot left" + at).isGreaterThanOrEqualTo(view[0]);
      assertThat(robot[1]).as("robot top" + at).isGreaterThanOrEqualTo(view[1]);
      assertThat(robot[0] + robot[2]).as("robot right" + at).isLessThanOrEqualTo(view[0] + view[2]);
      assertThat(robot[1] + robot[3]).as("robot bottom" + at).isLessThanOrEqualTo(view[1] + view[3]);
      double[] side = s.get("sidebar");
      assertThat(side[0] + side[2]).as("side column ends where the view starts").isLessThanOrEqualTo(view[0] + TOLERANCE_PX);
      assertThat(view[0] + view[2]).as("view ends where the pendant starts").isLessThanOrEqualTo(pendant[0] + TOLERANCE_PX);
      assertThat(view[2]).as("3D view width").isGreaterThanOrEqualTo(0.35 * w - 1);
      double[] card = s.get("card");
      boolean overlaps = card[2] > 0 && card[0] < robot[0] + robot[2] && robot[0] < card[0] + card[2]
          && card[1] < robot[1] + robot[3] && robot[1] < card[1] + card[3];
      assertThat(overlaps).as("first-start card " + java.util.Arrays.toString(card) + " covers the robot" + at).isFalse();
    }
  }

  @Test
  void aBoxAddedByClicksIsInTheSavedScenario() throws IOException {
    assertThat(lines).contains("objects table,tray,part1,part2,part3,box1");
    Path saved = dir.resolve("1").resolve("pick-and-place-edited.json");
    assertThat(saved).exists();
    String json = Files.readString(saved);
    assertThat(json).contains("\"name\" : \"box1\"").contains("\"shape\" : \"box\"");
    assertThat(lines.stream().filter(l -> l.startsWith("message ")).findFirst().orElse("")).contains("saved");
  }
}
