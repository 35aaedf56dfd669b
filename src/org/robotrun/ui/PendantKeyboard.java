package org.robotrun.ui;

import static org.lwjgl.glfw.GLFW.*;

import java.util.EnumSet;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.robotrun.pendant.Key;
import org.robotrun.pendant.Pendant;

/**
 * The computer keyboard as pendant keys. Keys act while held, as on a real pendant: a jog key
 * moves the arm from press to release; SHIFT (either Shift key) and the DEADMAN (Space) are
 * held, never latched. Jogging needs both held (and TP ENABLE on: a switch on the panel). Space,
 * not Ctrl: the window's shortcuts use Ctrl, and every Ctrl+Z would otherwise be a SRVO-003.
 *
 * <pre>
 * Shift          SHIFT (held)         Space           DEADMAN (held)
 *                                     F1..F5          F1..F5
 * arrows         cursor               Enter, Backspace ENTER, BACKSPACE
 * 0-9 . - ,      keypad               Escape          PREV
 * Q W E R T Y    +X/J1 ... +ZR/J6     A S D F G H     -X/J1 ... -ZR/J6
 * F6 NEXT  F7 COORD  F8 STEP  F9 FWD  F10 BWD  F11 HOLD  F12 RESET
 * Page Up / Page Down   +% / -%      Insert SELECT  Delete EDIT  End DATA
 * </pre>
 *
 * <p>While the pendant has an entry open (a program name, a comment, a number), letter keys
 * are text, not jog keys: the characters arrive through {@link #onChar}. A key is released to the
 * pendant only if its press reached it, so a Shift pressed while a text field of the window had
 * the keyboard does not reach the pendant when it comes up.
 */
public final class PendantKeyboard {
  private static final Map<Integer, Key> KEYS = Map.ofEntries(
      Map.entry(GLFW_KEY_LEFT_SHIFT, Key.SHIFT), Map.entry(GLFW_KEY_RIGHT_SHIFT, Key.SHIFT),
      Map.entry(GLFW_KEY_SPACE, Key.DEADMAN),
      Map.entry(GLFW_KEY_F1, Key.F1), Map.entry(GLFW_KEY_F2, Key.F2), Map.entry(GLFW_KEY_F3, Key.F3),
      Map.entry(GLFW_KEY_F4, Key.F4), Map.entry(GLFW_KEY_F5, Key.F5),
      Map.entry(GLFW_KEY_UP, Key.UP), Map.entry(GLFW_KEY_DOWN, Key.DOWN),
      Map.entry(GLFW_KEY_LEFT, Key.LEFT), Map.entry(GLFW_KEY_RIGHT, Key.RIGHT),
      Map.entry(GLFW_KEY_ENTER, Key.ENTER), Map.entry(GLFW_KEY_KP_ENTER, Key.ENTER),
      Map.entry(GLFW_KEY_BACKSPACE, Key.BACKSPACE), Map.entry(GLFW_KEY_ESCAPE, Key.PREV),
      Map.entry(GLFW_KEY_0, Key.D0), Map.entry(GLFW_KEY_1, Key.D1), Map.entry(GLFW_KEY_2, Key.D2),
      Map.entry(GLFW_KEY_3, Key.D3), Map.entry(GLFW_KEY_4, Key.D4), Map.entry(GLFW_KEY_5, Key.D5),
      Map.entry(GLFW_KEY_6, Key.D6), Map.entry(GLFW_KEY_7, Key.D7), Map.entry(GLFW_KEY_8, Key.D8),
      Map.entry(GLFW_KEY_9, Key.D9), Map.entry(GLFW_KEY_PERIOD, Key.DOT), Map.entry(GLFW_KEY_MINUS, Key.MINUS),
      Map.entry(GLFW_KEY_COMMA, Key.COMMA),
      Map.entry(GLFW_KEY_Q, Key.JOG_PLUS_1), Map.entry(GLFW_KEY_W, Key.JOG_PLUS_2), Map.entry(GLFW_KEY_E, Key.JOG_PLUS_3),
      Map.entry(GLFW_KEY_R, Key.JOG_PLUS_4), Map.entry(GLFW_KEY_T, Key.JOG_PLUS_5), Map.entry(GLFW_KEY_Y, Key.JOG_PLUS_6),
      Map.entry(GLFW_KEY_A, Key.JOG_MINUS_1), Map.entry(GLFW_KEY_S, Key.JOG_MINUS_2), Map.entry(GLFW_KEY_D, Key.JOG_MINUS_3),
      Map.entry(GLFW_KEY_F, Key.JOG_MINUS_4), Map.entry(GLFW_KEY_G, Key.JOG_MINUS_5), Map.entry(GLFW_KEY_H, Key.JOG_MINUS_6),
      Map.entry(GLFW_KEY_F6, Key.NEXT), Map.entry(GLFW_KEY_F7, Key.COORD), Map.entry(GLFW_KEY_F8, Key.STEP),
      Map.entry(GLFW_KEY_F9, Key.FWD), Map.entry(GLFW_KEY_F10, Key.BWD), Map.entry(GLFW_KEY_F11, Key.HOLD),
      Map.entry(GLFW_KEY_F12, Key.RESET),
      Map.entry(GLFW_KEY_PAGE_UP, Key.OVERRIDE_UP), Map.entry(GLFW_KEY_PAGE_DOWN, Key.OVERRIDE_DOWN),
      Map.entry(GLFW_KEY_INSERT, Key.SELECT), Map.entry(GLFW_KEY_DELETE, Key.EDIT), Map.entry(GLFW_KEY_END, Key.DATA));

