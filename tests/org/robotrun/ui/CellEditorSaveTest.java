package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.ScenarioLoad;
import org.robotrun.io.ScenarioReader;
import org.robotrun.world.CellEditor;

/** Issue 19: the cell editor saves a scenario as .rrcell (RobotRun's own extension) or .json. */
class CellEditorSaveTest {
  @TempDir Path dir;

  private CellEditorPanel panel() {
    ScenarioLoad l = ScenarioReader.read(Path.of("scenarios/pick-and-place.json"));
    return new CellEditorPanel(new CellEditor(((ScenarioLoad.Loaded) l).scenario(), (f, s) -> {
      throw new AssertionError("no meshes here");
    }), null);
  }

  @Test
  void aCellSavedAsRrcellReadsBackAsAScenario() throws Exception {
    Path f = dir.resolve("Cell for week 3.rrcell");
    assertThat(panel().save(f)).isInstanceOf(CellEditor.Result.Done.class);
    assertThat(ScenarioReader.read(f)).isInstanceOf(ScenarioLoad.Loaded.class);
    assertThat(panel().save(dir.resolve("cell.JSON"))).isInstanceOf(CellEditor.Result.Done.class);
  }

  @Test
  void anyOtherNameIsRefusedAndNothingWritten() {
    assertThat(panel().save(dir.resolve("cell.txt"))).isEqualTo(
        new CellEditor.Result.Refused("save as: expected a file name ending in .rrcell or .json, got 'cell.txt'"));
    assertThat(Files.exists(dir.resolve("cell.txt"))).isFalse();
  }
}
