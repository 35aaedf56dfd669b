package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.Scenario;
import org.robotrun.world.VisionSetup;

/** The scenario's "vision" section: read, written back, and every bad field named by its JSON path. */
class VisionJsonTest {
  @TempDir
  Path dir;

  static final String CELL = """
      {"format": 1,
       "robots": [{"name": "r1", "model": "lrmate200id"}],
       "objects": [
         {"name": "table", "kind": "fixture", "shape": "box", "size": {"x": 400, "y": 700, "z": 230},
          "pose": {"x": 420, "y": 0, "z": -330}},
         {"name": "b1", "kind": "part", "shape": "box", "size": {"x": 40, "y": 40, "z": 40}, "color": "#d9412b",
          "pose": {"x": 0, "y": 0, "z": 230}, "parent": "table"}
       ],
       "vision": %s}
      """;

  static final String GOOD = """
      {"seed": 5,
       "cameras": [{"name": "CAM1", "pose": {"x": 420, "y": 0, "z": 700, "w": 180}, "fovDeg": 40,
                    "imageSize": [640, 480], "noise": {"positionMm": 0.5, "rotationDeg": 0.1, "missProbability": 0.05}}],
       "models": [{"name": "BLOCK", "id": 3, "namePrefix": "b", "color": "#d9412b", "shape": "box"}],
       "processes": [{"name": "FIND", "camera": "CAM1", "models": ["BLOCK"], "userFrame": 1,
                      "reference": {"x": 10, "y": 20, "z": 0, "r": 15}, "type": "3D", "numberToFind": 4}],
       "placements": [{"parts": ["b1"], "xMm": [-50, 50], "yMm": [-60, 60], "rDeg": [-30, 30], "minGapMm": 10,
                       "kinds": [{"shape": "cylinder", "radius": 15, "height": 30, "color": "#2e9e4f"},
                                 {"shape": "box", "size": {"x": 30, "y": 30, "z": 30}, "color": "#d9412b"}]}]}
      """;

  ScenarioLoad load(String vision) throws Exception {
    Path f = dir.resolve("cell.json");
    Files.writeString(f, CELL.formatted(vision));
    return ScenarioReader.read(f);
  }

  Scenario loaded(String vision) throws Exception {
    return switch (load(vision)) {
      case ScenarioLoad.Loaded l -> l.scenario();
      case ScenarioLoad.Failed f -> throw new AssertionError(f.message());
    };
  }

  List<String> errors(String vision) throws Exception {
    return switch (load(vision)) {
      case ScenarioLoad.Loaded l -> throw new AssertionError("loaded: " + l.scenario().vision());
      case ScenarioLoad.Failed f -> f.errors().stream().map(e -> e.path() + ": " + e.message()).toList();
    };
  }

  @Test
  void aGoodSectionReadsWithItsValues() throws Exception {
    VisionSetup v = loaded(GOOD).vision();
    assertThat(v.seed()).isEqualTo(5);
    VisionSetup.Camera c = v.cameras().get(0);
    assertThat(c.robot()).isEmpty();
    assertThat(Math.toDegrees(c.fovRad())).isCloseTo(40, org.assertj.core.data.Offset.offset(1e-9));
    assertThat(c.window()).isEqualTo(new VisionSetup.Window(0, 0, 640, 480));
    assertThat(c.missProbability()).isEqualTo(0.05);
    assertThat(v.models().get(0).id()).isEqualTo(3);
    VisionSetup.Process p = v.process("find").orElseThrow();
    assertThat(p.type()).isEqualTo(VisionSetup.ProcessType.THREE_D);
    assertThat(p.maxFound()).isEqualTo(4);
    assertThat(p.userFrame()).isEqualTo(1);
    assertThat(v.placements().get(0).kinds()).hasSize(2);
  }

  @Test
  void noSectionIsNone() throws Exception {
    Path f = dir.resolve("plain.json");
    Files.writeString(f, CELL.substring(0, CELL.indexOf(",\n \"vision\"")) + "}");
    assertThat(((ScenarioLoad.Loaded) ScenarioReader.read(f)).scenario().vision()).isEqualTo(VisionSetup.NONE);
  }

  @Test
  void writingAndReadingAgainGivesTheSameSection() throws Exception {
    Scenario s = loaded(GOOD);
    String once = ScenarioWriter.toJson(s, dir);
    Path f = dir.resolve("again.json");
    Files.writeString(f, once);
    Scenario back = ((ScenarioLoad.Loaded) ScenarioReader.read(f)).scenario();
    assertThat(ScenarioWriter.toJson(back, dir)).isEqualTo(once);
    assertThat(back.vision().seed()).isEqualTo(5);
    assertThat(back.vision().processes()).hasSize(1);
    assertThat(back.vision().placements().get(0).kinds()).isEqualTo(s.vision().placements().get(0).kinds());
  }

