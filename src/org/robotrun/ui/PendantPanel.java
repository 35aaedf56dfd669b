package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCol;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiInputTextFlags;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImString;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import org.robotrun.pendant.Key;
import org.robotrun.pendant.Lcd;
import org.robotrun.pendant.Pendant;

/**
 * Draws the teach pendant laid out like a FANUC iPendant: the LCD on top, F1..F5 (with PREV and
 * NEXT) under it, the menu and cursor keys and the numeric keypad in the middle, the jog keys in
 * two columns (- left, + right) beside the keypad on the right, a SHIFT key on each side. Each key
 * shows its keyboard shortcut on hover. It only forwards input: a click is a key press and
 * release; a jog key or SHIFT is down while the mouse holds it (never latched), so SHIFT held on
 * the keyboard and a jog key held with the mouse jog together. TP ENABLE, DEADMAN and the E-stop
 * are switches above the LCD ({@link SafetySwitches}).
 */
public final class PendantPanel {
  public static final String TITLE = "Teach pendant";
  private static final float LCD_BG_R = 0.80f, LCD_BG_G = 0.86f, LCD_BG_B = 0.78f;
  /** Keys per row of the key block: side column, four keypad columns, two jog columns. */
  private static final int COLUMNS = 7;

  private final java.util.function.Supplier<Pendant> pendantNow;
  private final SafetySwitches switches;
  private final ImString typed = new ImString(128);
  /** Jog keys the mouse holds down. */
  private final Set<Key> latched = EnumSet.noneOf(Key.class);
  /** Where each key was drawn last frame (display pixels), for the layout tests. */
  private final List<KeyRect> drawnKeys = new ArrayList<>();
  private float requestedWidth;
  private float userWidth;

  /** A key's button as drawn: display pixels, origin top left. */
  public record KeyRect(Key key, float x, float y, float w, float h) {}

  public PendantPanel(Pendant pendant) {
    this(() -> pendant);
  }

  /** Drives whichever pendant {@code pendantNow} answers (the robot selector's choice) at each call. */
  public PendantPanel(java.util.function.Supplier<Pendant> pendantNow) {
    this.pendantNow = pendantNow;
    this.switches = new SafetySwitches(pendantNow);
  }

  /** Releases every jog key the mouse holds (the window lost focus, or the panel closes). */
  public void releaseLatched() {
    for (Key k : latched) {
      pendant().release(k);
    }
    latched.clear();
  }

  /** The width at which the LCD's 64 columns and every key show (display pixels); needs a frame. */
  public static float naturalWidth() {
    var style = ImGui.getStyle();
    float lcd = ImGui.calcTextSize("M").x * Lcd.WIDTH + 2 * style.getWindowPaddingX() + 2;
    return lcd + 2 * style.getWindowPaddingX() + style.getScrollbarSize();
  }

  /** The keys drawn in the last frame with their rectangles. */
  public List<KeyRect> drawnKeys() {
    return List.copyOf(drawnKeys);
  }

  /**
   * A width the student set by dragging the panel's left edge (display pixels), once, or 0.
   * The window stores it in its {@link LayoutState}.
   */
  public float takeUserWidth() {
    float w = userWidth;
    userWidth = 0;
    return w;
  }

  private SimulatorWindow.Fill lcdRect;

  /** The LCD's background drawn last frame (a clear under the panel), or null. */
  public SimulatorWindow.Fill lcdFill() {
    return lcdRect;
  }

