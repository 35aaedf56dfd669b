package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;

/**
 * Speed override steps as an R-30iB takes them with the +% / -% keys: VFINE, FINE, 1, 5, 10 %,
 * then 5 % steps to 100 %; with SHIFT held, VFINE, FINE, 1, 5, 50, 100 %. VFINE and FINE are
 * not speeds but incremental jogging (one small step per jog key press; programs run at 1 %).
 * Levels are ints: {@link #VFINE}, {@link #FINE}, or the percentage.
 */
final class OverrideSteps {
  private OverrideSteps() {}

  /** Level of VFINE (incremental jog, very fine steps). */
  static final int VFINE = -2;
  /** Level of FINE (incremental jog, fine steps). */
  static final int FINE = -1;

  private static final List<Integer> PLAIN = plain();
  private static final List<Integer> SHIFTED = List.of(VFINE, FINE, 1, 5, 50, 100);

  private static List<Integer> plain() {
    List<Integer> l = new ArrayList<>(List.of(VFINE, FINE, 1));
    for (int pct = 5; pct <= 100; pct += 5) {
      l.add(pct);
    }
    return List.copyOf(l);
  }

  /**
   * The next level from {@code current} (a level: VFINE, FINE or 1..100) up or down; an override
   * between steps (a program's OVERRIDE=37) goes to the next step in that direction.
   */
  static int next(int current, boolean up, boolean shift) {
    List<Integer> steps = shift ? SHIFTED : PLAIN;
    if (up) {
      for (int s : steps) {
        if (s > current) {
          return s;
        }
      }
      return steps.get(steps.size() - 1);
    }
    for (int i = steps.size() - 1; i >= 0; i--) {
      if (steps.get(i) < current) {
        return steps.get(i);
      }
    }
    return steps.get(0);
  }

  /** The level as the status line shows it: "VFINE", "FINE" or "10%". */
  static String display(int level) {
    return switch (level) {
      case VFINE -> "VFINE";
      case FINE -> "FINE";
      default -> level + "%";
    };
  }
}
