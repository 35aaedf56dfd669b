package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.grade.TaskLoad;
import org.robotrun.grade.TaskReader;

/**
 * The one set of JSON field helpers: every message names the file, the line, the JSON path,
 * what was expected (with its range) and what was found, and hostile values (1e999, NaN, nested
 * arrays, wrong types) are refused with one such line each.
 */
class JsonFieldReaderTest {
  /** A reader of one object whose helpers the test calls directly. */
  private static final class Reader extends JsonFieldReader {
    Reader() {
      super("f.json");
    }


    double[] numbers(LocatedJson.JObject o, boolean required, double lo, double hi, int... counts) {
      return numbers(o, "a", "top", required, "[min, max]", lo, hi, counts);
    }

    int[] integers(LocatedJson.JObject o, int lo, int hi) {
      return integers(o, "a", "top", false, "[width, height]", lo, hi, 2);
    }

    List<String> messages() {
      return errors.stream().map(ScenarioError::toString).toList();
    }
  }

  private static LocatedJson.JObject obj(String json) throws Exception {
    return (LocatedJson.JObject) LocatedJson.parse(json, new ArrayList<>());
  }

  private static String syntaxError(String json) {
    try {
      LocatedJson.parse(json, new ArrayList<>());
    } catch (LocatedJson.SyntaxError e) {
      return e.line() + ": " + e.getMessage();
    }
    throw new AssertionError("parsed: " + json);
  }

  @Test
  void brokenJsonIsDescribedWithLineAndColumnAndNoneOfTheParsersInnards() {
    assertThat(syntaxError("{\"a\": [1,\n 2}"))
        .isEqualTo("2: not valid JSON at column 3: Unexpected close marker '}': expected ']' (for Array starting on line 1, column 7)");
    assertThat(syntaxError("{\"a\": tru}")).startsWith("1: not valid JSON at column 10: Unrecognized token 'tru'");
    assertThat(syntaxError("[".repeat(5000))).isEqualTo("1: not valid JSON at column 1001: nested more than 1000 levels deep");
    for (String bad : List.of("{\"a\": [1, 2}", "[".repeat(5000), "{\"a\": \"x", "{'a': 1}")) {
      assertThat(syntaxError(bad)).doesNotContain("Source").doesNotContain("REDACTED").doesNotContain("`");
    }
  }

  @Test
  void anArrayOfBoundedNumbersIsReadOrEveryBadItemIsNamed() throws Exception {
    Reader r = new Reader();
    assertThat(r.numbers(obj("{\"a\": [1, 2.5]}"), true, -10, 10, 2)).containsExactly(1, 2.5);
    assertThat(r.numbers(obj("{\"a\": [4]}"), true, 0, 10, 6, 1)).containsExactly(4);
    assertThat(r.numbers(obj("{}"), false, 0, 10, 2)).isNull();
    assertThat(r.messages()).isEmpty();

    assertThat(r.numbers(obj("{\n\"a\": [1e999,\n [2], \"3\", NaN, 11, -0.5]}"), true, 0, 10, 6)).isNull();
    assertThat(r.numbers(obj("{\"a\": [1, 2, 3]}"), true, 0, 10, 2)).isNull();
    assertThat(r.numbers(obj("{\"a\": {\"b\": 1}}"), true, 0, 10, 2)).isNull();
    assertThat(r.numbers(obj("{\"b\": 1}"), true, 0, 10, 2)).isNull();
    assertThat(r.messages()).containsExactly(
        "f.json:2: top.a[0]: expected a number 0..10, got the number 1e999",
        "f.json:3: top.a[1]: expected a number 0..10, got an array",
        "f.json:3: top.a[2]: expected a number 0..10, got a string",
        "f.json:3: top.a[3]: expected a number 0..10, got the number NaN",
        "f.json:3: top.a[4]: expected a number 0..10, got the number 11",
        "f.json:3: top.a[5]: expected a number 0..10, got the number -0.5",
        "f.json:1: top.a: expected [min, max], got an array of 3",
        "f.json:1: top.a: expected [min, max], got an object",
        "f.json:1: top.a: missing: expected [min, max]");
  }

  @Test
  void anArrayOfWholeNumbersRefusesFractionsAndHugeValues() throws Exception {
    Reader r = new Reader();
    assertThat(r.integers(obj("{\"a\": [640, 480]}"), 16, 8192)).containsExactly(640, 480);
    assertThat(r.integers(obj("{\"a\": [640.5, 1e400]}"), 16, 8192)).isNull();
    assertThat(r.messages()).containsExactly(
        "f.json:1: top.a[0]: expected a whole number 16..8192, got the number 640.5",
        "f.json:1: top.a[1]: expected a whole number 16..8192, got the number 1e400");
  }

