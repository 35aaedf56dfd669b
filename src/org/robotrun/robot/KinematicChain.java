package org.robotrun.robot;

import org.robotrun.math.SinCos;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * An allocation-free form of a {@link RobotModel}'s joint chain for inner loops (IK, Jacobian,
 * resolved rate). Immutable and thread-safe; callers pass their own output arrays.
 *
 * <p>Poses are packed as 12 doubles in {@link Transform}'s field order: the row-major rotation
 * {@code r00..r22} then the translation {@code x, y, z} (mm). Everything is in the robot base
 * frame B.
 *
 * <p>Why: {@link ForwardKinematics} builds immutable {@link Transform}s per joint, clear but
 * about ten allocations per call; here each joint's {@code X_PJ · Rot(axis, q)} is precomputed
 * as {@code P + cos(q)·Q + sin(q)·S} (Rodrigues: {@code Rot = I + sin·K + (1−cos)·K²}), so a
 * joint costs one sin/cos pair and two 3x3 products, and a joint about an unrotated ±x/±y/±z
 * axis only turns two columns.
 */
public final class KinematicChain {
  private static final int DOF = RobotModel.DOF;

  // Per joint i: P, Q, S (row-major 3x3 each) and the joint frame's translation in its parent.
  private final double[] p = new double[DOF * 9];
  private final double[] qm = new double[DOF * 9];
  private final double[] s = new double[DOF * 9];
  private final double[] t = new double[DOF * 3];
  // Per joint i: its axis in the joint frame, rotated by X_PJ's rotation (axis in the parent link).
  private final double[] axisInParent = new double[DOF * 3];
  private final double[] x6f = new double[12];
  // Per joint: 0 for a general joint frame; 1, 2, 3 when the joint frame is not rotated and the
  // axis is ±x, ±y, ±z (every URDF arm we ship), which needs 12 multiplications instead of 54.
  private final int[] kind = new int[DOF];
  private final double[] axisSign = new double[DOF];
  private final double[] lower = new double[DOF];
  private final double[] upper = new double[DOF];
  // Scratch for linkPoses: one joint's (sin, cos).
  private final double[] sinCos = new double[2];

  public KinematicChain(RobotModel model) {
    for (int i = 0; i < DOF; i++) {
      JointSpec j = model.joint(i);
      Vec3 a = j.axis();
      double[] k = {0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0};
      double[] k2 = mul3(k, k);
      double[] r = j.X_PJ().rotationRowMajor();
      double[] iPlusK2 = k2.clone();
      iPlusK2[0] += 1;
      iPlusK2[4] += 1;
      iPlusK2[8] += 1;
      double[] pi = mul3(r, iPlusK2);
      double[] qi = mul3(r, k2);
      double[] si = mul3(r, k);
      for (int e = 0; e < 9; e++) {
        p[i * 9 + e] = pi[e];
        qm[i * 9 + e] = -qi[e];
        s[i * 9 + e] = si[e];
      }
      t[i * 3] = j.X_PJ().x();
      t[i * 3 + 1] = j.X_PJ().y();
      t[i * 3 + 2] = j.X_PJ().z();
      Vec3 ap = j.X_PJ().rotate(a);
      axisInParent[i * 3] = ap.x();
      axisInParent[i * 3 + 1] = ap.y();
      axisInParent[i * 3 + 2] = ap.z();
      lower[i] = j.lowerRad();
      upper[i] = j.upperRad();
      boolean unrotated = j.X_PJ().rotationAngleTo(Transform.IDENTITY) == 0;
      double[] comps = {a.x(), a.y(), a.z()};
      for (int c = 0; c < 3 && unrotated; c++) {
        if (Math.abs(comps[c]) == 1) {
          kind[i] = c + 1;
          axisSign[i] = comps[c];
        }
      }
    }
    pack(model.X_6F(), x6f, 0);
  }

