package org.robotrun.grade;

import java.util.List;

/**
 * A graded submission.
 *
 * @param submission the submission's name (zip or folder)
 * @param student the student's name from the manifest ("" when none)
 * @param checks every check, in the task's order (hidden ones included unless left out on request)
 * @param runs the simulated runs (nominal first); empty when the programs could not run
 * @param wallSec wall-clock seconds spent on this submission
 */
public record GradeResult(String submission, String student, List<CheckResult> checks, List<RunOutcome> runs,
    double wallSec) {

  public GradeResult {
    checks = List.copyOf(checks);
    runs = List.copyOf(runs);
  }

  /** The same result without its runs (what only the reports' pictures need): a large class fits in less memory. */
  public GradeResult withoutRuns() {
    return new GradeResult(submission, student, checks, List.of(), wallSec);
  }

  public double score() {
    return checks.stream().mapToDouble(CheckResult::score).sum();
  }

  public double maxScore() {
    return checks.stream().mapToDouble(CheckResult::maxScore).sum();
  }
}
