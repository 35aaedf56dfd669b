package org.robotrun.ui;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_F1;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F12;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_RIGHT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_PRESS;
import static org.lwjgl.glfw.GLFW.GLFW_RELEASE;

import java.util.HashSet;
import java.util.Set;

/**
 * Which key events reach the pendant while a text field has the keyboard. A key typed into the
 * field (its press came while typing) is the field's, press and release: its release must not
 * reach the pendant either, or a space typed into a name released the DEADMAN held with Space (or
 * with its switch) and stopped the arm with SRVO-003. A key pressed before the field took the
 * keyboard still reaches the pendant when it is let go (the DEADMAN let go is let go). Function
 * keys always reach the pendant, and so does Shift: it types nothing itself, and a student who
 * holds Shift and presses F9 (SHIFT+FWD) with the pendant's Type field still focused was told
 * "Hold SHIFT and press FWD to run" while holding it (issue 29).
 */
final class TypingKeyFilter {
  private final Set<Integer> typed = new HashSet<>();

  /** Whether this event goes on to the pendant ({@code typing}: a text field has the keyboard now). */
  boolean pass(int key, int action, boolean typing) {
    boolean functionKey = key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12
        || key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT;
    if (action == GLFW_RELEASE) {
      // the release of a key typed into the field is the field's, whatever has the keyboard now
      return !typed.remove(key);
    }
    if (typing && !functionKey) {
      if (action == GLFW_PRESS) {
        typed.add(key);
      }
      return false;
    }
    return true;
  }
}