  @Test
  void theExampleLabReadsAndRoundTrips() throws Exception {
    Scenario s = ((ScenarioLoad.Loaded) ScenarioReader.read(Path.of("scenarios/vision-pick.json"))).scenario();
    assertThat(s.vision().processes()).extracting(VisionSetup.Process::name).containsExactly("FIND_BLOCKS");
    String once = ScenarioWriter.toJson(s, Path.of("scenarios").toAbsolutePath());
    assertThat(once).contains("\"vision\"").contains("\"FIND_BLOCKS\"");
  }

  @Test
  void seedsUpTo16DigitsAreTakenAndWrittenBackUnchanged() throws Exception {
    for (long seed : new long[] {8_999_999_999_999_999L, -8_999_999_999_999_999L}) {
      Scenario s = loaded(GOOD.replace("\"seed\": 5", "\"seed\": " + seed));
      assertThat(s.vision().seed()).isEqualTo(seed);
      assertThat(ScenarioWriter.toJson(s, dir)).contains("\"seed\" : " + seed + ",");
    }
    assertThat(errors(GOOD.replace("\"seed\": 5", "\"seed\": 9000000000000000")))
        .containsExactly("vision.seed: expected a whole number from -8999999999999999 to 8999999999999999, got the number 9000000000000000");
  }

  @Test
  void badFieldsAreNamedByTheirPath() throws Exception {
    record Case(String from, String to, String expected) {}
    List<Case> cases = List.of(
        new Case("\"seed\": 5", "\"seed\": 1.5", "vision.seed: expected a whole number"),
        new Case("\"fovDeg\": 40", "\"fovDeg\": 190", "vision.cameras[0].fovDeg: expected a number 1..170"),
        new Case("[640, 480]", "[640]", "vision.cameras[0].imageSize: expected [width, height]"),
        new Case("\"missProbability\": 0.05", "\"missProbability\": 2",
            "vision.cameras[0].noise.missProbability: expected a number 0..1"),
        new Case("\"w\": 180}", "\"w\": 0}", "vision.cameras[0]: camera 'CAM1' sees no object of the cell"),
        new Case("\"fovDeg\": 40,", "\"fovDeg\": 40, \"robot\": \"r9\",", "vision.cameras[0].robot: no robot named 'r9'"),
        new Case("\"fovDeg\": 40,", "\"fovDeg\": 40, \"zoom\": 2,", "vision.cameras[0].zoom: unknown field"),
        new Case("\"namePrefix\": \"b\"", "\"namePrefix\": \"x\"", "vision.models[0]: model 'BLOCK' matches no part"),
        new Case("\"#d9412b\", \"shape\": \"box\"", "\"#d9412b\", \"shape\": \"sphere\"",
            "vision.models[0].shape: expected \"box\", \"cylinder\" or \"mesh\""),
        new Case("\"camera\": \"CAM1\"", "\"camera\": \"CAM2\"", "vision.processes[0].camera: no camera named 'CAM2'"),
        new Case("\"models\": [\"BLOCK\"]", "\"models\": [\"BOLT\"]", "vision.processes[0].models[0]: no model named 'BOLT'"),
        new Case("\"type\": \"3D\"", "\"type\": \"2.5D\"", "vision.processes[0].type: expected \"2D\" or \"3D\""),
        new Case("\"userFrame\": 1", "\"userFrame\": 11", "vision.processes[0].userFrame: expected a whole number 0..10"),
        new Case("\"name\": \"FIND\"", "\"name\": \"FIND IT\"", "vision.processes[0].name: expected a vision process name"),
        new Case("\"reference\": {\"x\": 10, ", "\"reference\": {", "vision.processes[0].reference.x: missing"),
        new Case("\"parts\": [\"b1\"]", "\"parts\": [\"table\"]", "vision.placements[0].parts[0]: 'table' is a fixture"),
        new Case("\"parts\": [\"b1\"]", "\"parts\": [\"b9\"]", "vision.placements[0].parts[0]: no object named 'b9'"),
        new Case("\"xMm\": [-50, 50]", "\"xMm\": [50, -50]", "vision.placements[0].xMm: expected [min, max] with min <= max"),
        new Case("\"radius\": 15, ", "", "vision.placements[0].kinds[0].radius: missing"));
    for (Case c : cases) {
      assertThat(GOOD).as(c.from()).contains(c.from());
      List<String> errs = errors(GOOD.replace(c.from(), c.to()));
      assertThat(errs).as(c.to()).anyMatch(e -> e.startsWith(c.expected()));
    }
  }

  @Test
  void errorsCarryTheFileAndLine() throws Exception {
    ScenarioLoad.Failed f = (ScenarioLoad.Failed) load(GOOD.replace("\"camera\": \"CAM1\"", "\"camera\": \"CAM2\""));
    ScenarioError e = f.errors().get(0);
    assertThat(e.file()).endsWith("cell.json");
    // the section starts on line 9 of the file; "camera" is on its 5th line
    assertThat(e.line()).isEqualTo(13);
  }
}