  /**
   * Computes the flange pose {@code X_BF} into {@code X_BF} (12 doubles) and, if
   * {@code axes} is not null, each joint's axis line in B into it (36 doubles: for joint i,
   * origin x, y, z at [6i..6i+2] (mm) and unit direction at [6i+3..6i+5]).
   */
  public void flangePose(double[] q, double[] X_BF, double[] axes) {
    // X_BF is written last, so it holds the six (sin, cos) pairs meanwhile: no allocation.
    for (int i = 0; i < DOF; i++) {
      SinCos.sinCos(q[i], X_BF, 2 * i);
    }
    double r00 = 1, r01 = 0, r02 = 0, r10 = 0, r11 = 1, r12 = 0, r20 = 0, r21 = 0, r22 = 1;
    double px = 0, py = 0, pz = 0;
    for (int i = 0; i < DOF; i++) {
      int o3 = i * 3;
      // Origin of joint i: X_B(i-1) applied to the joint's offset.
      double tx = t[o3], ty = t[o3 + 1], tz = t[o3 + 2];
      px += r00 * tx + r01 * ty + r02 * tz;
      py += r10 * tx + r11 * ty + r12 * tz;
      pz += r20 * tx + r21 * ty + r22 * tz;
      if (axes != null) {
        double ax = axisInParent[o3], ay = axisInParent[o3 + 1], az = axisInParent[o3 + 2];
        int o6 = i * 6;
        axes[o6] = px;
        axes[o6 + 1] = py;
        axes[o6 + 2] = pz;
        axes[o6 + 3] = r00 * ax + r01 * ay + r02 * az;
        axes[o6 + 4] = r10 * ax + r11 * ay + r12 * az;
        axes[o6 + 5] = r20 * ax + r21 * ay + r22 * az;
      }
      double sn = X_BF[2 * i], c = X_BF[2 * i + 1];
      switch (kind[i]) {
        case 1 -> {
          // R·Rx(±q): columns 1 and 2 turn.
          double s1 = axisSign[i] * sn;
          double n01 = r01 * c + r02 * s1, n02 = r02 * c - r01 * s1;
          double n11 = r11 * c + r12 * s1, n12 = r12 * c - r11 * s1;
          double n21 = r21 * c + r22 * s1, n22 = r22 * c - r21 * s1;
          r01 = n01; r02 = n02; r11 = n11; r12 = n12; r21 = n21; r22 = n22;
        }
        case 2 -> {
          // R·Ry(±q): columns 0 and 2 turn.
          double s1 = axisSign[i] * sn;
          double n00 = r00 * c - r02 * s1, n02 = r02 * c + r00 * s1;
          double n10 = r10 * c - r12 * s1, n12 = r12 * c + r10 * s1;
          double n20 = r20 * c - r22 * s1, n22 = r22 * c + r20 * s1;
          r00 = n00; r02 = n02; r10 = n10; r12 = n12; r20 = n20; r22 = n22;
        }
        case 3 -> {
          // R·Rz(±q): columns 0 and 1 turn.
          double s1 = axisSign[i] * sn;
          double n00 = r00 * c + r01 * s1, n01 = r01 * c - r00 * s1;
          double n10 = r10 * c + r11 * s1, n11 = r11 * c - r10 * s1;
          double n20 = r20 * c + r21 * s1, n21 = r21 * c - r20 * s1;
          r00 = n00; r01 = n01; r10 = n10; r11 = n11; r20 = n20; r21 = n21;
        }
        default -> {
          int o9 = i * 9;
          double m00 = p[o9] + c * qm[o9] + sn * s[o9];
          double m01 = p[o9 + 1] + c * qm[o9 + 1] + sn * s[o9 + 1];
          double m02 = p[o9 + 2] + c * qm[o9 + 2] + sn * s[o9 + 2];
          double m10 = p[o9 + 3] + c * qm[o9 + 3] + sn * s[o9 + 3];
          double m11 = p[o9 + 4] + c * qm[o9 + 4] + sn * s[o9 + 4];
          double m12 = p[o9 + 5] + c * qm[o9 + 5] + sn * s[o9 + 5];
          double m20 = p[o9 + 6] + c * qm[o9 + 6] + sn * s[o9 + 6];
          double m21 = p[o9 + 7] + c * qm[o9 + 7] + sn * s[o9 + 7];
          double m22 = p[o9 + 8] + c * qm[o9 + 8] + sn * s[o9 + 8];
          double n00 = r00 * m00 + r01 * m10 + r02 * m20;
          double n01 = r00 * m01 + r01 * m11 + r02 * m21;
          double n02 = r00 * m02 + r01 * m12 + r02 * m22;
          double n10 = r10 * m00 + r11 * m10 + r12 * m20;
          double n11 = r10 * m01 + r11 * m11 + r12 * m21;
          double n12 = r10 * m02 + r11 * m12 + r12 * m22;
          double n20 = r20 * m00 + r21 * m10 + r22 * m20;
          double n21 = r20 * m01 + r21 * m11 + r22 * m21;
          double n22 = r20 * m02 + r21 * m12 + r22 * m22;
          r00 = n00; r01 = n01; r02 = n02;
          r10 = n10; r11 = n11; r12 = n12;
          r20 = n20; r21 = n21; r22 = n22;
        }
      }
    }
    // Flange: X_B6 · X_6F.
    double[] f = x6f;
    X_BF[0] = r00 * f[0] + r01 * f[3] + r02 * f[6];
    X_BF[1] = r00 * f[1] + r01 * f[4] + r02 * f[7];
    X_BF[2] = r00 * f[2] + r01 * f[5] + r02 * f[8];
    X_BF[3] = r10 * f[0] + r11 * f[3] + r12 * f[6];
    X_BF[4] = r10 * f[1] + r11 * f[4] + r12 * f[7];
    X_BF[5] = r10 * f[2] + r11 * f[5] + r12 * f[8];
    X_BF[6] = r20 * f[0] + r21 * f[3] + r22 * f[6];
    X_BF[7] = r20 * f[1] + r21 * f[4] + r22 * f[7];
    X_BF[8] = r20 * f[2] + r21 * f[5] + r22 * f[8];
    X_BF[9] = px + r00 * f[9] + r01 * f[10] + r02 * f[11];
    X_BF[10] = py + r10 * f[9] + r11 * f[10] + r12 * f[11];
    X_BF[11] = pz + r20 * f[9] + r21 * f[10] + r22 * f[11];
  }

