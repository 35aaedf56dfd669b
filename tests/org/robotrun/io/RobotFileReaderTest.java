package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.robot.RobotModel;

/**
 * A robot file (RobotRun's JSON) is checked field by field: each bad field is named with its line,
 * its JSON path, the range or kind expected and what was found, every problem at once, and a field
 * the format does not have is refused (a misspelt "maxSpeeds" must not silently leave a default).
 */
class RobotFileReaderTest {
  @TempDir Path dir;

  private static String library(String id) throws Exception {
    try (var in = RobotDefinitions.class.getResourceAsStream("/robots/" + id + ".json")) {
      return new String(in.readAllBytes(), StandardCharsets.UTF_8);
    }
  }

  private Path write(String text) throws Exception {
    Path f = dir.resolve("arm.json");
    Files.writeString(f, text);
    return f;
  }

  /** The message loading {@code text} gives, every line without the file's folder. */
  private String problems(String text) throws Exception {
    Path f = write(text);
    try {
      RobotModel m = RobotDefinitions.loadFile(f);
      throw new AssertionError("loaded " + m.id());
    } catch (FileFormatException e) {
      return e.getMessage().replace(f.toString(), "arm.json");
    }
  }

  @Test
  void everyLibraryArmLoadsThroughTheCheckedReader() throws Exception {
    for (String id : RobotDefinitions.LIBRARY) {
      RobotModel fromFile = RobotDefinitions.loadFile(write(library(id)));
      assertThat(fromFile.id()).isEqualTo(id);
      assertThat(fromFile.joints()).hasSize(6);
    }
  }

  @Test
  void eachBadFieldIsNamedWithItsLineRangeAndWhatWasFound() throws Exception {
    String good = library("lrmate200id");
    record Case(String from, String to, String expected) {}
    List<Case> cases = List.of(
        new Case("\"maxSpeed\": 450}", "\"maxSpeed\": 0}", "arm.json:12: joints[0].maxSpeed: expected a number 0..3600 (more than 0), got the number 0"),
        new Case("\"lower\": -170, \"upper\": 170", "\"lower\": 170, \"upper\": -170",
            "arm.json:12: joints[0].upper: expected more than lower (170), got -170"),
        new Case("\"lower\": -170,", "\"lower\": -2000,", "arm.json:12: joints[0].lower: expected a number -1080..1080, got the number -2000"),
        new Case("\"axis\": [0, 0, 1]", "\"axis\": [0, 0, 0]", "arm.json:12: joints[0].axis: expected a direction, got [0, 0, 0]"),
        new Case("\"axis\": [0, 0, 1]", "\"axis\": [0, 1]", "arm.json:12: joints[0].axis: expected [x, y, z] (the joint's axis), got an array of 2"),
        new Case("\"xyz\": [50, 0, 0]", "\"xyz\": [50, 0, \"up\"]", "arm.json:13: joints[1].xyz[2]: expected a number -100000..100000, got a string"),
        new Case("\"maxSpeed\": 380", "\"maxSpeeds\": 380",
            "arm.json:13: joints[1].maxSpeeds: unknown field (expected one of: axis, lower, maxSpeed, name, rpy, upper, xyz)\n"
                + "arm.json:13: joints[1].maxSpeed: missing: expected a number 0..3600 (more than 0)"),
        new Case("\"units\": {\"length\": \"mm\"", "\"units\": {\"length\": \"m\"",
            "arm.json:8: units.length: expected \"mm\" (a robot file is in millimetres; robotrun robot import converts a URDF's), got \"m\""),
        new Case("\"format\": 1", "\"format\": 2", "arm.json:2: format: unsupported format 2: this RobotRun reads format 1"),
        new Case("\"coupledJ3\": true", "\"coupledJ3\": \"yes\"", "arm.json:9: coupledJ3: expected true or false, got a string"),
        new Case("\"worldInBase\": {\"x\": 0, ", "\"worldInBase\": {", "arm.json:10: worldInBase.x: missing: expected a number -100000..100000"),
        new Case("\"size\": [220, 220, 20]", "\"size\": [220, 0, 20]",
            "arm.json:22: links[0].shapes[0].size[1]: expected a number 0..100000 (more than 0), got the number 0"),
        new Case("\"radius\": 85,", "\"radius\": -85,", "arm.json:23: links[0].shapes[1].radius: expected a number 0..100000 (more than 0), got the number -85"),
        new Case("{\"type\": \"box\", \"xyz\": [0, 0, 10]", "{\"type\": \"sphere\", \"xyz\": [0, 0, 10]",
            "arm.json:22: links[0].shapes[0].type: expected \"box\" or \"cylinder\", got \"sphere\""),
        new Case("\"size\": [220, 220, 20], \"color\": \"base\"", "\"size\": [220, 220, 20], \"color\": \"pink\"",
            "arm.json:22: links[0].shapes[0].color: expected body, joint, base, flange, white or #rrggbb, got \"pink\""),
        new Case("\"flange\": {\"xyz\": [0, 0, 0], \"rpy\": [180, -90, 0]}", "\"flange\": {\"xyz\": [0, 0, 0], \"rpy\": [1e999, -90, 0]}",
            "arm.json:19: flange.rpy[0]: expected a number -360..360, got the number 1e999"),
        new Case("\"name\": \"J1\"", "\"name\": \"\"", "arm.json:12: joints[0].name: expected a name of 1..100 characters (no control characters), got \"\""),
        new Case("\"reachMm\": 716.8,", "\"reachMm\": 716.8, \"reach\": 1,", "arm.json:6: reach: unknown field (expected one of: "
            + "coupledJ3, flange, format, id, joints, links, maxLinearSpeed, name, payloadKg, reachMm, source, units, worldInBase)"));
    for (Case c : cases) {
      assertThat(good).as(c.from()).contains(c.from());
      assertThat(problems(good.replaceFirst(java.util.regex.Pattern.quote(c.from()), java.util.regex.Matcher.quoteReplacement(c.to()))))
          .as(c.to()).isEqualTo(c.expected());
    }
  }