  private final java.util.function.Supplier<Pendant> pendantNow;
  /** Keys whose press went to the pendant and whose release has not yet. */
  private final Set<Key> down = EnumSet.noneOf(Key.class);

  public PendantKeyboard(Pendant pendant) {
    this(() -> pendant);
  }

  /** Drives whichever pendant {@code pendantNow} answers (the robot selector's choice) at each call. */
  public PendantKeyboard(java.util.function.Supplier<Pendant> pendantNow) {
    this.pendantNow = pendantNow;
  }

  /** Every pendant key that has a computer key, with that key's name, in pendant-key order. */
  public static java.util.List<String[]> keyMap() {
    java.util.List<String[]> out = new java.util.ArrayList<>();
    for (Key k : Key.values()) {
      String sc = shortcut(k);
      if (!sc.isEmpty()) {
        out.add(new String[] {k.label(), sc});
      }
    }
    return out;
  }

  /** The pendant key a GLFW key stands for, if any. */
  public static Optional<Key> keyFor(int glfwKey) {
    return Optional.ofNullable(KEYS.get(glfwKey));
  }

  /**
   * The computer key that works as this pendant key, as a student reads it ("Shift", "Q",
   * "Insert"), or "" when only the on-screen button has it.
   */
  public static String shortcut(Key key) {
    String best = "";
    for (var e : KEYS.entrySet()) {
      if (e.getValue() == key) {
        String name = keyName(e.getKey());
        if (best.isEmpty() || name.length() < best.length()) {
          best = name;
        }
      }
    }
    return best;
  }

  private static String keyName(int glfwKey) {
    if (glfwKey >= GLFW_KEY_A && glfwKey <= GLFW_KEY_Z) {
      return String.valueOf((char) ('A' + glfwKey - GLFW_KEY_A));
    }
    if (glfwKey >= GLFW_KEY_0 && glfwKey <= GLFW_KEY_9) {
      return String.valueOf((char) ('0' + glfwKey - GLFW_KEY_0));
    }
    if (glfwKey >= GLFW_KEY_F1 && glfwKey <= GLFW_KEY_F12) {
      return "F" + (1 + glfwKey - GLFW_KEY_F1);
    }
    return switch (glfwKey) {
      case GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT -> "Shift";
      case GLFW_KEY_SPACE -> "Space";
      case GLFW_KEY_UP -> "Up arrow";
      case GLFW_KEY_DOWN -> "Down arrow";
      case GLFW_KEY_LEFT -> "Left arrow";
      case GLFW_KEY_RIGHT -> "Right arrow";
      case GLFW_KEY_ENTER -> "Enter";
      case GLFW_KEY_KP_ENTER -> "Keypad Enter";
      case GLFW_KEY_BACKSPACE -> "Backspace";
      case GLFW_KEY_ESCAPE -> "Esc";
      case GLFW_KEY_PERIOD -> ".";
      case GLFW_KEY_MINUS -> "-";
      case GLFW_KEY_COMMA -> ",";
      case GLFW_KEY_PAGE_UP -> "Page Up";
      case GLFW_KEY_PAGE_DOWN -> "Page Down";
      case GLFW_KEY_INSERT -> "Insert";
      case GLFW_KEY_DELETE -> "Delete";
      case GLFW_KEY_END -> "End";
      default -> "key " + glfwKey;
    };
  }

  /** Feeds a GLFW key event to the pendant; returns whether it was a pendant key. */
  public boolean onKey(int glfwKey, int action) {
    Optional<Key> k = keyFor(glfwKey);
    if (k.isEmpty() || action == GLFW_REPEAT) {
      return k.isPresent();
    }
    if (action == GLFW_PRESS) {
      if ((isLetter(glfwKey) || glfwKey == GLFW_KEY_SPACE) && pendant().entryOpen()) {
        return false;  // typed text: onChar delivers it
      }
      down.add(k.get());
      pendant().press(k.get());
    } else if (action == GLFW_RELEASE && down.remove(k.get())) {
      pendant().release(k.get());
    }
    return true;
  }

  /**
   * Feeds a typed character (GLFW's char callback) to an open pendant entry; returns whether it
   * was used. Digits and {@code . - ,} are not taken here: their keys already reach the pendant
   * as keypad keys.
   */
  public boolean onChar(int codepoint) {
    if (!pendant().entryOpen() || Character.isISOControl(codepoint)
        || codepoint >= '0' && codepoint <= '9' || codepoint == '.' || codepoint == '-' || codepoint == ',') {
      return false;
    }
    pendant().type(Character.toString(codepoint));
    return true;
  }

  /** Releases every key still down (the window lost the keyboard focus). */
  public void releaseAll() {
    for (Key k : down) {
      pendant().release(k);
    }
    down.clear();
  }

  private static boolean isLetter(int glfwKey) {
    return glfwKey >= GLFW_KEY_A && glfwKey <= GLFW_KEY_Z;
  }

  private Pendant pendant() {
    return pendantNow.get();
  }
}
