package org.robotrun.ui;

import imgui.ImGui;
import imgui.type.ImBoolean;
import org.robotrun.sim.Simulation;

/**
 * The "Cell" panel: reset the scene (parts back where the scenario put them), show the
 * collision boxes, and choose whether a collision stops the robot or is only shown (free play).
 * Acts on the simulation directly: the GUI steps it on the same thread that draws panels.
 */
public final class CellPanel {
  private final Simulation sim;
  private final ImBoolean showBoxes = new ImBoolean(false);
  private final ImBoolean alarms = new ImBoolean(true);

  public CellPanel(Simulation sim) {
    this.sim = sim;
    showBoxes.set(sim.showCollisionBoxes());
    alarms.set(sim.collisionAlarms());
  }

  /** Draws the panel's contents into the current window (the window's left column). */
  public void drawContents() {
    {
      if (ImGui.button("Reset scene")) {
        sim.resetScene();
      }
      if (ImGui.isItemHovered()) {
        Txt.tooltip("Every part back at its start pose; the gripper lets go");
      }
      if (ImGui.checkbox("Show collision boxes", showBoxes)) {
        sim.setShowCollisionBoxes(showBoxes.get());
      }
      if (ImGui.checkbox("Collisions stop the robot", alarms)) {
        sim.setCollisionAlarms(alarms.get());
      }
      var held = sim.heldParts();
      Txt.disabled(held.isEmpty() ? "holding nothing" : "holding " + String.join(", ", held.keySet()));
      int n = sim.collisionEvents().size();
      Txt.disabled(n == 0 ? "no collisions" : n + " collision" + (n == 1 ? "" : "s") + " so far");
    }
  }
}