  @Test
  void allProblemsAreReportedTogetherEachOnItsOwnLine() throws Exception {
    String bad = library("lrmate200id").replace("\"maxSpeed\": 450", "\"maxSpeed\": -1")
        .replace("\"size\": [220, 220, 20]", "\"size\": [220, 220]").replace("\"coupledJ3\": true", "\"coupled\": true");
    assertThat(problems(bad).lines()).containsExactly(
        "arm.json:9: coupled: unknown field (expected one of: coupledJ3, flange, format, id, joints, links, maxLinearSpeed, "
            + "name, payloadKg, reachMm, source, units, worldInBase)",
        "arm.json:12: joints[0].maxSpeed: expected a number 0..3600 (more than 0), got the number -1",
        "arm.json:22: links[0].shapes[0].size: expected [x, y, z] (mm, each more than 0), got an array of 2");
  }

  @Test
  void theChainsShapeIsChecked() throws Exception {
    String lr = library("lrmate200id");
    String fiveJoints = lr.replaceFirst("\\s*\\{\"name\": \"J6\"[^}]*\\}", "").replace("\"maxSpeed\": 545},", "\"maxSpeed\": 545}");
    assertThat(problems(fiveJoints)).isEqualTo("arm.json:11: joints: expected 6 joints (J1 to J6), got 5");
    assertThat(problems(lr.replace("\"joints\": [", "\"joint\": ["))).startsWith("arm.json:11: joint: unknown field");
    assertThat(problems("[1, 2]")).isEqualTo("arm.json:1: expected an object, got an array");
    assertThat(problems("{\"id\": \"a\",")).startsWith("arm.json:1: ");
    assertThat(problems(lr.replace("\"id\": \"lrmate200id\",", "\"id\": \"lrmate200id\", \"id\": \"x\",")))
        .isEqualTo("arm.json:3: id: field given twice");
  }

  @Test
  void aMeshOutsideTheRobotFilesFolderIsRefusedOnItsLine() throws Exception {
    String withMesh = library("lrmate200id").replace("{\"name\": \"base\", \"shapes\": [",
        "{\"name\": \"base\", \"meshes\": [{\"file\": \"../outside.stl\"}], \"shapes\": [");
    assertThat(problems(withMesh))
        .isEqualTo("arm.json:21: links[0].meshes[0].file: mesh '../outside.stl': expected a path relative to the robot file's folder");
    assertThatThrownBy(() -> RobotDefinitions.loadFile(write(withMesh.replace("../outside.stl", "none.stl"))))
        .isInstanceOf(FileFormatException.class).hasMessageContaining(":21: links[0].meshes[0].file: ");
  }
}
