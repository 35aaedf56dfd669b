package org.robotrun.motion;

import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/** Rotation-vector helpers (log and exp of SO(3)) for slerp and pose errors. */
final class Rotations {
  private Rotations() {}

  /**
   * The rotation vector (axis times angle, rad) of the row-major rotation {@code m[0..8]}:
   * log(R), angle in [0, π]. Near π the axis comes from the symmetric part (the skew part
   * vanishes there).
   */
  static void log(double[] m, double[] out) {
    double vx = m[7] - m[5], vy = m[2] - m[6], vz = m[3] - m[1];
    double s = 0.5 * Math.sqrt(vx * vx + vy * vy + vz * vz);
    double c = 0.5 * (m[0] + m[4] + m[8] - 1);
    double angle = Math.atan2(s, c);
    if (s > 1e-6) {
      double f = angle / (2 * s);
      out[0] = vx * f;
      out[1] = vy * f;
      out[2] = vz * f;
      return;
    }
    if (c > 0) {
      // Small angle: log R ≈ vee((R − Rᵀ)/2).
      out[0] = 0.5 * vx;
      out[1] = 0.5 * vy;
      out[2] = 0.5 * vz;
      return;
    }
    // Angle ≈ π: R ≈ 2aaᵀ − I, take the largest diagonal for the axis.
    double ax, ay, az;
    if (m[0] >= m[4] && m[0] >= m[8]) {
      ax = Math.sqrt(Math.max(0, (m[0] + 1) / 2));
      ay = (m[1] + m[3]) / (4 * ax);
      az = (m[2] + m[6]) / (4 * ax);
    } else if (m[4] >= m[8]) {
      ay = Math.sqrt(Math.max(0, (m[4] + 1) / 2));
      ax = (m[1] + m[3]) / (4 * ay);
      az = (m[5] + m[7]) / (4 * ay);
    } else {
      az = Math.sqrt(Math.max(0, (m[8] + 1) / 2));
      ax = (m[2] + m[6]) / (4 * az);
      ay = (m[5] + m[7]) / (4 * az);
    }
    double n = Math.sqrt(ax * ax + ay * ay + az * az);
    out[0] = ax / n * angle;
    out[1] = ay / n * angle;
    out[2] = az / n * angle;
  }

  /** The rotation vector of {@code R_A · R_Bᵀ} for two transforms: how to turn B into A, in the parent frame. */
  static Vec3 between(Transform X_a, Transform X_b) {
    Transform d = X_a.withTranslation(0, 0, 0).compose(X_b.withTranslation(0, 0, 0).inverse());
    double[] v = new double[3];
    log(d.rotationRowMajor(), v);
    return new Vec3(v[0], v[1], v[2]);
  }

  /** The rotation by the rotation vector {@code v} scaled by {@code f} (no translation). */
  static Transform exp(Vec3 v, double f) {
    double angle = v.norm();
    if (angle < 1e-15) {
      return Transform.IDENTITY;
    }
    return Transform.rotation(v.x() / angle, v.y() / angle, v.z() / angle, angle * f);
  }
}
