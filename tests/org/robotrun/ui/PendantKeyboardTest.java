package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.lwjgl.glfw.GLFW.*;

import org.junit.jupiter.api.Test;
import org.robotrun.pendant.Pendant;
import org.robotrun.pendant.StandInRobotControl;

/** The computer keyboard as pendant keys; GLFW key codes are constants, so no window is needed. */
class PendantKeyboardTest {
  private final StandInRobotControl control = new StandInRobotControl();
  private final Pendant pendant = new Pendant(control);
  private final PendantKeyboard keyboard = new PendantKeyboard(pendant);

  private void tap(int glfwKey) {
    keyboard.onKey(glfwKey, GLFW_PRESS);
    keyboard.onKey(glfwKey, GLFW_RELEASE);
  }

  /** What a keyboard sends for a capital letter: Shift down, the key and its character, Shift up. */
  private void typeCapital(int glfwKey, char c) {
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS);
    keyboard.onKey(glfwKey, GLFW_PRESS);
    keyboard.onChar(c);
    keyboard.onKey(glfwKey, GLFW_RELEASE);
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_RELEASE);
  }

  @Test
  void typingAProgramNameOnTheKeyboardEntersTextAndNeverJogs() {
    var before = control.currentJoints();
    tap(GLFW_KEY_F1);  // SELECT: CREATE opens the name entry
    assertThat(pendant.entryOpen()).isTrue();
    String name = "HELLO";
    int[] keys = {GLFW_KEY_H, GLFW_KEY_E, GLFW_KEY_L, GLFW_KEY_L, GLFW_KEY_O};
    for (int i = 0; i < keys.length; i++) {
      typeCapital(keys[i], name.charAt(i));
    }
    tap(GLFW_KEY_ENTER);

    assertThat(control.programNames()).containsExactly("HELLO");
    assertThat(control.currentJoints()).isEqualTo(before);
    assertThat(pendant.shift()).as("SHIFT latch after typing capitals").isFalse();
  }

  @Test
  void aShiftReleaseWhosePressWentElsewhereDoesNotToggleTheLatch() {
    // The press went to a text field of the window (never forwarded), the release comes here.
    for (int i = 0; i < 3; i++) {
      keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_RELEASE);
    }
    assertThat(pendant.shift()).isFalse();

    tap(GLFW_KEY_LEFT_SHIFT);  // a real tap still latches
    assertThat(pendant.shift()).isTrue();
  }

  @Test
  void withNoEntryOpenLetterKeysAreJogKeysAndCharactersAreIgnored() {
    double j1Before = control.currentJoints().j1Deg();
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS);
    keyboard.onKey(GLFW_KEY_Q, GLFW_PRESS);
    assertThat(keyboard.onChar('Q')).isFalse();
    pendant.advance(0.5);
    keyboard.onKey(GLFW_KEY_Q, GLFW_RELEASE);
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_RELEASE);

    assertThat(control.currentJoints().j1Deg()).isGreaterThan(j1Before);
  }

  @Test
  void losingTheFocusReleasesAHeldJogKey() {
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS);
    keyboard.onKey(GLFW_KEY_Q, GLFW_PRESS);
    pendant.advance(0.2);
    keyboard.releaseAll();
    double j1 = control.currentJoints().j1Deg();
    pendant.advance(0.5);

    assertThat(control.currentJoints().j1Deg()).isEqualTo(j1);
    assertThat(pendant.shift()).isFalse();
  }

  @Test
  void everyKeyOnTheKeyboardShowsItsShortcutAndTheKeyMapListsThem() {
    assertThat(PendantKeyboard.shortcut(org.robotrun.pendant.Key.SHIFT)).isEqualTo("Shift");
    assertThat(PendantKeyboard.shortcut(org.robotrun.pendant.Key.JOG_PLUS_1)).isEqualTo("Q");
    assertThat(PendantKeyboard.shortcut(org.robotrun.pendant.Key.SELECT)).isEqualTo("Insert");
    assertThat(PendantKeyboard.shortcut(org.robotrun.pendant.Key.MENU)).as("only on screen").isEmpty();
    assertThat(PendantKeyboard.keyMap()).extracting(r -> r[0] + "=" + r[1]).contains("F1=F1", "ENTER=Enter", "-X/J1=A");
  }
}
