package org.robotrun.grade;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Consumer;

/**
 * Grades many submissions at once, one per thread: each gets its own unpacked copy, its own
 * simulations and solvers; only the immutable task, scenario and robot models are shared. One
 * submission's failure (a broken zip, an endless loop, an error inside the simulator) is that
 * submission's result and never stops the others.
 */
public final class Grading {
  private Grading() {}

  /**
   * @param threads worker threads (at least 1)
   * @param onDone called (from a worker thread) as each submission is finished, e.g. for progress
   * @return the results in the order of {@code submissions}
   */
  public static List<GradeResult> gradeAll(Grader grader, SubmissionLoader loader, List<Path> submissions, int threads,
      boolean includeHidden, Consumer<GradeResult> onDone) {
    return gradeAll(grader, loader, submissions, threads, includeHidden, true, onDone);
  }

  /**
   * As above; with {@code keepRuns} false each result is kept without its runs once
   * {@code onDone} has seen it (about 1 MB less per submission: for classes whose reports need no pictures).
   */
  public static List<GradeResult> gradeAll(Grader grader, SubmissionLoader loader, List<Path> submissions, int threads,
      boolean includeHidden, boolean keepRuns, Consumer<GradeResult> onDone) {
    ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, threads), r -> {
      Thread t = new Thread(r, "grade");
      t.setDaemon(true);
      return t;
    });
    try {
      List<Future<GradeResult>> futures = new ArrayList<>();
      for (Path p : submissions) {
        futures.add(pool.submit(() -> {
          GradeResult r = gradeOne(grader, loader, p, includeHidden);
          onDone.accept(r);
          return keepRuns ? r : r.withoutRuns();
        }));
      }
      List<GradeResult> out = new ArrayList<>();
      for (int i = 0; i < futures.size(); i++) {
        try {
          out.add(futures.get(i).get());
        } catch (ExecutionException e) {
          out.add(crashed(grader, submissions.get(i), e.getCause(), includeHidden));
        } catch (InterruptedException e) {
          Thread.currentThread().interrupt();
          throw new IllegalStateException("grading was interrupted", e);
        }
      }
      return out;
    } finally {
      pool.shutdownNow();
    }
  }

  /** Loads and grades one submission; anything unexpected becomes a failed result. */
  public static GradeResult gradeOne(Grader grader, SubmissionLoader loader, Path path, boolean includeHidden) {
    try (Submission s = loader.load(path)) {
      return grader.grade(s, includeHidden);
    } catch (RuntimeException | StackOverflowError e) {
      return crashed(grader, path, e, includeHidden);
    }
  }

  private static GradeResult crashed(Grader grader, Path path, Throwable e, boolean includeHidden) {
    String why = "The grader failed on this submission (" + e.getClass().getSimpleName() + "); please report this.";
    List<CheckResult> checks = grader.task().checks().stream().filter(c -> includeHidden || !c.meta().hidden())
        .map(c -> new CheckResult(c, false, 0, why, java.util.Optional.empty(), java.util.Optional.empty())).toList();
    return new GradeResult(String.valueOf(path.getFileName()), "", checks, List.of(), 0);
  }
}
