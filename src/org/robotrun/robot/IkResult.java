package org.robotrun.robot;

/**
 * The outcome of an inverse-kinematics solve: never null, never a hang.
 */
public sealed interface IkResult {

  /** Why a target could not be reached. */
  enum Reason {
    /** Beyond the arm's reach or inside its inner (folded) reach limit. */
    OUT_OF_REACH,
    /** The pose is reachable only with some joint outside its limits (or not in the asked CONFIG). */
    JOINT_LIMIT,
    /** The solver met a singularity it could not leave. */
    SINGULAR,
    /** The numeric solver ran out of iterations or time. */
    NO_CONVERGENCE
  }

  /**
   * A solution.
   *
   * @param q joint values (rad, kinematic convention), within limits
   * @param positionErrorMm distance between the reached and the target TCP (mm)
   * @param orientationErrorRad rotation angle between reached and target orientation (rad)
   * @param iterations solver iterations (0 for the closed form)
   */
  record Solved(double[] q, double positionErrorMm, double orientationErrorRad, int iterations)
      implements IkResult {

    /** Joints in degrees, for logs and test messages (the array alone prints as a hash). */
    @Override
    public String toString() {
      StringBuilder sb = new StringBuilder("Solved[q=(");
      for (int i = 0; i < q.length; i++) {
        sb.append(i == 0 ? "" : ", ").append(String.format(java.util.Locale.ROOT, "%.4f", Math.toDegrees(q[i])));
      }
      return sb.append(String.format(java.util.Locale.ROOT,
          ") deg, error %.2e mm %.2e rad, %d iterations]", positionErrorMm, orientationErrorRad, iterations)).toString();
    }
  }

  /**
   * No solution.
   *
   * @param reason machine-readable cause
   * @param message what happened, fit for a pendant alarm line
   */
  record Unreachable(Reason reason, String message) implements IkResult {}
}
