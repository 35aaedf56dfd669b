package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 26: a cell its PLC starts (production.robot1.runStartsFromPlc) could not be graded: the
 * grader started the program itself and the scripted PLC's start of the same program clashed with
 * it. The grader now starts such a cell through its PLC, as {@code robotrun run} does.
 */
class PlcStartedTaskTest {
  private static final String SCENARIO = Path.of("scenarios/plc-cell.json").toAbsolutePath().toString()
      .replace("\\", "/");

  private static Grader grader(Path dir) throws Exception {
    Path t = dir.resolve("plc.task.json");
    Files.writeString(t, """
        {"format": 1, "title": "PLC start", "scenario": "%s", "program": "PNS0001",
         "limits": {"simSeconds": 60, "wallSeconds": 60},
         "checks": [
           {"name": "Runs to the end", "type": "runsToEnd", "points": 10, "message": "end"},
           {"name": "Back at HOME", "type": "endState", "points": 10, "values": {"DO[10]": true}, "message": "home"}
         ]}
        """.formatted(SCENARIO));
    TaskLoad l = TaskReader.read(t);
    assertThat(l).isInstanceOf(TaskLoad.Loaded.class);
    return new Grader(((TaskLoad.Loaded) l).task(), ((TaskLoad.Loaded) l).scenario());
  }

  private static Path submission(Path dir, String name, String... programs) throws Exception {
    Path sub = dir.resolve(name);
    Files.createDirectories(sub);
    for (String p : programs) {
      Files.copy(Path.of("scenarios/programs/" + p + ".LS"), sub.resolve(p + ".LS"));
    }
    return sub;
  }

  @Test
  void thePlcStartsTheJobAndTheReferenceProgramsScoreFullMarks(@TempDir Path dir) throws Exception {
    GradeResult r = Grading.gradeOne(grader(dir), new SubmissionLoader(),
        submission(dir, "ok", "PNS0001", "PNS0002", "BGLIGHT"), true);
    assertThat(HandIns.failed(r)).isEmpty();
    assertThat(r.score()).isEqualTo(20);
    // started through the PLC: its PNSTROBE selected job 1 (SNO1, UO[11], is ON only after that)
    assertThat(r.runs().get(0).registers().bit(org.robotrun.program.IoKind.UO, 11)).isTrue();
    // and only by it: a start of the grader's own made the PLC's refused (INTP-105, PROG-007)
    assertThat(r.runs().get(0).warnings()).isEmpty();
    // the run was the PLC's: no refused start, no clash
    assertThat(r.runs().get(0).alarm()).isEmpty();
  }

  @Test
  void aJobThePlcCannotStartFailsSayingWhy(@TempDir Path dir) throws Exception {
    Grader g = grader(dir);
    // PNS0001 missing (the PLC selects it)
    GradeResult r = Grading.gradeOne(g, new SubmissionLoader(), submission(dir, "none", "PNS0002", "BGLIGHT"), true);
    assertThat(HandIns.failed(r)).contains("Runs to the end");
    assertThat(r.checks().get(0).measured()).contains("no program PNS0001");
    // the BG Logic program the cell's production names is missing: the cell cannot start
    GradeResult bg = Grading.gradeOne(g, new SubmissionLoader(), submission(dir, "nobg", "PNS0001", "PNS0002"), true);
    assertThat(HandIns.failed(bg)).contains("Runs to the end");
    assertThat(bg.checks().get(0).measured()).contains("backgroundLogic[0]").contains("BGLIGHT");
  }
}
