package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.math.Transform;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Scenario;
import org.robotrun.world.Shape;

class ScenarioReaderTest {
  @TempDir Path dir;

  private static final String ROBOT = """
        "robots": [{"name": "robot1", "model": "lrmate200id", "endEffector": "gripper",
                    "basePose": {"x": 0, "y": 0, "z": -330}, "jointsDeg": [0, 0, 0, 0, -90, 0]}],
      """;

  /** A valid scenario with {@code objects} spliced in as the objects array body. */
  private static String withObjects(String objects) {
    return "{\n  \"format\": 1,\n" + ROBOT + "  \"objects\": [\n" + objects + "\n  ]\n}\n";
  }

  private static final String TABLE = """
          {"name": "table", "kind": "fixture", "shape": "box", "size": {"x": 400, "y": 700, "z": 230},
           "pose": {"x": 420, "y": 0, "z": -330}}""";

  private Path write(String name, String text) throws Exception {
    return Files.writeString(dir.resolve(name), text);
  }

  /** 1-based line of the first occurrence of {@code marker} in {@code text}. */
  private static int lineOf(String text, String marker) {
    int at = text.indexOf(marker);
    assertThat(at).as("marker %s", marker).isNotNegative();
    return (int) text.substring(0, at).chars().filter(c -> c == '\n').count() + 1;
  }

  private static List<ScenarioError> errors(Path file) {
    ScenarioLoad load = ScenarioReader.read(file);
    assertThat(load).isInstanceOf(ScenarioLoad.Failed.class);
    return ((ScenarioLoad.Failed) load).errors();
  }

  private static ScenarioError onlyError(Path file) {
    List<ScenarioError> e = errors(file);
    assertThat(e).hasSize(1);
    return e.getFirst();
  }

  @Test
  void validScenarioLoadsWithUnitsConvertedOnce() throws Exception {
    String text = withObjects(TABLE + """
        ,
          {"name": "p1", "kind": "part", "shape": "cylinder", "radius": 20, "height": 40,
           "color": "#ff0000", "pose": {"x": 10, "y": 0, "z": 230, "r": 90}, "parent": "table"}""");
    ScenarioLoad load = ScenarioReader.read(write("ok.json", text));
    assertThat(load).isInstanceOf(ScenarioLoad.Loaded.class);
    Scenario s = ((ScenarioLoad.Loaded) load).scenario();
    assertThat(s.robots().getFirst().endEffector()).isEqualTo(EndEffectorType.GRIPPER);
    assertThat(s.robots().getFirst().initialJointsRad().get(4)).isEqualTo(Math.toRadians(-90));
    assertThat(s.world().find("p1").orElseThrow().kind()).isEqualTo(ObjectKind.PART);
    // p1 sits on the table top: cell z = -330 + 230; R = 90 deg turns its x onto cell +y.
    Transform X_CP = s.world().poseInCell("p1");
    assertThat(X_CP.z()).isEqualTo(-100);
    assertThat(X_CP.x()).isEqualTo(430);
    assertThat(X_CP.axis(0).y()).isCloseTo(1, org.assertj.core.api.Assertions.within(1e-15));
    assertThat(s.world().collisionBox("p1").cz()).isEqualTo(-80);
  }

