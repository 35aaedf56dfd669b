package org.robotrun.math;

/**
 * Sine and cosine of one angle from a single range reduction, for kinematics inner loops where
 * trigonometry is most of the cost. Accurate to about 1 ulp for |x| below 1e5 rad (the
 * reduction uses a three-part π/2, exact for the quotients that occur); beyond that it falls
 * back to {@link Math#sin}/{@link Math#cos}.
 *
 * <p>Polynomials: the minimax coefficients of fdlibm's {@code __kernel_sin} and
 * {@code __kernel_cos} on [−π/4, π/4] (Sun Microsystems, 1993), with its three-part π/2 for
 * the Cody–Waite reduction.
 */
public final class SinCos {
  private SinCos() {}

  private static final double TWO_OVER_PI = 6.36619772367581382433e-01;
  private static final double PIO2_1 = 1.57079632673412561417e+00;
  private static final double PIO2_2 = 6.07710050630396597660e-11;
  private static final double PIO2_3 = 2.02226624879595063154e-21;

  private static final double S1 = -1.66666666666666324348e-01;
  private static final double S2 = 8.33333333332248946124e-03;
  private static final double S3 = -1.98412698298579493134e-04;
  private static final double S4 = 2.75573137070700676789e-06;
  private static final double S5 = -2.50507602534068634195e-08;
  private static final double S6 = 1.58969099521155010221e-10;

  private static final double C1 = 4.16666666666666019037e-02;
  private static final double C2 = -1.38888888888741095749e-03;
  private static final double C3 = 2.48015872894767294178e-05;
  private static final double C4 = -2.75573143513906633035e-07;
  private static final double C5 = 2.08757232129817482790e-09;
  private static final double C6 = -1.13596475577881948265e-11;

  /** Writes sin(x) to {@code dest[off]} and cos(x) to {@code dest[off + 1]}. */
  public static void sinCos(double x, double[] dest, int off) {
    if (!(Math.abs(x) < 1e5)) {
      dest[off] = Math.sin(x);
      dest[off + 1] = Math.cos(x);
      return;
    }
    double n = Math.rint(x * TWO_OVER_PI);
    double r = ((x - n * PIO2_1) - n * PIO2_2) - n * PIO2_3;
    double z = r * r;
    double s = r + r * z * (S1 + z * (S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)))));
    double hz = 0.5 * z;
    double w = 1.0 - hz;
    double c = w + (((1.0 - w) - hz) + z * z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6))))));
    switch ((int) n & 3) {
      case 0 -> {
        dest[off] = s;
        dest[off + 1] = c;
      }
      case 1 -> {
        dest[off] = c;
        dest[off + 1] = -s;
      }
      case 2 -> {
        dest[off] = -s;
        dest[off + 1] = -c;
      }
      default -> {
        dest[off] = -c;
        dest[off + 1] = s;
      }
    }
  }
}
