package org.robotrun.ui;

import imgui.ImGui;
import org.robotrun.math.Xyzwpr;

/** A small read-only panel: joint values as the pendant shows them and the flange in WORLD. */
public final class RobotStatusPanel {
  private RobotStatusPanel() {}

  /**
   * @param pendantDeg joint values in degrees, pendant convention
   * @param flangeInWorld the flange pose in WORLD (mm, rad)
   */
  public static void drawContents(double[] pendantDeg, Xyzwpr flangeInWorld) {
    {
      ImGui.textUnformatted("JOINT (deg)");
      for (int i = 0; i < pendantDeg.length; i++) {
        ImGui.textUnformatted(String.format(java.util.Locale.ROOT, "  J%d %9.3f", i + 1, shown(pendantDeg[i])));
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