  @Test
  void onCollisionWarnIsReadAndWrittenBack() throws Exception {
    String text = withObjects(TABLE).replace("\"format\": 1,", "\"format\": 1,\n  \"onCollision\": \"warn\",");
    Path file = write("warn.json", text);
    Scenario s = ((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario();
    assertThat(s.onCollision()).isEqualTo(org.robotrun.world.CollisionResponse.WARN);
    ScenarioWriter.write(s, file);
    assertThat(Files.readString(file)).contains("\"onCollision\" : \"warn\"");
    assertThat(((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario().onCollision())
        .isEqualTo(org.robotrun.world.CollisionResponse.WARN);
    // Absent means alarm.
    assertThat(((ScenarioLoad.Loaded) ScenarioReader.read(write("ok.json", withObjects(TABLE)))).scenario().onCollision())
        .isEqualTo(org.robotrun.world.CollisionResponse.ALARM);
  }

  @Test
  void modeIsReadAndWrittenBackAndABadOneIsNamedWithItsLine() throws Exception {
    String text = withObjects(TABLE).replace("\"format\": 1,", "\"format\": 1,\n  \"mode\": \"AUTO\",");
    Path file = write("mode.json", text);
    Scenario s = ((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario();
    assertThat(s.mode()).contains("AUTO");
    ScenarioWriter.write(s, file);
    assertThat(Files.readString(file)).contains("\"mode\" : \"AUTO\"");
    // absent: the window's default, T1
    assertThat(((ScenarioLoad.Loaded) ScenarioReader.read(write("ok.json", withObjects(TABLE)))).scenario().mode()).isEmpty();
    String bad = withObjects(TABLE).replace("\"format\": 1,", "\"format\": 1,\n  \"mode\": \"T3\",");
    ScenarioError e = onlyError(write("badmode.json", bad));
    assertThat(e.path()).isEqualTo("mode");
    assertThat(e.line()).isEqualTo(lineOf(bad, "\"mode\""));
    assertThat(e.message()).contains("'T3'").contains("T1").contains("AUTO");
  }

  @Test
  void unknownCollisionResponseIsNamedWithItsLine() throws Exception {
    String text = withObjects(TABLE).replace("\"format\": 1,", "\"format\": 1,\n  \"onCollision\": \"ignore\",");
    ScenarioError e = onlyError(write("bad.json", text));
    assertThat(e.path()).isEqualTo("onCollision");
    assertThat(e.line()).isEqualTo(lineOf(text, "\"onCollision\""));
    assertThat(e.message()).contains("'ignore'").contains("alarm").contains("warn");
  }

  @Test
  void toolIoMapsTheEndEffectorPortsAndIsWrittenBack() throws Exception {
    String text = withObjects(TABLE).replace("\"endEffector\": \"gripper\",",
        "\"endEffector\": \"gripper\", \"toolIo\": {\"output\": 3, \"holding\": 7},");
    Path file = write("io.json", text);
    Scenario s = ((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario();
    assertThat(s.robots().getFirst().toolIo()).isEqualTo(new org.robotrun.world.ToolIo(3, 1, 7));
    ScenarioWriter.write(s, file);
    assertThat(((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario().robots().getFirst().toolIo())
        .isEqualTo(new org.robotrun.world.ToolIo(3, 1, 7));
  }

  @Test
  void ioSizesAndUserAlarmTextsAreReadPerRobotAndWrittenBack() throws Exception {
    String text = withObjects(TABLE).replace("\"endEffector\": \"gripper\",",
        "\"endEffector\": \"gripper\", \"io\": {\"DO\": 1024, \"RO\": 16},"
            + " \"toolIo\": {\"output\": 12}, \"userAlarms\": {\"1\": \"Gripper did not close\", \"7\": \"Part missing\"},");
    Path file = write("io-sizes.json", text);
    Scenario s = ((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario();
    org.robotrun.world.RobotSetup r = s.robots().getFirst();
    assertThat(r.io()).containsExactly(java.util.Map.entry("DO", 1024), java.util.Map.entry("RO", 16));
    assertThat(r.userAlarms()).containsExactly(java.util.Map.entry(1, "Gripper did not close"), java.util.Map.entry(7, "Part missing"));
    assertThat(r.toolIo().output()).isEqualTo(12);
    ScenarioWriter.write(s, file);
    org.robotrun.world.RobotSetup again = ((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario().robots().getFirst();
    assertThat(again.io()).isEqualTo(r.io());
    assertThat(again.userAlarms()).isEqualTo(r.userAlarms());
  }

  @Test
  void theMacroTableIsReadInItsOrderAndWrittenBackByteForByte() throws Exception {
    String text = withObjects(TABLE).replace("\"endEffector\": \"gripper\",",
        "\"endEffector\": \"gripper\", \"macros\": [{\"name\": \"HAND1 OPEN\", \"program\": \"hopen\"},"
            + " {\"name\": \"GRIP CLOSE\", \"program\": \"GCLOSE\"}, {\"name\": \"ALARM_RESET\", \"program\": \"RESET1\"}],");
    Path file = write("macros.json", text);
    Scenario s = ((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario();
    assertThat(s.robots().getFirst().macros()).containsExactly(new org.robotrun.world.RobotSetup.Macro("HAND1 OPEN", "HOPEN"),
        new org.robotrun.world.RobotSetup.Macro("GRIP CLOSE", "GCLOSE"), new org.robotrun.world.RobotSetup.Macro("ALARM_RESET", "RESET1"));
    ScenarioWriter.write(s, file);
    byte[] first = Files.readAllBytes(file);
    Scenario again = ((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario();
    assertThat(again.robots().getFirst().macros()).isEqualTo(s.robots().getFirst().macros());
    ScenarioWriter.write(again, file);
    assertThat(Files.readAllBytes(file)).isEqualTo(first);
  }

  @Test
  void badMacroRowsAreNamedWithTheirPathAndLine() throws Exception {
    String text = withObjects(TABLE).replace("\"endEffector\": \"gripper\",",
        "\"endEffector\": \"gripper\",\n \"macros\": [{\"name\": \"HAND1  OPEN\", \"program\": \"HOPEN\"},\n"
            + " {\"name\": \"X\", \"program\": \"1BAD\"},\n {\"name\": \"x\", \"program\": \"P\", \"key\": 1},\n 5],");
    List<ScenarioError> errors = ((ScenarioLoad.Failed) ScenarioReader.read(write("bad-macros.json", text))).errors();
    assertThat(errors).extracting(ScenarioError::path).containsExactlyInAnyOrder("robots[0].macros[0].name",
        "robots[0].macros[1].program", "robots[0].macros[2].key", "robots[0].macros[2].name", "robots[0].macros[3]");
    assertThat(errors).extracting(ScenarioError::message).anySatisfy(m -> assertThat(m).contains("already in the table"))
        .anySatisfy(m -> assertThat(m).contains("separated by one space"));
    assertThat(errors).filteredOn(e -> e.path().equals("robots[0].macros[1].program")).singleElement()
        .satisfies(e -> assertThat(e.line()).isEqualTo(lineOf(text, "1BAD")));
  }

  @Test
  void badIoSizesAreNamedWithTheirLine() throws Exception {
    String text = withObjects(TABLE).replace("\"endEffector\": \"gripper\",",
        "\"endEffector\": \"gripper\",\n \"io\": {\"XO\": 8,\n \"DI\": 5000},");
    List<ScenarioError> errors = ((ScenarioLoad.Failed) ScenarioReader.read(write("bad-sizes.json", text))).errors();
    assertThat(errors).extracting(ScenarioError::path).containsExactlyInAnyOrder("robots[0].io.XO", "robots[0].io.DI");
    assertThat(errors).extracting(ScenarioError::message).anySatisfy(m -> assertThat(m).contains("unknown I/O kind 'XO'"))
        .anySatisfy(m -> assertThat(m).contains("1..4096").contains("5000"));
    // A tool port beyond the robot's (default) 8 robot outputs.
    String beyond = withObjects(TABLE).replace("\"endEffector\": \"gripper\",",
        "\"endEffector\": \"gripper\",\n \"toolIo\": {\"output\": 9},");
    ScenarioError e = onlyError(write("beyond.json", beyond));
    assertThat(e.path()).isEqualTo("robots[0].toolIo.output");
    assertThat(e.message()).contains("RO[9]").contains("RO[1..8]").contains("io.RO");
  }

  @Test
  void badToolIoPortIsNamedWithItsLine() throws Exception {
    String text = withObjects(TABLE).replace("\"endEffector\": \"gripper\",",
        "\"endEffector\": \"gripper\",\n \"toolIo\": {\"output\": 65},");
    ScenarioError e = onlyError(write("bad-io.json", text));
    assertThat(e.path()).isEqualTo("robots[0].toolIo.output");
    assertThat(e.line()).isEqualTo(lineOf(text, "\"toolIo\""));
    assertThat(e.message()).contains("1..64").contains("65");
  }

  @Test
  void unknownFieldIsNamedWithItsLine() throws Exception {
    String text = withObjects(TABLE.replace("\"kind\"", "\"colour\": \"#ffffff\", \"kind\""));
    ScenarioError e = onlyError(write("s.json", text));
    assertThat(e.path()).isEqualTo("objects[0].colour");
    assertThat(e.line()).isEqualTo(lineOf(text, "\"colour\""));
    assertThat(e.message()).startsWith("unknown field (expected one of: color,");
    assertThat(e.toString()).startsWith(dir.resolve("s.json") + ":" + e.line() + ": objects[0].colour: unknown field");
  }

  @Test
  void wrongTypeIsNamedWithItsLine() throws Exception {
    String text = withObjects(TABLE).replace("\"model\": \"lrmate200id\"", "\"model\": 200");
    ScenarioError e = onlyError(write("s.json", text));
    assertThat(e.path()).isEqualTo("robots[0].model");
    assertThat(e.line()).isEqualTo(lineOf(text, "\"model\""));
    assertThat(e.message()).isEqualTo("expected a string, got the number 200");
  }

  @Test
  void nanIsRejectedWithItsPath() throws Exception {
    String text = withObjects(TABLE.replace("\"x\": 420", "\"x\": NaN"));
    ScenarioError e = onlyError(write("s.json", text));
    assertThat(e.path()).isEqualTo("objects[0].pose.x");
    assertThat(e.line()).isEqualTo(lineOf(text, "NaN"));
    assertThat(e.message()).isEqualTo("expected a number -100000..100000, got the number NaN");
  }

  @Test
  void infiniteNumberIsRejectedWithItsPath() throws Exception {
    String text = withObjects(TABLE.replace("\"y\": 700", "\"y\": 1e999"));
    ScenarioError e = onlyError(write("s.json", text));
    assertThat(e.path()).isEqualTo("objects[0].size.y");
    assertThat(e.line()).isEqualTo(lineOf(text, "1e999"));
    assertThat(e.message()).isEqualTo("expected a number 0..100000 (more than 0), got the number 1e999");
  }

  @Test
  void negativeSizeIsRejectedWithItsPath() throws Exception {
    String text = withObjects(TABLE + ",\n" + TABLE.replace("table", "t2") + ",\n" + TABLE.replace("table", "t3") + ",\n"
        + TABLE.replace("table", "t4").replace("\"x\": 400", "\"x\": -10"));
    ScenarioError e = onlyError(write("s.json", text));
    assertThat(e.path()).isEqualTo("objects[3].size.x");
    assertThat(e.line()).isEqualTo(lineOf(text, "-10"));
    assertThat(e.message()).isEqualTo("expected a number 0..100000 (more than 0), got the number -10");
  }

  @Test
  void missingMeshFileIsNamedWithItsPath() throws Exception {
    String text = withObjects("""
          {"name": "bracket", "kind": "fixture", "shape": "mesh",
           "file": "meshes/bracket.stl", "scale": 1, "pose": {"x": 0, "y": 0, "z": 0}}""");
    ScenarioError e = onlyError(write("s.json", text));
    assertThat(e.path()).isEqualTo("objects[0].file");
    assertThat(e.line()).isEqualTo(lineOf(text, "\"file\""));
    assertThat(e.message()).startsWith("mesh file not found: " + dir.resolve("meshes/bracket.stl"));
  }

  @Test
  void meshIsReadRelativeToTheScenario() throws Exception {
    Files.createDirectories(dir.resolve("meshes"));
    Files.write(dir.resolve("meshes/tri.stl"), binaryTriangle());
    String text = withObjects("""
          {"name": "bracket", "kind": "fixture", "shape": "mesh",
           "file": "meshes/tri.stl", "scale": 1000, "pose": {"x": 0, "y": 0, "z": 0}}""");
    ScenarioLoad load = ScenarioReader.read(write("s.json", text));
    Shape.Mesh mesh = (Shape.Mesh) ((ScenarioLoad.Loaded) load).scenario().world().find("bracket").orElseThrow().shape();
    assertThat(mesh.mesh().triangleCount()).isEqualTo(1);
    assertThat(mesh.mesh().max().x()).isEqualTo(1000);
    assertThat(mesh.file()).isEqualTo(dir.resolve("meshes/tri.stl").toAbsolutePath().normalize());
  }

  @Test
  void duplicateNamesAreNamedWithBothPlaces() throws Exception {
    String text = withObjects(TABLE + ",\n" + TABLE.replace("\"x\": 420", "\"x\": 0") + ",\n" + TABLE.replace("\"x\": 420", "\"x\": 9"));
    List<ScenarioError> e = errors(write("s.json", text));
    assertThat(e).hasSize(2);
    assertThat(e.get(0).path()).isEqualTo("objects[1].name");
    assertThat(e.get(1).path()).isEqualTo("objects[2].name");
    assertThat(e.get(0).message()).isEqualTo("duplicate name 'table': already used by objects[0] (line "
        + lineOf(text, "\"table\"") + ")");
    assertThat(e.get(1).line()).isGreaterThan(e.get(0).line());
  }

  @Test
  void syntaxErrorNamesItsLine() throws Exception {
    String text = withObjects(TABLE).replace("\"objects\": [", "\"objects\": [,");
    ScenarioError e = onlyError(write("s.json", text));
    assertThat(e.line()).isEqualTo(lineOf(text, "[,"));
    assertThat(e.message()).startsWith("not valid JSON");
  }

  @Test
  void severalErrorsAreReportedAtOnceInLineOrder() throws Exception {
    String text = withObjects(TABLE.replace("\"y\": 700", "\"y\": -1").replace("\"x\": 420", "\"x\": \"far\""))
        .replace("\"gripper\"", "\"hammer\"").replace("\"format\": 1", "\"format\": 2");
    List<ScenarioError> e = errors(write("s.json", text));
    assertThat(e).extracting(ScenarioError::path)
        .containsExactly("format", "robots[0].endEffector", "objects[0].size.y", "objects[0].pose.x");
    assertThat(e.get(0).message()).isEqualTo("unsupported format 2: this RobotRun reads format 1");
    assertThat(e.get(1).message()).startsWith("unknown end effector 'hammer': expected one of [faceplate, gripper");
  }

  @Test
  void parentMustBeAnExistingFixtureWithoutLoops() throws Exception {
    String text = withObjects(TABLE.replace("}}", "}, \"parent\": \"jig\"}") + """
        ,
          {"name": "jig", "kind": "fixture", "shape": "box", "size": {"x": 1, "y": 1, "z": 1},
           "pose": {"x": 0, "y": 0, "z": 0}, "parent": "table"},
          {"name": "p", "kind": "part", "shape": "box", "size": {"x": 1, "y": 1, "z": 1},
           "pose": {"x": 0, "y": 0, "z": 0}, "parent": "nowhere"},
          {"name": "q", "kind": "part", "shape": "box", "size": {"x": 1, "y": 1, "z": 1},
           "pose": {"x": 0, "y": 0, "z": 0}, "parent": "p"}""");
    List<ScenarioError> e = errors(write("s.json", text));
    assertThat(e).extracting(ScenarioError::message).containsExactly(
        "parents form a loop through 'table'",
        "parents form a loop through 'jig'",
        "no object named 'nowhere' to be relative to",
        "'p' is a part; only a fixture can be a parent");
  }

  @Test
  void anObjectThatIsItsOwnParentIsAnErrorNotAnException() throws Exception {
    String text = withObjects(TABLE.replace("}}", "}, \"parent\": \"table\"}"));
    ScenarioError e = onlyError(write("s.json", text));
    assertThat(e.path()).isEqualTo("objects[0].parent");
    assertThat(e.message()).isEqualTo("'table' cannot be its own parent");
    // A second object named like the first and sitting on it: the duplicate and the parent.
    String dup = withObjects(TABLE + ",\n" + TABLE.replace("}}", "}, \"parent\": \"table\"}"));
    assertThat(errors(write("d.json", dup))).extracting(ScenarioError::path)
        .containsExactly("objects[1].name", "objects[1].parent");
  }

  @Test
  void hugeCoordinatesAndSizesAreRefusedWithTheirPath() throws Exception {
    String text = withObjects(TABLE.replace("\"x\": 420", "\"x\": 1e308").replace("\"y\": 700", "\"y\": 700000"));
    assertThat(errors(write("s.json", text))).extracting(ScenarioError::path, ScenarioError::message).containsExactly(
        org.assertj.core.groups.Tuple.tuple("objects[0].size.y", "expected a number 0..100000 (more than 0), got the number 700000"),
        org.assertj.core.groups.Tuple.tuple("objects[0].pose.x", "expected a number -100000..100000, got the number 1e308"));
  }

  @Test
  void anglesBeyondTheSharedBoundAreRefusedWithTheirPath() throws Exception {
    String text = withObjects(TABLE.replace("\"z\": -330}", "\"z\": -330, \"w\": 36001, \"r\": -36000}"));
    assertThat(errors(write("s.json", text))).extracting(ScenarioError::path, ScenarioError::message).containsExactly(
        org.assertj.core.groups.Tuple.tuple("objects[0].pose.w", "expected a number -36000..36000, got the number 36001"));
  }

  @Test
  void aUtf8ByteOrderMarkIsIgnored() throws Exception {
    Path f = write("bom.json", "\uFEFF" + withObjects(TABLE));
    assertThat(ScenarioReader.read(f)).isInstanceOf(ScenarioLoad.Loaded.class);
  }

  @Test
  void jointsOutsideLimitsAndProgramsAreChecked() throws Exception {
    String text = withObjects(TABLE).replace("[0, 0, 0, 0, -90, 0]", "[0, 0, 0, 0, -150, 0]")
        .replace("\"objects\"", "\"programs\": [\"PICK.LS\"], \"mainProgram\": \"PLACE\",\n  \"objects\"");
    List<ScenarioError> e = errors(write("s.json", text));
    assertThat(e).extracting(ScenarioError::path).containsExactly("robots[0].jointsDeg[4]", "programs[0]", "mainProgram");
    assertThat(e.get(0).message()).startsWith("J5 = -150 deg puts the robot outside its joint limits (J5 must lie in [-125, 125] deg");
    assertThat(e.get(1).message()).startsWith("program file not found");
  }

  private static final String PUNCTUATION = "{}[]:,\"0a-. ";

  @Test
  void mangledFilesGiveErrorsNeverExceptions() throws Exception {
    // Method: 500 seeded random edits of a valid scenario (drop, duplicate or replace a
    // character, or swap a value for another type); each load must return a result, and a
    // failed one must carry at least one error with a message.
    String valid = Files.readString(Path.of("scenarios/pick-and-place.json"));
    String[] values = {"NaN", "-1", "1e999", "\"x\"", "[]", "{}", "null", "true", "0"};
    java.util.Random random = new java.util.Random(1234);
    Path f = dir.resolve("m.json");
    for (int i = 0; i < 500; i++) {
      StringBuilder t = new StringBuilder(valid);
      int at = random.nextInt(t.length());
      switch (random.nextInt(4)) {
        case 0 -> t.deleteCharAt(at);
        case 1 -> t.insert(at, t.charAt(at));
        case 2 -> t.setCharAt(at, PUNCTUATION.charAt(random.nextInt(PUNCTUATION.length())));
        default -> {
          int colon = t.indexOf(":", at);
          int end = colon < 0 ? -1 : Math.min(t.indexOf(",", colon) < 0 ? t.length() : t.indexOf(",", colon),
              t.indexOf("}", colon) < 0 ? t.length() : t.indexOf("}", colon));
          if (colon >= 0 && end > colon) {
            t.replace(colon + 1, end, " " + values[random.nextInt(values.length)]);
          }
        }
      }
      Files.writeString(f, t);
      ScenarioLoad load = ScenarioReader.read(f);
      if (load instanceof ScenarioLoad.Failed failed) {
        assertThat(failed.errors()).allSatisfy(e -> assertThat(e.message()).isNotBlank());
      }
    }
  }

  @Test
  void impossiblePathIsAnError() throws Exception {
    String text = withObjects(TABLE).replace("\"objects\"", "\"programs\": [\"bad\\u0000name.LS\"],\n  \"objects\"");
    ScenarioError e = onlyError(write("s.json", text));
    assertThat(e.path()).isEqualTo("programs[0]");
    assertThat(e.message()).startsWith("not a valid path");
  }

  @Test
  void notAnObjectAndMissingFileAreErrorsNotExceptions() throws Exception {
    assertThat(onlyError(write("a.json", "[1, 2]")).message()).isEqualTo("expected an object, got an array");
    assertThat(onlyError(write("e.json", "")).message()).startsWith("empty file");
    assertThat(onlyError(dir.resolve("none.json")).message()).isEqualTo("no such file");
    assertThat(errors(write("f.json", "{\"robots\": []}"))).extracting(ScenarioError::message)
        .containsExactly("missing: expected \"format\": 1", "expected at least one robot");
  }

  private static byte[] binaryTriangle() {
    ByteBuffer b = ByteBuffer.allocate(84 + 50).order(ByteOrder.LITTLE_ENDIAN);
    b.position(80);
    b.putInt(1);
    b.putFloat(0).putFloat(0).putFloat(1);
    b.putFloat(0).putFloat(0).putFloat(0);
    b.putFloat(1).putFloat(0).putFloat(0);
    b.putFloat(0).putFloat(1).putFloat(0);
    b.putShort((short) 0);
    return b.array();
  }
}
