package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The example task scenarios/tasks/pick-and-place.task.json against its reference solution and
 * the typical wrong submissions in tests/resources/grade/: each scores exactly what it should,
 * for the reasons it should.
 */
class ExampleTaskTest {
  private static final Path TASK = Path.of("scenarios/tasks/pick-and-place.task.json");
  private static final Path SUBMISSIONS = Path.of("tests/resources/grade");
  private static Grader grader;

  @TempDir static Path dir;

  @BeforeAll
  static void loadTask() {
    TaskLoad.Loaded l = (TaskLoad.Loaded) TaskReader.read(TASK);
    grader = new Grader(l.task(), l.scenario());
  }

  private static GradeResult gradeZip(String name) throws Exception {
    Path zip = HandIns.zip(SUBMISSIONS.resolve(name), "Ada " + name, dir.resolve(name + ".zip"));
    return Grading.gradeOne(grader, new SubmissionLoader(), zip, true);
  }

  @Test
  void theTaskIsWorth105PointsOf90Visible() {
    assertThat(grader.task().maxPoints()).isEqualTo(105);
    assertThat(grader.task().visiblePoints()).isEqualTo(90);
    assertThat(grader.task().variations().count()).isEqualTo(5);
  }

  @Test
  void referenceSolutionScoresFullMarks() throws Exception {
    GradeResult r = gradeZip("reference");
    assertThat(HandIns.failed(r)).isEmpty();
    assertThat(r.score()).isEqualTo(105);
    assertThat(r.student()).isEqualTo("Ada reference");
    assertThat(r.runs()).hasSize(6);
    assertThat(HandIns.check(r, "part2 on the tray").feedback())
        .isEqualTo("part2 is 0.0 mm from its place on the tray (allowed 3 mm)");
    assertThat(HandIns.check(r, "Parts found where they are").feedback()).startsWith("passed in all 5 runs");
  }

  @Test
  void hardCodedPickPositionsFailOnlyTheVariations() throws Exception {
    GradeResult r = gradeZip("hardcoded");
    assertThat(HandIns.failed(r)).containsExactly("Parts found where they are", "Variations: part2", "Variations: part3");
    assertThat(r.score()).isEqualTo(90);
    CheckResult c = HandIns.check(r, "Parts found where they are");
    assertThat(c.feedback()).matches("(?s)In the variation 1 \\(override \\d+%\\): part1 is \\d+\\.\\d mm from its place "
        + "on the tray \\(allowed 3 mm\\)\nThe parts are not always in the same place.*");
    assertThat(c.failedRun()).contains(1);
    assertThat(c.focus_C()).isPresent();
  }

  @Test
  void twoPartsOnlyLosesThePart3Checks() throws Exception {
    GradeResult r = gradeZip("two-parts");
    assertThat(HandIns.failed(r)).containsExactly("part3 on the tray", "Variations: part3");
    assertThat(r.score()).isEqualTo(90);
    assertThat(HandIns.check(r, "part3 on the tray").feedback())
        .startsWith("part3 rests on the table, not on the tray (it was not moved)");
  }

  @Test
  void aSlowProgramFailsTheCycleTime() throws Exception {
    GradeResult r = gradeZip("slow");
    assertThat(HandIns.failed(r)).containsExactly("Cycle time");
    assertThat(r.score()).isEqualTo(95);
    assertThat(HandIns.check(r, "Cycle time").feedback()).matches("(?s)cycle time 1\\d\\.\\d\\d s \\(allowed 10 s\\)\nToo slow.*");
  }

  @Test
  void aJmpLoopFailsTheProgramStructure() throws Exception {
    GradeResult r = gradeZip("jmp-loop");
    assertThat(HandIns.failed(r)).containsExactly("Program structure");
    assertThat(r.score()).isEqualTo(95);
    assertThat(HandIns.check(r, "Program structure").feedback()).startsWith(
        "the programs do not use a FOR loop; PICKPLACE line 28 uses a JMP to a label above it, which this task does not allow");
  }

