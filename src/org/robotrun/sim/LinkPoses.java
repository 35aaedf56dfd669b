package org.robotrun.sim;

import org.robotrun.math.Transform;
import org.robotrun.robot.KinematicChain;
import org.robotrun.robot.RobotModel;

/**
 * Link poses of one robot in the cell, computed every tick for the collision check: the robot's
 * {@link KinematicChain} with the base placed in the cell. Gives the same poses as
 * {@code ForwardKinematics.linkPosesInWorld} composed with the placement (a test checks it).
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

  /** Fills {@code out[0..6]} with links 0..6 and {@code out[7]} with the flange, in the cell. */
  void compute(double[] q, Transform[] out) {
    chain.linkPoses(X_CB, q, out);
    out[RobotModel.DOF + 1] = out[RobotModel.DOF].compose(X_6F);
  }
}
