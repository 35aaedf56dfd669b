package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCol;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiInputTextFlags;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImString;
import java.util.EnumSet;
import java.util.Set;
import org.robotrun.pendant.Key;
import org.robotrun.pendant.Lcd;
import org.robotrun.pendant.Pendant;

/**
 * Draws the teach pendant: its LCD (text from the pendant state machine) and its keys as
 * buttons. It only forwards input: a click is a key press and release; a jog key or SHIFT is
 * down while the mouse holds it (never latched), so SHIFT held on the keyboard and a jog key
 * held with the mouse jog together. TP ENABLE, DEADMAN and the E-stop are switches
 * ({@link SafetySwitches}).
 */
public final class PendantPanel {
  private static final float LCD_BG_R = 0.80f, LCD_BG_G = 0.86f, LCD_BG_B = 0.78f;

  private final Pendant pendant;
  private final SafetySwitches switches;
  private final ImString typed = new ImString(128);
  /** Jog keys the mouse holds down. */
  private final Set<Key> latched = EnumSet.noneOf(Key.class);

  public PendantPanel(Pendant pendant) {
    this.pendant = pendant;
    this.switches = new SafetySwitches(pendant);
  }

  /** Releases every jog key the mouse holds (the window lost focus, or the panel closes). */
  public void releaseLatched() {
    for (Key k : latched) {
      pendant.release(k);
    }
    latched.clear();
  }

  public void draw(int framebufferWidth, int framebufferHeight) {
    ImGui.setNextWindowPos(framebufferWidth - 560, 10, ImGuiCond.FirstUseEver);
    ImGui.setNextWindowSize(550, Math.min(framebufferHeight - 20, 780), ImGuiCond.FirstUseEver);
    if (ImGui.begin("Teach pendant", ImGuiWindowFlags.NoCollapse)) {
      switches.draw();
      drawLcd();
      drawFunctionKeys();
      ImGui.separator();
      drawTextEntry();
      ImGui.separator();
      drawKeys();
    }
    ImGui.end();
  }

  private void drawLcd() {
    Lcd lcd = pendant.lcd();
    ImGui.pushStyleColor(ImGuiCol.ChildBg, LCD_BG_R, LCD_BG_G, LCD_BG_B, 1f);
    ImGui.pushStyleColor(ImGuiCol.Text, 0.05f, 0.08f, 0.05f, 1f);
    float lineH = ImGui.getTextLineHeightWithSpacing();
    ImGui.beginChild("lcd", 0, lineH * Lcd.HEIGHT + 10, true, ImGuiWindowFlags.NoScrollbar);
    for (int i = 0; i < Lcd.HEIGHT; i++) {
      String row = lcd.row(i);
      boolean highlight = i == 1 && !row.isBlank()  // the alarm line
          || row.startsWith(">");
      if (i == 1 && !row.isBlank()) {
        ImGui.pushStyleColor(ImGuiCol.Text, 0.75f, 0.05f, 0.05f, 1f);
        ImGui.textUnformatted(row);
        ImGui.popStyleColor();
      } else if (highlight) {
        ImGui.pushStyleColor(ImGuiCol.Text, 0.0f, 0.15f, 0.55f, 1f);
        ImGui.textUnformatted(row);
        ImGui.popStyleColor();
      } else {
        ImGui.textUnformatted(row);
      }
    }
    ImGui.endChild();
    ImGui.popStyleColor(2);
  }

  private void drawFunctionKeys() {
    float w = (ImGui.getContentRegionAvailX() - 4 * ImGui.getStyle().getItemSpacingX()) / 5;
    Key[] fk = {Key.F1, Key.F2, Key.F3, Key.F4, Key.F5};
    for (int i = 0; i < fk.length; i++) {
      if (i > 0) {
        ImGui.sameLine();
      }
      key(fk[i], w);
    }
  }

  private void drawTextEntry() {
    ImGui.text("Type");
    ImGui.sameLine();
    ImGui.setNextItemWidth(ImGui.getContentRegionAvailX() - 70);
    boolean enter = ImGui.inputText("##type", typed, ImGuiInputTextFlags.EnterReturnsTrue);
    ImGui.sameLine();
    if (ImGui.button("Send") || enter) {
      String t = typed.get();
      if (!t.isEmpty()) {
        pendant.type(t);
        typed.set("");
      }
    }
  }

  private void drawKeys() {
    float bw = 74;
    Key[][] left = {
      {Key.PREV, Key.NEXT, Key.ITEM, Key.ENTER},
      {Key.MENU, Key.SELECT, Key.EDIT, Key.DATA},
      {Key.FCTN, Key.DISP, Key.POSN, Key.IO},
      {Key.STATUS, Key.BACKSPACE, Key.UP, Key.DOWN},
      {Key.LEFT, Key.RIGHT, Key.TOOL1, Key.TOOL2},
      {Key.D7, Key.D8, Key.D9, Key.MINUS},
      {Key.D4, Key.D5, Key.D6, Key.COMMA},
      {Key.D1, Key.D2, Key.D3, Key.DOT},
      {Key.D0, Key.COORD, Key.STEP, Key.RESET},
      {Key.HOLD, Key.FWD, Key.BWD, Key.OVERRIDE_DOWN},
    };
    ImGui.beginGroup();
    for (Key[] row : left) {
      for (int i = 0; i < row.length; i++) {
        if (i > 0) {
          ImGui.sameLine();
        }
        key(row[i], bw);
      }
    }
    shiftKey(bw * 2 + ImGui.getStyle().getItemSpacingX());
    ImGui.sameLine();
    key(Key.OVERRIDE_UP, bw);
    ImGui.endGroup();

    ImGui.sameLine(0, 18);
    ImGui.beginGroup();
    ImGui.textDisabled("Jog (hold: DEADMAN + SHIFT)");
    for (int axis = 1; axis <= 6; axis++) {
      jogKey(Key.jog(axis, -1), bw);
      ImGui.sameLine();
      jogKey(Key.jog(axis, +1), bw);
    }
    ImGui.endGroup();
  }

  private void key(Key k, float width) {
    if (ImGui.button(k.label() + "##" + k.name(), width, 0)) {
      pendant.tap(k);
    }
  }

  private boolean shiftByMouse;

  /** SHIFT is down while the mouse holds the button. */
  private void shiftKey(float width) {
    boolean on = pendant.shift();
    if (on) {
      ImGui.pushStyleColor(ImGuiCol.Button, 0.85f, 0.55f, 0.1f, 1f);
    }
    ImGui.button((on ? "SHIFT (held)" : "SHIFT") + "##SHIFT", width, 0);
    boolean active = ImGui.isItemActive();
    if (active && !shiftByMouse) {
      pendant.press(Key.SHIFT);
    } else if (!active && shiftByMouse) {
      pendant.release(Key.SHIFT);
    }
    shiftByMouse = active;
    if (on) {
      ImGui.popStyleColor();
    }
  }

  /** A jog key is down while the mouse holds it (SHIFT and the DEADMAN held too: keyboard, switch). */
  private void jogKey(Key k, float width) {
    boolean down = latched.contains(k);
    if (down) {
      ImGui.pushStyleColor(ImGuiCol.Button, 0.2f, 0.6f, 0.25f, 1f);
    }
    ImGui.button(k.label() + "##" + k.name(), width, 0);
    boolean active = ImGui.isItemActive();
    if (down) {
      ImGui.popStyleColor();
    }
    if (active && !down) {
      pendant.press(k);
      latched.add(k);
    } else if (!active && down) {
      pendant.release(k);
      latched.remove(k);
    }
  }
}