  @Test
  void aTypoFailsEverythingButTheHandInAndSaysWhere() throws Exception {
    GradeResult r = gradeZip("typo");
    assertThat(r.score()).isEqualTo(5);
    assertThat(HandIns.check(r, "Hand-in").passed()).isTrue();
    assertThat(HandIns.check(r, "Programs read").feedback()).contains("programs/PICKPLACE.LS:38: ").contains("found 'OON'");
    assertThat(HandIns.check(r, "Runs to the end").feedback()).startsWith("not run: the programs have errors");
    assertThat(r.runs()).isEmpty();
  }

  @Test
  void aWorkspaceFolderIsGradedButIsNotAHandIn() throws Exception {
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), SUBMISSIONS.resolve("reference"), true);
    assertThat(HandIns.failed(r)).containsExactly("Hand-in");
    assertThat(HandIns.check(r, "Hand-in").feedback()).startsWith("a workspace folder, not a hand-in .zip");
  }

  @Test
  void aFolderOfProgramsRunsOnTheTasksScenario() throws Exception {
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), SUBMISSIONS.resolve("reference/programs"), true);
    assertThat(HandIns.failed(r)).containsExactly("Hand-in");
  }

  @Test
  void aChangedFileFailsTheHandInCheckOnly() throws Exception {
    Path zip = HandIns.zip(SUBMISSIONS.resolve("reference"), "Bob", dir.resolve("tampered.zip"));
    // Re-zip with the manifest of the original but a program edited afterwards.
    var entries = new java.util.LinkedHashMap<String, byte[]>();
    try (var z = new java.util.zip.ZipInputStream(Files.newInputStream(zip))) {
      for (var e = z.getNextEntry(); e != null; e = z.getNextEntry()) {
        entries.put(e.getName(), z.readAllBytes());
      }
    }
    String ls = new String(entries.get("programs/PICKPLACE.LS"), java.nio.charset.StandardCharsets.UTF_8);
    entries.put("programs/PICKPLACE.LS", ls.replace("3 parts onto the tray", "3 parts onto the TRAY")
        .getBytes(java.nio.charset.StandardCharsets.UTF_8));
    Files.write(zip, HandIns.rawZip(entries));
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), zip, true);
    assertThat(HandIns.failed(r)).containsExactly("Hand-in");
    assertThat(HandIns.check(r, "Hand-in").feedback()).startsWith(
        "\"programs/PICKPLACE.LS\" was changed after the hand-in was made (its SHA-256 does not match manifest.json)");
  }

  @Test
  void aStudentsCheckLeavesHiddenChecksOut() throws Exception {
    Path zip = HandIns.zip(SUBMISSIONS.resolve("hardcoded"), "Cy", dir.resolve("student.zip"));
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), zip, false);
    assertThat(r.checks()).noneMatch(CheckResult::hidden);
    assertThat(r.maxScore()).isEqualTo(90);
    assertThat(HandIns.failed(r)).isEqualTo(List.of("Parts found where they are"));
  }

  @Test
  void variationsAreTheSameEveryTime() throws Exception {
    GradeResult a = gradeZip("hardcoded");
    GradeResult b = gradeZip("hardcoded");
    assertThat(a.checks()).extracting(CheckResult::feedback).isEqualTo(b.checks().stream().map(CheckResult::feedback).toList());
  }

  @Test
  void checkMyWorkRunsTheVisibleChecksOnProgramsInMemory() throws Exception {
    var program = org.robotrun.io.LsReader.read(SUBMISSIONS.resolve("hardcoded/programs/PICKPLACE.LS")).program();
    GradeResult r = grader.checkMyWork(List.of(program), java.util.Map.of(), java.util.Map.of(), java.util.Map.of());
    assertThat(r.checks()).noneMatch(CheckResult::hidden).noneMatch(c -> c.check() instanceof Check.HandIn);
    assertThat(r.maxScore()).isEqualTo(85);
    assertThat(HandIns.failed(r)).containsExactly("Parts found where they are");
    assertThat(r.score()).isEqualTo(80);
  }

  @Test
  void checkMyWorkUsesTheStudentsFrames() throws Exception {
    var program = org.robotrun.io.LsReader.read(SUBMISSIONS.resolve("reference/programs/PICKPLACE.LS")).program();
    // UFRAME 1 taught 30 mm too high: the gripper closes above part1, finds nothing and the program alarms.
    var uf1 = org.robotrun.math.Transform.translation(220, -350, -70);
    GradeResult r = grader.checkMyWork(List.of(program), java.util.Map.of(), java.util.Map.of(1, uf1), java.util.Map.of());
    assertThat(HandIns.check(r, "part1 on the tray").feedback()).startsWith("part1 rests on the table, not on the tray (it was not moved)");
    assertThat(HandIns.check(r, "Runs to the end").feedback()).startsWith("the program stopped with alarm INTP-213 (PICKPLACE, 31)");
  }

  @Test
  void checkMyWorkKeepsTheStudentsPositionRegistersButTheTaskWritesItsOffsets() throws Exception {
    var program = org.robotrun.io.LsReader.read(SUBMISSIONS.resolve("reference/programs/PICKPLACE.LS")).program();
    var off = new org.robotrun.program.Position.Cartesian(30, 0, 0, 0, 0, 0, org.robotrun.program.Config.DEFAULT);
    // PR[4] (PLACE OFS, only its x is set by the program) taught 30 mm off in y: every part lands 30 mm off.
    var placeY = new org.robotrun.program.Position.Cartesian(0, 30, 0, 0, 0, 0, org.robotrun.program.Config.DEFAULT);
    GradeResult r = grader.checkMyWork(List.of(program), java.util.Map.of(), java.util.Map.of(), java.util.Map.of(),
        java.util.Map.of(4, placeY, 11, off));
    assertThat(HandIns.check(r, "part1 on the tray").feedback())
        .startsWith("part1 is 30.0 mm from its place on the tray (allowed 3 mm)");
    // PR[11] is the task's: the student's value is overwritten, so the pick is not 30 mm off.
    assertThat(HandIns.check(r, "Runs to the end").passed()).isTrue();
  }

  @Test
  void aHandInWrittenByTheWorkspaceHandInScoresFullMarks() throws Exception {
    // The contract between the two sides: io.HandIn writes, the grader reads.
    Path ws = dir.resolve("ws-ref");
    Files.createDirectories(ws.resolve("programs"));
    Files.copy(SUBMISSIONS.resolve("reference/cell.json"), ws.resolve("cell.json"));
    Files.copy(SUBMISSIONS.resolve("reference/programs/PICKPLACE.LS"), ws.resolve("programs/PICKPLACE.LS"));
    Path zip = dir.resolve("handin.zip");
    org.robotrun.io.HandIn.write(ws, zip, "Grace Hopper", "0.1.0-SNAPSHOT", false);
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), zip, true);
    assertThat(HandIns.failed(r)).isEmpty();
    assertThat(r.student()).isEqualTo("Grace Hopper");
  }

  @Test
  void aHandInWithTheCellEditorsOtherScenariosStillScoresFullMarks() throws Exception {
    // scenarios/NAME.json (the cell editor's other scenarios) ride along in the hand-in; grading ignores them
    Path ws = dir.resolve("ws-ref2");
    Files.createDirectories(ws.resolve("programs"));
    Files.createDirectories(ws.resolve("scenarios"));
    Files.copy(SUBMISSIONS.resolve("reference/cell.json"), ws.resolve("cell.json"));
    Files.copy(SUBMISSIONS.resolve("reference/programs/PICKPLACE.LS"), ws.resolve("programs/PICKPLACE.LS"));
    Files.copy(Path.of("scenarios/empty-cell.json"), ws.resolve("scenarios/practice.json"));
    Path zip = dir.resolve("handin2.zip");
    var m = org.robotrun.io.HandIn.write(ws, zip, "Grace Hopper", "0.1.0-SNAPSHOT", false);
    assertThat(m.files()).containsKey("scenarios/practice.json");
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), zip, true);
    assertThat(HandIns.failed(r)).isEmpty();
    assertThat(r.student()).isEqualTo("Grace Hopper");
  }
}
