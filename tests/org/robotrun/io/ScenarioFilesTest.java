package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.robotrun.collision.Obb;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Scenario;
import org.robotrun.world.WorldObject;

/** The example scenarios shipped in scenarios/ (top level of the repository). */
class ScenarioFilesTest {
  private static final Path SCENARIOS = Path.of("scenarios");

  private static List<Path> files() throws Exception {
    try (Stream<Path> s = Files.list(SCENARIOS)) {
      return s.filter(p -> p.toString().endsWith(".json")).sorted().toList();
    }
  }

  @Test
  void everyScenarioLoadsWithoutErrors() throws Exception {
    List<Path> files = files();
    assertThat(files).extracting(p -> p.getFileName().toString())
        .contains("empty-cell.json", "pick-and-place.json", "frame-teaching.json");
    for (Path f : files) {
      ScenarioLoad load = ScenarioReader.read(f);
      assertThat(load).as(f + ": " + (load instanceof ScenarioLoad.Failed e ? e.message() : "")).isInstanceOf(ScenarioLoad.Loaded.class);
    }
  }

  @Test
  void pickAndPlacePartsRestOnTheTableWithinReach() throws Exception {
    Scenario s = ((ScenarioLoad.Loaded) ScenarioReader.read(SCENARIOS.resolve("pick-and-place.json"))).scenario();
    List<WorldObject> parts = s.world().objects().stream().filter(o -> o.kind() == ObjectKind.PART).toList();
    assertThat(parts).hasSize(3);
    Obb table = s.world().collisionBox("table");
    double tableTop = table.cz() + table.hz();
    assertThat(tableTop).isBetween(-100.0, 0.0);
    for (WorldObject p : parts) {
      Obb box = s.world().collisionBox(p.name());
      // Resting: bottom face on the table top (to 1e-9 mm); reachable: within 650 mm of J1/J2.
      assertThat(box.cz() - box.hz()).isCloseTo(tableTop, org.assertj.core.api.Assertions.within(1e-9));
      assertThat(Math.hypot(Math.hypot(box.cx() - 50, box.cy()), box.cz())).isLessThan(650);
    }
  }
}
