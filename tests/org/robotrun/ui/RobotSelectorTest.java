package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.lwjgl.glfw.GLFW.*;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.pendant.Pendant;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/** The robot selector: the keyboard drives the chosen robot's pendant, and keys held are let go on a switch. */
class RobotSelectorTest {
  private final Simulation sim = new Simulation(List.of(DefaultCell.controller(RobotDefinitions.defaultRobot(), "robot1"),
      DefaultCell.controller(RobotDefinitions.defaultRobot(), "robot2")), List.of(org.robotrun.math.Transform.IDENTITY,
      org.robotrun.math.Transform.IDENTITY), new org.robotrun.world.World(List.of()), 0, Simulation.DEFAULT_TICK_SEC);
  private final Pendant one = new Pendant(new ControllerPort(sim.controllers().get(0)));
  private final Pendant two = new Pendant(new ControllerPort(sim.controllers().get(1)));
  private final RobotSelector selector = new RobotSelector(List.of("robot1", "robot2"), List.of(one, two));
  private final PendantKeyboard keyboard = new PendantKeyboard(selector);

  @Test
  void theKeyboardDrivesTheSelectedRobotsPendantAndLetsGoOfHeldKeysOnASwitch() {
    selector.onBeforeSwitch(keyboard::releaseAll);
    keyboard.onKey(GLFW_KEY_SPACE, GLFW_PRESS);  // DEADMAN held on robot1's pendant
    keyboard.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS);
    assertThat(one.deadmanHeld()).isTrue();
    assertThat(one.shift()).isTrue();
    selector.select(1);
    // Nothing stays held on the robot left behind, and nothing was pressed on the new one.
    assertThat(one.deadmanHeld()).isFalse();
    assertThat(one.shift()).isFalse();
    assertThat(two.deadmanHeld()).isFalse();
    keyboard.onKey(GLFW_KEY_SPACE, GLFW_PRESS);
    assertThat(two.deadmanHeld()).isTrue();
    assertThat(one.deadmanHeld()).isFalse();
    assertThat(selector.get()).isSameAs(two);
    assertThat(selector.selectedName()).isEqualTo("robot2");
  }

  @Test
  void selectingTheRobotAlreadyChosenChangesNothingAndAnUnknownOneIsRefused() {
    int[] switches = {0};
    selector.onBeforeSwitch(() -> switches[0]++);
    selector.select(0);
    assertThat(switches[0]).isZero();
    assertThatThrownBy(() -> selector.select(2)).isInstanceOf(IllegalArgumentException.class).hasMessageContaining("no robot 3");
    assertThat(selector.selected()).isZero();
  }
}
