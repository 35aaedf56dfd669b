package org.robotrun.robot;

/**
 * The joint limits as the closed-form solvers ({@link ClosedFormIk}, {@link OffsetWristIk},
 * {@link UrTypeIk}) test and choose joint values: inside the limits or outside by no more than
 * round-off ({@link #SLACK}), and clamped onto them when an answer is given, so a solution never
 * lies outside its robot's limits by even 1e-9 rad.
 */
final class JointRange {
  /** How far outside a limit a value may lie and still count as inside (round-off), rad. */
  static final double SLACK = 1e-9;
  private static final double TWO_PI = 2 * Math.PI;

  private final double[] lower;
  private final double[] upper;
  private final double[] lowerSlack = new double[6];
  private final double[] upperSlack = new double[6];

  JointRange(RobotModel model) {
    lower = model.lowerLimits();
    upper = model.upperLimits();
    for (int i = 0; i < 6; i++) {
      lowerSlack[i] = lower[i] - SLACK;
      upperSlack[i] = upper[i] + SLACK;
    }
  }

  double lower(int i) {
    return lower[i];
  }

  double upper(int i) {
    return upper[i];
  }

  /** Inside joint i's limits, or outside by no more than round-off (false for NaN). */
  boolean ok(double v, int i) {
    return v >= lowerSlack[i] && v <= upperSlack[i];
  }

  /** The first joint of {@code q} outside its limits (see {@link #ok}), or -1. */
  int firstOutside(double[] q) {
    for (int i = 0; i < 6; i++) {
      if (!ok(q[i], i)) {
        return i;
      }
    }
    return -1;
  }

  /** {@code v} onto joint i's limits (NaN stays NaN). */
  double clamp(double v, int i) {
    return v < lower[i] ? lower[i] : (v > upper[i] ? upper[i] : v);
  }

  /** Every joint of {@code q} onto its limits. */
  void clampAll(double[] q) {
    for (int i = 0; i < 6; i++) {
      q[i] = clamp(q[i], i);
    }
  }

  /**
   * The variant of {@code q} (± 2π multiples) within joint i's limits nearest to {@code ref},
   * clamped onto them; NaN if none.
   */
  double nearestTurn(double q, double ref, int i) {
    double v = q + TWO_PI * Math.rint((ref - q) / TWO_PI);
    if (ok(v, i)) {
      return clamp(v, i);
    }
    // v − 2π and v + 2π cannot both be inside while v is not (the range is one interval), so at
    // most one of them is.
    double lo = v - TWO_PI, hi = v + TWO_PI;
    return ok(lo, i) ? clamp(lo, i) : (ok(hi, i) ? clamp(hi, i) : Double.NaN);
  }

  /** The smallest k with q + 2πk inside joint i's limits (see {@link #ok}); above {@link #lastTurn} if none. */
  int firstTurn(double q, int i) {
    return (int) Math.ceil((lowerSlack[i] - q) / TWO_PI);
  }

  /** The largest k with q + 2πk inside joint i's limits (see {@link #ok}). */
  int lastTurn(double q, int i) {
    return (int) Math.floor((upperSlack[i] - q) / TWO_PI);
  }

  /**
   * Every whole-turn variant of {@code q} (each joint moved by 2πk, k from {@link #firstTurn} to
   * {@link #lastTurn}) that lies inside all six limits, clamped onto them, J1's turn outermost and
   * J6's innermost; empty when a joint has no turn inside. A file may give a joint up to ±1080°,
   * so the turns are counted from the limits, not from a fixed ±2. Allocates (for allSolutions).
   */
  java.util.List<double[]> turnVariants(double[] q) {
    int[] first = new int[6];
    int[] last = new int[6];
    for (int i = 0; i < 6; i++) {
      first[i] = firstTurn(q[i], i);
      last[i] = lastTurn(q[i], i);
      if (first[i] > last[i]) {
        return java.util.List.of();
      }
    }
    java.util.List<double[]> out = new java.util.ArrayList<>();
    int[] k = first.clone();
    while (true) {
      double[] v = new double[6];
      for (int i = 0; i < 6; i++) {
        v[i] = q[i] + TWO_PI * k[i];
      }
      if (firstOutside(v) < 0) {
        clampAll(v);
        out.add(v);
      }
      int i = 5;
      while (i >= 0 && k[i] == last[i]) {
        k[i] = first[i];
        i--;
      }
      if (i < 0) {
        return out;
      }
      k[i]++;
    }
  }

  /** {@code q} (in (-π, π]) or its ±2π variant, whichever lies inside joint i's limits, clamped; else q. */
  double intoLimits(double q, int i) {
    if (ok(q, i)) {
      return clamp(q, i);
    }
    double alt = q > 0 ? q - TWO_PI : q + TWO_PI;
    return ok(alt, i) ? clamp(alt, i) : q;
  }

  /** Why {@code config} cannot be taken: joint i would need {@code q} (rad), outside its limits. */
  String outside(Config config, int i, double q) {
    return String.format(java.util.Locale.ROOT, "CONFIG '%s' needs J%d = %.1f deg, outside %.1f..%.1f deg", config,
        i + 1, Math.toDegrees(q), Math.toDegrees(lower[i]), Math.toDegrees(upper[i]));
  }

  /** The answer when the pose is reached, but by no solution with every joint inside its limits. */
  static IkResult.Unreachable everySolutionOutside() {
    return new IkResult.Unreachable(IkResult.Reason.JOINT_LIMIT,
        "the pose is within reach but every solution has a joint outside its limits");
  }

  /** The answer when the pose is reached only in other configurations than {@code config}. */
  static IkResult.Unreachable otherConfigsOnly(Config config) {
    return new IkResult.Unreachable(IkResult.Reason.OUT_OF_REACH,
        "the pose is out of reach in CONFIG '" + config + "' (only other configurations reach it)");
  }

  /** The squared distance between two joint vectors, rad². */
  static double distance(double[] a, double[] b) {
    double d = 0;
    for (int i = 0; i < 6; i++) {
      double e = a[i] - b[i];
      d += e * e;
    }
    return d;
  }
}
