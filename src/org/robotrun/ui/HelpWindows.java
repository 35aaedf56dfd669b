package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiTableFlags;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImBoolean;

/**
 * The window's on-screen help: the key map overlay (Ctrl+H or ?; F1 stays the pendant's F1),
 * the first-start card with the three things to know, and where the user guide is. Drawn over
 * the 3D view, centred in it.
 */
public final class HelpWindows {
  /** Where the guides are: shipped beside the program and in the source tree. */
  public static final String USER_GUIDE = "docs/user-guide.md";
  public static final String PENDANT_GUIDE = "docs/pendant.md";
  public static final String TP_GUIDE = "docs/tp-language.md";

  private final ImBoolean keyMap = new ImBoolean(false);
  private final ImBoolean welcome = new ImBoolean(false);
  private final ImBoolean guides = new ImBoolean(false);

  public void toggleKeyMap() {
    keyMap.set(!keyMap.get());
  }

  public boolean keyMapOpen() {
    return keyMap.get();
  }

  public void showWelcome(boolean show) {
    welcome.set(show);
  }

  public boolean welcomeOpen() {
    return welcome.get();
  }

  public void showGuides() {
    guides.set(true);
  }

  /** Items of the Help menu. */
  public void menuItems() {
    if (ImGui.menuItem("Key map", "Ctrl+H  or  ?", keyMap.get())) {
      toggleKeyMap();
    }
    if (ImGui.menuItem("First steps")) {
      welcome.set(true);
    }
    if (ImGui.menuItem("User guide ...")) {
      guides.set(true);
    }
  }

  /**
   * Draws whichever help windows are open, centred in the 3D view.
   *
   * @param task the scenario's exercise text ("" when it has none)
   */
  public void draw(WindowLayout.Rect view, String task) {
    float cx = view.x() + view.w() / 2, cy = view.y() + view.h() / 2;
    if (welcome.get()) {
      ImGui.setNextWindowPos(cx, cy, ImGuiCond.Appearing, 0.5f, 0.5f);
      ImGui.setNextWindowSizeConstraints(0, 0, Math.max(200, view.w() - 20), Math.max(150, view.h() - 20));
      if (ImGui.begin("First steps", welcome, ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoCollapse)) {
        ImGui.pushTextWrapPos(ImGui.getFontSize() * 34);
        if (!task.isBlank()) {
          Txt.colored(0.95f, 0.8f, 0.35f, 1f, "Your task");
          Txt.wrapped(task);
          ImGui.separator();
        }
        Txt.colored(0.95f, 0.8f, 0.35f, 1f, "1. TP ENABLE, DEADMAN, SHIFT");
        Txt.wrapped("As on a real teach pendant the robot only moves with TP ENABLE on and the DEADMAN and "
            + "SHIFT held: click DEADMAN above the LCD (or hold Space) and hold Shift. Letting the DEADMAN go is "
            + "alarm SRVO-003 (hold it, then RESET = F12). The cell starts in T1 (at most 250 mm/s) at 10% override.");
        Txt.colored(0.95f, 0.8f, 0.35f, 1f, "2. Jogging");
        Txt.wrapped("With the DEADMAN held, hold Shift and Q W E R T Y to move +J1..+J6 (or +X +Y +Z +W +P +R), "
            + "A S D F G H for the minus direction. F7 (COORD) switches JOINT / JGFRM / WORLD / TOOL / USER. "
            + "Page Up / Page Down change the speed override.");
        Txt.colored(0.95f, 0.8f, 0.35f, 1f, "3. Your first program");
        Txt.wrapped("SELECT (Insert) -> F1 CREATE, type a name, Enter. Then jog and press Shift+F1 "
            + "(POINT) to record each position. Shift+F9 (FWD) runs it while you keep Shift held (T1 hold-to-run).");
        ImGui.separator();
        Txt.disabled("Every key: Help > Key map (Ctrl+H).  Hover a pendant key to see its keyboard key.");
        ImGui.popTextWrapPos();
        if (ImGui.button("Got it")) {
          welcome.set(false);
        }
      }
      ImGui.end();
    }
    if (keyMap.get()) {
      ImGui.setNextWindowPos(cx, cy, ImGuiCond.Appearing, 0.5f, 0.5f);
      ImGui.setNextWindowSizeConstraints(0, 0, Math.max(200, view.w() - 20), Math.max(150, view.h() - 20));
      if (ImGui.begin("Key map (Ctrl+H)", keyMap, ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoCollapse)) {
        Txt.disabled("Keys act while held, as on the pendant. Space is the DEADMAN, Shift is SHIFT.");
        // the keypad keys are their own characters: one line for them below
        var map = PendantKeyboard.keyMap().stream().filter(r -> !r[0].matches("[0-9.,\\-]")).toList();
        int half = (map.size() + 1) / 2;
        if (ImGui.beginTable("keys", 4, ImGuiTableFlags.RowBg | ImGuiTableFlags.SizingFixedFit)) {
          for (int i = 0; i < half; i++) {
            ImGui.tableNextRow();
            cell(map.get(i)[1]);
            cell(map.get(i)[0]);
            if (i + half < map.size()) {
              cell(map.get(i + half)[1]);
              cell(map.get(i + half)[0]);
            }
          }
          ImGui.endTable();
        }
        ImGui.textUnformatted("0-9 . - ,   the keypad");
        ImGui.separator();
        ImGui.pushTextWrapPos(ImGui.getFontSize() * 30);
        Txt.wrapped("Window: Ctrl+H or ? this map, Ctrl+Z / Ctrl+Y undo / redo a cell edit, Home resets the view.");
        Txt.wrapped("Mouse: left drag orbits, right or middle drag pans, wheel zooms, a click selects an object.");
        ImGui.popTextWrapPos();
      }
      ImGui.end();
    }
    if (guides.get()) {
      ImGui.setNextWindowPos(cx, cy, ImGuiCond.Appearing, 0.5f, 0.5f);
      if (ImGui.begin("User guide", guides, ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoCollapse)) {
        ImGui.textUnformatted("The guides come with RobotRun, in its docs folder:");
        guide("Getting started, the window, the keyboard", USER_GUIDE);
        guide("The teach pendant, screen by screen", PENDANT_GUIDE);
        guide("The TP language", TP_GUIDE);
      }
      ImGui.end();
    }
  }

  private static void guide(String what, String path) {
    Txt.bullet(what + ":  " + path);
    ImGui.sameLine();
    if (ImGui.smallButton("Copy##" + path)) {
      ImGui.setClipboardText(path);
    }
  }

  private static void cell(String s) {
    ImGui.tableNextColumn();
    ImGui.textUnformatted(s);
  }
}
