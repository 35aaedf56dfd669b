package org.robotrun.sim;

import java.util.List;

/**
 * An immutable picture of the world at one instant, as a draw list: the simulation fills it,
 * the renderer only reads it (and never sees robot models or programs).
 *
 * @param simTimeSec simulated time (s)
 * @param items what to draw, in WORLD
 * @param floorZ height of the floor in WORLD (mm)
 */
public record SceneSnapshot(double simTimeSec, List<DrawItem> items, double floorZ) {
  public SceneSnapshot {
    items = List.copyOf(items);
  }
}
