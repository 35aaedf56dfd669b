package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Tuple;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Angles;
import org.robotrun.math.Transform;

/**
 * Issue 18: every target the closed-form solver finds inside the limits, the numeric solver
 * finds too, from the home position and from a start elsewhere — over the whole joint space,
 * with extra weight at a limit (one joint within 0.05 rad of it), at the wrist singularity
 * (J5 = 0 and 1e-7..1e-2 rad) and at axis-aligned values; and a second property over corners,
 * several joints at their limits at once with the wrist singular or nearly so.
 */
class NumericIkCoverageTest {
  private static final RobotModel ROBOT = RobotDefinitions.defaultRobot();
  private final NumericIk numeric = new NumericIk(ROBOT);
  private final ClosedFormIk closed = new ClosedFormIk(ROBOT);

  @Provide
  Arbitrary<double[]> joints() {
    double[] lo = ROBOT.lowerLimits();
    double[] hi = ROBOT.upperLimits();
    // Uniform over the limits, then one joint moved to within 0..0.05 rad of a limit, or to a
    // singular or axis-aligned value (J5 = 0: wrist axes in line).
    // randomValue: truly uniform (jqwik's own double generation favours the interval's ends).
    Arbitrary<double[]> uniform = Arbitraries.randomValue(r -> {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = lo[i] + r.nextDouble() * (hi[i] - lo[i]);
      }
      return q;
    });
    Arbitrary<Integer> joint = Arbitraries.integers().between(0, 5);
    Arbitrary<Double> offset = Arbitraries.randomValue(r -> 0.05 * r.nextDouble());
    Arbitrary<double[]> nearLimit = net.jqwik.api.Combinators.combine(uniform, joint, offset, Arbitraries.of(true, false))
        .as((q, i, d, low) -> {
          double[] c = q.clone();
          c[i] = low ? lo[i] + d : hi[i] - d;
          return c;
        });
    Arbitrary<double[]> singular = net.jqwik.api.Combinators.combine(uniform, Arbitraries.of(0.0, 1e-7, -1e-6, 1e-5, -1e-4, 1e-3, -1e-3, 1e-2))
        .as((q, j5) -> {
          double[] c = q.clone();
          c[4] = j5;
          return c;
        });
    Arbitrary<double[]> axisAligned = net.jqwik.api.Combinators.combine(uniform, joint,
        Arbitraries.of(0.0, Math.PI / 2, -Math.PI / 2, Math.PI, -Math.PI)).as((q, i, v) -> {
          double[] c = q.clone();
          c[i] = Math.max(lo[i], Math.min(hi[i], v));
          return c;
        });
    return Arbitraries.frequencyOf(Tuple.of(4, uniform), Tuple.of(3, nearLimit), Tuple.of(2, singular),
        Tuple.of(1, axisAligned));
  }

  @Property(seed = "18", tries = 1500, edgeCases = net.jqwik.api.EdgeCasesMode.NONE)
  void whatTheClosedFormFindsTheNumericSolverFindsToo(@ForAll("joints") double[] q, @ForAll("starts") int start) {
    Transform X_BF = ForwardKinematics.flangePoseInBase(ROBOT, q);
    // The closed form lists every solution inside the limits; q is one, so it must find some.
    assertThat(closed.allSolutions(X_BF)).isNotEmpty();
    double[] q0 = switch (start) {
      case 0 -> new double[6];
      case 1 -> farStart(q);
      default -> q.clone();
    };
    IkResult r = numeric.solve(X_BF, q0);
    assertThat(r).as("target %s from %s", java.util.Arrays.toString(Angles.toDegrees(q)), start)
        .isInstanceOf(IkResult.Solved.class);
    double[] sol = ((IkResult.Solved) r).q();
    Transform reached = ForwardKinematics.flangePoseInBase(ROBOT, sol);
    assertThat(reached.distanceTo(X_BF)).isLessThan(1e-6);
    assertThat(reached.rotationAngleTo(X_BF)).isLessThan(1e-8);
    assertThat(ROBOT.firstJointOutsideLimits(sol)).isEqualTo(-1);
  }

  /**
   * Corners: each joint independently at a limit (exactly, or within 1e-6..0.05 rad of it) with
   * probability one half, so several joints sit at their limits at once, and J5 at or near the
   * wrist singularity (0, ±1e-7..±1e-3 rad) in most draws.
   */
  @Provide
  Arbitrary<double[]> corners() {
    double[] lo = ROBOT.lowerLimits();
    double[] hi = ROBOT.upperLimits();
    double[] offsets = {0, 0, 1e-9, 1e-6, 1e-4, 1e-3, 0.01, 0.05};
    double[] wrist = {0, 0, 1e-7, -1e-7, 1e-6, -1e-5, 1e-4, -1e-4, 3e-4, -1e-3};
    return Arbitraries.randomValue(r -> {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = lo[i] + r.nextDouble() * (hi[i] - lo[i]);
        if (r.nextBoolean()) {
          double d = offsets[r.nextInt(offsets.length)];
          q[i] = r.nextBoolean() ? lo[i] + d : hi[i] - d;
        }
      }
      if (r.nextInt(4) != 0) {
        q[4] = wrist[r.nextInt(wrist.length)];
      }
      return q;
    });
  }

  @Property(seed = "1818", tries = 2000, edgeCases = net.jqwik.api.EdgeCasesMode.NONE)
  void severalJointsAtTheirLimitsWithTheWristSingularAreSolvedToo(@ForAll("corners") double[] q,
      @ForAll("starts") int start) {
    whatTheClosedFormFindsTheNumericSolverFindsToo(q, start);
  }

  @Provide
  Arbitrary<Integer> starts() {
    return Arbitraries.of(0, 0, 1);
  }

  /** A start on the far side of each joint's range from the target (a deterministic "random" start). */
  private static double[] farStart(double[] q) {
    double[] lo = ROBOT.lowerLimits();
    double[] hi = ROBOT.upperLimits();
    double[] s = new double[6];
    for (int i = 0; i < 6; i++) {
      double mid = 0.5 * (lo[i] + hi[i]);
      s[i] = q[i] > mid ? lo[i] + 0.25 * (hi[i] - lo[i]) : hi[i] - 0.25 * (hi[i] - lo[i]);
    }
    return s;
  }

  @Test
  void theWristFoldedBackOverTheBaseIsSolvedFromHome() {
    // The reproducer of issue 18: J2 near +139 deg, J3 -68 deg, J4 +185 deg, the wrist folded back
    // over the base; tried over J1, J5, J6 on a grid.
    java.util.List<String> failures = new java.util.ArrayList<>();
    for (double j1 : new double[] {-150, -60, 0, 45, 120, 165}) {
      for (double j5 : new double[] {-120, -60, -10, 10, 60, 120}) {
        for (double j6 : new double[] {-300, 0, 170}) {
          double[] q = Angles.toRadians(new double[] {j1, 139, -68, 185, j5, j6});
          Transform X_BF = ForwardKinematics.flangePoseInBase(ROBOT, q);
          if (!(numeric.solve(X_BF, new double[6]) instanceof IkResult.Solved)) {
            failures.add(j1 + "/" + j5 + "/" + j6);
          }
        }
      }
    }
    assertThat(failures).isEmpty();
  }
}
