package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCol;
import org.robotrun.pendant.Key;
import org.robotrun.pendant.Pendant;

/**
 * The pendant's safety controls for the mouse: TP ENABLE and DEADMAN as switches whose state is
 * always visible (one pointer cannot hold the DEADMAN and click a key at once), and the pendant's
 * E-stop. On the keyboard the DEADMAN is held with Space and SHIFT with Shift ({@link PendantKeyboard}).
 */
public final class SafetySwitches {
  private final java.util.function.Supplier<Pendant> pendantNow;

  public SafetySwitches(Pendant pendant) {
    this(() -> pendant);
  }

  /** Drives whichever pendant {@code pendantNow} answers (the robot selector's choice) at each call. */
  public SafetySwitches(java.util.function.Supplier<Pendant> pendantNow) {
    this.pendantNow = pendantNow;
  }

  /** One row: TP ENABLE, DEADMAN, E-STOP. */
  public void draw() {
    boolean enabled = pendant().tpEnabled();
    if (coloured("TP ENABLE: " + (enabled ? "ON " : "OFF") + "##tpenable", enabled, 0.2f, 0.6f, 0.25f, 0)) {
      pendant().setTpEnabled(!enabled);
    }
    hint("TP ENABLE switch: ON to jog and run from the pendant (T1/T2); OFF to run from the operator panel in AUTO");
    ImGui.sameLine();
    boolean held = pendant().deadmanHeld();
    if (coloured("DEADMAN: " + (held ? "HELD" : "released") + "##deadman", held, 0.2f, 0.6f, 0.25f, 0)) {
      if (held) {
        pendant().release(Key.DEADMAN);
      } else {
        pendant().press(Key.DEADMAN);
      }
    }
    hint("DEADMAN (also: hold Space). Jogging and SHIFT+FWD need it held; letting it go with the TP on is SRVO-003");
    ImGui.sameLine();
    boolean estop = pendant().control().emergencyStopped();
    if (coloured((estop ? "E-STOP (pressed)" : "E-STOP") + "##tpestop", true, 0.8f, 0.1f, 0.1f, 0)) {
      if (estop) {
        pendant().releaseEmergencyStop();
      } else {
        pendant().emergencyStop(true);
      }
    }
    hint(estop ? "Click to twist the E-stop out, then RESET" : "Teach pendant E-stop (SRVO-002): the arm stops at once");
  }

  /** A button drawn in {@code r,g,b} when {@code on}; returns whether it was clicked. */
  static boolean coloured(String label, boolean on, float r, float g, float b, float width) {
    if (on) {
      ImGui.pushStyleColor(ImGuiCol.Button, r, g, b, 1f);
    }
    boolean clicked = ImGui.button(label, width, 0);
    if (on) {
      ImGui.popStyleColor();
    }
    return clicked;
  }

  static void hint(String text) {
    if (ImGui.isItemHovered()) {
      Txt.tooltip(text);
    }
  }

  private Pendant pendant() {
    return pendantNow.get();
  }
}
