package org.robotrun.sim;

import org.robotrun.math.SinCos;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.JointSpec;
import org.robotrun.robot.RobotModel;

/**
 * Link poses of one robot in the cell, computed every tick for the collision check with one
 * {@link Transform} per link: each joint's {@code X_PJ · Rot(axis, q)} is precomputed as
 * {@code P + cos(q)·Q + sin(q)·S} (Rodrigues: {@code Rot = I + sin·K + (1 − cos)·K²}), the same
 * factorisation {@code robot.KinematicChain} uses for the flange. Gives the same poses as
 * {@code ForwardKinematics.linkPosesInWorld} composed with the placement (a test checks it).
 * Not thread-safe (a scratch array); one per robot.
 */
final class LinkPoses {
  private static final int DOF = RobotModel.DOF;
  private final double[] p = new double[DOF * 9];
  private final double[] qm = new double[DOF * 9];
  private final double[] s = new double[DOF * 9];
  private final double[] t = new double[DOF * 3];
  private final Transform X_CB;
  private final Transform X_6F;
  private final double[] sc = new double[2];

  /** @param X_CW the robot's WORLD in the cell */
  LinkPoses(RobotModel model, Transform X_CW) {
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
    }
    this.X_CB = X_CW.compose(model.X_WB());
    this.X_6F = model.X_6F();
  }

  /** Fills {@code out[0..6]} with links 0..6 and {@code out[7]} with the flange, in the cell. */
  void compute(double[] q, Transform[] out) {
    Transform x = X_CB;
    out[0] = x;
    double r00 = x.r00(), r01 = x.r01(), r02 = x.r02();
    double r10 = x.r10(), r11 = x.r11(), r12 = x.r12();
    double r20 = x.r20(), r21 = x.r21(), r22 = x.r22();
    double px = x.x(), py = x.y(), pz = x.z();
    for (int i = 0; i < DOF; i++) {
      int o3 = i * 3;
      double tx = t[o3], ty = t[o3 + 1], tz = t[o3 + 2];
      px += r00 * tx + r01 * ty + r02 * tz;
      py += r10 * tx + r11 * ty + r12 * tz;
      pz += r20 * tx + r21 * ty + r22 * tz;
      // One range reduction for both (the joint sines and cosines are most of the cost).
      SinCos.sinCos(q[i], sc, 0);
      double sn = sc[0], c = sc[1];
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
    out[DOF + 1] = out[DOF].compose(X_6F);
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
