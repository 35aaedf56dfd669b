package org.robotrun.app;

import java.io.PrintWriter;
import org.robotrun.program.bench.InterpreterWorkload;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robotrun bench interp}: interpreter throughput on non-motion TP lines, one thread.
 * Prints {@code instructions_per_sec=X}. The JMH form is
 * {@link org.robotrun.program.bench.InterpreterBenchmark}.
 */
@Command(
    name = "interp",
    mixinStandardHelpOptions = true,
    description = "Interpreter throughput on non-motion TP lines (one core); prints instructions_per_sec=X.")
public final class BenchInterpCommand implements Runnable {
  @Spec CommandSpec spec;

  @Option(names = "--seconds", defaultValue = "3", description = "Measuring time in seconds after warm-up (default: ${DEFAULT-VALUE}).")
  double seconds;

  @Option(names = "--warmup-seconds", defaultValue = "2", description = "Warm-up time in seconds (default: ${DEFAULT-VALUE}).")
  double warmupSeconds;

  @Option(names = "--loops", defaultValue = "100000", description = "Loop iterations of the workload program per run (default: ${DEFAULT-VALUE}).")
  int loops;

  @Override
  public void run() {
    if (!(seconds > 0) || !(warmupSeconds >= 0) || loops < 1) {
      throw new UserError("--seconds must be > 0, --warmup-seconds >= 0 and --loops >= 1");
    }
    InterpreterWorkload w = new InterpreterWorkload(loops);
    runFor(w, warmupSeconds);
    long start = System.nanoTime();
    long lines = runFor(w, seconds);
    double elapsedSec = (System.nanoTime() - start) / 1e9;
    PrintWriter out = spec.commandLine().getOut();
    out.printf(java.util.Locale.ROOT, "instructions_per_sec=%.0f lines=%d seconds=%.3f loops_per_run=%d checksum=%.0f%n",
        lines / elapsedSec, lines, elapsedSec, loops, w.checksum());
    out.flush();
  }

  private static long runFor(InterpreterWorkload w, double seconds) {
    long end = System.nanoTime() + (long) (seconds * 1e9);
    long lines = 0;
    do {
      lines += w.run();
    } while (System.nanoTime() < end);
    return lines;
  }
}
