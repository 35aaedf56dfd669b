package org.robotrun.pendant;

/**
 * Speed override steps as a controller takes them: fine steps at the bottom (1, 5, 10 %), 5 %
 * steps above; with SHIFT the big steps 5, 50, 100 %.
 */
final class OverrideSteps {
  private OverrideSteps() {}

  private static final int[] FINE = {1, 5, 10};
  private static final int[] BIG = {5, 50, 100};

  /** The next override from {@code currentPct} up or down. */
  static int next(int currentPct, boolean up, boolean shift) {
    int[] steps = shift ? BIG : null;
    if (steps != null) {
      return pick(steps, currentPct, up);
    }
    if (up) {
      for (int s : FINE) {
        if (s > currentPct) {
          return s;
        }
      }
      return Math.min(100, (currentPct / 5 + 1) * 5);
    }
    if (currentPct > 10) {
      return Math.max(10, ((currentPct - 1) / 5) * 5);
    }
    int best = FINE[0];
    for (int s : FINE) {
      if (s < currentPct) {
        best = s;
      }
    }
    return best;
  }

  private static int pick(int[] steps, int current, boolean up) {
    if (up) {
      for (int s : steps) {
        if (s > current) {
          return s;
        }
      }
      return steps[steps.length - 1];
    }
    for (int i = steps.length - 1; i >= 0; i--) {
      if (steps[i] < current) {
        return steps[i];
      }
    }
    return 1;
  }
}
