package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link Dense6} against oracles written here: the determinant by Laplace expansion (its sign
 * included: luDecompose "returns the determinant", and every row swap flips it), A·x = b checked
 * by multiplying back, on random matrices and on row permutations of the identity (every pivot a
 * swap), and 0 for an exactly singular matrix; Cholesky on A·Aᵀ + I.
 */
class Dense6OracleTest {

  static double laplace(double[] m, int n, int[] rows, int[] cols) {
    if (n == 1) {
      return m[rows[0] * 6 + cols[0]];
    }
    double d = 0;
    int[] sub = new int[n - 1];
    int[] subRows = java.util.Arrays.copyOfRange(rows, 1, n);
    for (int c = 0; c < n; c++) {
      for (int k = 0, j = 0; k < n; k++) {
        if (k != c) {
          sub[j++] = cols[k];
        }
      }
      double e = m[rows[0] * 6 + cols[c]];
      if (e != 0) {
        d += (c % 2 == 0 ? 1 : -1) * e * laplace(m, n - 1, subRows, sub.clone());
      }
    }
    return d;
  }

  static double det(double[] m) {
    int[] all = {0, 1, 2, 3, 4, 5};
    return laplace(m, 6, all, all.clone());
  }

  @Test
  void theDeterminantAndTheSolutionOfRandomAndPermutedMatrices() {
    Random rnd = new Random(66);
    for (int k = 0; k < 40; k++) {
      double[] a = new double[36];
      if (k < 20) {
        for (int i = 0; i < 36; i++) {
          a[i] = rnd.nextDouble() * 2 - 1;
        }
      } else {
        // A row permutation of diag(1..6): det = ±720, every column pivots on another row.
        int[] p = {0, 1, 2, 3, 4, 5};
        for (int i = 5; i > 0; i--) {
          int j = rnd.nextInt(i + 1);
          int t = p[i];
          p[i] = p[j];
          p[j] = t;
        }
        for (int r = 0; r < 6; r++) {
          a[r * 6 + p[r]] = p[r] + 1;
        }
      }
      double want = det(a);
      double[] lu = a.clone();
      int[] perm = new int[6];
      double got = Dense6.luDecompose(lu, perm);
      assertThat(got).as("det %d", k).isCloseTo(want, org.assertj.core.api.Assertions.within(1e-9 * Math.max(1, Math.abs(want))));
      double[] b = new double[6];
      for (int i = 0; i < 6; i++) {
        b[i] = rnd.nextDouble() * 10 - 5;
      }
      double[] x = new double[6];
      Dense6.luSolve(lu, perm, b, x);
      for (int r = 0; r < 6; r++) {
        double s = 0;
        for (int c = 0; c < 6; c++) {
          s += a[r * 6 + c] * x[c];
        }
        assertThat(s).as("row %d of A·x, matrix %d", r, k).isCloseTo(b[r], org.assertj.core.api.Assertions.within(1e-8));
      }
    }
  }

  @Test
  void anExactlySingularMatrixHasDeterminantZero() {
    double[] a = new double[36];
    for (int r = 0; r < 6; r++) {
      for (int c = 0; c < 6; c++) {
        a[r * 6 + c] = c == 4 ? 0 : r + 2 * c + 1;
      }
    }
    assertThat(Dense6.luDecompose(a.clone(), new int[6])).isZero();
  }

  @Test
  void choleskySolvesASymmetricPositiveDefiniteSystem() {
    Random rnd = new Random(67);
    for (int k = 0; k < 10; k++) {
      double[] m = new double[36];
      for (int i = 0; i < 36; i++) {
        m[i] = rnd.nextDouble() * 2 - 1;
      }
      double[] a = new double[36];
      for (int r = 0; r < 6; r++) {
        for (int c = 0; c < 6; c++) {
          double s = r == c ? 1 : 0;
          for (int i = 0; i < 6; i++) {
            s += m[r * 6 + i] * m[c * 6 + i];
          }
          a[r * 6 + c] = s;
        }
      }
      double[] b = new double[6];
      for (int i = 0; i < 6; i++) {
        b[i] = rnd.nextDouble() * 10 - 5;
      }
      double[] x = b.clone();
      Dense6.choleskySolve(a.clone(), x, new double[6]);
      for (int r = 0; r < 6; r++) {
        double s = 0;
        for (int c = 0; c < 6; c++) {
          s += a[r * 6 + c] * x[c];
        }
        assertThat(s).isCloseTo(b[r], org.assertj.core.api.Assertions.within(1e-9));
      }
    }
  }
}