  /** Draws the pendant filling {@code r}. */
  public void draw(WindowLayout.Rect r) {
    drawnKeys.clear();
    lcdRect = null;
    if (!r.visible()) {
      return;
    }
    ImGui.setNextWindowPos(r.x(), r.y(), ImGuiCond.Always);
    ImGui.setNextWindowSize(r.w(), r.h(), ImGuiCond.Always);
    requestedWidth = r.w();
    // the background is a clear (SimulatorWindow.Panels#fills), not a blended quad
    ImGui.pushStyleColor(ImGuiCol.WindowBg, 0f, 0f, 0f, 0f);
    boolean open = ImGui.begin(TITLE, ImGuiWindowFlags.NoCollapse | ImGuiWindowFlags.NoMove
        | ImGuiWindowFlags.NoBringToFrontOnFocus | ImGuiWindowFlags.NoTitleBar);
    ImGui.popStyleColor();
    if (open) {
      if (Math.abs(ImGui.getWindowWidth() - requestedWidth) > 0.5f) {
        userWidth = ImGui.getWindowWidth();
      }
      float keyH = keyHeight(r.h(), Metrics.current());
      switches.draw();
      drawLcd();
      drawFunctionKeys(keyH);
      drawTextEntry();
      drawKeys(keyH);
    }
    ImGui.end();
  }

  /**
   * The sizes the pendant's vertical layout depends on (display pixels): a text line with its
   * spacing, a button's frame height, the frame height with spacing, the item spacing, the window
   * padding.
   */
  public record Metrics(float lineH, float frameH, float frameHWithSpacing, float spacingY, float paddingY) {
    /** The current ImGui style's. */
    static Metrics current() {
      var style = ImGui.getStyle();
      return new Metrics(ImGui.getTextLineHeightWithSpacing(), ImGui.getFrameHeight(), ImGui.getFrameHeightWithSpacing(),
          style.getItemSpacingY(), style.getWindowPaddingY());
    }

    /** The smallest key height: a key keeps its legend's line. */
    public float minKeyH() {
      return frameH - 2;
    }
  }

  /** Rows of keys: the function keys and the nine rows of the key block. */
  static final int KEY_ROWS = 10;

  /** Everything but the keys: padding, the safety switches, the LCD, the text entry, the spacing. */
  private static float fixedHeight(Metrics m) {
    float lcd = m.lineH() * Lcd.HEIGHT + 10 + m.spacingY();
    float entry = 2 * m.frameHWithSpacing() + 2;  // the text entry and the safety switches
    return 2 * m.paddingY() + lcd + entry + KEY_ROWS * m.spacingY() + 4;
  }

  /**
   * Key height so that the safety switches, the LCD, the function keys, the entry and nine key
   * rows fit the height (never below {@link Metrics#minKeyH}: below {@link #minimumHeight} the
   * panel scrolls).
   */
  static float keyHeight(float panelHeight, Metrics m) {
    float left = panelHeight - fixedHeight(m);
    return Math.max(m.minKeyH(), Math.min(m.frameH() * 1.6f, left / KEY_ROWS));
  }

  /** The height the panel's contents take with keys {@code keyH} high. */
  static float contentHeight(float keyH, Metrics m) {
    return fixedHeight(m) + KEY_ROWS * keyH;
  }

  /** The least panel height at which every key, the jog keys and SHIFT included, shows. */
  public static float minimumHeight(Metrics m) {
    return contentHeight(m.minKeyH(), m);
  }

  /** {@link #minimumHeight(Metrics)} in the current style; needs a frame. */
  public static float minimumHeight() {
    return minimumHeight(Metrics.current());
  }

  private int drawnLcdHash;

  /** The hash of the LCD text drawn last (the window's idle check compares it instead of building the screen again). */
  public int drawnLcdHash() {
    return drawnLcdHash;
  }

