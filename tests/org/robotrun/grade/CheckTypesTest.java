package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The check types the example task does not use, each on a small task of its own. */
class CheckTypesTest {
  private static final Path REFERENCE = Path.of("tests/resources/grade/reference");

  @TempDir Path dir;

  private GradeResult grade(String checks, Path submission) throws Exception {
    Path task = dir.resolve("t.task.json");
    Files.writeString(task, "{\"format\": 1, \"scenario\": \"" + Path.of("scenarios/pick-and-place.json").toAbsolutePath()
        + "\", \"checks\": [" + checks + "]}");
    TaskLoad l = TaskReader.read(task);
    assertThat(l).as(l instanceof TaskLoad.Failed f ? f.message() : "").isInstanceOf(TaskLoad.Loaded.class);
    TaskLoad.Loaded t = (TaskLoad.Loaded) l;
    return Grading.gradeOne(new Grader(t.task(), t.scenario()), new SubmissionLoader(), submission, true);
  }

  /** The reference workspace with its cell.json edited. */
  private Path workspace(String from, String to) throws Exception {
    Path ws = Files.createDirectories(dir.resolve("ws/programs"));
    Files.copy(REFERENCE.resolve("programs/PICKPLACE.LS"), ws.resolve("PICKPLACE.LS"));
    String cell = Files.readString(REFERENCE.resolve("cell.json"));
    assertThat(cell).contains(from);
    Files.writeString(dir.resolve("ws/cell.json"), cell.replace(from, to));
    return dir.resolve("ws");
  }

  @Test
  void aTaughtFrameIsComparedWithTheTrueOne() throws Exception {
    String check = "{\"name\": \"uf1\", \"type\": \"frame\", \"points\": 4, \"frame\": \"UF[1]\","
        + " \"pose\": {\"x\": 220, \"y\": -350, \"z\": -100, \"w\": 0, \"p\": 0, \"r\": 0}}";
    assertThat(grade(check, REFERENCE).checks().get(0).feedback())
        .isEqualTo("UF[1] is 0.00 mm and 0.00 deg from the true frame (allowed 1 mm, 1 deg)");
    GradeResult off = grade(check, workspace("\"x\": 220", "\"x\": 223"));
    assertThat(off.score()).isZero();
    assertThat(off.checks().get(0).feedback()).isEqualTo("UF[1] is 3.00 mm and 0.00 deg from the true frame (allowed 1 mm, 1 deg)");
  }

  @Test
  void aCellJsonThatDoesNotLoadIsANoteAndTheTasksFramesAreUsed() throws Exception {
    String check = "{\"name\": \"uf1\", \"type\": \"frame\", \"points\": 4, \"frame\": \"UF[1]\","
        + " \"pose\": {\"x\": 220, \"y\": -350, \"z\": -100, \"w\": 0, \"p\": 0, \"r\": 0}}";
    GradeResult r = grade(check, workspace("\"format\": 1", "\"format\": 1, \"bogus\": 2"));
    assertThat(r.checks().get(0).passed()).isTrue();
    assertThat(r.checks().get(0).feedback()).isEqualTo("UF[1] is 0.00 mm and 0.00 deg from the true frame (allowed 1 mm, 1 deg)"
        + "\nnote: cell.json:2: bogus: unknown field (expected one of: camera, description, format, frames, mainProgram, "
        + "mode, name, objects, onCollision, production, programs, registers, robots, state, vision, wiring) (so the task's frames and registers were used)");
  }

  @Test
  void aWorkspacesSavedStateGivesTheRunItsRegistersAndPositionRegisters() throws Exception {
    Path ws = workspace("\"format\": 1,", "\"format\": 1, \"state\": {\"registers\": {\"2\": 1},"
        + " \"positionRegisters\": {\"4\": {\"x\": 0, \"y\": 30, \"z\": 0, \"w\": 0, \"p\": 0, \"r\": 0,"
        + " \"config\": \"N U T, 0, 0, 0\"}}},");
    GradeResult r = grade("{\"name\": \"count\", \"type\": \"endState\", \"points\": 1, \"values\": {\"R[2]\": 1}},"
        + "{\"name\": \"p1\", \"type\": \"partAt\", \"points\": 1, \"part\": \"part1\", \"fixture\": \"tray\","
        + " \"position\": {\"x\": -50, \"y\": 0, \"z\": 10}}", ws);
    // R[2] = 1 from the state: one part only; PR[4] (place offset, y taught 30 mm) from the state.
    assertThat(HandIns.check(r, "count").passed()).isTrue();
    assertThat(HandIns.check(r, "p1").feedback()).startsWith("part1 is 30.0 mm from its place on the tray");
  }

