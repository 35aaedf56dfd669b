package org.robotrun.sim;

import org.robotrun.world.EndEffectorGeometry;
import org.robotrun.world.ToolIo;

/**
 * An end effector on a robot's flange: what it is and which of the robot's I/O ports drive it.
 *
 * @param geometry the tool (TCP, boxes, pickup zone)
 * @param io the output that switches it and the inputs that report it
 */
public record MountedTool(EndEffectorGeometry geometry, ToolIo io) {
  /** {@code geometry} on the default ports RO[1], RI[1], RI[2]. */
  public static MountedTool of(EndEffectorGeometry geometry) {
    return new MountedTool(geometry, ToolIo.DEFAULT);
  }
}
