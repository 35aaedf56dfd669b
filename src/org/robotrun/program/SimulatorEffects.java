package org.robotrun.program;

import java.util.Optional;

/**
 * Instructions a controller acts on but the simulator accepts without effect, so that neither
 * {@code robotrun check} nor the pendant lets them pass silently (a semantic check, apart from the
 * statement grammar).
 *
 * <ul>
 *   <li>{@code PAYLOAD[n]}: a controller switches the payload schedule (mass, centre of gravity,
 *       inertia), which changes the accelerations its motion planner allows; RobotRun plans
 *       motion without dynamics, so the schedule changes nothing.
 *   <li>{@code Wjnt}: a controller keeps the wrist joints' attitude on a linear or circular move
 *       (the tool's orientation is not held); RobotRun moves the tool with its orientation
 *       interpolated, as without Wjnt.
 * </ul>
 */
public final class SimulatorEffects {
  private SimulatorEffects() {}

  /** The warning for {@code in} if the simulator carries it out without effect. */
  public static Optional<String> noEffect(Instruction in) {
    if (in instanceof Instruction.Payload) {
      return Optional.of("PAYLOAD has no effect in the simulator: motion is planned without payload dynamics");
    }
    if (in instanceof Instruction.Move m && m.options().stream().anyMatch(o -> o instanceof Motion.Wjnt)) {
      return Optional.of("Wjnt has no effect in the simulator: the tool orientation is interpolated as without it");
    }
    return Optional.empty();
  }
}
