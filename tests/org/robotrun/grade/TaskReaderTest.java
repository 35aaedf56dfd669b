package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Task files are read as strictly as scenarios: every problem with its line and JSON path. */
class TaskReaderTest {
  @TempDir Path dir;

  private String read(String json) throws Exception {
    Files.copy(Path.of("scenarios/pick-and-place.json"), dir.resolve("cell.json"));
    Files.createDirectories(dir.resolve("programs"));
    Files.copy(Path.of("scenarios/programs/PICKPLACE.LS"), dir.resolve("programs/PICKPLACE.LS"));
    Path f = dir.resolve("t.task.json");
    Files.writeString(f, json);
    TaskLoad l = TaskReader.read(f);
    return l instanceof TaskLoad.Failed failed ? failed.message().replace(f.toString(), "t.task.json") : "loaded";
  }

  @Test
  void theExampleTaskLoads() {
    TaskLoad l = TaskReader.read(Path.of("scenarios/tasks/pick-and-place.task.json"));
    assertThat(l).isInstanceOf(TaskLoad.Loaded.class);
    Task t = ((TaskLoad.Loaded) l).task();
    assertThat(t.program()).isEqualTo("PICKPLACE");
    assertThat(t.checks()).hasSize(16);
    assertThat(t.variations().parts()).extracting(Task.PartJitter::offsetRegister).extracting(o -> o.orElseThrow())
        .containsExactly(11, 12, 13);
  }

  @Test
  void theAutograderSectionIsReadStrictly() throws Exception {
    assertThat(read("{\"format\":1,\"scenario\":\"cell.json\",\"checks\":[{\"name\":\"end\",\"type\":\"runsToEnd\",\"points\":1}],\n"
        + "\"autograder\": {\"hiddenVisibility\": \"later\", \"leaderboard\": 1, \"colour\": 2}}").lines().toList())
        .containsExactly(
            "t.task.json:2: autograder.colour: unknown field (expected one of: hiddenVisibility, leaderboard)",
            "t.task.json:2: autograder.hiddenVisibility: expected one of hidden, after_due_date, after_published "
                + "(Gradescope's visibilities), got \"later\"",
            "t.task.json:2: autograder.leaderboard: expected true or false, got the number 1");
  }

  @Test
  void aGoodAutograderSectionLoads() throws Exception {
    assertThat(read("{\"format\":1,\"scenario\":\"cell.json\",\"checks\":[{\"name\":\"end\",\"type\":\"runsToEnd\",\"points\":1}],"
        + "\"autograder\": {\"hiddenVisibility\": \"after_due_date\", \"leaderboard\": true}}")).isEqualTo("loaded");
  }

  @Test
  void aMinimalTaskUsesTheScenariosMainProgramAndDefaults() throws Exception {
    assertThat(read("{\"format\":1,\"scenario\":\"cell.json\",\"checks\":[{\"name\":\"end\",\"type\":\"runsToEnd\",\"points\":1}]}"))
        .isEqualTo("loaded");
  }

  @Test
  void unknownFieldsWrongTypesAndBadNamesAreReportedWithLineAndPath() throws Exception {
    String msg = read("""
        {"format": 1, "scenario": "cell.json", "colour": "red",
         "variations": {"count": 3.5, "parts": [{"part": "part9", "xMm": -1}]},
         "checks": [
           {"name": "a", "type": "partAt", "points": 5, "part": "part1", "fixture": "tray",
            "position": {"x": 0, "y": 0, "z": "ten"}},
           {"name": "a", "type": "cycleTime", "points": "ten", "maxSec": 5},
           {"name": "b", "type": "teleport", "points": 1},
           {"name": "c", "type": "programUse", "points": 1, "requires": ["goto"], "extra": true},
           {"name": "d", "type": "endState", "points": 1, "values": {"R[1]": true, "Q[2]": 1}},
           {"name": "e", "type": "frame", "points": 1, "frame": "UT[11]", "pose": {"x": 0, "y": 0, "z": 0}}
         ]}
        """);
    assertThat(msg.lines().toList()).containsExactly(
        "t.task.json:1: colour: unknown field (expected one of: autograder, checks, format, limits, program, robots, scenario, title, variations)",
        "t.task.json:2: variations.count: expected a whole number 0..100, got the number 3.5",
        "t.task.json:2: variations.parts[0].part: the scenario has no part named 'part9'",
        "t.task.json:2: variations.parts[0].xMm: expected a number 0..1000, got the number -1",
        "t.task.json:5: checks[0].position.z: expected a number -100000..100000, got a string",
        "t.task.json:6: checks[1].name: check name \"a\" is used twice",
        "t.task.json:6: checks[1].points: expected a number 0..10000, got a string",
        "t.task.json:7: checks[2].type: unknown check type \"teleport\" (expected one of: handIn, programs, runsToEnd, "
            + "partAt, nothingHeld, noneDropped, noCollision, noMotionStop, cycleTime, programUse, endState, frame, positionRegister, tcpVisits)",
        "t.task.json:8: checks[3].extra: unknown field (expected one of: forbids, hidden, maxMotionLines, message, name, "
            + "points, requires, robot, runs, type)",
        "t.task.json:8: checks[3].requires[0]: unknown feature \"goto\" (expected one of: offsetPR, toolOffsetPR, "
            + "prTarget, for, call, jmpBackward, wait, if, select, joint, linear, circular, cnt, fine, run, voffset)",
        "t.task.json:9: checks[4].values.R[1]: expected a finite number, got a boolean",
        "t.task.json:9: checks[4].values.Q[2]: expected a name like R[1], F[2], DO[3], RO[1], GO[1]",
        "t.task.json:10: checks[5].frame: expected UT[n] or UF[n] with n 1..10, got \"UT[11]\"");
  }

