package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Grading a class: results in order; without their runs when nothing needs them, scores unchanged. */
class GradingTest {
  @Test
  void resultsWithoutRunsKeepTheirScoresAndTheCallbackSeesTheRuns() {
    TaskLoad.Loaded t = (TaskLoad.Loaded) TaskReader.read(Path.of("scenarios/tasks/pick-and-place.task.json"));
    Grader g = new Grader(t.task(), t.scenario());
    List<Path> subs = List.of(Path.of("tests/resources/grade/slow"), Path.of("tests/resources/grade/typo"));
    List<Integer> seen = new ArrayList<>();
    List<GradeResult> kept = Grading.gradeAll(g, new SubmissionLoader(), subs, 2, true, r -> { });
    List<GradeResult> lean = Grading.gradeAll(g, new SubmissionLoader(), subs, 2, true, false,
        r -> {
          synchronized (seen) {
            seen.add(r.runs().size());
          }
        });
    assertThat(lean).extracting(GradeResult::score).containsExactly(kept.get(0).score(), kept.get(1).score());
    assertThat(lean).extracting(GradeResult::submission).containsExactly("slow", "typo");
    assertThat(lean).allSatisfy(r -> assertThat(r.runs()).isEmpty());
    assertThat(kept.get(0).runs()).hasSize(6);
    assertThat(seen).containsExactlyInAnyOrder(6, 0);
  }
}
