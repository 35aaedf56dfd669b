package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.Scenario;

/** Every robot of a cell can be given registers, frames and a mode, not only the first. */
class ScenarioPerRobotTest {
  @TempDir Path dir;

  private static final String CELL = """
      {
        "format": 1,
        "robots": [
          {"name": "left", "model": "lrmate200id"},
          {"name": "right", "model": "lrmate200id", "basePose": {"x": 900, "y": 0, "z": 0},
           "registers": {"5": 7, "6": 2.5},
           "frames": {"tool": {"1": {"x": 0, "y": 0, "z": 120, "w": 0, "p": 0, "r": 0}},
                      "user": {"2": {"x": 400, "y": -100, "z": 0, "w": 0, "p": 0, "r": 90}}},
           "mode": "AUTO"}
        ],
        "objects": [],
        "registers": {"1": 3},
        "frames": {"user": {"1": {"x": 300, "y": 0, "z": 0, "w": 0, "p": 0, "r": 0}}},
        "mode": "T2"
      }
      """;

  private Scenario load(String name, String text) throws Exception {
    Path f = Files.writeString(dir.resolve(name), text);
    return switch (ScenarioReader.read(f)) {
      case ScenarioLoad.Loaded l -> l.scenario();
      case ScenarioLoad.Failed failed -> throw new AssertionError(failed.message());
    };
  }

  private String errors(String text) throws Exception {
    Path f = Files.writeString(dir.resolve("bad.json"), text);
    return ScenarioReader.read(f) instanceof ScenarioLoad.Failed failed ? failed.message() : "";
  }

  @Test
  void aRobotAfterTheFirstHasItsOwnRegistersFramesAndMode() throws Exception {
    Scenario s = load("cell.json", CELL);
    Scenario.Preload right = s.preload(1);
    assertThat(right.registers()).isEqualTo(Map.of(5, 7.0, 6, 2.5));
    assertThat(right.toolFrames().get(1).translationVector().z()).isEqualTo(120);
    assertThat(right.userFrames()).containsOnlyKeys(2);
    assertThat(right.mode()).isEqualTo(Optional.of("AUTO"));
    // the top-level presets are the first robot's, and only the first's
    Scenario.Preload left = s.preload(0);
    assertThat(left.registers()).isEqualTo(Map.of(1, 3.0));
    assertThat(left.userFrames()).containsOnlyKeys(1);
    assertThat(left.mode()).isEqualTo(Optional.of("T2"));
    assertThat(right.registers()).doesNotContainKey(1);
  }

  @Test
  void writtenAndReadBackTheyStayOnTheirRobotByteForByte() throws Exception {
    Scenario s = load("cell.json", CELL);
    Path out = dir.resolve("out.json");
    ScenarioWriter.write(s, out);
    String text = Files.readString(out);
    Scenario again = load("again-src.json", text);
    assertThat(again.robots().get(1).registers()).isEqualTo(s.robots().get(1).registers());
    assertThat(again.robots().get(1).mode()).isEqualTo(Optional.of("AUTO"));
    assertThat(again.registers()).isEqualTo(s.registers());
    Path out2 = dir.resolve("out2.json");
    ScenarioWriter.write(again, out2);
    assertThat(Files.readString(out2)).isEqualTo(text);
    // a robot without presets of its own is written as before: no new fields
    assertThat(text.substring(text.indexOf("\"left\""), text.indexOf("\"right\""))).doesNotContain("\"registers\"", "\"frames\"", "\"mode\"");
  }

  @Test
  void theFirstRobotsPresetsInTwoPlacesAreRefusedWithBothLines() throws Exception {
    String twice = CELL.replace("{\"name\": \"left\", \"model\": \"lrmate200id\"}",
        "{\"name\": \"left\", \"model\": \"lrmate200id\", \"registers\": {\"2\": 1}}");
    assertThat(errors(twice)).contains("bad.json:4: robots[0].registers: the first robot's registers are given at the top "
        + "level too (\"registers\" at line 12): give them in one place");
  }

  @Test
  void aBadPresetOfAnyRobotNamesItsPath() throws Exception {
    assertThat(errors(CELL.replace("\"registers\": {\"5\": 7", "\"registers\": {\"0\": 7")))
        .contains("robots[1].registers.0");
    assertThat(errors(CELL.replace("\"user\": {\"2\":", "\"user\": {\"11\":"))).contains("robots[1].frames.user.11");
    assertThat(errors(CELL.replace("\"mode\": \"AUTO\"", "\"mode\": \"T3\""))).contains("robots[1].mode: unknown mode 'T3'");
  }
}
