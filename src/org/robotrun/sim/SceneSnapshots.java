package org.robotrun.sim;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.math.Transform;
import org.robotrun.robot.RobotModel;

/** Builds draw lists for simple cells. */
public final class SceneSnapshots {
  private SceneSnapshots() {}

  /**
   * A cell with one robot standing on the floor at the WORLD origin.
   *
   * @param q joint values (rad, kinematic convention)
   */
  public static SceneSnapshot singleRobot(RobotModel model, double[] q, double simTimeSec) {
    List<DrawItem> items = new ArrayList<>();
    RobotDrawList.addRobot(items, "robot1", model, Transform.IDENTITY, q);
    return new SceneSnapshot(simTimeSec, items, model.X_WB().z());
  }
}