  @Test
  void aMissingPointsFieldIsAnError() throws Exception {
    assertThat(read("{\"format\":1,\"scenario\":\"cell.json\",\"checks\":[{\"name\":\"end\",\"type\":\"runsToEnd\"}]}"))
        .isEqualTo("t.task.json:1: checks[0].points: missing: expected a number of points (0 or more)");
  }

  @Test
  void aWrongFormatAndABrokenScenarioAreTheTasksErrors() throws Exception {
    assertThat(read("{\"format\":2,\"scenario\":\"nope.json\",\"checks\":[]}").lines().toList()).containsExactly(
        "t.task.json:1: format: unsupported format 2: this RobotRun reads format 1",
        "t.task.json:1: scenario: scenario file not found: " + dir.resolve("nope.json") + " (paths are relative to the task file)",
        "t.task.json:1: checks: expected at least one check");
  }

  @Test
  void invalidJsonSaysWhere() throws Exception {
    assertThat(read("{\"format\":1,\n\"scenario\": }")).startsWith("t.task.json:2: not valid JSON");
  }

  /** A task on the two-robot example cell, written next to a copy of it. */
  private String readCell(String json) throws Exception {
    Files.copy(Path.of("scenarios/two-robot-handshake.json"), dir.resolve("cell2.json"));
    Files.createDirectories(dir.resolve("programs"));
    Files.copy(Path.of("scenarios/programs/LOADER.LS"), dir.resolve("programs/LOADER.LS"));
    Files.copy(Path.of("scenarios/programs/UNLOADER.LS"), dir.resolve("programs/UNLOADER.LS"));
    Path f = dir.resolve("t.task.json");
    Files.writeString(f, json);
    TaskLoad l = TaskReader.read(f);
    return l instanceof TaskLoad.Failed failed ? failed.message().replace(f.toString(), "t.task.json") : "loaded";
  }

  @Test
  void robotsAndRobotFieldsNameRobotsOfTheScenarioAndOnlyRobotChecksTakeARobot() throws Exception {
    String msg = readCell("""
        {"format": 1, "scenario": "cell2.json",
         "robots": {"robot1": {"program": "X"}, "robot9": {"program": "Y"}, "robot2": {"prog": "Z"}},
         "checks": [
           {"name": "a", "type": "runsToEnd", "points": 1, "robot": "robot3"},
           {"name": "b", "type": "partAt", "points": 1, "robot": "robot2", "part": "part1", "fixture": "tray",
            "position": {"x": 0, "y": 0, "z": 10}},
           {"name": "c", "type": "endState", "points": 1, "robot": "robot2", "values": {"DO[1]": true}}
         ]}
        """);
    assertThat(msg.lines().toList()).containsExactly(
        "t.task.json:2: robots.robot1: the first robot's program is the task's \"program\"; list only the robots after it here",
        "t.task.json:2: robots.robot9: the scenario has no robot \"robot9\" (robots: robot1, robot2)",
        "t.task.json:2: robots.robot2.prog: unknown field (expected one of: program)",
        "t.task.json:2: robots.robot2.program: missing: expected a string",
        "t.task.json:4: checks[0].robot: the scenario has no robot \"robot3\" (robots: robot1, robot2)",
        "t.task.json:5: checks[1].robot: a partAt check looks at the whole cell; \"robot\" is for cycleTime, endState, "
            + "frame, noMotionStop, programUse, runsToEnd checks");
  }

  @Test
  void robotsAfterTheFirstRunTheirScenarioMainProgramUnlessTheTaskNamesAnother() throws Exception {
    assertThat(readCell("{\"format\":1,\"scenario\":\"cell2.json\",\"checks\":[{\"name\":\"end\",\"type\":\"runsToEnd\","
        + "\"points\":1,\"robot\":\"robot2\"}]}")).isEqualTo("loaded");
    Task t = ((TaskLoad.Loaded) TaskReader.read(dir.resolve("t.task.json"))).task();
    assertThat(t.program()).isEqualTo("LOADER");
    assertThat(t.otherPrograms()).containsExactly(java.util.Map.entry("robot2", "UNLOADER"));
    assertThat(t.checks().get(0).meta().robot()).contains("robot2");
    Files.writeString(dir.resolve("t.task.json"), "{\"format\":1,\"scenario\":\"cell2.json\",\"robots\":{\"robot2\":"
        + "{\"program\":\"other\"}},\"checks\":[{\"name\":\"end\",\"type\":\"runsToEnd\",\"points\":1}]}");
    Task t2 = ((TaskLoad.Loaded) TaskReader.read(dir.resolve("t.task.json"))).task();
    assertThat(t2.otherPrograms()).containsExactly(java.util.Map.entry("robot2", "OTHER"));
    assertThat(t2.checks().get(0).meta().robot()).isEmpty();
  }
}
