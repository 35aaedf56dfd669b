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
  // Unrolled by hand (generated): with every element in a local the JIT keeps the whole
  // factorisation in registers, several times faster than the loop form.
  static void choleskySolve(double[] a, double[] b, double[] invDiag) {
    double a00 = a[0];
    double a10 = a[6];
    double a11 = a[7];
    double a20 = a[12];
    double a21 = a[13];
    double a22 = a[14];
    double a30 = a[18];
    double a31 = a[19];
    double a32 = a[20];
    double a33 = a[21];
    double a40 = a[24];
    double a41 = a[25];
    double a42 = a[26];
    double a43 = a[27];
    double a44 = a[28];
    double a50 = a[30];
    double a51 = a[31];
    double a52 = a[32];
    double a53 = a[33];
    double a54 = a[34];
    double a55 = a[35];
    double l00 = Math.sqrt(a00);
    double i0 = 1 / l00;
    double l10 = (a10) * i0;
    double l20 = (a20) * i0;
    double l30 = (a30) * i0;
    double l40 = (a40) * i0;
    double l50 = (a50) * i0;
    double l11 = Math.sqrt(a11 - l10 * l10);
    double i1 = 1 / l11;
    double l21 = (a21 - l20 * l10) * i1;
    double l31 = (a31 - l30 * l10) * i1;
    double l41 = (a41 - l40 * l10) * i1;
    double l51 = (a51 - l50 * l10) * i1;
    double l22 = Math.sqrt(a22 - l20 * l20 - l21 * l21);
    double i2 = 1 / l22;
    double l32 = (a32 - l30 * l20 - l31 * l21) * i2;
    double l42 = (a42 - l40 * l20 - l41 * l21) * i2;
    double l52 = (a52 - l50 * l20 - l51 * l21) * i2;
    double l33 = Math.sqrt(a33 - l30 * l30 - l31 * l31 - l32 * l32);
    double i3 = 1 / l33;
    double l43 = (a43 - l40 * l30 - l41 * l31 - l42 * l32) * i3;
    double l53 = (a53 - l50 * l30 - l51 * l31 - l52 * l32) * i3;
    double l44 = Math.sqrt(a44 - l40 * l40 - l41 * l41 - l42 * l42 - l43 * l43);
    double i4 = 1 / l44;
    double l54 = (a54 - l50 * l40 - l51 * l41 - l52 * l42 - l53 * l43) * i4;
    double l55 = Math.sqrt(a55 - l50 * l50 - l51 * l51 - l52 * l52 - l53 * l53 - l54 * l54);
    double i5 = 1 / l55;
    double y0 = (b[0]) * i0;
    double y1 = (b[1] - l10 * y0) * i1;
    double y2 = (b[2] - l20 * y0 - l21 * y1) * i2;
    double y3 = (b[3] - l30 * y0 - l31 * y1 - l32 * y2) * i3;
    double y4 = (b[4] - l40 * y0 - l41 * y1 - l42 * y2 - l43 * y3) * i4;
    double y5 = (b[5] - l50 * y0 - l51 * y1 - l52 * y2 - l53 * y3 - l54 * y4) * i5;
    double x5 = (y5) * i5;
    double x4 = (y4 - l54 * x5) * i4;
    double x3 = (y3 - l43 * x4 - l53 * x5) * i3;
    double x2 = (y2 - l32 * x3 - l42 * x4 - l52 * x5) * i2;
    double x1 = (y1 - l21 * x2 - l31 * x3 - l41 * x4 - l51 * x5) * i1;
    double x0 = (y0 - l10 * x1 - l20 * x2 - l30 * x3 - l40 * x4 - l50 * x5) * i0;
    b[0] = x0;
    b[1] = x1;
    b[2] = x2;
    b[3] = x3;
    b[4] = x4;
    b[5] = x5;
    invDiag[0] = i0;
    invDiag[1] = i1;
    invDiag[2] = i2;
    invDiag[3] = i3;
    invDiag[4] = i4;
    invDiag[5] = i5;
    a[0] = l00;
    a[6] = l10;
    a[7] = l11;
    a[12] = l20;
    a[13] = l21;
    a[14] = l22;
    a[18] = l30;
    a[19] = l31;
    a[20] = l32;
    a[21] = l33;
    a[24] = l40;
    a[25] = l41;
    a[26] = l42;
    a[27] = l43;
    a[28] = l44;
    a[30] = l50;
    a[31] = l51;
    a[32] = l52;
    a[33] = l53;
    a[34] = l54;
    a[35] = l55;
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
