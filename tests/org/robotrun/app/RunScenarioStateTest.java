package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code run --scenario} puts the scenario's saved state into every robot it names, not only the first. */
class RunScenarioStateTest {
  @TempDir Path dir;

  private Path cell(String state) throws Exception {
    Files.createDirectories(dir.resolve("programs"));
    // each program divides by a register only the state sets: 0 there is INTP's division by zero
    Files.writeString(dir.resolve("programs/FIRST.LS"), "/PROG  FIRST\n/ATTR\n/MN\n   1:  R[1]=1/R[6] ;\n/POS\n/END\n");
    Files.writeString(dir.resolve("programs/SECOND.LS"), "/PROG  SECOND\n/ATTR\n/MN\n   1:  R[1]=1/R[5] ;\n/POS\n/END\n");
    return Files.writeString(dir.resolve("cell.json"), """
        {
          "format": 1,
          "robots": [
            {"name": "robot1", "model": "lrmate200id", "programs": ["programs/FIRST.LS"], "mainProgram": "FIRST"},
            {"name": "robot2", "model": "lrmate200id", "basePose": {"x": 2000, "y": 0, "z": 0},
             "programs": ["programs/SECOND.LS"], "mainProgram": "SECOND"}
          ],
          "objects": [],
          "state": %s
        }
        """.formatted(state));
  }

  @Test
  void theSecondRobotsSavedRegistersAreApplied() throws Exception {
    Path f = cell("{\"registers\": {\"6\": 2}, \"robots\": {\"robot2\": {\"registers\": {\"5\": 7}}}}");
    assertThat(Main.execute("run", "--scenario", f.toString())).isEqualTo(Main.EXIT_OK);
  }

  @Test
  void withoutTheSecondRobotsStateItsProgramAlarms() throws Exception {
    Path f = cell("{\"registers\": {\"6\": 2}}");
    assertThat(Main.execute("run", "--scenario", f.toString())).isEqualTo(Main.EXIT_FAILED);
  }
}
