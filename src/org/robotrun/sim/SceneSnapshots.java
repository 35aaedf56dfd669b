package org.robotrun.sim;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.math.Transform;
import org.robotrun.robot.RobotModel;
import org.robotrun.world.World;

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

  /**
   * A robot placed in a cell.
   *
   * @param name the robot's name in the scenario ("robot1")
   * @param X_CB its base plate in the cell frame (mm)
   * @param q joint values (rad, kinematic convention)
   */
  public record PlacedRobot(String name, RobotModel model, Transform X_CB, double[] q) {}

  /**
   * A whole cell: the world's fixtures and parts and every robot. The floor is at the lowest
   * robot base plate.
   */
  public static SceneSnapshot cell(World world, List<PlacedRobot> robots, double simTimeSec) {
    List<DrawItem> items = new ArrayList<>();
    double floorZ = 0;
    boolean first = true;
    for (PlacedRobot r : robots) {
      // The robot's WORLD in the cell: its base plate pose, then up from the plate to WORLD.
      Transform X_CW = r.X_CB().compose(r.model().X_WB().inverse());
      RobotDrawList.addRobot(items, r.name(), r.model(), X_CW, r.q());
      floorZ = first ? r.X_CB().z() : Math.min(floorZ, r.X_CB().z());
      first = false;
    }
    WorldDrawList.addWorld(items, world);
    return new SceneSnapshot(simTimeSec, items, floorZ);
  }
}
