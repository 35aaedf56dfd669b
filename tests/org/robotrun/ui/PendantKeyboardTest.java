package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.lwjgl.glfw.GLFW.*;

import org.junit.jupiter.api.Test;
import org.robotrun.pendant.Pendant;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.KeyScript;
import org.robotrun.sim.CellStepper;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/** The computer keyboard as pendant keys; GLFW key codes are constants, so no window is needed. */
class PendantKeyboardTest {
  private final Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
  private final CellStepper stepper = new CellStepper(sim);
  private final ControllerPort control = new ControllerPort(sim.controllers().get(0));
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
  void aShiftReleaseWhosePressWentElsewhereDoesNothingAndATapNeverLatches() {
    // The press went to a text field of the window (never forwarded), the release comes here.
    for (int i = 0; i < 3; i++) {
      keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_RELEASE);
    }
    assertThat(pendant.shift()).isFalse();

    tap(GLFW_KEY_LEFT_SHIFT);  // SHIFT is held, never latched: a tap leaves it off
    assertThat(pendant.shift()).isFalse();
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS);
    assertThat(pendant.shift()).isTrue();
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_RELEASE);
    assertThat(pendant.shift()).isFalse();
  }

  @Test
  void withNoEntryOpenLetterKeysAreJogKeysAndCharactersAreIgnored() {
    double j1Before = control.currentJoints().j1Deg();
    keyboard.onKey(GLFW_KEY_SPACE, GLFW_PRESS);  // DEADMAN
    assertThat(pendant.deadmanHeld()).isTrue();
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS);
    keyboard.onKey(GLFW_KEY_Q, GLFW_PRESS);
    assertThat(keyboard.onChar('Q')).isFalse();
    KeyScript.advance(pendant, stepper::advance, 0.5);
    keyboard.onKey(GLFW_KEY_Q, GLFW_RELEASE);
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_RELEASE);

    assertThat(control.currentJoints().j1Deg()).isGreaterThan(j1Before);
  }

  @Test
  void losingTheFocusReleasesAHeldJogKey() {
    keyboard.onKey(GLFW_KEY_SPACE, GLFW_PRESS);
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS);
    keyboard.onKey(GLFW_KEY_Q, GLFW_PRESS);
    KeyScript.advance(pendant, stepper::advance, 0.2);
    keyboard.releaseAll();
    double j1 = control.currentJoints().j1Deg();
    assertThat(j1).as("the held jog moved J1 before the focus went").isGreaterThan(0);
    KeyScript.advance(pendant, stepper::advance, 0.5);

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
