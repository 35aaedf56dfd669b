package org.robotrun.math;

/** Angle helpers (radians). */
public final class Angles {
  private Angles() {}

  /** Wraps an angle into (-π, π]. */
  public static double wrapPi(double a) {
    double r = Math.IEEEremainder(a, 2 * Math.PI);
    return r <= -Math.PI ? r + 2 * Math.PI : r;
  }

  public static double[] toRadians(double[] deg) {
    double[] out = new double[deg.length];
    for (int i = 0; i < deg.length; i++) {
      out[i] = Math.toRadians(deg[i]);
    }
    return out;
  }

  public static double[] toDegrees(double[] rad) {
    double[] out = new double[rad.length];
    for (int i = 0; i < rad.length; i++) {
      out[i] = Math.toDegrees(rad[i]);
    }
    return out;
  }
}
