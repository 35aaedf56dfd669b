package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The "state" section of cell.json: every bad entry is named by its JSON path and line. */
class StateJsonTest {
  @Test
  void badStateEntriesAreNamedByPath(@TempDir Path tmp) throws Exception {
    String base = Files.readString(Path.of("scenarios/empty-cell.json")).strip();
    String withState = base.substring(0, base.lastIndexOf('}')) + """
        ,
          "state": {
            "overridePct": 0,
            "utool": 11,
            "registers": {"0": 1, "2": "x"},
            "positionRegisters": {"1": {"x": 1, "y": 2, "z": 3, "config": "Q U T, 0, 0, 0"}, "2": {"joints": [1, 2]}},
            "outputs": {"DI[1]": 1, "DO[2]": 3, "GO[1]": 7},
            "comments": {"Q[1]": "x"},
            "stringRegisters": {"26": "x", "3": 4, "4": "ok"},
            "colour": 1
          }
        }
        """;
    Path f = tmp.resolve("cell.json");
    Files.writeString(f, withState);
    String message = ((CellLoad.Failed) ScenarioReader.readCell(f)).message();
    assertThat(message).contains("state.overridePct").contains("state.utool").contains("state.registers.0")
        .contains("state.registers.2").contains("state.positionRegisters.1.config").doesNotContain("state.positionRegisters.1.w")
        .contains("state.positionRegisters.2.joints").contains("state.outputs.DI[1]").contains("state.outputs.DO[2]")
        .contains("state.comments.Q[1]")
        .contains("state.stringRegisters.26").contains("state.stringRegisters.3").doesNotContain("state.stringRegisters.4").contains("state.colour").doesNotContain("state.outputs.GO[1]");
    // A plain scenario read checks the section too (and ignores it when it is good).
    assertThat(ScenarioReader.read(f)).isInstanceOf(ScenarioLoad.Failed.class);
  }

  @Test
  void theStateSpeaksTheScenarioReadersMessagesWithFileLineAndPath(@TempDir Path tmp) throws Exception {
    // one set of JSON field helpers (JsonFieldReader): the same texts as the rest of the file
    String base = Files.readString(Path.of("scenarios/empty-cell.json")).strip();
    String withState = base.substring(0, base.lastIndexOf('}')) + """
        ,
          "state": {
            "utool": 2.5,
            "created": 7,
            "registers": {"x": 1},
            "robots": {"B": {"userFrames": {"11": {"x": 1, "y": 2, "z": 3}}, "colour": 1}}
          }
        }
        """;
    Path f = tmp.resolve("cell.json");
    Files.writeString(f, withState);
    String message = ((CellLoad.Failed) ScenarioReader.readCell(f)).message();
    assertThat(message)
        .contains("cell.json:").contains("state.utool: expected a whole number 0..10, got the number 2.5")
        .contains("state.created: expected a string, got the number 7")
        .contains("state.registers.x: expected a register number 1..200 as the key, got \"x\"")
        .contains("state.robots.B.userFrames.11: expected a user frame number 1..10 as the key, got \"11\"")
        .contains("state.robots.B.colour: unknown field (expected one of: ");
  }

  @Test
  void hostileValuesGiveTheRangeAndWhatWasFound(@TempDir Path tmp) throws Exception {
    String base = Files.readString(Path.of("scenarios/empty-cell.json")).strip();
    String withState = base.substring(0, base.lastIndexOf('}')) + """
        ,
          "state": {
            "registers": {"1": 1e999, "2": [3]},
            "stringRegisters": {"1": 5, "2": "%s"},
            "comments": {"R[1]": ["x"]},
            "outputs": {"DO[1]": 2, "GO[1]": 1e999},
            "positionRegisters": {"1": {"joints": [0, 0, [0], 0, 0, 1e999]}, "2": {"y": 0, "z": 0, "w": 36001}}
          }
        }
        """.formatted("s".repeat(255));
    Path f = tmp.resolve("cell.json");
    Files.writeString(f, withState);
    String message = ((CellLoad.Failed) ScenarioReader.readCell(f)).message();
    assertThat(message.lines().map(l -> l.replaceFirst("^.*?cell\\.json:\\d+: ", ""))).contains(
        "state.registers.1: expected a finite number, got the number 1e999",
        "state.registers.2: expected a finite number, got an array",
        "state.stringRegisters.1: expected a string, got the number 5",
        "state.stringRegisters.2: expected at most 254 characters, got 255",
        "state.comments.R[1]: expected a string, got an array",
        "state.outputs.DO[1]: expected a whole number 0..1, got the number 2",
        "state.outputs.GO[1]: expected a whole number -2147483647..2147483647, got the number 1e999",
        "state.positionRegisters.1.joints[2]: expected a number -36000..36000, got an array",
        "state.positionRegisters.1.joints[5]: expected a number -36000..36000, got the number 1e999",
        "state.positionRegisters.2.x: missing: expected a number -100000..100000",
        "state.positionRegisters.2.w: expected a number -36000..36000, got the number 36001");
  }
}
