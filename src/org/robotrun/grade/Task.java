package org.robotrun.grade;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * A grading task (docs/grading.md): the scenario a submission runs on, its program, limits,
 * seeded variations and the checks with their points.
 *
 * @param file the task file as given, for messages
 * @param title shown at the top of each report
 * @param scenario the scenario file (resolved against the task's folder)
 * @param program the program to run, by /PROG name (upper case)
 * @param limits per-run simulated-time and per-submission wall-clock limits
 * @param variations the seeded variations (count 0: none)
 * @param checks in the order they are reported
 * @param otherPrograms in a cell of several robots: the program each robot after the first runs,
 *     by robot name in scenario order (a robot not listed does not run); empty for one robot
 * @param autograder what the course platforms' autograders do beyond the checks
 */
public record Task(String file, String title, Path scenario, String program, Limits limits, Variations variations,
    List<Check> checks, Map<String, String> otherPrograms, Autograder autograder) {
  public Task {
    checks = List.copyOf(checks);
    otherPrograms = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(otherPrograms));
  }

  /** A task with the default autograder settings. */
  public Task(String file, String title, Path scenario, String program, Limits limits, Variations variations,
      List<Check> checks, Map<String, String> otherPrograms) {
    this(file, title, scenario, program, limits, variations, checks, otherPrograms, Autograder.DEFAULT);
  }

  /** The same task with other variations (e.g. {@code bench grade --variations}). */
  public Task withVariations(Variations v) {
    return new Task(file, title, scenario, program, limits, v, checks, otherPrograms, autograder);
  }

  /** The same task with other limits. */
  public Task withLimits(Limits l) {
    return new Task(file, title, scenario, program, l, variations, checks, otherPrograms, autograder);
  }

  /**
   * The task's {@code "autograder"} section (docs/grading.md).
   *
   * @param hiddenVisibility the Gradescope visibility of hidden checks: {@code hidden} (never shown to
   *     students), {@code after_due_date} or {@code after_published}
   * @param leaderboard whether the Gradescope results carry a leaderboard of the first robot's cycle
   *     time in the nominal run (ascending: faster ranks higher)
   */
  public record Autograder(String hiddenVisibility, boolean leaderboard) {
    public static final Autograder DEFAULT = new Autograder("hidden", false);
    /** The visibilities Gradescope offers for a test that students do not always see. */
    public static final List<String> HIDDEN_VISIBILITIES = List.of("hidden", "after_due_date", "after_published");
  }

  /** A task for a one-robot cell (or one that runs only the first robot). */
  public Task(String file, String title, Path scenario, String program, Limits limits, Variations variations,
      List<Check> checks) {
    this(file, title, scenario, program, limits, variations, checks, Map.of());
  }

  /** Total points of all checks. */
  public double maxPoints() {
    return checks.stream().mapToDouble(c -> c.meta().points()).sum();
  }

  /** Total points of the checks students see. */
  public double visiblePoints() {
    return checks.stream().filter(c -> !c.meta().hidden()).mapToDouble(c -> c.meta().points()).sum();
  }

  /**
   * @param simSeconds simulated seconds one run may take before it is stopped (RUN-001)
   * @param wallSeconds wall-clock seconds one submission may take, all runs together
   */
  public record Limits(double simSeconds, double wallSeconds) {
    public static final Limits DEFAULT = new Limits(120, 30);
  }

  /**
   * @param count how many variations besides the nominal run
   * @param seed variation i uses seed + i; the same task grades the same way every time
   * @param parts parts whose start poses are jittered
   * @param overrideMinPct lowest speed override drawn for a variation
   * @param overrideMaxPct highest (the nominal run uses 100)
   * @param varyVisionSeed variation i places the scenario's vision parts with {@code vision.seed + i}
   *     (the nominal run with the scenario's own seed), so a vision program is graded over several
   *     placements
   */
  public record Variations(int count, long seed, List<PartJitter> parts, int overrideMinPct, int overrideMaxPct,
      boolean varyVisionSeed) {
    public static final Variations NONE = new Variations(0, 0, List.of(), 100, 100, false);

    public Variations {
      parts = List.copyOf(parts);
    }

    /** Variations that leave the vision seed alone. */
    public Variations(int count, long seed, List<PartJitter> parts, int overrideMinPct, int overrideMaxPct) {
      this(count, seed, parts, overrideMinPct, overrideMaxPct, false);
    }

    /** The same variations, {@code n} of them. */
    public Variations withCount(int n) {
      return new Variations(n, seed, parts, overrideMinPct, overrideMaxPct, varyVisionSeed);
    }
  }

  /**
   * A part moved on its fixture by a uniform draw within ±{@code xMm}, ±{@code yMm} (in its
   * parent's frame) and turned within ±{@code rDeg} about the parent's z axis. The offset drawn is
   * written to {@code offsetRegister} as PR[i] = (dx, dy, 0, 0, 0, dr) in mm and degrees, as a
   * vision system or a PLC would report it; the nominal run writes zeros there.
   */
  public record PartJitter(String part, double xMm, double yMm, double rDeg, Optional<Integer> offsetRegister) {}
}
