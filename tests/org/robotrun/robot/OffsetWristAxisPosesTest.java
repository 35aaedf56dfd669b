package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The CRX with its wrist point O5 (where the J4 and J5 axes meet) on the J1 axis, and with its
 * elbow O3 (where J3 and J4 meet) on it. The arm plane is then not fixed by O5 (z1 × O5 = 0):
 * the search must take it from the elbow instead (docs/kinematics.md, the offset-wrist search);
 * with the elbow on the axis, from O5. The postures are built here: J2 = 0 puts the elbow over
 * the shoulder, and J3 is found by bisection (on the test's own FK) where the signed distance of
 * O5 from the J1 axis, measured across the arm plane, changes sign. On the library arm and on the
 * same arm mounted at a slant (J1's axis along no base axis, its origin off the base origin, so no
 * term of the arm-plane normal vanishes), the joints that made each pose must be among the
 * solutions, every solution must reach the pose, and the nearest solution to the truth is the truth.
 */
class OffsetWristAxisPosesTest {

  /** The closest point between two lines (the middle of the shortest segment). */
  static Vec3 meet(Vec3 p, Vec3 d, Vec3 q, Vec3 e) {
    Vec3 r = q.minus(p);
    double dd = d.dot(d), ee = e.dot(e), de = d.dot(e), rd = r.dot(d), re = r.dot(e);
    double den = dd * ee - de * de;
    double s = (rd * ee - re * de) / den;
    double t = (rd * de - re * dd) / den;
    return p.plus(d.times(s)).plus(q.plus(e.times(t))).times(0.5);
  }

  /** Joint i's axis line at q: a point and the direction, in the base. */
  static Vec3[] axis(RobotModel m, double[] q, int i) {
    Transform[] L = ForwardKinematics.linkPosesInBase(m, q);
    return new Vec3[] {L[i + 1].translationVector(), L[i + 1].rotate(m.joint(i).axis())};
  }

  /** O5's distance from the J1 axis, signed across the arm plane (by the J2 axis). */
  static double o5Across(RobotModel m, double[] q) {
    Vec3[] a4 = axis(m, q, 3), a5 = axis(m, q, 4), a1 = axis(m, q, 0), a2 = axis(m, q, 1);
    Vec3 o5 = meet(a4[0], a4[1], a5[0], a5[1]);
    return o5.minus(a1[0]).cross(a1[1]).dot(a2[1]);
  }

  /** J3 where O5 crosses the J1 axis, between lo and hi (a sign change of {@link #o5Across}). */
  static double j3OnAxis(RobotModel m, double[] q, double lo, double hi) {
    double[] a = q.clone(), b = q.clone();
    a[2] = lo;
    b[2] = hi;
    double fa = o5Across(m, a);
    assertThat(fa * o5Across(m, b)).as("a sign change of O5 across the axis").isNegative();
    for (int it = 0; it < 200; it++) {
      double[] c = q.clone();
      c[2] = 0.5 * (a[2] + b[2]);
      double fc = o5Across(m, c);
      if (fc == 0 || c[2] == a[2] || c[2] == b[2]) {
        return c[2];
      }
      if (fc * fa < 0) {
        b = c;
      } else {
        a = c;
        fa = fc;
      }
    }
    return 0.5 * (a[2] + b[2]);
  }

  static void solvesIncludingTheTruth(RobotModel m, double[] q, String what) {
    OffsetWristIk ik = new OffsetWristIk(m);
    Transform X = ForwardKinematics.flangePoseInBase(m, q);
    List<double[]> base = ik.baseSolutions(X);
    assertThat(base.stream().anyMatch(s -> OffsetWristCompletenessTest.wrappedDiff(s, q) < 1e-6))
        .as("%s %s: its own joints among %d solutions", what, Arrays.toString(q), base.size()).isTrue();
    for (double[] s : base) {
      Transform Y = ForwardKinematics.flangePoseInBase(m, s);
      assertThat(Y.distanceTo(X)).as("%s: solution %s", what, Arrays.toString(s)).isLessThan(1e-6);
      assertThat(Y.rotationAngleTo(X)).isLessThan(1e-9);
    }
    IkResult near = ik.solveNearest(X, q);
    assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), q)).as("%s: nearest", what).isLessThan(1e-6);
  }

  @ParameterizedTest
  @ValueSource(booleans = {false, true})
  void theWristPointOnTheJ1AxisIsSolved(boolean slanted) {
    RobotModel crx = RobotDefinitions.load("crx10ia");
    RobotModel m = slanted ? MountedArmInvarianceTest.mounted(crx, MountedArmInvarianceTest.MOUNT) : crx;
    String what = slanted ? "slanted CRX, O5 on the J1 axis" : "CRX, O5 on the J1 axis";
    int found = 0;
    for (double q2 : new double[] {0.35, -0.5, 0.9}) {
      double[] q = {0.6, q2, 0, 0.8, -0.9, 0.3};
      // The forearm turns through the vertical once in J3's range, where O5 crosses the axis.
      double lo = m.joint(2).lowerRad() + 0.05, hi = m.joint(2).upperRad() - 0.05;
      double[] grid = new double[41];
      for (int k = 0; k <= 40; k++) {
        q[2] = lo + k * (hi - lo) / 40;
        grid[k] = o5Across(m, q);
      }
      for (int k = 0; k < 40; k++) {
        if (grid[k] * grid[k + 1] < 0) {
          q[2] = j3OnAxis(m, q, lo + k * (hi - lo) / 40, lo + (k + 1) * (hi - lo) / 40);
          assertThat(Math.abs(o5Across(m, q))).as("O5 on the axis").isLessThan(1e-9);
          solvesIncludingTheTruth(m, q.clone(), what);
          found++;
        }
      }
    }
    assertThat(found).as("postures with O5 on the axis").isGreaterThanOrEqualTo(3);
  }

  @ParameterizedTest
  @ValueSource(booleans = {false, true})
  void theElbowOverTheShoulderIsSolved(boolean slanted) {
    // J2 = 0: the upper arm along the J1 axis, O3 on it; O5 is off the axis.
    RobotModel crx = RobotDefinitions.load("crx10ia");
    RobotModel m = slanted ? MountedArmInvarianceTest.mounted(crx, MountedArmInvarianceTest.MOUNT) : crx;
    for (double q3 : new double[] {0.4, -0.7, 1.5}) {
      for (double q1 : new double[] {0.6, -2.2}) {
        double[] q = {q1, 0, q3, -1.1, 0.7, 2.0};
        solvesIncludingTheTruth(m, q, (slanted ? "slanted " : "") + "CRX, elbow over the shoulder");
      }
    }
  }
}
