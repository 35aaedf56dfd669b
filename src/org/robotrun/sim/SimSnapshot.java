package org.robotrun.sim;

import java.util.List;

/**
 * An immutable picture of the simulation: the draw list for the renderer and each robot's state.
 *
 * @param simTimeSec simulated time (s)
 * @param scene what to draw
 * @param robots one entry per controller, in order
 */
public record SimSnapshot(double simTimeSec, SceneSnapshot scene, List<RobotState> robots) {
  public SimSnapshot {
    robots = List.copyOf(robots);
  }
}
