package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * The CRX search finds every solution: each pose is also solved here by an independent damped
 * Newton iteration (finite-difference Jacobian of {@link ForwardKinematics}, written in this test)
 * from 48 random starts (12 under mutation testing), and every posture it converges to must be among the search's solutions.
 * The poses include the postures a teacher meets most and where the search's equations degenerate:
 * J4 at 0 and at 180° (the J5 axis across the arm plane, where the elbow is solved as a plane
 * two-link problem), J5 a hair from 0, and the elbow nearly stretched. The joints that made each pose
 * are among the solutions, every solution reaches the pose, and nearest-solution solving returns them.
 */
class OffsetWristCompletenessTest {
  /** Newton starts per pose (fewer under mutation testing: the same first ones, {@link org.robotrun.PitScale}). */
  static final int STARTS = org.robotrun.PitScale.samples(48, 12);

  /** J4 = 0 and 180°, J5 near 0, the elbow nearly stretched, and plain random joints. */
  static List<double[]> poses(RobotModel m, long seed) {
    Random rnd = new Random(seed);
    List<double[]> out = new ArrayList<>();
    for (int k = 0; k < 10; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        double lo = Math.max(m.joint(i).lowerRad(), -Math.PI) + 0.15;
        double hi = Math.min(m.joint(i).upperRad(), Math.PI) - 0.15;
        q[i] = lo + rnd.nextDouble() * (hi - lo);
      }
      switch (k % 5) {
        case 0 -> q[3] = 0;
        case 1 -> q[3] = Math.PI;
        case 2 -> q[4] = 1e-3 * (rnd.nextBoolean() ? 1 : -1);
        case 3 -> q[2] = 0.02 * (rnd.nextDouble() - 0.5);
        default -> { }
      }
      if (m.firstJointOutsideLimits(q) < 0) {
        out.add(q);
      }
    }
    return out;
  }

  /** 6-vector error of pose {@code got} from {@code want}: position / 300 mm, rotation vector (sin form). */
  static double[] error(Transform want, Transform got) {
    double[] r = want.compose(got.inverse()).rotationRowMajor();
    return new double[] {(want.x() - got.x()) / 300, (want.y() - got.y()) / 300, (want.z() - got.z()) / 300,
      0.5 * (r[7] - r[5]), 0.5 * (r[2] - r[6]), 0.5 * (r[3] - r[1])};
  }

  /** Damped Newton from {@code q}; the converged joints (wrapped to (−π, π]) or null. */
  static double[] newton(RobotModel m, Transform X, double[] start) {
    double[] q = start.clone();
    for (int it = 0; it < 60; it++) {
      Transform F = ForwardKinematics.flangePoseInBase(m, q);
      if (F.distanceTo(X) < 1e-9 && F.rotationAngleTo(X) < 1e-11) {
        for (int i = 0; i < 6; i++) {
          q[i] = Math.IEEEremainder(q[i], 2 * Math.PI);
        }
        return q;
      }
      double[] e = error(X, F);
      double[][] J = new double[6][6];
      for (int c = 0; c < 6; c++) {
        double[] qh = q.clone();
        qh[c] += 1e-7;
        double[] eh = error(X, ForwardKinematics.flangePoseInBase(m, qh));
        for (int r = 0; r < 6; r++) {
          J[r][c] = (e[r] - eh[r]) / 1e-7;
        }
      }
      double lambda = 1e-3 * Math.min(1, Arrays.stream(e).map(x -> x * x).sum());
      double[][] A = new double[6][7];
      for (int r = 0; r < 6; r++) {
        for (int c = 0; c < 6; c++) {
          for (int k = 0; k < 6; k++) {
            A[r][c] += J[k][r] * J[k][c];
          }
        }
        A[r][r] += lambda;
        for (int k = 0; k < 6; k++) {
          A[r][6] += J[k][r] * e[k];
        }
      }
      double[] dq = gauss(A);
      double n = Math.sqrt(Arrays.stream(dq).map(x -> x * x).sum());
      double scale = n > 0.5 ? 0.5 / n : 1;
      for (int i = 0; i < 6; i++) {
        q[i] += scale * dq[i];
      }
    }
    return null;
  }

  static double[] gauss(double[][] a) {
    int n = 6;
    for (int c = 0; c < n; c++) {
      int p = c;
      for (int r = c + 1; r < n; r++) {
        if (Math.abs(a[r][c]) > Math.abs(a[p][c])) {
          p = r;
        }
      }
      double[] t = a[c];
      a[c] = a[p];
      a[p] = t;
      for (int r = c + 1; r < n; r++) {
        double f = a[r][c] / a[c][c];
        for (int k = c; k <= n; k++) {
          a[r][k] -= f * a[c][k];
        }
      }
    }
    double[] x = new double[n];
    for (int r = n - 1; r >= 0; r--) {
      double s = a[r][n];
      for (int k = r + 1; k < n; k++) {
        s -= a[r][k] * x[k];
      }
      x[r] = s / a[r][r];
    }
    return x;
  }

  static double wrappedDiff(double[] a, double[] b) {
    double w = 0;
    for (int i = 0; i < 6; i++) {
      w = Math.max(w, Math.abs(Math.IEEEremainder(a[i] - b[i], 2 * Math.PI)));
    }
    return w;
  }

  @ParameterizedTest
  @ValueSource(strings = {"crx10ia", "crx10ial"})
  void everyPostureAnIndependentNewtonSearchFindsIsAmongTheSolutions(String id) {
    RobotModel m = RobotDefinitions.load(id);
    OffsetWristIk ik = new OffsetWristIk(m);
    Random starts = new Random(77);
    int found = 0;
    for (double[] q : poses(m, 500 + id.length())) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      List<double[]> base = ik.baseSolutions(X);
      String what = id + " pose " + Arrays.toString(q);
      assertThat(base.stream().anyMatch(s -> wrappedDiff(s, q) < 1e-6)).as("%s: its own joints", what).isTrue();
      for (double[] s : base) {
        Transform Y = ForwardKinematics.flangePoseInBase(m, s);
        assertThat(Y.distanceTo(X)).as("%s: solution %s", what, Arrays.toString(s)).isLessThan(1e-6);
        assertThat(Y.rotationAngleTo(X)).isLessThan(1e-9);
        for (double v : s) {
          assertThat(v).as("%s: wrapped", what).isBetween(-Math.PI, Math.PI);
        }
      }
      for (int k = 0; k < base.size(); k++) {
        for (int j = 0; j < k; j++) {
          assertThat(wrappedDiff(base.get(j), base.get(k))).as("%s: solutions listed once", what).isGreaterThan(1e-7);
        }
      }
      for (int k = 0; k < STARTS; k++) {
        double[] start = new double[6];
        for (int i = 0; i < 6; i++) {
          start[i] = Math.PI * (2 * starts.nextDouble() - 1);
        }
        double[] s = newton(m, X, start);
        if (s == null) {
          continue;
        }
        found++;
        assertThat(base.stream().anyMatch(b -> wrappedDiff(b, s) < 1e-5))
            .as("%s: Newton's posture %s among the %d solutions", what, Arrays.toString(s), base.size()).isTrue();
      }
      // The arm standing at the truth gets it back as the nearest solution.
      IkResult near = ik.solveNearest(X, q);
      assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), q)).as("%s: nearest", what).isLessThan(1e-6);
    }
    assertThat(found).as("postures the independent search converged to").isGreaterThanOrEqualTo(STARTS);
  }
}
