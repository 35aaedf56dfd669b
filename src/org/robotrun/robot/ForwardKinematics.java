package org.robotrun.robot;

import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Forward kinematics of a {@link RobotModel}: joint values (rad, kinematic convention) to link
 * and flange poses. Stateless; every method computes.
 */
public final class ForwardKinematics {
  private ForwardKinematics() {}

  /**
   * Poses of links 0..6 in the base frame B: {@code X_BL[i]}. Link 0 is the base itself.
   */
  public static Transform[] linkPosesInBase(RobotModel model, double[] q) {
    checkLength(q);
    Transform[] out = new Transform[RobotModel.DOF + 1];
    Transform X_BL = Transform.IDENTITY;
    out[0] = X_BL;
    for (int i = 0; i < RobotModel.DOF; i++) {
      JointSpec j = model.joint(i);
      Vec3 a = j.axis();
      X_BL = X_BL.compose(j.X_PJ()).compose(Transform.rotation(a.x(), a.y(), a.z(), q[i]));
      out[i + 1] = X_BL;
    }
    return out;
  }

  /** Poses of links 0..6 in WORLD. */
  public static Transform[] linkPosesInWorld(RobotModel model, double[] q) {
    Transform[] X_BL = linkPosesInBase(model, q);
    for (int i = 0; i < X_BL.length; i++) {
      X_BL[i] = model.X_WB().compose(X_BL[i]);
    }
    return X_BL;
  }

  /** The flange frame in the base frame: {@code X_BF}. */
  public static Transform flangePoseInBase(RobotModel model, double[] q) {
    return linkPosesInBase(model, q)[RobotModel.DOF].compose(model.X_6F());
  }

  /** The flange frame in WORLD: {@code X_WF}. */
  public static Transform flangePoseInWorld(RobotModel model, double[] q) {
    return model.X_WB().compose(flangePoseInBase(model, q));
  }

  private static void checkLength(double[] q) {
    if (q.length != RobotModel.DOF) {
      throw new IllegalArgumentException("expected 6 joint values, got " + q.length);
    }
  }
}
