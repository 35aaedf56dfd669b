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

  /** Characters the window's font (Dear ImGui's, Latin-1 only) lacks, as the ASCII a reader expects. */
  private static final java.util.Map<Character, String> PLAIN = java.util.Map.ofEntries(
      java.util.Map.entry('\u2192', "->"), java.util.Map.entry('\u2190', "<-"), java.util.Map.entry('\u25b8', ">"),
      java.util.Map.entry('\u2212', "-"), java.util.Map.entry('\u2013', "-"), java.util.Map.entry('\u2014', "-"),
      java.util.Map.entry('\u2026', "..."), java.util.Map.entry('\u2018', "'"), java.util.Map.entry('\u2019', "'"),
      java.util.Map.entry('\u201c', "\""), java.util.Map.entry('\u201d', "\""), java.util.Map.entry('\u2264', "<="),
      java.util.Map.entry('\u2265', ">="), java.util.Map.entry('\u2248', "~"), java.util.Map.entry('\u2022', "*"),
      java.util.Map.entry('\u2213', "-/+"), java.util.Map.entry('\u2260', "!="), java.util.Map.entry('\u00a0', " "));

  /**
   * {@code text} with the characters the font cannot draw (it showed "JOINT ? JGFRM ? WORLD" for
   * arrows and "+X/?X" for a minus sign) spelled in ASCII; other characters above Latin-1 stay
   * (Dear ImGui draws them as '?'). The same string back when there is nothing to change.
   */
  public static String plain(String text) {
    int i = 0;
    while (i < text.length() && text.charAt(i) < 0x100 && text.charAt(i) != '\u00a0') {
      i++;
    }
    if (i == text.length()) {
      return text;
    }
    StringBuilder sb = new StringBuilder(text.length() + 8).append(text, 0, i);
    for (; i < text.length(); i++) {
      char c = text.charAt(i);
      String r = PLAIN.get(c);
      if (r != null) {
        sb.append(r);
      } else {
        sb.append(c);
      }
    }
    return sb.toString();
  }

  /** Wrapped at the window's edge. */
  public static void wrapped(String text) {
    ImGui.pushTextWrapPos(0f);
    ImGui.textUnformatted(plain(text));
    ImGui.popTextWrapPos();
  }

  /** In the style's dimmed text colour, wrapped at the window's edge (or the wrap position pushed last when {@code keepWrap}). */
  public static void disabledWrapped(String text, boolean keepWrap) {
    imgui.ImVec4 c = ImGui.getStyle().getColor(ImGuiCol.TextDisabled);
    ImGui.pushStyleColor(ImGuiCol.Text, c.x, c.y, c.z, c.w);
    if (keepWrap) {
      ImGui.textUnformatted(plain(text));
    } else {
      wrapped(text);
    }
    ImGui.popStyleColor();
  }

  /** In the style's dimmed text colour. */
  public static void disabled(String text) {
    imgui.ImVec4 c = ImGui.getStyle().getColor(ImGuiCol.TextDisabled);
    ImGui.pushStyleColor(ImGuiCol.Text, c.x, c.y, c.z, c.w);
    ImGui.textUnformatted(plain(text));
    ImGui.popStyleColor();
  }

  /** In the colour given (components 0..1). */
  public static void colored(float r, float g, float b, float a, String text) {
    ImGui.pushStyleColor(ImGuiCol.Text, r, g, b, a);
    ImGui.textUnformatted(plain(text));
    ImGui.popStyleColor();
  }

  /** A tooltip for the item under the mouse. */
  public static void tooltip(String text) {
    ImGui.beginTooltip();
    ImGui.textUnformatted(plain(text));
    ImGui.endTooltip();
  }

  /** A bullet, then the text. */
  public static void bullet(String text) {
    ImGui.bullet();
    ImGui.sameLine();
    ImGui.textUnformatted(plain(text));
  }
}
