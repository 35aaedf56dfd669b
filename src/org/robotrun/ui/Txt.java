package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCol;

/**
 * Text in the window, never read as a printf format. Dear ImGui's {@code Text*} and
 * {@code SetTooltip} functions take a format string, and the binding passes our text as that
 * format: a {@code %} in a scenario description, a program comment or a typed value would be
 * dropped or, worse, make the native side read arguments that are not there. Everything here
 * draws through {@code TextUnformatted}.
 */
public final class Txt {
  private Txt() {}

  /** Wrapped at the window's edge. */
  public static void wrapped(String text) {
    ImGui.pushTextWrapPos(0f);
    ImGui.textUnformatted(text);
    ImGui.popTextWrapPos();
  }

  /** In the style's dimmed text colour, wrapped at the window's edge (or the wrap position pushed last when {@code keepWrap}). */
  public static void disabledWrapped(String text, boolean keepWrap) {
    imgui.ImVec4 c = ImGui.getStyle().getColor(ImGuiCol.TextDisabled);
    ImGui.pushStyleColor(ImGuiCol.Text, c.x, c.y, c.z, c.w);
    if (keepWrap) {
      ImGui.textUnformatted(text);
    } else {
      wrapped(text);
    }
    ImGui.popStyleColor();
  }

  /** In the style's dimmed text colour. */
  public static void disabled(String text) {
    imgui.ImVec4 c = ImGui.getStyle().getColor(ImGuiCol.TextDisabled);
    ImGui.pushStyleColor(ImGuiCol.Text, c.x, c.y, c.z, c.w);
    ImGui.textUnformatted(text);
    ImGui.popStyleColor();
  }

  /** In the colour given (components 0..1). */
  public static void colored(float r, float g, float b, float a, String text) {
    ImGui.pushStyleColor(ImGuiCol.Text, r, g, b, a);
    ImGui.textUnformatted(text);
    ImGui.popStyleColor();
  }

  /** A tooltip for the item under the mouse. */
  public static void tooltip(String text) {
    ImGui.beginTooltip();
    ImGui.textUnformatted(text);
    ImGui.endTooltip();
  }

  /** A bullet, then the text. */
  public static void bullet(String text) {
    ImGui.bullet();
    ImGui.sameLine();
    ImGui.textUnformatted(text);
  }
}
