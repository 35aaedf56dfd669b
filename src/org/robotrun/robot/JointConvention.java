package org.robotrun.robot;

/**
 * The one place that converts between the pendant's joint values (FANUC's coupled J3: the
 * forearm's angle from horizontal) and the kinematic chain's (URDF, uncoupled J3).
 *
 * <p>{@code J3_kin = J3_pendant + J2} and {@code J3_pendant = J3_kin − J2}; other joints are
 * the same. For a model whose pendant is not coupled, both directions are the identity.
 */
public final class JointConvention {
  private JointConvention() {}

  /** Pendant joint values (rad) to kinematic joint values (rad). */
  public static double[] pendantToKinematic(RobotModel model, double[] pendant) {
    double[] q = pendant.clone();
    if (model.coupledJ3()) {
      q[2] = pendant[2] + pendant[1];
    }
    return q;
  }

  /** Kinematic joint values (rad) to pendant joint values (rad). */
  public static double[] kinematicToPendant(RobotModel model, double[] q) {
    double[] pendant = q.clone();
    if (model.coupledJ3()) {
      pendant[2] = q[2] - q[1];
    }
    return pendant;
  }
}
