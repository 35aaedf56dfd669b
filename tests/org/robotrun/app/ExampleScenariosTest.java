package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.Scenario;

/** Every file in scenarios/ loads, and its main program (if any) runs to the end headless. */
class ExampleScenariosTest {
  static List<Path> examples() throws Exception {
    try (Stream<Path> s = Files.list(Path.of("scenarios"))) {
      return s.filter(p -> p.toString().endsWith(".json")).sorted().toList();
    }
  }

  @Test
  void everyExampleLoadsAndItsMainProgramRunsToTheEnd(@TempDir Path dir) throws Exception {
    List<Path> files = examples();
    assertThat(files).extracting(p -> p.getFileName().toString())
        .contains("empty-cell.json", "pick-and-place.json", "frame-teaching.json", "two-robot-handshake.json");
    int ran = 0;
    for (Path f : files) {
      Scenario sc = ScenarioFiles.load(f);
      // A cell of several robots may name its main programs per robot.
      if (sc.mainProgram().isEmpty() && sc.robots().stream().allMatch(r -> r.mainProgram().isEmpty())) {
        continue;
      }
      Path report = dir.resolve(f.getFileName() + ".report.json");
      int code = Main.execute("run", "--scenario", f.toString(), "--report", report.toString());
      assertThat(code).as(f.toString()).isEqualTo(0);
      JsonNode r = new ObjectMapper().readTree(report.toFile());
      assertThat(r.get("status").asText()).as(f.toString()).isEqualTo("finished");
      assertThat(r.get("collisions")).as(f + " collisions").isEmpty();
      ran++;
    }
    assertThat(ran).as("examples with a main program").isGreaterThanOrEqualTo(3);
  }

  @Test
  void pickAndPlaceReportListsThePartsOnTheTray(@TempDir Path dir) throws Exception {
    Path report = dir.resolve("r.json");
    assertThat(Main.execute("run", "--scenario", "scenarios/pick-and-place.json", "--report", report.toString())).isZero();
    JsonNode parts = new ObjectMapper().readTree(report.toFile()).get("parts");
    assertThat(parts).hasSize(3);
    for (int k = 0; k < 3; k++) {
      JsonNode p = parts.get(k);
      assertThat(p.get("name").asText()).isEqualTo("part" + (k + 1));
      assertThat(p.get("parent").asText()).isEqualTo("tray");
      assertThat(p.get("heldBy").isNull()).isTrue();
      assertThat(p.get("pose_cell").get("x").asDouble()).isEqualTo(350.0 + 50 * k);
      assertThat(p.get("pose_cell").get("z").asDouble()).isEqualTo(-90.0);
    }
  }

  @Test
  void thePlcCellStartsJobOneByPnsAndEndsAtHome(@TempDir Path dir) throws Exception {
    Path report = dir.resolve("r.json");
    assertThat(Main.execute("run", "--scenario", "scenarios/plc-cell.json", "--report", report.toString())).isZero();
    JsonNode r = new ObjectMapper().readTree(report.toFile());
    assertThat(r.get("program").asText()).isEqualTo("PNS0001");
    JsonNode robot = r.get("robots").get(0);
    assertThat(robot.get("registers").get("R").get("1").asInt()).isEqualTo(1);
    // back at HOME: the HOME output (DO[10]) and ATPERCH (UO[7]) are on; the BG logic set the ready light
    assertThat(robot.get("io").get("DO").get("10").asBoolean()).isTrue();
    assertThat(robot.get("io").get("UO").get("7").asBoolean()).isTrue();
    assertThat(robot.get("io").get("DO").get("13").asBoolean()).isTrue();
    // SNO1 shows the PNS number 1
    assertThat(robot.get("io").get("UO").get("11").asBoolean()).isTrue();
    assertThat(robot.get("motions")).allSatisfy(m -> assertThat(m.get("program").asText()).isEqualTo("PNS0001"));
    // the PLC, the UOP handshake and the BG logic are deterministic: a second run writes the same bytes
    Path again = dir.resolve("r2.json");
    assertThat(Main.execute("run", "--scenario", "scenarios/plc-cell.json", "--report", again.toString())).isZero();
    assertThat(Files.readAllBytes(again)).isEqualTo(Files.readAllBytes(report));
  }

  @Test
  void aWorkspaceMadeFromThePlcCellAlsoStartsFromItsPlc(@TempDir Path dir) throws Exception {
    // run --workspace ignored runStartsFromPlc (it asked for --program, the scenario did not)
    Path ws = WorkspaceFiles.createFromScenario(Path.of("scenarios/plc-cell.json"), dir.resolve("ws"));
    Path report = dir.resolve("r.json");
    assertThat(Main.execute("run", "--workspace", ws.toString(), "--report", report.toString())).isZero();
    JsonNode r = new ObjectMapper().readTree(report.toFile());
    assertThat(r.get("program").asText()).isEqualTo("PNS0001");
    assertThat(r.get("robots").get(0).get("io").get("DO").get("10").asBoolean()).isTrue();
  }
}
