package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.Scenario;

/**
 * scenarios/mixed-cell.json: an LR Mate 200iD and a CRX-10iA side by side in one cell, wired
 * by a handshake. As shipped both programs finish without contact; with the CRX's WAIT removed
 * the two arms meet in the shared zone and the run stops on a collision between them.
 */
class MixedCellTest {
  @TempDir Path dir;

  private JsonNode run(Path scenario) throws Exception {
    Path report = dir.resolve("report-" + System.nanoTime() + ".json");
    Main.execute("run", "--scenario", scenario.toString(), "--report", report.toString());
    return new ObjectMapper().readTree(report.toFile());
  }

  @Test
  void twoModelsShareTheCellAndTheHandshakeKeepsThemApart() throws Exception {
    Scenario sc = ScenarioFiles.load(Path.of("scenarios/mixed-cell.json"));
    assertThat(sc.robots()).extracting(r -> r.modelId()).containsExactly("lrmate200id", "crx10ia");
    JsonNode r = run(Path.of("scenarios/mixed-cell.json"));
    assertThat(r.get("status").asText()).isEqualTo("finished");
    assertThat(r.get("collisions")).isEmpty();
  }

  @Test
  void withoutTheWaitTheArmsCollide() throws Exception {
    Files.createDirectories(dir.resolve("programs"));
    Files.copy(Path.of("scenarios/mixed-cell.json"), dir.resolve("mixed-cell.json"));
    Files.copy(Path.of("scenarios/programs/LRMREACH.LS"), dir.resolve("programs/LRMREACH.LS"));
    String crx = Files.readString(Path.of("scenarios/programs/CRXREACH.LS"));
    assertThat(crx).contains("  WAIT DI[1:LRM CLEAR]=ON ;");
    Files.writeString(dir.resolve("programs/CRXREACH.LS"), crx.replace("  WAIT DI[1:LRM CLEAR]=ON ;", "  ! forgot to wait ;"));
    JsonNode r = run(dir.resolve("mixed-cell.json"));
    assertThat(r.get("status").asText()).isNotEqualTo("finished");
    JsonNode hits = r.get("collisions");
    assertThat(hits).isNotEmpty();
    String a = hits.get(0).get("a").asText(), b = hits.get(0).get("b").asText();
    assertThat(a.substring(0, a.indexOf('/')) + " " + b.substring(0, b.indexOf('/'))).isEqualTo("robot1 robot2");
  }
}
