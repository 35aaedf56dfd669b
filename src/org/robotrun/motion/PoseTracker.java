package org.robotrun.motion;

import org.robotrun.math.Transform;
import org.robotrun.robot.KinematicChain;
import org.robotrun.robot.ResolvedRate;
import org.robotrun.robot.RobotModel;

/**
 * Follows a Cartesian path tick by tick with the resolved-rate method: from the current joints,
 * the damped-pseudoinverse step {@code Δq = J⁺·e} for the pose error e (position mm, rotation
 * vector rad, in the base frame), repeated a few times (Newton) until the TCP sits on the
 * desired pose. Near singularities the damping keeps Δq bounded, so the error stays large
 * instead of the wrist whipping; the caller sees that in the result and slows down or stops.
 *
 * <p>Not thread-safe (scratch arrays): one per controller.
 */
public final class PoseTracker {
  /** Stop iterating below these errors: far finer than the 0.1 mm the paths promise. */
  static final double POSITION_EPS_MM = 1e-7;
  static final double ROTATION_EPS_RAD = 1e-9;
  static final int MAX_ITERATIONS = 6;

  private final KinematicChain chain;
  private final ResolvedRate rate;
  private final Transform X_BW;
  private final double[] flange = new double[12];
  private final double[] tcp = new double[12];
  private final double[] tool = new double[12];
  private final double[] want = new double[12];
  private final double[] rel = new double[9];
  private final double[] err = new double[6];
  private final double[] rot = new double[3];
  private final double[] dq = new double[6];
  private int lastIterations;
  private double positionErrorMm;
  private double rotationErrorRad;

  public PoseTracker(RobotModel model) {
    this.chain = new KinematicChain(model);
    this.rate = new ResolvedRate(chain, ResolvedRate.Settings.defaults());
    this.X_BW = model.X_WB().inverse();
  }

  /** The arm's joint chain (for limits and forward kinematics). */
  public KinematicChain chain() {
    return chain;
  }

  /**
   * Moves {@code q} (in place) so the TCP reaches {@code X_WT}.
   *
   * @param X_WT desired TCP pose in WORLD
   * @param X_FT the TCP in the flange frame
   * @return whether the final errors are within {@code tolMm} and {@code tolRad}
   */
  public boolean track(double[] q, Transform X_WT, Transform X_FT, double tolMm, double tolRad) {
    KinematicChain.pack(X_BW.compose(X_WT), want, 0);
    KinematicChain.pack(X_FT, tool, 0);
    for (int it = 0; ; it++) {
      computeError(q);
      if ((positionErrorMm < POSITION_EPS_MM && rotationErrorRad < ROTATION_EPS_RAD) || it == MAX_ITERATIONS) {
        lastIterations = it;
        break;
      }
      rate.step(q, err, tool, dq);
      for (int i = 0; i < 6; i++) {
        q[i] += dq[i];
      }
    }
    return positionErrorMm <= tolMm && rotationErrorRad <= tolRad;
  }

  /** Newton steps the last {@link #track} took. */
  public int lastIterations() {
    return lastIterations;
  }

  /** Position error (mm) after the last {@link #track}. */
  public double positionErrorMm() {
    return positionErrorMm;
  }

  /** Orientation error (rad) after the last {@link #track}. */
  public double rotationErrorRad() {
    return rotationErrorRad;
  }

  /** Manipulability seen by the last resolved-rate step (small near singularities). */
  public double manipulability() {
    return rate.lastManipulability();
  }

  private void computeError(double[] q) {
    chain.flangePose(q, flange, null);
    KinematicChain.compose(flange, tool, tcp);
    err[0] = want[9] - tcp[9];
    err[1] = want[10] - tcp[10];
    err[2] = want[11] - tcp[11];
    // R_want · R_tcpᵀ, row-major.
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) {
        rel[r * 3 + c] = want[r * 3] * tcp[c * 3] + want[r * 3 + 1] * tcp[c * 3 + 1] + want[r * 3 + 2] * tcp[c * 3 + 2];
      }
    }
    Rotations.log(rel, rot);
    err[3] = rot[0];
    err[4] = rot[1];
    err[5] = rot[2];
    positionErrorMm = Math.sqrt(err[0] * err[0] + err[1] * err[1] + err[2] * err[2]);
    rotationErrorRad = Math.sqrt(rot[0] * rot[0] + rot[1] * rot[1] + rot[2] * rot[2]);
  }
}
