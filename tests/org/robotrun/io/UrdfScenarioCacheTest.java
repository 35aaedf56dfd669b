package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.Scenario;

/**
 * A scenario that names a {@code .urdf} directly: its {@code "packages"} map gives package
 * folders (relative to the scenario), the import is kept while the URDF and its meshes are
 * unchanged ({@link UrdfCache}), and the writer keeps the map.
 */
class UrdfScenarioCacheTest {
  @TempDir
  Path tmp;

  private Path scenario(String robotJson) throws Exception {
    Path f = tmp.resolve("cell.json");
    Files.writeString(f, "{\"format\": 1, \"robots\": [" + robotJson + "]}");
    return f;
  }

  @Test
  void packagesFromTheScenarioFindTheMeshesAndTheImportIsKeptUntilAMeshChanges() throws Exception {
    Path urdf = TestArms.sphericalPackage(tmp);
    String model = tmp.relativize(urdf).toString().replace('\\', '/');
    // Without the "extra" package (outside the workspace) the mesh cannot be found: a clear error.
    ScenarioLoad bad = ScenarioReader.read(scenario("{\"name\": \"robot1\", \"model\": \"" + model + "\"}"));
    assertThat(bad).isInstanceOf(ScenarioLoad.Failed.class);
    assertThat(((ScenarioLoad.Failed) bad).message()).contains("robots[0].model").contains("package 'extra' not found");
    Path sc = scenario("{\"name\": \"robot1\", \"model\": \"" + model + "\", \"packages\": {\"extra\": \"elsewhere/extra\"}}");
    int before = UrdfCache.imports();
    ScenarioLoad a = ScenarioReader.read(sc);
    assertThat(a).as(a.toString()).isInstanceOf(ScenarioLoad.Loaded.class);
    assertThat(UrdfCache.imports()).isEqualTo(before + 1);
    // Loading again, and a builder loading by the stored path alone: no new import.
    assertThat(ScenarioReader.read(sc)).isInstanceOf(ScenarioLoad.Loaded.class);
    Scenario s = ((ScenarioLoad.Loaded) a).scenario();
    assertThat(RobotDefinitions.load(s.robots().get(0).modelId()).joints()).hasSize(6);
    assertThat(UrdfCache.imports()).isEqualTo(before + 1);
    // A mesh changes: imported again.
    Path mesh = tmp.resolve("elsewhere/extra/link_4.dae");
    Files.writeString(mesh, Files.readString(mesh).replace("<up_axis>Y_UP</up_axis>", "<up_axis>Z_UP</up_axis>"));
    assertThat(ScenarioReader.read(sc)).isInstanceOf(ScenarioLoad.Loaded.class);
    assertThat(UrdfCache.imports()).isEqualTo(before + 2);
    // The writer keeps the package folders, relative to the scenario.
    String json = ScenarioWriter.toJson(s, tmp);
    assertThat(json.replaceAll("\\s", "")).contains("\"packages\":{\"extra\":\"elsewhere/extra\"}");
  }

  @Test
  void badPackageMapsNameTheirField() throws Exception {
    Path urdf = TestArms.sphericalPackage(tmp);
    String model = tmp.relativize(urdf).toString().replace('\\', '/');
    ScenarioLoad missing = ScenarioReader.read(scenario("{\"name\": \"robot1\", \"model\": \"" + model
        + "\", \"packages\": {\"extra\": \"nowhere\"}}"));
    assertThat(((ScenarioLoad.Failed) missing).message()).contains("robots[0].packages.extra").contains("package folder not found");
    ScenarioLoad notString = ScenarioReader.read(scenario("{\"name\": \"robot1\", \"model\": \"" + model
        + "\", \"packages\": {\"extra\": 3}}"));
    assertThat(((ScenarioLoad.Failed) notString).message()).contains("robots[0].packages.extra").contains("expected the package's folder");
    ScenarioLoad library = ScenarioReader.read(scenario("{\"name\": \"robot1\", \"model\": \"lrmate200id\", \"packages\": {}}"));
    assertThat(((ScenarioLoad.Failed) library).message()).contains("robots[0].packages").contains("for a model that names a .urdf file");
  }
}
