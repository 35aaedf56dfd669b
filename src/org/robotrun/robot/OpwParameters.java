package org.robotrun.robot;

/**
 * Ortho-parallel wrist (OPW) parameters of Brandstötter, Angerer and Hofbaur, "An analytical
 * solution of the inverse kinematics problem of industrial serial manipulators with an
 * ortho-parallel basis and a spherical wrist" (2014). Lengths in mm.
 *
 * <p>Joint values map as {@code q = sign[i] · (θ_opw[i] + offset[i])}.
 */
public record OpwParameters(
    double a1, double a2, double b, double c1, double c2, double c3, double c4,
    double[] offsetsRad, int[] signs) {

  public OpwParameters {
    if (offsetsRad.length != 6 || signs.length != 6) {
      throw new IllegalArgumentException("OPW offsets and signs need 6 entries each");
    }
    for (int s : signs) {
      if (s != 1 && s != -1) {
        throw new IllegalArgumentException("OPW sign corrections must be 1 or -1");
      }
    }
    offsetsRad = offsetsRad.clone();
    signs = signs.clone();
  }

  @Override
  public double[] offsetsRad() {
    return offsetsRad.clone();
  }

  @Override
  public int[] signs() {
    return signs.clone();
  }

  public double offsetRad(int i) {
    return offsetsRad[i];
  }

  public int sign(int i) {
    return signs[i];
  }
}
