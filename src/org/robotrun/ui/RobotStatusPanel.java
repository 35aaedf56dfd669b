package org.robotrun.ui;

import imgui.ImGui;
import org.robotrun.math.Xyzwpr;

/** A small read-only panel: joint values as the pendant shows them and the flange in WORLD. */
public final class RobotStatusPanel {
  private RobotStatusPanel() {}

  /**
   * @param modelName the robot's model (shown on top; empty: not shown)
   * @param jointNames the joints' names, base to wrist
   * @param pendantDeg joint values in degrees, pendant convention
   * @param flangeInWorld the flange pose in WORLD (mm, rad)
   */
  public static void drawContents(String modelName, java.util.List<String> jointNames, double[] pendantDeg, Xyzwpr flangeInWorld) {
    {
      if (!modelName.isEmpty()) {
        ImGui.textUnformatted(modelName);
        ImGui.separator();
      }
      ImGui.textUnformatted("JOINT (deg)");
      for (int i = 0; i < pendantDeg.length; i++) {
        String name = i < jointNames.size() ? jointNames.get(i) : "J" + (i + 1);
        ImGui.textUnformatted(String.format(java.util.Locale.ROOT, "  %-2s %9.3f", name, shown(pendantDeg[i])));
      }
      ImGui.separator();
      ImGui.textUnformatted("WORLD, flange (mm, deg)");
      Xyzwpr p = flangeInWorld;
      ImGui.textUnformatted(String.format(java.util.Locale.ROOT, "  X %9.3f  W %8.3f", shown(p.x()), shown(p.wDeg())));
      ImGui.textUnformatted(String.format(java.util.Locale.ROOT, "  Y %9.3f  P %8.3f", shown(p.y()), shown(p.pDeg())));
      ImGui.textUnformatted(String.format(java.util.Locale.ROOT, "  Z %9.3f  R %8.3f", shown(p.z()), shown(p.rDeg())));
      ImGui.separator();
      ImGui.pushTextWrapPos(0);
      Txt.disabled("Mouse: drag orbit, right-drag pan, wheel zoom, Home resets");
      ImGui.popTextWrapPos();
      Txt.disabled(String.format(java.util.Locale.ROOT, "%.0f frames/s", ImGui.getIO().getFramerate()));
    }
  }

  /** A value as shown with three decimals: anything that would print as -0.000 shows 0.000. */
  static double shown(double v) {
    return Math.abs(v) < 0.0005 ? 0.0 : v;
  }
}
