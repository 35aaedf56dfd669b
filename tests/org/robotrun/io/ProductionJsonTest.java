package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.ProductionSetup;
import org.robotrun.world.Scenario;

/** The scenario's "production" section: read with JSON paths and lines, written back the same. */
class ProductionJsonTest {
  @TempDir Path dir;

  private static String scenario(String production) {
    return """
        {
          "format": 1,
          "robots": [{"name": "robot1", "model": "lrmate200id"}],
          "production": %s
        }
        """.formatted(production);
  }

  private ScenarioLoad load(String text) throws Exception {
    return ScenarioReader.read(Files.writeString(dir.resolve("s.json"), text));
  }

  @Test
  void theExampleCellReadsAndWritesBackTheSame() throws Exception {
    Scenario sc = ((ScenarioLoad.Loaded) ScenarioReader.read(Path.of("scenarios/plc-cell.json"))).scenario();
    ProductionSetup.Robot r = sc.production().of("robot1").orElseThrow();
    assertThat(r.selection()).isEqualTo(ProductionSetup.Selection.PNS);
    assertThat(r.referencePositions().get(0).output()).contains(new ProductionSetup.Signal("DO", 10));
    assertThat(r.referencePositions().get(0).toleranceDeg()).containsExactly(2.0, 2.0, 2.0, 2.0, 2.0, 2.0);
    assertThat(r.plc()).hasSize(11);
    assertThat(r.plc().get(4).delaySec()).isEqualTo(0.032);
    assertThat(r.backgroundLogic()).containsExactly("BGLIGHT");
    assertThat(r.startFromPlc()).isTrue();
    ScenarioLoad again = load(ScenarioWriter.toJson(sc, dir));
    assertThat(again).isInstanceOf(ScenarioLoad.Loaded.class);
    assertThat(((ScenarioLoad.Loaded) again).scenario().production()).isEqualTo(sc.production());
  }

  @Test
  void misconfigurationsAreNamedByJsonPathAndLine() throws Exception {
    String text = scenario("""
        {
            "robot9": {},
            "robot1": {
              "selection": "RSR",
              "pnsBase": 99999,
              "referencePositions": [{"number": 1, "jointsDeg": [0, 0, 0], "output": "UO[7]"}],
              "plc": [{"set": {"UO[1]": true}}, {}],
              "runStartsFromPlc": true,
              "uop": false
            }
          }""");
    ScenarioLoad l = load(text);
    assertThat(l).isInstanceOf(ScenarioLoad.Failed.class);
    List<ScenarioError> e = ((ScenarioLoad.Failed) l).errors();
    assertThat(e).extracting(ScenarioError::path).contains(
        "production.robot9", "production.robot1.pnsBase", "production.robot1.referencePositions[0].jointsDeg",
        "production.robot1.plc[0].set.UO[1]", "production.robot1.plc[1]", "production.robot1.rsr",
        "production.robot1.runStartsFromPlc");
    assertThat(e).filteredOn(x -> x.path().equals("production.robot9")).first()
        .satisfies(x -> assertThat(x.message()).contains("no robot named 'robot9'"))
        .satisfies(x -> assertThat(x.line()).isEqualTo(5));
    assertThat(e).filteredOn(x -> x.path().equals("production.robot1.rsr")).first()
        .satisfies(x -> assertThat(x.message()).contains("selection RSR needs at least one RSR program number"));
    assertThat(e).filteredOn(x -> x.path().equals("production.robot1.plc[0].set.UO[1]")).first()
        .satisfies(x -> assertThat(x.message()).contains("DI[i]").contains("UI[i]"));
  }

  @Test
  void plcSignalsAreCheckedAgainstTheRobotsOwnIoSizes() throws Exception {
    // DI[20] on a robot with 16 DI: refused at load (it used to pass and fail inside a simulation tick).
    ScenarioLoad l = load("""
        {
          "format": 1,
          "robots": [{"name": "robot1", "model": "lrmate200id", "io": {"DI": 16}}],
          "production": {"robot1": {"plc": [{"set": {"DI[20]": true}}]}}
        }
        """);
    assertThat(l).isInstanceOf(ScenarioLoad.Failed.class);
    assertThat(((ScenarioLoad.Failed) l).errors()).filteredOn(x -> x.path().endsWith("DI[20]")).singleElement().satisfies(x -> {
      assertThat(x.path()).isEqualTo("production.robot1.plc[0].set.DI[20]");
      assertThat(x.message()).contains("DI[20]").contains("1..16");
    });
    // and the robot's larger range is allowed where the default would refuse it
    ScenarioLoad big = load("""
        {
          "format": 1,
          "robots": [{"name": "robot1", "model": "lrmate200id", "io": {"DI": 1024}}],
          "production": {"robot1": {"plc": [{"set": {"DI[700]": true}}]}}
        }
        """);
    assertThat(big).isInstanceOf(ScenarioLoad.Loaded.class);
  }

  @Test
  void noSectionIsNone() throws Exception {
    ScenarioLoad l = load("""
        {"format": 1, "robots": [{"name": "robot1", "model": "lrmate200id"}]}
        """);
    assertThat(((ScenarioLoad.Loaded) l).scenario().production()).isEqualTo(ProductionSetup.NONE);
    assertThat(ScenarioWriter.toJson(((ScenarioLoad.Loaded) l).scenario(), dir)).doesNotContain("production");
  }
}
