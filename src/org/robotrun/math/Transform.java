package org.robotrun.math;

/**
 * An immutable rigid transform: a rotation matrix and a translation (millimetres).
 *
 * <p>Named by its two frames where it is used: {@code X_AB} is frame B seen in frame A, and
 * {@code X_AC = X_AB.compose(X_BC)}. Applied to a point it maps coordinates in B to
 * coordinates in A: {@code p_A = X_AB.apply(p_B)}.
 */
public record Transform(
    double r00, double r01, double r02,
    double r10, double r11, double r12,
    double r20, double r21, double r22,
    double x, double y, double z) {

  public static final Transform IDENTITY = new Transform(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0);

  /** A pure translation (mm). */
  public static Transform translation(double x, double y, double z) {
    return new Transform(1, 0, 0, 0, 1, 0, 0, 0, 1, x, y, z);
  }

  /** A rotation of {@code angle} rad about the unit axis (ax, ay, az), Rodrigues' formula. */
  public static Transform rotation(double ax, double ay, double az, double angle) {
    double c = Math.cos(angle), s = Math.sin(angle), t = 1 - c;
    return new Transform(
        t * ax * ax + c, t * ax * ay - s * az, t * ax * az + s * ay,
        t * ax * ay + s * az, t * ay * ay + c, t * ay * az - s * ax,
        t * ax * az - s * ay, t * ay * az + s * ax, t * az * az + c,
        0, 0, 0);
  }

  /** Builds a transform from a row-major 3x3 rotation and a translation. */
  public static Transform of(double[] rowMajorRotation, double x, double y, double z) {
    double[] m = rowMajorRotation;
    return new Transform(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], x, y, z);
  }

  /** Roll-pitch-yaw as in URDF: R = Rz(yaw)·Ry(pitch)·Rx(roll), same as FANUC W, P, R. */
  public static Transform fromRpy(double x, double y, double z, double roll, double pitch, double yaw) {
    return Xyzwpr.of(x, y, z, roll, pitch, yaw).toTransform();
  }

  /** {@code this · other}: if this is X_AB and other is X_BC, the result is X_AC. */
  public Transform compose(Transform o) {
    return new Transform(
        r00 * o.r00 + r01 * o.r10 + r02 * o.r20,
        r00 * o.r01 + r01 * o.r11 + r02 * o.r21,
        r00 * o.r02 + r01 * o.r12 + r02 * o.r22,
        r10 * o.r00 + r11 * o.r10 + r12 * o.r20,
        r10 * o.r01 + r11 * o.r11 + r12 * o.r21,
        r10 * o.r02 + r11 * o.r12 + r12 * o.r22,
        r20 * o.r00 + r21 * o.r10 + r22 * o.r20,
        r20 * o.r01 + r21 * o.r11 + r22 * o.r21,
        r20 * o.r02 + r21 * o.r12 + r22 * o.r22,
        r00 * o.x + r01 * o.y + r02 * o.z + x,
        r10 * o.x + r11 * o.y + r12 * o.z + y,
        r20 * o.x + r21 * o.y + r22 * o.z + z);
  }

  /** The inverse: if this is X_AB the result is X_BA. */
  public Transform inverse() {
    return new Transform(
        r00, r10, r20,
        r01, r11, r21,
        r02, r12, r22,
        -(r00 * x + r10 * y + r20 * z),
        -(r01 * x + r11 * y + r21 * z),
        -(r02 * x + r12 * y + r22 * z));
  }

  /** Maps a point given in the child frame to the parent frame. */
  public Vec3 apply(Vec3 p) {
    return new Vec3(
        r00 * p.x() + r01 * p.y() + r02 * p.z() + x,
        r10 * p.x() + r11 * p.y() + r12 * p.z() + y,
        r20 * p.x() + r21 * p.y() + r22 * p.z() + z);
  }

  /** Rotates a direction (no translation). */
  public Vec3 rotate(Vec3 v) {
    return new Vec3(
        r00 * v.x() + r01 * v.y() + r02 * v.z(),
        r10 * v.x() + r11 * v.y() + r12 * v.z(),
        r20 * v.x() + r21 * v.y() + r22 * v.z());
  }

  public Vec3 translationVector() {
    return new Vec3(x, y, z);
  }

  /** Column i of the rotation: the child frame's axis i seen in the parent. */
  public Vec3 axis(int i) {
    return switch (i) {
      case 0 -> new Vec3(r00, r10, r20);
      case 1 -> new Vec3(r01, r11, r21);
      case 2 -> new Vec3(r02, r12, r22);
      default -> throw new IllegalArgumentException("axis index " + i);
    };
  }

  /** Same rotation, new translation. */
  public Transform withTranslation(double nx, double ny, double nz) {
    return new Transform(r00, r01, r02, r10, r11, r12, r20, r21, r22, nx, ny, nz);
  }

  /** Row-major rotation. */
  public double[] rotationRowMajor() {
    return new double[] {r00, r01, r02, r10, r11, r12, r20, r21, r22};
  }

  /** Column-major 4x4, as OpenGL and JOML expect. */
  public void toColumnMajor(float[] dest) {
    dest[0] = (float) r00; dest[1] = (float) r10; dest[2] = (float) r20; dest[3] = 0;
    dest[4] = (float) r01; dest[5] = (float) r11; dest[6] = (float) r21; dest[7] = 0;
    dest[8] = (float) r02; dest[9] = (float) r12; dest[10] = (float) r22; dest[11] = 0;
    dest[12] = (float) x; dest[13] = (float) y; dest[14] = (float) z; dest[15] = 1;
  }

  /** Angle (rad) of the rotation that takes this orientation to the other one. */
  public double rotationAngleTo(Transform o) {
    // trace(R_this^T R_o) = 1 + 2 cos(theta)
    double tr = r00 * o.r00 + r10 * o.r10 + r20 * o.r20
        + r01 * o.r01 + r11 * o.r11 + r21 * o.r21
        + r02 * o.r02 + r12 * o.r12 + r22 * o.r22;
    double c = Math.max(-1, Math.min(1, (tr - 1) / 2));
    // acos loses precision near 0: use the skew part for small angles.
    double sx = (r01 * o.r02 + r11 * o.r12 + r21 * o.r22) - (r02 * o.r01 + r12 * o.r11 + r22 * o.r21);
    double sy = (r02 * o.r00 + r12 * o.r10 + r22 * o.r20) - (r00 * o.r02 + r10 * o.r12 + r20 * o.r22);
    double sz = (r00 * o.r01 + r10 * o.r11 + r20 * o.r21) - (r01 * o.r00 + r11 * o.r10 + r21 * o.r20);
    double s = 0.5 * Math.sqrt(sx * sx + sy * sy + sz * sz);
    return Math.atan2(s, c);
  }

  /** Distance (mm) between the two origins. */
  public double distanceTo(Transform o) {
    double dx = x - o.x, dy = y - o.y, dz = z - o.z;
    return Math.sqrt(dx * dx + dy * dy + dz * dz);
  }
}
