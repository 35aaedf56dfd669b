package org.robotrun.app;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robotrun.grade.GradeResult;
import org.robotrun.grade.Grader;
import org.robotrun.grade.Grading;
import org.robotrun.grade.SubmissionLoader;
import org.robotrun.grade.Task;
import org.robotrun.grade.TaskLoad;
import org.robotrun.grade.TaskReader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code robotrun bench grade}: how long a class takes to grade, and the memory it needs. */
@Command(
    name = "grade",
    mixinStandardHelpOptions = true,
    description = {
      "Grade --count submissions (the given ones, repeated in turn) against a task on --jobs threads, after one "
          + "warm-up submission, as robotrun grade does without writing reports (--variations N: with N seeded "
          + "variations instead of the task's).",
      "Prints the wall-clock time, the process's CPU time (all threads, GC included: the figure that does not "
          + "depend on what else the machine runs), the time per submission, simulated runs, the mean score, and the peak heap "
          + "used (sum of the heap pools' peaks since the start of the measured part).",
      "Output: task=T submissions=N jobs=J runs=R wall_s=W cpu_s=C per_submission_ms=P mean_score=S peak_heap_mb=M"
    })
public final class BenchGradeCommand implements Callable<Integer> {
  @picocli.CommandLine.Spec picocli.CommandLine.Model.CommandSpec spec;

  @Option(names = "--task", required = true, paramLabel = "TASK.json", description = "The task file.")
  Path task;

  @Parameters(arity = "1..*", paramLabel = "SUBMISSION", description = "Submissions to repeat (zip or folders).")
  List<Path> submissions;

  @Option(names = "--count", defaultValue = "100", description = "Submissions to grade (default: ${DEFAULT-VALUE}).")
  int count;

  @Option(names = "--jobs", paramLabel = "N", description = "Threads (default: the number of cores).")
  Integer jobs;

  @Option(names = "--variations", paramLabel = "N",
      description = "Grade with N seeded variations instead of the task's count (0..100).")
  Integer variations;

  /** CPU time of the whole process (all threads, GC included), or -1 where the JVM does not say. */
  private static long processCpuNanos() {
    return ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
        ? os.getProcessCpuTime() : -1;
  }

  @Override
  public Integer call() {
    if (count < 1 || count > 100_000) {
      throw new UserError("--count: expected 1..100000, got " + count);
    }
    int threads = jobs == null ? Runtime.getRuntime().availableProcessors() : jobs;
    if (threads < 1 || threads > 256) {
      throw new UserError("--jobs: expected 1 to 256, got " + threads);
    }
    TaskLoad.Loaded loaded = switch (TaskReader.read(task)) {
      case TaskLoad.Loaded l -> l;
      case TaskLoad.Failed f -> throw new UserError(f.message());
    };
    Task t = loaded.task();
    if (variations != null) {
      if (variations < 0 || variations > TaskReader.MAX_VARIATIONS) {
        throw new UserError("--variations: expected 0.." + TaskReader.MAX_VARIATIONS + ", got " + variations);
      }
      t = t.withVariations(t.variations().withCount(variations));
    }
    Grader grader = new Grader(t, loaded.scenario());
    SubmissionLoader loader = new SubmissionLoader();
    Grading.gradeOne(grader, loader, submissions.get(0), true);
    List<Path> all = new ArrayList<>();
    for (int i = 0; i < count; i++) {
      all.add(submissions.get(i % submissions.size()));
    }
    System.gc();
    List<MemoryPoolMXBean> heap = ManagementFactory.getMemoryPoolMXBeans().stream()
        .filter(p -> p.getType() == MemoryType.HEAP).toList();
    heap.forEach(MemoryPoolMXBean::resetPeakUsage);
    long t0 = System.nanoTime();
    long cpu0 = processCpuNanos();
    java.util.concurrent.atomic.AtomicInteger runCount = new java.util.concurrent.atomic.AtomicInteger();
    List<GradeResult> results = Grading.gradeAll(grader, loader, all, threads, true, false,
        r -> runCount.addAndGet(r.runs().size()));
    double wall = (System.nanoTime() - t0) / 1e9;
    double cpu = (processCpuNanos() - cpu0) / 1e9;
    long peak = heap.stream().mapToLong(p -> p.getPeakUsage().getUsed()).sum();
    int runs = runCount.get();
    double mean = results.stream().mapToDouble(GradeResult::score).average().orElse(0);
    spec.commandLine().getOut().printf(Locale.ROOT,
        "task=%s submissions=%d jobs=%d runs=%d wall_s=%.2f cpu_s=%.2f per_submission_ms=%.1f mean_score=%.1f "
            + "peak_heap_mb=%.0f%n",
        task.getFileName(), count, threads, runs, wall, cpu, wall * 1000 / count, mean, peak / 1048576.0);
    return Main.EXIT_OK;
  }
}
