package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class BenchGradeCommandTest {
  @Test
  void printsOneSummaryLineWithTheMeanScore() {
    StringWriter out = new StringWriter();
    CommandLine cl = Main.commandLine();
    cl.setOut(new PrintWriter(out, true));
    int exit = cl.execute("bench", "grade", "--task", "scenarios/tasks/pick-and-place.task.json", "--count", "2",
        "--jobs", "1", "tests/resources/grade/slow", "tests/resources/grade/typo");
    assertThat(exit).isZero();
    assertThat(out.toString()).matches("task=pick-and-place.task.json submissions=2 jobs=1 runs=6 wall_s=\\d+\\.\\d\\d "
        + "cpu_s=\\d+\\.\\d\\d per_submission_ms=\\d+\\.\\d mean_score=45\\.0 peak_heap_mb=\\d+\\n");
  }

  @Test
  void variationsReplaceTheTasksCount() {
    StringWriter out = new StringWriter();
    CommandLine cl = Main.commandLine();
    cl.setOut(new PrintWriter(out, true));
    int exit = cl.execute("bench", "grade", "--task", "scenarios/tasks/pick-and-place.task.json", "--count", "1",
        "--jobs", "1", "--variations", "2", "tests/resources/grade/slow");
    assertThat(exit).isZero();
    // The nominal run and two variations (the task has five).
    assertThat(out.toString()).contains(" runs=3 ");
  }
}
