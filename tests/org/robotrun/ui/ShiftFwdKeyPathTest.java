package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F9;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_SPACE;
import static org.lwjgl.glfw.GLFW.GLFW_PRESS;
import static org.lwjgl.glfw.GLFW.GLFW_RELEASE;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.sim.CellStepper;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * Issue 29: Shift+F9 (SHIFT+FWD) with the cursor on a program's last line, as the window's key
 * callback passes it on (TypingKeyFilter, then PendantKeyboard) to the real controller, says what
 * the key script says: only that line runs. With the pendant's Type field focused too: Shift is
 * held by the student, so the pendant must not answer "Hold SHIFT".
 */
class ShiftFwdKeyPathTest {
  private final Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
  private final CellStepper stepper = new CellStepper(sim);
  private final Pendant pendant = new Pendant(new ControllerPort(sim.controllers().get(0)));
  private final PendantKeyboard keyboard = new PendantKeyboard(pendant);
  private final TypingKeyFilter filter = new TypingKeyFilter();

  private void keys(String script) {
    KeyScript s = switch (KeyScript.parse("test.keys", script.lines().toList())) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new AssertionError(bad.error().display());
    };
    s.run(pendant, stepper::advance, text -> { });
  }

  /** One GLFW key event as SimulatorWindow's key callback hands it on. */
  private void key(int glfwKey, int action, boolean typing) {
    if (filter.pass(glfwKey, action, typing)) {
      keyboard.onKey(glfwKey, action);
    }
  }

  @ParameterizedTest(name = "Type field focused: {0}")
  @ValueSource(booleans = {false, true})
  void shiftF9OnTheLastLineStartsThatLineAndSaysSo(boolean typing) {
    // two points, the arm left away from the second, the cursor on line 2 (the last)
    keys("""
        HOLD DEADMAN
        SELECT
        F1
        TYPE PICK1
        ENTER
        SHIFT+F1
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.5
        RELEASE +X/J1
        RELEASE SHIFT
        SHIFT+F1
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.5
        RELEASE +X/J1
        RELEASE SHIFT
        RELEASE DEADMAN
        RESET
        """);
    assertThat(pendant.lcd().body()).anyMatch(l -> l.startsWith(">") && l.contains("2:"));

    key(GLFW_KEY_SPACE, GLFW_PRESS, false);        // DEADMAN held before the field took the keyboard
    key(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS, typing);
    KeyScript.advance(pendant, stepper::advance, 0.1);
    key(GLFW_KEY_F9, GLFW_PRESS, typing);
    KeyScript.advance(pendant, stepper::advance, 0.1);
    key(GLFW_KEY_F9, GLFW_RELEASE, typing);        // FWD let go, SHIFT still held: it runs on
    KeyScript.advance(pendant, stepper::advance, 0.3);

    assertThat(pendant.lcd().promptLine()).contains("Started at line 2, the last line of PICK1");
    assertThat(pendant.lcd().statusLine()).contains("RUNNING");
    KeyScript.advance(pendant, stepper::advance, 10);
    assertThat(pendant.lcd().statusLine()).contains("ABORTED");
    assertThat(pendant.lcd().promptLine()).as("the notice stays after the line ends")
        .contains("the last line of PICK1");
    key(GLFW_KEY_LEFT_SHIFT, GLFW_RELEASE, typing);
    assertThat(pendant.lcd().promptLine()).contains("the last line of PICK1");
  }
}
