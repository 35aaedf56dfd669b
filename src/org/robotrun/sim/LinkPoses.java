package org.robotrun.sim;

import org.robotrun.math.Transform;
import org.robotrun.robot.KinematicChain;
import org.robotrun.robot.RobotModel;

/**
 * Link poses of one robot in the cell: the robot's {@link KinematicChain} with the base placed in
 * the cell. Gives the same poses as {@code ForwardKinematics.linkPosesInWorld} composed with the
 * placement (a test checks it). {@link #at} computes them once per joint position, so a tick's
 * users (the flange for grips and held parts, the links for the collision check) share one chain.
 * Not thread-safe (the chain has scratch space); one per robot.
 */
final class LinkPoses {
  private final KinematicChain chain;
  private final Transform X_CB;
  private final Transform X_6F;

  /** @param X_CW the robot's WORLD in the cell */
  LinkPoses(RobotModel model, Transform X_CW) {
    this.chain = new KinematicChain(model);
    this.X_CB = X_CW.compose(model.X_WB());
    this.X_6F = model.X_6F();
  }

  private double[] lastQ;
  private final Transform[] poses = new Transform[RobotModel.DOF + 2];

  /**
   * Links 0..6 and (index 7) the flange in the cell at joints {@code q}: computed when {@code q}
   * differs from the last call's, else the same poses again. The array is shared: read it, do not
   * keep or change it.
   */
  Transform[] at(double[] q) {
    if (lastQ == null || !java.util.Arrays.equals(q, lastQ)) {
      compute(q, poses);
      lastQ = q.clone();
    }
    return poses;
  }

  /** The flange in the cell at joints {@code q} ({@link #at}'s index 7). */
  Transform flange(double[] q) {
    return at(q)[RobotModel.DOF + 1];
  }

  /** Fills {@code out[0..6]} with links 0..6 and {@code out[7]} with the flange, in the cell. */
  void compute(double[] q, Transform[] out) {
    chain.linkPoses(X_CB, q, out);
    out[RobotModel.DOF + 1] = out[RobotModel.DOF].compose(X_6F);
  }
}
