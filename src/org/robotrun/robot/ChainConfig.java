package org.robotrun.robot;

/**
 * FANUC CONFIG flags of a joint vector for any arm, from the link geometry (the closed form
 * has its own, equivalent formulas for OPW arms). W is the wrist point, J5's origin (on the CRX
 * the point where the J4 and J5 axes meet); f is link 1's forward direction, perpendicular to
 * J1 and J2, pointing at q = 0 toward W (else toward +x).
 * <ul>
 *   <li>F/N: F when J5 &gt; 0 (wrapped).
 *   <li>U/D: U when the wrist point lies on the forward side of the upper arm:
 *       ((J3 − J2) × (W − J3)) · (z1 × f) &gt; 0, z1 the J1 axis.
 *   <li>T/B: T when W lies in front of the J1 axis along f.
 *   <li>turn numbers of J1, J4, J6 as {@link Config#turnOf}.
 * </ul>
 * On an OPW arm these equal {@link ClosedFormIk#configOf} (a test checks it on the LR Mate).
 * Not thread-safe (scratch arrays).
 */
final class ChainConfig {
  private final KinematicChain chain;
  private final double sigma;
  private final double[] pose = new double[12];
  private final double[] axes = new double[36];

  ChainConfig(KinematicChain chain) {
    this.chain = chain;
    chain.flangePose(new double[6], pose, axes);
    double[] f = forwardRaw();
    double wx = axes[24] - axes[0], wy = axes[25] - axes[1], wz = axes[26] - axes[2];
    double toward = f[0] * wx + f[1] * wy + f[2] * wz;
    sigma = toward < -1e-9 || (Math.abs(toward) <= 1e-9 && f[0] < 0) ? -1 : 1;
  }

  /** J2 axis × J1 axis, from the current {@link #axes}. */
  private double[] forwardRaw() {
    double ax = axes[9], ay = axes[10], az = axes[11];
    double bx = axes[3], by = axes[4], bz = axes[5];
    return new double[] {ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx};
  }

  Config configOf(double[] q) {
    chain.flangePose(q, pose, axes);
    double[] f = forwardRaw();
    f[0] *= sigma;
    f[1] *= sigma;
    f[2] *= sigma;
    double wx = axes[24], wy = axes[25], wz = axes[26];
    // T/B: W in front of the J1 axis along f.
    double top = f[0] * (wx - axes[0]) + f[1] * (wy - axes[1]) + f[2] * (wz - axes[2]);
    // U/D: (J3 − J2) × (W − J3) against z1 × f.
    double ux = axes[12] - axes[6], uy = axes[13] - axes[7], uz = axes[14] - axes[8];
    double vx = wx - axes[12], vy = wy - axes[13], vz = wz - axes[14];
    double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    double zx = axes[3], zy = axes[4], zz = axes[5];
    double nx = zy * f[2] - zz * f[1], ny = zz * f[0] - zx * f[2], nz = zx * f[1] - zy * f[0];
    double up = cx * nx + cy * ny + cz * nz;
    return new Config(ClosedFormIk.wrap(q[4]) > 0, up > 0, top > 0,
        Config.turnOf(q[0]), Config.turnOf(q[3]), Config.turnOf(q[5]));
  }
}
