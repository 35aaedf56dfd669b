package org.robotrun.world;

import java.util.List;
import org.robotrun.math.Transform;

/**
 * A robot placed in a cell.
 *
 * @param name unique in the scenario, used in alarms ("robot1")
 * @param modelId the robot definition, e.g. "lrmate200id"
 * @param X_CB the robot's base frame (on its mounting plate, on the J1 axis) in the cell (mm)
 * @param endEffector the tool on its flange
 * @param initialJointsRad six joint values in the pendant's convention (FANUC coupled J3), rad
 */
public record RobotSetup(String name, String modelId, Transform X_CB, EndEffectorType endEffector, List<Double> initialJointsRad) {
  public RobotSetup {
    initialJointsRad = List.copyOf(initialJointsRad);
    if (initialJointsRad.size() != 6) {
      throw new IllegalArgumentException("a robot needs 6 initial joint values, got " + initialJointsRad.size());
    }
  }

  /** The initial joints as an array (rad, pendant convention). */
  public double[] initialJoints() {
    return initialJointsRad.stream().mapToDouble(Double::doubleValue).toArray();
  }
}
