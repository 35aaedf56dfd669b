package org.robotrun.grade;

import java.util.Optional;
import org.robotrun.math.Vec3;

/**
 * One check graded.
 *
 * @param check the check
 * @param passed whether it passed
 * @param score points given (all or nothing)
 * @param measured what was measured, in words a student can act on
 * @param failedRun index into {@link GradeResult#runs()} of the run where it failed, if a run did
 * @param focus_C for a part check that failed, where the part ended (cell frame, mm)
 */
public record CheckResult(Check check, boolean passed, double score, String measured, Optional<Integer> failedRun,
    Optional<Vec3> focus_C) {

  public String name() {
    return check.meta().name();
  }

  public double maxScore() {
    return check.meta().points();
  }

  public boolean hidden() {
    return check.meta().hidden();
  }

  /** What a student reads: the measurement, then (when it failed) the task's message. */
  public String feedback() {
    String msg = check.meta().message();
    if (passed || msg.isEmpty()) {
      return measured;
    }
    return measured + (measured.isEmpty() ? "" : "\n") + msg;
  }
}
