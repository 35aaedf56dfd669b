package org.robotrun.math;

/**
 * A unit quaternion {@code w + xi + yj + zk} for a rotation, in the Hamilton convention used by
 * the reference data and by JOML: rotating v is {@code q v q*}. Canonical sign: {@code w ≥ 0}.
 *
 * <p>Conversion from a matrix uses Shepperd's method (pick the largest of the four squared
 * components to divide by), which stays accurate for every rotation, 180° turns included.
 */
public record Quaternion(double w, double x, double y, double z) {

  /** The rotation part of a transform as a quaternion with {@code w ≥ 0}. */
  public static Quaternion fromTransform(Transform t) {
    double tr = t.r00() + t.r11() + t.r22();
    double w, x, y, z;
    if (tr >= t.r00() && tr >= t.r11() && tr >= t.r22()) {
      double s = 2 * Math.sqrt(1 + tr);
      w = 0.25 * s;
      x = (t.r21() - t.r12()) / s;
      y = (t.r02() - t.r20()) / s;
      z = (t.r10() - t.r01()) / s;
    } else if (t.r00() >= t.r11() && t.r00() >= t.r22()) {
      double s = 2 * Math.sqrt(1 + t.r00() - t.r11() - t.r22());
      w = (t.r21() - t.r12()) / s;
      x = 0.25 * s;
      y = (t.r01() + t.r10()) / s;
      z = (t.r02() + t.r20()) / s;
    } else if (t.r11() >= t.r22()) {
      double s = 2 * Math.sqrt(1 + t.r11() - t.r00() - t.r22());
      w = (t.r02() - t.r20()) / s;
      x = (t.r01() + t.r10()) / s;
      y = 0.25 * s;
      z = (t.r12() + t.r21()) / s;
    } else {
      double s = 2 * Math.sqrt(1 + t.r22() - t.r00() - t.r11());
      w = (t.r10() - t.r01()) / s;
      x = (t.r02() + t.r20()) / s;
      y = (t.r12() + t.r21()) / s;
      z = 0.25 * s;
    }
    return new Quaternion(w, x, y, z).canonical();
  }

  /** The same rotation with {@code w ≥ 0} and unit norm. */
  public Quaternion canonical() {
    double n = Math.sqrt(w * w + x * x + y * y + z * z);
    if (n == 0) {
      throw new ArithmeticException("zero quaternion is not a rotation");
    }
    double s = w < 0 ? -1 / n : 1 / n;
    return new Quaternion(w * s, x * s, y * s, z * s);
  }

  /** The rotation matrix of this (normalised) quaternion with translation (x, y, z) in mm. */
  public Transform toTransform(double px, double py, double pz) {
    Quaternion q = canonical();
    double ww = q.w, xx = q.x, yy = q.y, zz = q.z;
    return new Transform(
        1 - 2 * (yy * yy + zz * zz), 2 * (xx * yy - zz * ww), 2 * (xx * zz + yy * ww),
        2 * (xx * yy + zz * ww), 1 - 2 * (xx * xx + zz * zz), 2 * (yy * zz - xx * ww),
        2 * (xx * zz - yy * ww), 2 * (yy * zz + xx * ww), 1 - 2 * (xx * xx + yy * yy),
        px, py, pz);
  }

  /** XYZWPR (FANUC) to quaternion, via the one convention owner {@link Xyzwpr}. */
  public static Quaternion fromXyzwpr(Xyzwpr pose) {
    return fromTransform(pose.toTransform());
  }

  /** Quaternion plus position (mm) to XYZWPR. */
  public Xyzwpr toXyzwpr(double px, double py, double pz) {
    return Xyzwpr.fromTransform(toTransform(px, py, pz));
  }
}