  /**
   * Every link pose, for callers that need them all (the collision check each tick): fills
   * {@code out[0]} with {@code X_AB} (the base in some frame A) and {@code out[1..6]} with links
   * 1..6 in A. One {@link Transform} per link; the joint factors are the ones
   * {@link #flangePose} uses.
   */
  public void linkPoses(Transform X_AB, double[] q, Transform[] out) {
    out[0] = X_AB;
    double r00 = X_AB.r00(), r01 = X_AB.r01(), r02 = X_AB.r02();
    double r10 = X_AB.r10(), r11 = X_AB.r11(), r12 = X_AB.r12();
    double r20 = X_AB.r20(), r21 = X_AB.r21(), r22 = X_AB.r22();
    double px = X_AB.x(), py = X_AB.y(), pz = X_AB.z();
    for (int i = 0; i < DOF; i++) {
      int o3 = i * 3;
      double tx = t[o3], ty = t[o3 + 1], tz = t[o3 + 2];
      px += r00 * tx + r01 * ty + r02 * tz;
      py += r10 * tx + r11 * ty + r12 * tz;
      pz += r20 * tx + r21 * ty + r22 * tz;
      SinCos.sinCos(q[i], sinCos, 0);
      double sn = sinCos[0], c = sinCos[1];
      int o = i * 9;
      double m00 = p[o] + c * qm[o] + sn * s[o];
      double m01 = p[o + 1] + c * qm[o + 1] + sn * s[o + 1];
      double m02 = p[o + 2] + c * qm[o + 2] + sn * s[o + 2];
      double m10 = p[o + 3] + c * qm[o + 3] + sn * s[o + 3];
      double m11 = p[o + 4] + c * qm[o + 4] + sn * s[o + 4];
      double m12 = p[o + 5] + c * qm[o + 5] + sn * s[o + 5];
      double m20 = p[o + 6] + c * qm[o + 6] + sn * s[o + 6];
      double m21 = p[o + 7] + c * qm[o + 7] + sn * s[o + 7];
      double m22 = p[o + 8] + c * qm[o + 8] + sn * s[o + 8];
      double n00 = r00 * m00 + r01 * m10 + r02 * m20;
      double n01 = r00 * m01 + r01 * m11 + r02 * m21;
      double n02 = r00 * m02 + r01 * m12 + r02 * m22;
      double n10 = r10 * m00 + r11 * m10 + r12 * m20;
      double n11 = r10 * m01 + r11 * m11 + r12 * m21;
      double n12 = r10 * m02 + r11 * m12 + r12 * m22;
      double n20 = r20 * m00 + r21 * m10 + r22 * m20;
      double n21 = r20 * m01 + r21 * m11 + r22 * m21;
      double n22 = r20 * m02 + r21 * m12 + r22 * m22;
      r00 = n00; r01 = n01; r02 = n02;
      r10 = n10; r11 = n11; r12 = n12;
      r20 = n20; r21 = n21; r22 = n22;
      out[i + 1] = new Transform(r00, r01, r02, r10, r11, r12, r20, r21, r22, px, py, pz);
    }
  }

  /** Lower joint limit i (rad). */
  public double lower(int i) {
    return lower[i];
  }

  /** Upper joint limit i (rad). */
  public double upper(int i) {
    return upper[i];
  }

  /** Whether every joint lies inside its limits (inclusive). */
  public boolean withinLimits(double[] q) {
    for (int i = 0; i < DOF; i++) {
      if (!(q[i] >= lower[i] && q[i] <= upper[i])) {
        return false;
      }
    }
    return true;
  }

  /** Packs a transform into 12 doubles at {@code off}. */
  public static void pack(Transform x, double[] dest, int off) {
    dest[off] = x.r00(); dest[off + 1] = x.r01(); dest[off + 2] = x.r02();
    dest[off + 3] = x.r10(); dest[off + 4] = x.r11(); dest[off + 5] = x.r12();
    dest[off + 6] = x.r20(); dest[off + 7] = x.r21(); dest[off + 8] = x.r22();
    dest[off + 9] = x.x(); dest[off + 10] = x.y(); dest[off + 11] = x.z();
  }

  /** Unpacks 12 doubles into a transform. */
  public static Transform unpack(double[] a) {
    return new Transform(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], a[9], a[10], a[11]);
  }

  /** {@code dest = a · b} for packed poses; dest may not alias a or b. */
  public static void compose(double[] a, double[] b, double[] dest) {
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) {
        dest[r * 3 + c] = a[r * 3] * b[c] + a[r * 3 + 1] * b[3 + c] + a[r * 3 + 2] * b[6 + c];
      }
      dest[9 + r] = a[r * 3] * b[9] + a[r * 3 + 1] * b[10] + a[r * 3 + 2] * b[11] + a[9 + r];
    }
  }

  private static double[] mul3(double[] a, double[] b) {
    double[] out = new double[9];
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) {
        out[r * 3 + c] = a[r * 3] * b[c] + a[r * 3 + 1] * b[3 + c] + a[r * 3 + 2] * b[6 + c];
      }
    }
    return out;
  }
}
