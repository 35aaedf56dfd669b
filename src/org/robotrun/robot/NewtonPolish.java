package org.robotrun.robot;

/**
 * A few Newton steps on the chain's own FK, for closed forms derived from a geometry that
 * matches their family only to within the rounding of the file's numbers (a URDF's
 * {@code rpy="0 1.5708 0"} leaves axes 4e-6 rad off parallel): the closed form's answer is then
 * a start a fraction of a millimetre away, and these steps bring it onto the target (1e-9 mm).
 * Not thread-safe (scratch arrays).
 */
final class NewtonPolish {
  private final int steps;
  private final double giveUpMm;
  private final double giveUpRad;
  private final KinematicChain chain;
  private final double[] fk = new double[12];
  private final double[] jac = new double[36];
  private final double[] scratch = new double[Jacobian.SCRATCH];
  private final double[] err = new double[6];
  private final double[] dq = new double[6];
  private final int[] perm = new int[6];

  /** At most 6 steps from a start within 10 mm and 0.05 rad: a closed form on rounded numbers. */
  NewtonPolish(KinematicChain chain) {
    this(chain, 6, 10, 0.05);
  }

  /**
   * At most {@code steps} steps, and none from a start farther than {@code giveUpMm} or
   * {@code giveUpRad} from the target (a start that far is another answer's, not this one's).
   */
  NewtonPolish(KinematicChain chain, int steps, double giveUpMm, double giveUpRad) {
    this.chain = chain;
    this.steps = steps;
    this.giveUpMm = giveUpMm;
    this.giveUpRad = giveUpRad;
  }

  /**
   * Moves {@code q} onto the packed flange pose {@code target}; true when it ends within 1e-6 mm
   * and 1e-9 rad (q is left where the steps took it either way).
   */
  boolean polish(double[] q, double[] target) {
    for (int it = 0; ; it++) {
      chain.flangePose(q, fk, null);
      double dx = target[9] - fk[9], dy = target[10] - fk[10], dz = target[11] - fk[11];
      double pos = Math.sqrt(dx * dx + dy * dy + dz * dz);
      double rot = ClosedFormIk.rotationAngle(fk, target);
      if ((pos < 1e-9 && rot < 1e-12) || it == steps) {
        return pos < 1e-6 && rot < 1e-9;
      }
      if (pos > giveUpMm || rot > giveUpRad) {
        return false;
      }
      // Orientation error: ½·Σ (r_fk,i × r_target,i) over the columns (small-angle rotation vector).
      double ex = 0, ey = 0, ez = 0;
      for (int c = 0; c < 3; c++) {
        double ax = fk[c], ay = fk[3 + c], az = fk[6 + c];
        double bx = target[c], by = target[3 + c], bz = target[6 + c];
        ex += ay * bz - az * by;
        ey += az * bx - ax * bz;
        ez += ax * by - ay * bx;
      }
      err[0] = dx;
      err[1] = dy;
      err[2] = dz;
      err[3] = 0.5 * ex;
      err[4] = 0.5 * ey;
      err[5] = 0.5 * ez;
      Jacobian.tcpJacobianInBase(chain, q, null, jac, fk, scratch);
      if (Dense6.luDecompose(jac, perm) == 0) {
        return pos < 1e-6 && rot < 1e-9;
      }
      Dense6.luSolve(jac, perm, err, dq);
      for (int i = 0; i < 6; i++) {
        q[i] += dq[i];
      }
    }
  }
}
