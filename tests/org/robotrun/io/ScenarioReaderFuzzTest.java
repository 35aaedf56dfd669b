package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.lifecycle.AfterContainer;
import net.jqwik.api.lifecycle.BeforeContainer;

/**
 * Fuzzing the scenario reader (issue 18): mutations of a valid scenario (cut, spliced bytes,
 * odd numbers and names, deep nesting, duplicated members) must give a scenario or a list of
 * errors naming the file, never an exception. The quick property runs in every build with a
 * fixed seed; {@link ScenarioReaderFuzzCampaign} is the long campaign ({@code -Pfuzz}, docs/fuzzing.md).
 */
class ScenarioReaderFuzzTest {
  private static Path dir;

  @BeforeContainer
  static void makeDir() throws Exception {
    dir = Files.createTempDirectory("scenario-fuzz");
    Files.writeString(dir.resolve("m.stl"), "solid m\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
        + "vertex 0 1 0\nendloop\nendfacet\nendsolid m\n");
  }

  @AfterContainer
  static void removeDir() throws Exception {
    try (var s = Files.walk(dir)) {
      s.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
    }
  }

  static final String VALID = """
      {"format": 1, "name": "fuzz", "onCollision": "alarm",
       "robots": [{"name": "robot1", "model": "lrmate200id", "endEffector": "gripper",
                   "basePose": {"x": 0, "y": 0, "z": -330, "w": 0, "p": 0, "r": 0},
                   "jointsDeg": [0, 0, 0, 0, -90, 0], "toolIo": {"output": "RO[1]"}}],
       "objects": [
         {"name": "table", "kind": "fixture", "shape": "box", "size": {"x": 400, "y": 700, "z": 230},
          "pose": {"x": 420, "y": 0, "z": -330}, "color": "#806040"},
         {"name": "part1", "kind": "part", "shape": "cylinder", "radius": 20, "height": 40,
          "pose": {"x": 0, "y": 100, "z": 230}, "parent": "table"},
         {"name": "mesh", "kind": "fixture", "shape": "mesh", "file": "m.stl", "scale": 1,
          "pose": {"x": 0, "y": -300, "z": 0}}],
       "registers": {"R": {"1": 5}},
       "camera": {"target": {"x": 0, "y": 0, "z": 0}, "distance": 2000, "yawDeg": 30, "pitchDeg": 20}}
      """;

  /** Pieces a hostile or careless author might put anywhere. */
  private static final List<String> PIECES = List.of(
      "0x1p3", "1d", "1e999", "-1e308", "NaN", "Infinity", "null", "\"\"", "\"\\u001b[2J\"", "[", "]", "{", "}",
      ",", ":", "\"parent\": \"part1\"", "\"parent\": \"table\"", "\"name\": \"table\"", "\"x\": ", "1e30",
      "\"file\": \"/dev/zero\"", "\"file\": \".\"", "\"file\": \"../../../../etc/passwd\"", "\"A" + "x".repeat(300) + "\"",
      "[".repeat(2000), "{\"a\":".repeat(500), "\uFEFF", "\u0000", "\"\\ud800\"", "-0", "99999999999999999999",
      "\"kind\": \"part\"", "\"shape\": \"mesh\"", "\"format\": 2", "true");

  @Provide
  Arbitrary<byte[]> mutated() {
    Arbitrary<Integer> at = Arbitraries.integers().between(0, VALID.length());
    Arbitrary<String> piece = Arbitraries.oneOf(Arbitraries.of(PIECES),
        Arbitraries.strings().ofMaxLength(12), Arbitraries.strings().withCharRange('\u0000', '\u00ff').ofMaxLength(6));
    Arbitrary<String> splice = Combinators.combine(at, at, piece).as((a, b, p) -> {
      int lo = Math.min(a, b);
      int hi = Math.min(Math.max(a, b), lo + 40);
      return VALID.substring(0, lo) + p + VALID.substring(hi);
    });
    Arbitrary<String> twice = Combinators.combine(splice, at, at).as((s, a, b) -> {
      int lo = Math.min(Math.min(a, b), s.length());
      return s.substring(0, lo) + s.substring(Math.min(Math.max(a, b), s.length()));
    });
    Arbitrary<String> cut = at.map(n -> VALID.substring(0, n));
    Arbitrary<byte[]> text = Arbitraries.oneOf(splice, twice, cut).map(s -> s.getBytes(StandardCharsets.UTF_8));
    Arbitrary<byte[]> flipped = Combinators.combine(at, Arbitraries.bytes()).as((n, b) -> {
      byte[] v = VALID.getBytes(StandardCharsets.UTF_8);
      v[Math.min(n, v.length - 1)] = b;
      return v;
    });
    return Arbitraries.frequencyOf(
        net.jqwik.api.Tuple.of(6, text), net.jqwik.api.Tuple.of(1, flipped));
  }

  @Property(seed = "18", tries = 200)
  void mutatedScenariosGiveAScenarioOrErrorsNeverAnException(@ForAll("mutated") byte[] content) throws Exception {
    check(content);
  }

  static void check(byte[] content) throws Exception {
    Path f = dir.resolve("s.json");
    Files.write(f, content);
    ScenarioLoad load = ScenarioReader.read(f);
    if (load instanceof ScenarioLoad.Failed failed) {
      assertThat(failed.errors()).isNotEmpty();
      for (ScenarioError e : failed.errors()) {
        assertThat(e.toString()).startsWith(f.toString());
        assertThat(e.line()).isNotNegative();
      }
    }
  }
}
