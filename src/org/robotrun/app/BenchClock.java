package org.robotrun.app;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;

/**
 * What a benchmark times with: wall-clock time, or the CPU time of the measuring thread, which
 * leaves out the time the thread waited for a core on a machine busy with other work.
 */
enum BenchClock {
  WALL,
  CPU;

  private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

  /** Now, in nanoseconds on this clock. */
  long nanos() {
    return switch (this) {
      case WALL -> System.nanoTime();
      case CPU -> THREADS.getCurrentThreadCpuTime();
    };
  }
}
