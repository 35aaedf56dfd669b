package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.function.ToDoubleFunction;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The T/B and U/D lines of the CRX (ChainConfig) and of the UR-type arms (UrTypeIk), crossed
 * closely: each flag must change exactly where its documented margin changes sign
 * (docs/kinematics.md), not merely on the right side far from the line. The margins are worked
 * out here from the joint axis lines that FK gives:
 * <ul>
 *   <li>W is J5's origin (CRX: ChainConfig's wrist point) or the point where the J5 and J6 axes
 *       meet (UR);
 *   <li>f is J1 × J2, oriented so that W lies in front of the J1 axis at q = 0; T when
 *       f · (W − J1) &gt; 0;
 *   <li>U when ((J3 − J2) × (P − J3)) · (J1 × f) &gt; 0, P being W on the CRX and J4 on the UR,
 *       with J2, J3, J4 points on those (parallel) axes.
 * </ul>
 * Each arm is written with its base and flange frames turned and its link frames turned
 * (ReframedChainInvarianceTest's rewriting), so that no term of either solver's formulas is zero.
 * For joint vectors where J2 (for T/B) or J3 (for U/D) carries the margin through zero, the root
 * is found here by bisection and the flags are checked 2e-4 rad either side.
 */
class ConfigBoundaryTest {

  static RobotModel arm(String id) {
    RobotModel m = id.equals("ur5") ? IkSolverContractTest.ur5(Math.PI) : RobotDefinitions.load(id);
    return ReframedChainInvarianceTest.rewritten(m, new ReframedChainInvarianceTest.Rewrite(
        ReframedChainInvarianceTest.BASE, ReframedChainInvarianceTest.FLANGE, 23, new int[] {1, 1, 1, 1, 1, 1}));
  }

  /** Points of the joint axis lines at q: [i][0] a point, [i][1] the direction. */
  static Vec3[][] axisLines(RobotModel m, double[] q) {
    Transform[] L = ForwardKinematics.linkPosesInBase(m, q);
    Vec3[][] out = new Vec3[6][];
    for (int i = 0; i < 6; i++) {
      out[i] = new Vec3[] {L[i + 1].translationVector(), L[i + 1].rotate(m.joint(i).axis()).normalized()};
    }
    return out;
  }

  /** The point where two (meeting) lines meet: the midpoint of their closest points. */
  static Vec3 meet(Vec3[] a, Vec3[] b) {
    Vec3 w = a[0].minus(b[0]);
    double ab = a[1].dot(b[1]), aw = a[1].dot(w), bw = b[1].dot(w);
    double den = 1 - ab * ab;
    double s = (ab * bw - aw) / den, t = (bw - ab * aw) / den;
    return a[0].plus(a[1].times(s)).plus(b[0].plus(b[1].times(t))).times(0.5);
  }

  static Vec3 wrist(String id, Vec3[][] ax) {
    return id.equals("ur5") ? meet(ax[4], ax[5]) : ax[4][0];
  }

  static double topMargin(String id, RobotModel m, double[] q) {
    Vec3[][] ax = axisLines(m, q);
    Vec3[][] ax0 = axisLines(m, new double[6]);
    Vec3 f0 = ax0[0][1].cross(ax0[1][1]);
    double s = Math.signum(f0.dot(wrist(id, ax0).minus(ax0[0][0])));
    Vec3 f = ax[0][1].cross(ax[1][1]).times(s);
    return f.dot(wrist(id, ax).minus(ax[0][0]));
  }

  static double upMargin(String id, RobotModel m, double[] q) {
    Vec3[][] ax = axisLines(m, q);
    Vec3[][] ax0 = axisLines(m, new double[6]);
    Vec3 f0 = ax0[0][1].cross(ax0[1][1]);
    double s = Math.signum(f0.dot(wrist(id, ax0).minus(ax0[0][0])));
    Vec3 f = ax[0][1].cross(ax[1][1]).times(s);
    Vec3 p = id.equals("ur5") ? ax[3][0] : wrist(id, ax);
    return ax[2][0].minus(ax[1][0]).cross(p.minus(ax[2][0])).dot(ax[0][1].cross(f));
  }

  /** Checks {@code flag} against {@code margin} either side of every zero of it along joint {@code j}; returns the zeros crossed. */
  static int crossings(IkSolver ik, RobotModel m, double[] q0, int j, ToDoubleFunction<double[]> margin,
      java.util.function.Predicate<Config> flag, String what) {
    int found = 0;
    double lo = Math.max(m.joint(j).lowerRad(), -Math.PI), hi = Math.min(m.joint(j).upperRad(), Math.PI);
    double[] q = q0.clone();
    double step = 0.02;
    for (double a = lo; a + step <= hi; a += step) {
      q[j] = a;
      double ma = margin.applyAsDouble(q);
      q[j] = a + step;
      double mb = margin.applyAsDouble(q);
      if (Math.signum(ma) == Math.signum(mb)) {
        continue;
      }
      double x = a, y = a + step;
      for (int k = 0; k < 60; k++) {
        double mid = 0.5 * (x + y);
        q[j] = mid;
        if (Math.signum(margin.applyAsDouble(q)) == Math.signum(ma)) {
          x = mid;
        } else {
          y = mid;
        }
      }
      // 2e-4 rad either side: W a tenth of a millimetre or so off the line.
      double eps = 2e-4;
      for (double side : new double[] {-eps, eps}) {
        q[j] = 0.5 * (x + y) + side;
        double mm = margin.applyAsDouble(q);
        assertThat(flag.test(ik.configOf(q))).as("%s J%d = %.9f, margin %.3g, q = %s", what, j + 1, q[j], mm, Arrays.toString(q))
            .isEqualTo(mm > 0);
      }
      found++;
    }
    return found;
  }

  @ParameterizedTest
  @ValueSource(strings = {"crx10ia", "ur5"})
  void eachFlagChangesExactlyWhereItsMarginDoes(String id) {
    RobotModel m = arm(id);
    IkSolver ik = IkSolver.forModel(m);
    int tops = 0, ups = 0;
    for (double[] q : IkSolverContractTest.samples(m, 620 + id.length(), 5)) {
      tops += crossings(ik, m, q, 1, x -> topMargin(id, m, x), Config::top, id + " T/B");
      ups += crossings(ik, m, q, 2, x -> upMargin(id, m, x), Config::up, id + " U/D");
    }
    assertThat(tops).as("T/B lines crossed").isGreaterThanOrEqualTo(3);
    assertThat(ups).as("U/D lines crossed").isGreaterThanOrEqualTo(3);
  }
}
