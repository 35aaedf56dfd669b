package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.render.GlTestSupport;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** {@code robotrun grade} end to end: console, Gradescope JSON, CSV and HTML. */
class GradeCommandTest {
  private static final String TASK = "scenarios/tasks/pick-and-place.task.json";
  private static final String SUBS = "tests/resources/grade/";

  private record Run(int exit, String out, String err) {}

  private static Run run(String... args) {
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    CommandLine cl = Main.commandLine();
    cl.setOut(new PrintWriter(out, true));
    cl.setErr(new PrintWriter(err, true));
    return new Run(cl.execute(args), out.toString(), err.toString());
  }

  @Test
  void aBadTaskIsExitTwoWithFileAndLine(@TempDir Path dir) throws Exception {
    Path task = dir.resolve("t.json");
    Files.writeString(task, "{\"format\": 1,\n \"scenario\": \"x.json\", \"checks\": 3}");
    Run r = run("grade", "--task", task.toString(), SUBS + "reference");
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).startsWith("robotrun: " + task + ":2: scenario: scenario file not found");
    assertThat(r.err()).contains(task + ":2: checks: expected an array, got the number 3")
        .doesNotContain("missing");
  }

  @Test
  void writesGradescopeResultsCsvAndHtml(@TempDir Path dir) throws Exception {
    Path out = dir.resolve("out");
    Run r = run("grade", "--task", TASK, "--out", out.toString(), "--no-pictures", "--jobs", "2",
        SUBS + "two-parts", SUBS + "typo");
    assertThat(r.exit()).as(r.err()).isZero();
    assertThat(r.out()).contains("two-parts: 85 of 105 points\n").contains("typo: 0 of 105 points\n")
        .contains("  FAIL 0/10 part3 on the tray\n       part3 rests on the table, not on the tray (it was not moved)\n");

    JsonNode json = new ObjectMapper().readTree(out.resolve("two-parts/results.json").toFile());
    assertThat(json.get("score").asDouble()).isEqualTo(85);
    assertThat(json.get("tests")).hasSize(16);
    JsonNode part3 = json.get("tests").get(7);
    assertThat(part3.get("name").asText()).isEqualTo("part3 on the tray");
    assertThat(part3.get("score").asDouble()).isZero();
    assertThat(part3.get("max_score").asDouble()).isEqualTo(10);
    assertThat(part3.get("visibility").asText()).isEqualTo("visible");
    assertThat(part3.get("output").asText()).startsWith("part3 rests on the table");
    assertThat(json.get("tests").get(9).get("visibility").asText()).isEqualTo("hidden");

    List<String> csv = Files.readAllLines(out.resolve("summary.csv"));
    assertThat(csv).hasSize(3);
    assertThat(csv.get(0)).startsWith("submission,student,folder,score,max_score,Hand-in,Programs read,");
    assertThat(csv.get(1)).startsWith("two-parts,,two-parts,85,105,0,5,10,5,5,10,10,0,");

    String html = Files.readString(out.resolve("typo/report.html"));
    assertThat(html).contains("<b>0 of 105</b>").contains("programs/PICKPLACE.LS:38: expected a value (number, R[i], PR[i,j], DI[i], F[i], TIMER[i], AR[i], ON, OFF or &#39;(&#39;), found &#39;OON&#39;");
  }

  @Test
  void writesOneGradescopeFileForTheAutograder(@TempDir Path dir) throws Exception {
    Path results = dir.resolve("results.json");
    Run r = run("grade", "--task", TASK, "--gradescope", results.toString(), "-q", SUBS + "slow");
    assertThat(r.exit()).as(r.err()).isZero();
    assertThat(r.out()).isEqualTo("slow: 90 of 105 points\n");
    assertThat(new ObjectMapper().readTree(results.toFile()).get("score").asDouble()).isEqualTo(90);
    assertThat(run("grade", "--task", TASK, "--gradescope", results.toString(), SUBS + "slow", SUBS + "typo").err())
        .startsWith("robotrun: --gradescope: grade exactly one submission (got 2)");
  }

  @Test
  void theReportShowsTheCellAndWhereAFailedPartEnded(@TempDir Path dir) throws Exception {
    GlTestSupport.rendererOrSkip(16, 16).close();
    Path out = dir.resolve("out");
    Run r = run("grade", "--task", TASK, "--out", out.toString(), "-q", SUBS + "two-parts");
    assertThat(r.exit()).as(r.err()).isZero();
    String html = Files.readString(out.resolve("two-parts/report.html"));
    // The overview and one picture for each failed part check (part3, nominal and variations).
    assertThat(html.split("src=\"data:image/png;base64,", -1)).hasSize(4);
  }

  @Test
  void folderNamesAreSafeAndUnique() {
    var used = new java.util.HashSet<String>(java.util.Set.of("summary.csv"));
    assertThat(GradeCommand.uniqueFolder("summary.csv", used)).isEqualTo("summary.csv-2");
    assertThat(GradeCommand.uniqueFolder("../../etc.zip", used)).isEqualTo("submission.._.._etc");
    assertThat(GradeCommand.uniqueFolder("Ann Lee.zip", used)).isEqualTo("Ann_Lee");
    assertThat(GradeCommand.uniqueFolder("Ann_Lee.ZIP", used)).isEqualTo("Ann_Lee-2");
  }

  @Test
  void namesFromSubmissionsCannotDriveTheTerminal(@TempDir Path dir) throws Exception {
    Path evil = Files.createDirectories(dir.resolve("evil\u001b[2Jname"));
    Files.copy(Path.of(SUBS + "reference/programs/PICKPLACE.LS"), evil.resolve("PICKPLACE.LS"));
    Run r = run("grade", "--task", TASK, "-q", evil.toString());
    assertThat(r.exit()).isZero();
    assertThat(r.out()).doesNotContain("\u001b").startsWith("evil\\e[2Jname: 100 of 105 points");
  }

  @Test
  void aTwoRobotFolderRunsBothRobotsAndEveryRobotCheckNamesItsRobot(@TempDir Path dir) throws Exception {
    Path sub = dir.resolve("cell-folder");
    Files.createDirectories(sub.resolve("robot2"));
    Files.copy(Path.of("scenarios/programs/LOADER.LS"), sub.resolve("LOADER.LS"));
    Files.copy(Path.of("scenarios/programs/UNLOADER.LS"), sub.resolve("robot2/UNLOADER.LS"));
    Path out = dir.resolve("out");
    Run r = run("grade", "--task", "scenarios/tasks/two-robot-handshake.task.json", "--out", out.toString(),
        "--no-pictures", sub.toString());
    assertThat(r.exit()).as(r.err()).isZero();
    assertThat(r.out()).contains("cell-folder: 95 of 100 points\n")
        .contains("  PASS 10/10 robot2 runs to the end\n       robot2: the program ran to its end in 10.30 s\n")
        .contains("  PASS 5/5 robot2 handshake outputs\n       robot2: DO[1] = ON, R[1] = 3\n");
    JsonNode json = new ObjectMapper().readTree(out.resolve("cell-folder/results.json").toFile());
    assertThat(json.get("tests").get(3).get("output").asText()).startsWith("robot2: the program ran to its end");
  }

  @Test
  void outputsThatCannotBeWrittenAreExitTwoBeforeAnyGrading(@TempDir Path dir) throws Exception {
    for (String[] o : List.of(new String[] {"--out", "/proc/robotrun-out"},
        new String[] {"--gradescope", "/proc/self/results.json"},
        new String[] {"--gradescope", dir.resolve("no/such/folder/results.json").toString()},
        new String[] {"--out", Files.writeString(dir.resolve("a-file"), "x").toString()})) {
      long t0 = System.nanoTime();
      Run r = run("grade", "--task", TASK, "-q", o[0], o[1], SUBS + "reference");
      assertThat(r.exit()).as(String.join(" ", o)).isEqualTo(2);
      assertThat(r.err()).startsWith("robotrun: " + o[0] + ": ").doesNotContain("internal error").doesNotContain("\tat ");
      assertThat(r.out()).as("nothing graded").isEmpty();
      assertThat((System.nanoTime() - t0) / 1e9).as("seconds").isLessThan(5);
    }
  }

  @Test
  void summaryCsvEscapesControlCharactersOfStudentNames() {
    assertThat(GradeReports.csv("Eve\u0000\u001b[2J\rMallory")).isEqualTo("Eve\\u0000\\e[2J\\rMallory");
    assertThat(GradeReports.csv("two\nlines")).isEqualTo("two\\nlines");
    assertThat(GradeReports.csv("=cmd, x")).isEqualTo("\"'=cmd, x\"");
  }

  /** Issue 26: programs/*.LS and programs/ROBOT/*.LS without cell.json, as docs/grading.md lays it out, scored 0. */
  @Test
  void aFolderLaidOutAsAWorkspaceWithoutCellJsonIsGraded(@TempDir Path dir) throws Exception {
    Path sub = dir.resolve("laid-out");
    Files.createDirectories(sub.resolve("programs/robot2"));
    Files.copy(Path.of("scenarios/programs/LOADER.LS"), sub.resolve("programs/LOADER.LS"));
    Files.copy(Path.of("scenarios/programs/UNLOADER.LS"), sub.resolve("programs/robot2/UNLOADER.LS"));
    Run r = run("grade", "--task", "scenarios/tasks/two-robot-handshake.task.json", "-q", sub.toString());
    assertThat(r.exit()).as(r.err()).isZero();
    assertThat(r.out()).isEqualTo("laid-out: 95 of 100 points\n");
  }
}
