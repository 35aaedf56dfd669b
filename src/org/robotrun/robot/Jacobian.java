package org.robotrun.robot;

import org.robotrun.math.Transform;

/**
 * The analytic geometric Jacobian of the tool centre point, {@code J_B}: joint rates (rad/s)
 * to the TCP's twist in the base frame B, rows linear velocity (mm/s) then angular velocity
 * (rad/s). Column i is {@code [z_i × (p_BTcp − p_i); z_i]} for revolute joint i with axis
 * direction z_i through the point p_i (Siciliano et al., Robotics, §3.1).
 *
 * <p>Arrays are row-major 6x6 ({@code J[row * 6 + col]}); poses are packed as in
 * {@link KinematicChain}.
 */
public final class Jacobian {
  /** Scratch length needed by {@link #tcpJacobianInBase}. */
  public static final int SCRATCH = 48;

  private Jacobian() {}

  /**
   * Fills {@code J_B} (36) and the TCP pose {@code X_BT} (12) at joints {@code q}.
   *
   * @param X_FT the tool frame in the flange frame (packed 12), or null for the flange itself
   * @param scratch at least {@link #SCRATCH} doubles, overwritten
   */
  public static void tcpJacobianInBase(
      KinematicChain chain, double[] q, double[] X_FT, double[] J_B, double[] X_BT, double[] scratch) {
    // scratch[0..35]: joint axes in B; scratch[36..47]: flange pose.
    chain.flangePose(q, X_BT, scratch);
    if (X_FT != null) {
      System.arraycopy(X_BT, 0, scratch, 36, 12);
      composeFrom(scratch, 36, X_FT, X_BT);
    }
    double tx = X_BT[9], ty = X_BT[10], tz = X_BT[11];
    for (int i = 0; i < RobotModel.DOF; i++) {
      int o = i * 6;
      double dx = tx - scratch[o], dy = ty - scratch[o + 1], dz = tz - scratch[o + 2];
      double zx = scratch[o + 3], zy = scratch[o + 4], zz = scratch[o + 5];
      J_B[i] = zy * dz - zz * dy;
      J_B[6 + i] = zz * dx - zx * dz;
      J_B[12 + i] = zx * dy - zy * dx;
      J_B[18 + i] = zx;
      J_B[24 + i] = zy;
      J_B[30 + i] = zz;
    }
  }

  /** Convenience form that allocates: the 6x6 TCP Jacobian in B for a tool {@code X_FT}. */
  public static double[] tcpJacobianInBase(RobotModel model, double[] q, Transform X_FT) {
    double[] tool = new double[12];
    KinematicChain.pack(X_FT, tool, 0);
    double[] J = new double[36];
    tcpJacobianInBase(new KinematicChain(model), q, tool, J, new double[12], new double[SCRATCH]);
    return J;
  }

  /** dest = a[aOff..] · b for packed poses. */
  private static void composeFrom(double[] a, int o, double[] b, double[] dest) {
    for (int r = 0; r < 3; r++) {
      double a0 = a[o + r * 3], a1 = a[o + r * 3 + 1], a2 = a[o + r * 3 + 2];
      dest[r * 3] = a0 * b[0] + a1 * b[3] + a2 * b[6];
      dest[r * 3 + 1] = a0 * b[1] + a1 * b[4] + a2 * b[7];
      dest[r * 3 + 2] = a0 * b[2] + a1 * b[5] + a2 * b[8];
      dest[9 + r] = a0 * b[9] + a1 * b[10] + a2 * b[11] + a[o + 9 + r];
    }
  }
}
