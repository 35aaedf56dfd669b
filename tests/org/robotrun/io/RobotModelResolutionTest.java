package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.NumericSolver;
import org.robotrun.robot.RobotModel;
import org.robotrun.world.Scenario;

/** A scenario's robot "model": a library id or a robot file relative to the scenario (RobotDefinitions.resolve). */
class RobotModelResolutionTest {
  @TempDir Path dir;

  private static String scenario(String model1, String model2) {
    return """
        {"format": 1, "robots": [
          {"name": "robot1", "model": "%s", "basePose": {"x": 0, "y": 0, "z": -330}},
          {"name": "robot2", "model": "%s", "basePose": {"x": 1500, "y": 0, "z": -330}}
        ]}
        """.formatted(model1, model2);
  }

  /** The library's CRX file with another id and name, in a folder of its own. */
  private Path ownRobotFile() throws Exception {
    String text;
    try (var in = RobotDefinitions.class.getResourceAsStream("/robots/crx10ia.json")) {
      text = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
    }
    Path f = dir.resolve("robots/my-crx.json");
    Files.createDirectories(f.getParent());
    Files.writeString(f, text.replace("\"id\": \"crx10ia\"", "\"id\": \"mycrx\"").replace("FANUC CRX-10iA", "Our CRX"));
    return f;
  }

  @Test
  void aLibraryIdAndARobotFileRelativeToTheScenarioShareACell() throws Exception {
    ownRobotFile();
    Path sc = Files.writeString(dir.resolve("cell.json"), scenario("lrmate200id", "robots/my-crx.json"));
    ScenarioLoad load = ScenarioReader.read(sc);
    assertThat(load).as(load.toString()).isInstanceOf(ScenarioLoad.Loaded.class);
    Scenario s = ((ScenarioLoad.Loaded) load).scenario();
    assertThat(s.robots().get(0).modelId()).isEqualTo("lrmate200id");
    String key = s.robots().get(1).modelId();
    assertThat(Path.of(key)).isAbsolute().isEqualTo(dir.resolve("robots/my-crx.json").toAbsolutePath().normalize());
    RobotModel m = RobotDefinitions.load(key);
    assertThat(m.displayName()).isEqualTo("Our CRX");
    assertThat(IkSolver.kindFor(m)).isEqualTo("offset-wrist");
    // Written back relative to the file being saved, as meshes are.
    Path out = dir.resolve("sub/saved.json");
    Files.createDirectories(out.getParent());
    ScenarioWriter.write(s, out);
    assertThat(Files.readString(out)).contains("\"model\" : \"../robots/my-crx.json\"");
    assertThat(ScenarioReader.read(out)).isInstanceOf(ScenarioLoad.Loaded.class);
  }

  @Test
  void anUnknownIdAndAMissingFileAreErrorsOnTheModelLine() throws Exception {
    Path sc = Files.writeString(dir.resolve("cell.json"), scenario("lrmate300x", "robots/none.json"));
    List<ScenarioError> errors = ((ScenarioLoad.Failed) ScenarioReader.read(sc)).errors();
    assertThat(errors).hasSize(2);
    assertThat(errors.get(0).toString()).contains(":2:").contains("robots[0].model")
        .contains("unknown robot model 'lrmate300x'").contains("crx10ia");
    assertThat(errors.get(1).toString()).contains(":3:").contains("robots[1].model")
        .contains("cannot load robot file 'robots/none.json'").contains("robot file not found");
  }

  @Test
  void aBrokenRobotFileNamesTheFileAndTheField() throws Exception {
    Path f = ownRobotFile();
    Files.writeString(f, Files.readString(f).replace("\"maxSpeed\": 120.0", "\"maxSpeed\": \"fast\""));
    assertThatThrownBy(() -> RobotDefinitions.resolve("robots/my-crx.json", dir))
        .isInstanceOf(FileFormatException.class)
        .hasMessageContaining("my-crx.json:13: joints[0].maxSpeed: expected a number 0..3600 (more than 0), got a string");
  }

  @Test
  void anInfiniteNumberInARobotFilesArrayIsRefused() throws Exception {
    // it used to load: the flange 1e999 mm away (infinity in every pose)
    Path f = ownRobotFile();
    Files.writeString(f, Files.readString(f).replace("\"flange\": {\"xyz\": [160, 0, 0]", "\"flange\": {\"xyz\": [1e999, 0, 0]"));
    assertThatThrownBy(() -> RobotDefinitions.resolve("robots/my-crx.json", dir))
        .isInstanceOf(FileFormatException.class)
        .hasMessage(f + ":20: flange.xyz[0]: expected a number -100000..100000, got the number 1e999");
  }

  @Test
  void theMaximumTcpSpeedComesFromTheRobotFileAndIsRangeChecked() throws Exception {
    // the CRX's file gives 1000 mm/s; a file that does not say gets the controller's 2000
    assertThat(RobotDefinitions.load("crx10ia").maxLinearSpeedMmPerSec()).isEqualTo(1000);
    assertThat(RobotDefinitions.load("lrmate200id").maxLinearSpeedMmPerSec()).isEqualTo(2000);
    Path f = ownRobotFile();
    Files.writeString(f, Files.readString(f).replace("\"maxLinearSpeed\": 1000", "\"maxLinearSpeed\": 1500"));
    assertThat(RobotDefinitions.resolve(f.toString(), null).maxLinearSpeedMmPerSec()).isEqualTo(1500);
    Files.writeString(f, Files.readString(f).replace("\"maxLinearSpeed\": 1500", "\"maxLinearSpeed\": 0"));
    assertThatThrownBy(() -> RobotDefinitions.resolve("robots/my-crx.json", dir))
        .isInstanceOf(FileFormatException.class)
        .hasMessageContaining("my-crx.json:10: maxLinearSpeed: expected a number 1..10000, got the number 0");
  }

  @Test
  void aChainThatIsNeitherOpwNorTheCrxLayoutGetsTheNumericSolver() throws Exception {
    Path f = ownRobotFile();
    // Move J5 off the J4 axis: no spherical wrist, no CRX layout.
    Files.writeString(f, Files.readString(f).replace("\"xyz\": [540, 0, 0]", "\"xyz\": [540, 0, 30]"));
    RobotModel m = RobotDefinitions.resolve(f.toString(), null);
    assertThat(m.wristKind()).isEqualTo("other");
    IkSolver ik = IkSolver.forModel(m);
    assertThat(ik).isInstanceOf(NumericSolver.class);
    double[] q = {0.3, 0.4, 0.2, 0.5, -1.0, 0.7};
    var X = org.robotrun.robot.ForwardKinematics.flangePoseInBase(m, q);
    var r = ik.solve(X, ik.configOf(q), new double[] {0.25, 0.35, 0.25, 0.45, -0.9, 0.6});
    assertThat(r).isInstanceOf(org.robotrun.robot.IkResult.Solved.class);
    assertThat(((org.robotrun.robot.IkResult.Solved) r).positionErrorMm()).isLessThan(1e-3);
  }
}
