package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;
import org.robotrun.math.Xyzwpr;

/** A small read-only panel: joint values as the pendant shows them and the flange in WORLD. */
public final class RobotStatusPanel {
  private RobotStatusPanel() {}

  /**
   * @param pendantDeg joint values in degrees, pendant convention
   * @param flangeInWorld the flange pose in WORLD (mm, rad)
   */
  public static void draw(String title, double[] pendantDeg, Xyzwpr flangeInWorld) {
    ImGui.setNextWindowPos(10, 10, ImGuiCond.FirstUseEver);
    ImGui.setNextWindowBgAlpha(0.85f);
    if (ImGui.begin(title, ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoFocusOnAppearing)) {
      ImGui.text("JOINT (deg)");
      for (int i = 0; i < pendantDeg.length; i++) {
        ImGui.text(String.format("  J%d %9.3f", i + 1, pendantDeg[i] + 0.0));
      }
      ImGui.separator();
      ImGui.text("WORLD, flange (mm, deg)");
      Xyzwpr p = flangeInWorld;
      // Adding 0.0 turns -0.0 into 0.0, so the panel never shows "-0.000".
      ImGui.text(String.format("  X %9.3f  W %8.3f", p.x() + 0.0, p.wDeg() + 0.0));
      ImGui.text(String.format("  Y %9.3f  P %8.3f", p.y() + 0.0, p.pDeg() + 0.0));
      ImGui.text(String.format("  Z %9.3f  R %8.3f", p.z() + 0.0, p.rDeg() + 0.0));
      ImGui.separator();
      ImGui.textDisabled("Mouse: drag orbit, right-drag pan, wheel zoom, Home resets");
      ImGui.textDisabled(String.format("%.0f frames/s", ImGui.getIO().getFramerate()));
    }
    ImGui.end();
  }
}