  @Test
  void endStateReadsRegistersAndOutputs() throws Exception {
    GradeResult r = grade("{\"name\": \"end\", \"type\": \"endState\", \"points\": 1,"
        + " \"values\": {\"R[2]\": 3, \"RO[1]\": true, \"DO[2]\": false}}", REFERENCE);
    assertThat(r.checks().get(0).feedback()).isEqualTo("RO[1] is OFF, expected ON");
    r = grade("{\"name\": \"end\", \"type\": \"endState\", \"points\": 1, \"values\": {\"R[2]\": 3, \"RO[1]\": false}}",
        REFERENCE);
    assertThat(r.checks().get(0).passed()).isTrue();
    assertThat(r.checks().get(0).feedback()).isEqualTo("R[2] = 3, RO[1] = OFF");
  }

  @Test
  void anExpectedAlarmIsAPass() throws Exception {
    // Without COUNT the loop runs once more than there are parts: the gripper closes on nothing, UALM[1].
    Path ws = workspace("\"2\": 3", "\"2\": 4");
    GradeResult r = grade("{\"name\": \"alarm\", \"type\": \"runsToEnd\", \"points\": 1, \"alarm\": \"INTP-213\"},"
        + "{\"name\": \"end\", \"type\": \"runsToEnd\", \"points\": 1},"
        + "{\"name\": \"held\", \"type\": \"nothingHeld\", \"points\": 1},"
        + "{\"name\": \"dropped\", \"type\": \"noneDropped\", \"points\": 1},"
        + "{\"name\": \"cycle\", \"type\": \"cycleTime\", \"points\": 1, \"maxSec\": 100}", ws);
    assertThat(HandIns.check(r, "alarm").passed()).isTrue();
    assertThat(HandIns.check(r, "end").feedback()).isEqualTo("the program stopped with alarm INTP-213 (PICKPLACE, 31) UALM[1]");
    assertThat(HandIns.check(r, "held").passed()).isTrue();
    assertThat(HandIns.check(r, "dropped").passed()).isTrue();
    assertThat(HandIns.check(r, "cycle").feedback()).startsWith("the program did not reach its end, so it has no cycle time");
  }

  @Test
  void aProgramThatLetsGoInTheAirIsCaught() throws Exception {
    Path ws = Files.createDirectories(dir.resolve("air/programs"));
    String ls = Files.readString(REFERENCE.resolve("programs/PICKPLACE.LS"))
        .replace("L P[3:PLACE] 300mm/sec FINE Offset,PR[4:PLACE OFS]", "L P[3:PLACE] 300mm/sec FINE Offset,PR[6:PLACE UP]");
    Files.writeString(ws.resolve("PICKPLACE.LS"), ls);
    GradeResult r = grade("{\"name\": \"dropped\", \"type\": \"noneDropped\", \"points\": 1},"
        + "{\"name\": \"p1\", \"type\": \"partAt\", \"points\": 1, \"part\": \"part1\", \"fixture\": \"tray\","
        + " \"position\": {\"x\": -50, \"y\": 0, \"z\": 10}}", ws);
    // part1 is let go 60 mm above the tray (the run may stop later, e.g. at the part left hanging in the air).
    assertThat(HandIns.check(r, "dropped").feedback()).startsWith("let go in the air, not on a fixture: part1");
    assertThat(HandIns.check(r, "p1").feedback()).startsWith("part1 was let go in the air at (350.0, 180.0, ");
  }

  @Test
  void programUseCountsMotionLinesAndFeatures() throws Exception {
    GradeResult r = grade("{\"name\": \"use\", \"type\": \"programUse\", \"points\": 1, \"requires\": [\"call\"],"
        + " \"forbids\": [\"wait\"], \"maxMotionLines\": 4}", REFERENCE);
    assertThat(r.checks().get(0).feedback()).isEqualTo("the programs do not use a CALL; PICKPLACE line 18 uses a WAIT, "
        + "which this task does not allow; 8 motion lines (allowed 4)");
  }
}
