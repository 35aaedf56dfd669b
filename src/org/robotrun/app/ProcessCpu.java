package org.robotrun.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** CPU time of this process and of its native threads (benchmarks). */
final class ProcessCpu {
  /**
   * The thread names under which Mesa's software renderer draws (llvmpipe's rasteriser threads,
   * as Linux names them in /proc): a frame's pixels are their work, not the window thread's.
   */
  static final List<String> GL_THREADS = List.of("llvmpipe-");

  /** Linux's clock ticks per second for /proc's utime and stime (USER_HZ, 100 on every Linux port). */
  private static final long TICKS_PER_SEC = 100;

  private ProcessCpu() {}

  /** CPU time of the whole process (every thread), in ns; 0 when the platform does not say. */
  static long processNanos() {
    if (java.lang.management.ManagementFactory.getOperatingSystemMXBean()
        instanceof com.sun.management.OperatingSystemMXBean os) {
      long t = os.getProcessCpuTime();
      if (t >= 0) {
        return t;
      }
    }
    return ProcessHandle.current().info().totalCpuDuration().map(java.time.Duration::toNanos).orElse(0L);
  }

  /**
   * CPU time (ns, in steps of 10 ms) of this process's threads whose name starts with one of
   * {@code prefixes}, read from /proc/self/task; 0 where there is no /proc (not Linux).
   */
  static long nativeThreadsNanos(List<String> prefixes) {
    Path tasks = Path.of("/proc/self/task");
    if (!Files.isDirectory(tasks)) {
      return 0;
    }
    long ticks = 0;
    try (var ls = Files.list(tasks)) {
      for (Path t : ls.toList()) {
        try {
          String name = Files.readString(t.resolve("comm")).strip();
          if (prefixes.stream().noneMatch(name::startsWith)) {
            continue;
          }
          ticks += userAndSystemTicks(Files.readString(t.resolve("stat")));
        } catch (IOException | RuntimeException e) {
          // the thread ended meanwhile
        }
      }
    } catch (IOException e) {
      return 0;
    }
    return ticks * (1_000_000_000L / TICKS_PER_SEC);
  }

  /** utime + stime (fields 14 and 15) of a /proc stat line; the name in parentheses may hold spaces. */
  static long userAndSystemTicks(String stat) {
    String[] f = stat.substring(stat.lastIndexOf(')') + 2).trim().split(" ");
    // f[0] is field 3 (state): utime is field 14, stime field 15
    return Long.parseLong(f[11]) + Long.parseLong(f[12]);
  }
}