  @Test
  void positiveAndFiniteGiveTheirRange() throws Exception {
    Reader r = new Reader();
    assertThat(r.positive(obj("{\"a\": 0.001}"), "a", "s", true, 100)).contains(0.001);
    assertThat(r.finite(obj("{\"a\": -1e300}"), "a", "s", true)).contains(-1e300);
    assertThat(r.positive(obj("{\"a\": 0}"), "a", "s", true, 100)).isEmpty();
    assertThat(r.positive(obj("{\"a\": 100.5}"), "a", "s", true, 100)).isEmpty();
    assertThat(r.positive(obj("{}"), "a", "s", true, 100)).isEmpty();
    assertThat(r.finite(obj("{\"a\": 1e999}"), "a", "s", true)).isEmpty();
    assertThat(r.finite(obj("{\"a\": [[1]]}"), "a", "s", false)).isEmpty();
    assertThat(r.finite(obj("{}"), "a", "s", false)).isEmpty();
    assertThat(r.messages()).containsExactly(
        "f.json:1: s.a: expected a number 0..100 (more than 0), got the number 0",
        "f.json:1: s.a: expected a number 0..100 (more than 0), got the number 100.5",
        "f.json:1: s.a: missing: expected a number 0..100 (more than 0)",
        "f.json:1: s.a: expected a finite number, got the number 1e999",
        "f.json:1: s.a: expected a finite number, got an array");
  }

  @Test
  void theFormatFieldIsCheckedOnceForEveryFileKind() throws Exception {
    Reader r = new Reader();
    r.format(obj("{\"format\": 1}"), 1);
    assertThat(r.messages()).isEmpty();
    for (String f : List.of("{}", "{\"format\": \"1\"}", "{\"format\": 1.0}", "{\"format\": 2}", "{\"format\": 1e999}")) {
      r.format(obj(f), 1);
    }
    assertThat(r.messages()).containsExactly(
        "f.json:1: format: missing: expected \"format\": 1",
        "f.json:1: format: expected the integer 1, got a string",
        "f.json:1: format: expected the integer 1, got the number 1.0",
        "f.json:1: format: unsupported format 2: this RobotRun reads format 1",
        "f.json:1: format: expected the integer 1, got the number 1e999");
  }

  @Test
  void aScenarioNamesRangesForJointsCameraIoAndRegisters(@TempDir Path tmp) throws Exception {
    Path f = tmp.resolve("s.json");
    Files.writeString(f, """
        {
          "format": 1,
          "robots": [{"name": "robot1", "model": "lrmate200id", "jointsDeg": [0, 0, 0, 0, 0],
                      "io": {"DO": 0}, "tool": {"x": 0, "y": 0, "z": 0}, "registers": {"3": "x"}}],
          "camera": {"target": {"x": 0, "y": 0, "z": 1e999}, "distance": 0, "pitchDeg": 90, "yawDeg": [0]}
        }
        """);
    assertThat(((ScenarioLoad.Failed) ScenarioReader.read(f)).errors()).extracting(ScenarioError::toString)
        .contains(
            f + ":3: robots[0].jointsDeg: expected an array of 6 joint angles (degrees), got an array of 5",
            f + ":4: robots[0].io.DO: expected a whole number 1..4096, got the number 0",
            f + ":4: robots[0].registers.3: expected a finite number, got a string",
            f + ":5: camera.target.z: expected a number -100000..100000, got the number 1e999",
            f + ":5: camera.distance: expected a number 0..100000 (more than 0), got the number 0",
            f + ":5: camera.yawDeg: expected a number -36000..36000, got an array",
            f + ":5: camera.pitchDeg: expected a number -89..89, got the number 90");
  }

  @Test
  void aTaskNamesItsFormatAndItsVisionSeedSwitchLikeTheScenario(@TempDir Path tmp) throws Exception {
    Files.copy(Path.of("scenarios/empty-cell.json"), tmp.resolve("cell.json"));
    Path t = tmp.resolve("t.task.json");
    Files.writeString(t, """
        {"format": 1.5, "scenario": "cell.json", "program": "MAIN",
         "variations": {"count": 1, "varyVisionSeed": 1},
         "checks": [{"name": "s", "type": "endState", "points": 1, "values": {"R[1]": [1], "DO[1]": 1}}]}
        """);
    assertThat(((TaskLoad.Failed) TaskReader.read(t)).errors()).extracting(ScenarioError::toString).containsExactly(
        t + ":1: format: expected the integer 1, got the number 1.5",
        t + ":2: variations.varyVisionSeed: expected true or false, got the number 1",
        t + ":3: checks[0].values.R[1]: expected a finite number, got an array",
        t + ":3: checks[0].values.DO[1]: expected true or false, got the number 1");
  }
}
