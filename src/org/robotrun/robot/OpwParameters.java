package org.robotrun.robot;

import org.robotrun.math.Transform;

/**
 * Ortho-parallel wrist (OPW) parameters of Brandstötter, Angerer and Hofbaur, "An analytical
 * solution of the inverse kinematics problem of industrial serial manipulators with an
 * ortho-parallel basis and a spherical wrist" (2014). Lengths in mm.
 *
 * <p>Joint values map as {@code q = sign[i] · (θ_opw[i] + offset[i])}.
 *
 * <p>Two constant corrections let the family include arms whose files do not put the frames
 * where OPW wants them (a URDF's base turned or moved, a wall or ceiling mount, a flange frame
 * whose z is not along J6, e.g. a ROS-Industrial {@code flange} link): {@code base} is OPW's
 * base frame O in the robot base B ({@code X_BO}: z along J1, origin on the J1 axis), and
 * {@code flange} is the arm's flange F in OPW's canonical flange F' ({@code X_F'F}: F' on the J6
 * axis with z along it). The chain's flange pose is then {@code X_BF = X_BO · OPW(q) · X_F'F},
 * so the closed form solves for {@code X_BO⁻¹ · X_BF · X_F'F⁻¹}. Both are the identity for
 * every library arm.
 *
 * <p>{@code approximate}: the chain is OPW only to within the rounding of its file's numbers
 * (axes up to 1e-4 rad off, lines up to 0.05 mm apart, e.g. a URDF's {@code rpy="0 1.5708 0"});
 * the closed form's answers are then finished by a few Newton steps on the chain itself.
 */
public record OpwParameters(
    double a1, double a2, double b, double c1, double c2, double c3, double c4,
    double[] offsetsRad, int[] signs, Transform base, Transform flange, boolean approximate) {

  /** Parameters without corrections (base and flange frames already where OPW puts them). */
  public OpwParameters(double a1, double a2, double b, double c1, double c2, double c3, double c4,
      double[] offsetsRad, int[] signs) {
    this(a1, a2, b, c1, c2, c3, c4, offsetsRad, signs, Transform.IDENTITY, Transform.IDENTITY, false);
  }

  /** Exact parameters with corrections. */
  public OpwParameters(double a1, double a2, double b, double c1, double c2, double c3, double c4,
      double[] offsetsRad, int[] signs, Transform base, Transform flange) {
    this(a1, a2, b, c1, c2, c3, c4, offsetsRad, signs, base, flange, false);
  }

  /** The same parameters marked approximate (see the class comment). */
  public OpwParameters asApproximate() {
    return new OpwParameters(a1, a2, b, c1, c2, c3, c4, offsetsRad, signs, base, flange, true);
  }

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

  /** Whether the base or flange correction is other than the identity. */
  public boolean corrected() {
    return !base.equals(Transform.IDENTITY) || !flange.equals(Transform.IDENTITY);
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
