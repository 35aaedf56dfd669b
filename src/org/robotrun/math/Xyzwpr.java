package org.robotrun.math;

/**
 * A FANUC Cartesian pose: position X, Y, Z (mm) and orientation W, P, R (radians here;
 * degrees only at the boundary via {@link #ofDegrees} and {@link #wDeg()} etc.).
 *
 * <p>W, P, R are fixed-axis rotations about X, then Y, then Z, so the rotation matrix is
 * {@code R = Rz(r) · Ry(p) · Rx(w)} (the same as URDF roll-pitch-yaw). This class owns that
 * convention; nothing else in the code converts between angles and matrices.
 */
public record Xyzwpr(double x, double y, double z, double w, double p, double r) {

  /** Near |P| = 90° W and R are not separable; below this cos(P) we fix W = 0. */
  private static final double GIMBAL_EPS = 1e-12;

  public static Xyzwpr of(double x, double y, double z, double wRad, double pRad, double rRad) {
    return new Xyzwpr(x, y, z, wRad, pRad, rRad);
  }

  /** From the pendant / file form: mm and degrees. */
  public static Xyzwpr ofDegrees(double x, double y, double z, double wDeg, double pDeg, double rDeg) {
    return new Xyzwpr(x, y, z, Math.toRadians(wDeg), Math.toRadians(pDeg), Math.toRadians(rDeg));
  }

  public double wDeg() {
    return Math.toDegrees(w);
  }

  public double pDeg() {
    return Math.toDegrees(p);
  }

  public double rDeg() {
    return Math.toDegrees(r);
  }

  /** The rigid transform with this position and {@code Rz(r)·Ry(p)·Rx(w)}. */
  public Transform toTransform() {
    double cw = Math.cos(w), sw = Math.sin(w);
    double cp = Math.cos(p), sp = Math.sin(p);
    double cr = Math.cos(r), sr = Math.sin(r);
    return new Transform(
        cr * cp, cr * sp * sw - sr * cw, cr * sp * cw + sr * sw,
        sr * cp, sr * sp * sw + cr * cw, sr * sp * cw - cr * sw,
        -sp, cp * sw, cp * cw,
        x, y, z);
  }

  /**
   * The XYZWPR of a transform, with P in [-90°, 90°] and W, R in (-180°, 180°]. At the gimbal
   * (|P| = 90°) only W ∓ R is defined; W is set to 0 and R carries the whole rotation.
   */
  public static Xyzwpr fromTransform(Transform t) {
    double cp = Math.hypot(t.r00(), t.r10());
    double p = Math.atan2(-t.r20(), cp);
    double w;
    double r;
    if (cp > GIMBAL_EPS) {
      w = Math.atan2(t.r21(), t.r22());
      r = Math.atan2(t.r10(), t.r00());
    } else {
      // cos P = 0: Rz(r)·Ry(±90°)·Rx(w) depends on r ∓ w only; with w = 0, r01 = -sin r, r11 = cos r.
      w = 0;
      r = Math.atan2(-t.r01(), t.r11());
    }
    return new Xyzwpr(t.x(), t.y(), t.z(), w, p, r);
  }

  /** Position part. */
  public Vec3 position() {
    return new Vec3(x, y, z);
  }
}
