package org.robotrun.robot;

/**
 * 6x6 dense linear algebra for the kinematics inner loops, on row-major {@code double[36]}
 * arrays, allocation-free. Package-private: {@link ResolvedRate} and {@link NumericIk} use it.
 */
final class Dense6 {
  private Dense6() {}

  /**
   * Solves {@code A·x = b} for symmetric positive definite A by Cholesky ({@code A = L·Lᵀ}).
   * Only the lower triangle of {@code a} is read; it is overwritten by L. {@code b} is
   * overwritten by x. {@code invDiag} (6) receives 1/L_ii: one division per row instead of one
   * per element.
   */
  static void choleskySolve(double[] a, double[] b, double[] invDiag) {
    for (int c = 0; c < 6; c++) {
      int co = c * 6;
      double d = a[co + c];
      for (int k = 0; k < c; k++) {
        d -= a[co + k] * a[co + k];
      }
      d = Math.sqrt(d);
      a[co + c] = d;
      double inv = 1 / d;
      invDiag[c] = inv;
      for (int r = c + 1; r < 6; r++) {
        int ro = r * 6;
        double sum = a[ro + c];
        for (int k = 0; k < c; k++) {
          sum -= a[ro + k] * a[co + k];
        }
        a[ro + c] = sum * inv;
      }
    }
    for (int r = 0; r < 6; r++) {
      int ro = r * 6;
      double sum = b[r];
      for (int k = 0; k < r; k++) {
        sum -= a[ro + k] * b[k];
      }
      b[r] = sum * invDiag[r];
    }
    for (int r = 5; r >= 0; r--) {
      double sum = b[r];
      for (int k = r + 1; k < 6; k++) {
        sum -= a[k * 6 + r] * b[k];
      }
      b[r] = sum * invDiag[r];
    }
  }

  /** In-place LU with partial pivoting; returns the determinant (0 if exactly singular). */
  static double luDecompose(double[] m, int[] perm) {
    double det = 1;
    for (int i = 0; i < 6; i++) {
      perm[i] = i;
    }
    for (int k = 0; k < 6; k++) {
      int p = k;
      double max = Math.abs(m[k * 6 + k]);
      for (int r = k + 1; r < 6; r++) {
        double v = Math.abs(m[r * 6 + k]);
        if (v > max) {
          max = v;
          p = r;
        }
      }
      if (max == 0) {
        return 0;
      }
      if (p != k) {
        for (int c = 0; c < 6; c++) {
          double tmp = m[k * 6 + c];
          m[k * 6 + c] = m[p * 6 + c];
          m[p * 6 + c] = tmp;
        }
        int tp = perm[k];
        perm[k] = perm[p];
        perm[p] = tp;
        det = -det;
      }
      double pivot = m[k * 6 + k];
      det *= pivot;
      double inv = 1 / pivot;
      for (int r = k + 1; r < 6; r++) {
        double f = m[r * 6 + k] * inv;
        m[r * 6 + k] = f;
        for (int c = k + 1; c < 6; c++) {
          m[r * 6 + c] -= f * m[k * 6 + c];
        }
      }
    }
    return det;
  }

  /** Solves with an LU from {@link #luDecompose}: x = A⁻¹·b (b not modified, x not b). */
  static void luSolve(double[] m, int[] perm, double[] b, double[] x) {
    for (int r = 0; r < 6; r++) {
      double sum = b[perm[r]];
      for (int k = 0; k < r; k++) {
        sum -= m[r * 6 + k] * x[k];
      }
      x[r] = sum;
    }
    for (int r = 5; r >= 0; r--) {
      double sum = x[r];
      for (int k = r + 1; k < 6; k++) {
        sum -= m[r * 6 + k] * x[k];
      }
      x[r] = sum / m[r * 6 + r];
    }
  }
}