  private void drawLcd() {
    Lcd lcd = pendant().lcd();
    drawnLcdHash = lcd.hashCode();
    ImGui.pushStyleColor(ImGuiCol.ChildBg, 0f, 0f, 0f, 0f);  // filled by a clear (lcdRect)
    ImGui.pushStyleColor(ImGuiCol.Text, 0.05f, 0.08f, 0.05f, 1f);
    float lineH = ImGui.getTextLineHeightWithSpacing();
    ImGui.beginChild("lcd", 0, lineH * Lcd.HEIGHT + 10, true, ImGuiWindowFlags.NoScrollbar);
    lcdRect = new SimulatorWindow.Fill(ImGui.getWindowPosX(), ImGui.getWindowPosY(), ImGui.getWindowWidth(),
        ImGui.getWindowHeight(), LCD_BG_R, LCD_BG_G, LCD_BG_B);
    String driven = pendant().robotLabel();  // a cell of several robots: the driven one's name
    for (int i = 0; i < Lcd.HEIGHT; i++) {
      String row = lcd.row(i);
      if (i == 0 && !driven.isEmpty() && row.startsWith(driven)) {
        // the name on the status line in the colour that marks the robot in the 3D view
        float x = ImGui.getCursorScreenPosX(), y = ImGui.getCursorScreenPosY();
        ImGui.getWindowDrawList().addRectFilled(x - 2, y, x + ImGui.calcTextSize(driven).x + 2, y + ImGui.getTextLineHeight(),
            ImGui.colorConvertFloat4ToU32(DrivenRobotMark.R, DrivenRobotMark.G, DrivenRobotMark.B, 1f), 2f);
      }
      if (lcd.isAlarmRow(i) && !row.isBlank()) {
        // the alarm line (a long alarm wraps onto the rows below)
        ImGui.pushStyleColor(ImGuiCol.Text, 0.75f, 0.05f, 0.05f, 1f);
        ImGui.textUnformatted(row);
        ImGui.popStyleColor();
      } else if (row.startsWith(">")) {
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

  private void drawFunctionKeys(float keyH) {
    Key[] row = {Key.PREV, Key.F1, Key.F2, Key.F3, Key.F4, Key.F5, Key.NEXT};
    float w = keyWidth();
    for (int i = 0; i < row.length; i++) {
      if (i > 0) {
        ImGui.sameLine();
      }
      key(row[i], w, keyH);
    }
  }

  private static float keyWidth() {
    return (ImGui.getContentRegionAvailX() - (COLUMNS - 1) * ImGui.getStyle().getItemSpacingX()) / COLUMNS;
  }

  private void drawTextEntry() {
    ImGui.alignTextToFramePadding();
    Txt.disabled("Type");
    if (ImGui.isItemHovered()) {
      Txt.tooltip("Text for an open entry (a program name, a comment); Enter sends it and presses ENTER.\n"
          + "The keyboard goes back to the pendant after Enter.");
    }
    ImGui.sameLine();
    // room for the Send button at any UI scale
    float send = ImGui.calcTextSize("Send").x + 4 * ImGui.getStyle().getFramePaddingX() + ImGui.getStyle().getItemSpacingX();
    ImGui.setNextItemWidth(ImGui.getContentRegionAvailX() - send);
    boolean enter = ImGui.inputText("##type", typed, ImGuiInputTextFlags.EnterReturnsTrue);
    ImGui.sameLine();
    if (ImGui.button("Send", ImGui.getContentRegionAvailX(), 0) || enter) {
      send();
    }
  }

  /** One Enter (or Send) sends the text and confirms the pendant's entry with ENTER. */
  private void send() {
    String t = typed.get();
    if (t.isEmpty()) {
      return;
    }
    pendant().type(t);
    typed.set("");
    if (pendant().entryOpen()) {
      pendant().tap(Key.ENTER);
    }
  }

  private void drawKeys(float keyH) {
    float w = keyWidth();
    // side column | keypad (4) | jog - | jog +
    Key[][] rows = {
      {Key.RESET, Key.SELECT, Key.EDIT, Key.DATA, Key.FCTN, Key.COORD, Key.STEP},
      {Key.BACKSPACE, Key.MENU, Key.UP, Key.DISP, Key.ITEM, Key.JOG_MINUS_1, Key.JOG_PLUS_1},
      {Key.ENTER, Key.LEFT, Key.DOWN, Key.RIGHT, Key.POSN, Key.JOG_MINUS_2, Key.JOG_PLUS_2},
      {Key.SHIFT, Key.D7, Key.D8, Key.D9, Key.IO, Key.JOG_MINUS_3, Key.JOG_PLUS_3},
      {Key.HOLD, Key.D4, Key.D5, Key.D6, Key.STATUS, Key.JOG_MINUS_4, Key.JOG_PLUS_4},
      {Key.FWD, Key.D1, Key.D2, Key.D3, Key.TOOL1, Key.JOG_MINUS_5, Key.JOG_PLUS_5},
      {Key.BWD, Key.D0, Key.DOT, Key.MINUS, Key.TOOL2, Key.JOG_MINUS_6, Key.JOG_PLUS_6},
      {null, Key.COMMA, null, null, null, Key.OVERRIDE_DOWN, Key.OVERRIDE_UP},
      {Key.SHIFT, null, null, null, null, Key.SHIFT, null},
    };
    float spacing = ImGui.getStyle().getItemSpacingX();
    for (int r = 0; r < rows.length; r++) {
      Key[] row = rows[r];
      for (int c = 0; c < COLUMNS; c++) {
        if (c > 0) {
          ImGui.sameLine();
        }
        Key k = row[c];
        if (k == null) {
          ImGui.dummy(w, keyH);
        } else if (k == Key.SHIFT) {
          // the right SHIFT spans both jog columns, under the jog keys, as on an iPendant
          boolean wide = c == 5;
          shiftKey(r * COLUMNS + c, wide ? 2 * w + spacing : w, keyH);
          if (wide) {
            break;
          }
        } else if (k.isJog()) {
          jogKey(k, w, keyH);
        } else {
          key(k, w, keyH);
        }
      }
    }
  }

  /** The legend on the button: as on the pendant, shortened where a narrow key cannot hold it. */
  private static String legend(Key k) {
    return k == Key.BACKSPACE ? "BACK SP" : k.label();
  }

  private void key(Key k, float w, float h) {
    if (ImGui.button(legend(k) + "##" + k.name(), w, h)) {
      pendant().tap(k);
    }
    after(k);
  }

  /** Records the key's rectangle and shows its keyboard shortcut on hover. */
  private void after(Key k) {
    drawnKeys.add(new KeyRect(k, ImGui.getItemRectMinX(), ImGui.getItemRectMinY(),
        ImGui.getItemRectSizeX(), ImGui.getItemRectSizeY()));
    if (ImGui.isItemHovered()) {
      String sc = PendantKeyboard.shortcut(k);
      Txt.tooltip(k.label() + (sc.isEmpty() ? "  (no keyboard key: click it)" : "   keyboard: " + sc)
          + (k.isJog() ? "\nhold the DEADMAN and SHIFT, then this key, to jog" : ""));
    }
  }

  private int shiftHeldBy = -1;

  /** SHIFT is down while the mouse holds one of the SHIFT buttons (never latched). */
  private void shiftKey(int id, float w, float h) {
    boolean on = pendant().shift();
    if (on) {
      ImGui.pushStyleColor(ImGuiCol.Button, 0.85f, 0.55f, 0.1f, 1f);
    }
    ImGui.button("SHIFT##SHIFT" + id, w, h);
    boolean active = ImGui.isItemActive();
    if (active && shiftHeldBy < 0) {
      shiftHeldBy = id;
      pendant().press(Key.SHIFT);
    } else if (!active && shiftHeldBy == id) {
      shiftHeldBy = -1;
      pendant().release(Key.SHIFT);
    }
    if (on) {
      ImGui.popStyleColor();
    }
    after(Key.SHIFT);
  }

  /** A jog key is down while the mouse holds it (with the DEADMAN and SHIFT held: switch, keyboard). */
  private void jogKey(Key k, float w, float h) {
    boolean down = latched.contains(k);
    if (down) {
      ImGui.pushStyleColor(ImGuiCol.Button, 0.2f, 0.6f, 0.25f, 1f);
    } else {
      ImGui.pushStyleColor(ImGuiCol.Button, 0.22f, 0.32f, 0.45f, 1f);
    }
    ImGui.button(k.label() + "##" + k.name(), w, h);
    boolean active = ImGui.isItemActive();
    ImGui.popStyleColor();
    if (active && !down) {
      pendant().press(k);
      latched.add(k);
    } else if (!active && down) {
      pendant().release(k);
      latched.remove(k);
    }
    after(k);
  }

  private Pendant pendant() {
    return pendantNow.get();
  }
}
