package org.robotrun.app;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;

/**
 * What a benchmark times with: wall-clock time, or the CPU time of the measuring thread, which
 * leaves out the time the thread waited for a core on a machine busy with other work.
 */
enum BenchClock {
  WALL,
  CPU;

  private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

  /** The clock a {@code --clock wall|cpu} option names. */
  static BenchClock named(String name) {
    return switch (name) {
      case "wall" -> WALL;
      case "cpu" -> CPU;
      default -> throw new UserError("--clock: expected wall or cpu, got '" + name + "'");
    };
  }

  /** Runs {@code pass} {@code repeat} times (at least once) and returns the median time of one run (ns). */
  long medianNanos(int repeat, Runnable pass) {
    long[] ns = new long[repeat];
    for (int r = 0; r < repeat; r++) {
      long t0 = nanos();
      pass.run();
      ns[r] = nanos() - t0;
    }
    Arrays.sort(ns);
    return ns[repeat / 2];
  }

  /** Now, in nanoseconds on this clock. */
  long nanos() {
    return switch (this) {
      case WALL -> System.nanoTime();
      case CPU -> THREADS.getCurrentThreadCpuTime();
    };
  }
}
