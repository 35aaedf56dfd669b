package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiTableFlags;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImBoolean;

/**
 * The window's on-screen help: the key map overlay (Ctrl+H or ?; F1 stays the pendant's F1),
 * the first-start card with the three things to know (docked along the bottom of the 3D view, so
 * it never hides the robot), and where the user guide is (centred in the 3D view).
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

  /** The first-start card's height last frame (display pixels); 0 before it was drawn. */
  private float welcomeHeight;
  private WindowLayout.Rect welcomeRect = new WindowLayout.Rect(0, 0, 0, 0);

  /** Where the first-start card was drawn last frame (display pixels); empty when closed (tests). */
  public WindowLayout.Rect welcomeRect() {
    return welcome.get() ? welcomeRect : new WindowLayout.Rect(0, 0, 0, 0);
  }

  /**
   * How much of the bottom of the 3D view the first-start card takes (display pixels): it is
   * docked there, so the camera frames the robot above it and the card never hides the arm.
   */
  public float welcomeDock(WindowLayout.Rect view) {
    if (!welcome.get() || !view.visible()) {
      return 0;
    }
    // before the first draw: about nine lines of text
    float h = welcomeHeight > 0 ? welcomeHeight : ImGui.getFontSize() * 11;
    return Math.min(h, view.h() * WindowLayout.WELCOME_MAX_FRACTION);
  }

  /** Whether the card's height is known (or it is closed): the camera frames the scene once it is. */
  public boolean welcomeMeasured() {
    return !welcome.get() || welcomeHeight > 0;
  }

  /**
   * Draws the first-start card docked along the bottom of {@code view} (the 3D view before the
   * card took its part): the three things to know side by side, and the task when there is one
   * and the left column does not show it.
   */
  public void drawWelcome(WindowLayout.Rect view, String task) {
    if (!welcome.get() || !view.visible()) {
      return;
    }
    ImGui.setNextWindowPos(view.x(), view.bottom(), ImGuiCond.Always, 0f, 1f);
    ImGui.setNextWindowSizeConstraints(view.w(), 0, view.w(), view.h() * WindowLayout.WELCOME_MAX_FRACTION);
    ImGui.setNextWindowBgAlpha(0.96f);
    if (ImGui.begin("First steps##card", welcome, ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoCollapse
        | ImGuiWindowFlags.NoMove | ImGuiWindowFlags.NoSavedSettings)) {
      boolean hasTask = !task.isBlank();
      // side by side when the view is wide enough to read them so, else one under the other
      int columns = WindowLayout.welcomeColumns(view.w(), ImGui.getFontSize(), hasTask);
      if (ImGui.beginTable("steps", columns, ImGuiTableFlags.SizingStretchSame | ImGuiTableFlags.BordersInnerV)) {
        ImGui.tableNextRow();
        if (columns == 4) {
          step("Your task", task);
        }
        step("1. DEADMAN + SHIFT", "The robot moves only with TP ENABLE on, the DEADMAN held (Space, or click it above "
            + "the LCD) and Shift held. Letting the DEADMAN go is SRVO-003: hold it, then RESET (F12).");
        step("2. Jog", "Hold Space and Shift, then Q W E R T Y: +J1..+J6 (+X +Y +Z +W +P +R); A S D F G H: minus. "
            + "F7 COORD changes the frame; Page Up / Down the speed.");
        step("3. A program", "SELECT (Insert), F1 CREATE, type a name, Enter. Jog, then Shift+F1 POINT records a "
            + "position. Shift+F9 FWD runs it while Shift is held.");
        ImGui.endTable();
      }
      if (hasTask && columns != 4) {
        Txt.wrapped("Your task: " + task);
      }
      if (ImGui.button("Got it")) {
        welcome.set(false);
      }
      ImGui.sameLine();
      Txt.disabledWrapped("Every key: Help > Key map (Ctrl+H). Hover a pendant key to see its keyboard key. "
          + "A course of graded labs: the Labs menu (start with lab 1). This card again: Help > First steps."
          // the task is on this card when the left column is hidden; the panels a task names are there
          + (hasTask ? " The robot's position and the controller's panels: View > Side panel." : ""), false);
      welcomeHeight = ImGui.getWindowHeight();
      welcomeRect = new WindowLayout.Rect(ImGui.getWindowPosX(), ImGui.getWindowPosY(), ImGui.getWindowWidth(),
          ImGui.getWindowHeight());
    }
    ImGui.end();
  }

  private static void step(String title, String text) {
    ImGui.tableNextColumn();
    Txt.colored(0.95f, 0.8f, 0.35f, 1f, title);
    Txt.wrapped(text);
  }

  /** Draws the other help windows that are open (key map, guides), centred in the 3D view. */
  public void draw(WindowLayout.Rect view) {
    float cx = view.x() + view.w() / 2, cy = view.y() + view.h() / 2;
    if (keyMap.get()) {
      ImGui.setNextWindowPos(cx, cy, ImGuiCond.Appearing, 0.5f, 0.5f);
      ImGui.setNextWindowSizeConstraints(0, 0, Math.max(200, view.w() - 20), Math.max(150, view.h() - 20));
      if (ImGui.begin("Key map (Ctrl+H)", keyMap, ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoCollapse)) {
        ImGui.pushTextWrapPos(ImGui.getFontSize() * 30);
        Txt.disabledWrapped("Keys act while held, as on the pendant. Space is the DEADMAN, Shift is SHIFT.", true);
        ImGui.popTextWrapPos();
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
