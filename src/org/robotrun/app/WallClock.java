package org.robotrun.app;

import java.util.Locale;

/**
 * The real-time safety net of {@code run} and {@code pendant} ({@code --max-wall-seconds}): a
 * grader running hundreds of submissions must not be held up by one. It only ever stops a job;
 * what a job computes never depends on it, so results stay deterministic.
 */
final class WallClock {
  /** Largest value --max-wall-seconds takes: a day. */
  static final double MAX_SECONDS = 86_400;

  private final long deadlineNanos;

  private WallClock(long deadlineNanos) {
    this.deadlineNanos = deadlineNanos;
  }

  /** Refuses a value outside 1..{@link #MAX_SECONDS}. */
  static void checkOption(double seconds) {
    if (!(seconds >= 1 && seconds <= MAX_SECONDS)) {
      throw new UserError("--max-wall-seconds: expected 1.." + (long) MAX_SECONDS + " seconds, got " + format(seconds));
    }
  }

  static WallClock start(double seconds) {
    return new WallClock(System.nanoTime() + (long) (seconds * 1e9));
  }

  /** Whether the time is up. */
  boolean expired() {
    return System.nanoTime() - deadlineNanos > 0;
  }

  static String format(double v) {
    return v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v) : String.format(Locale.ROOT, "%.6g", v);
  }
}
