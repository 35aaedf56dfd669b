package org.robotrun.pendant;

import org.robotrun.control.RobotControl;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.sim.CellStepper;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * Test helper: the pendant's port on the real controller ({@code sim.ControllerPort} on the
 * default cell's robot), as the window and {@code robotrun pendant} drive it. Every pendant test
 * runs on it; {@link ArmByHand} works out the default arm's figures by hand for their assertions.
 */
final class RealController {
  private RealController() {}

  /** The cell stepper of each port made here: simulated time, as the window and key scripts advance it. */
  private static final java.util.Map<RobotControl, CellStepper> STEPPERS =
      java.util.Collections.synchronizedMap(new java.util.WeakHashMap<>());

  /** A fresh default cell's first robot, behind its port. */
  static RobotControl control() {
    return control(RobotDefinitions.defaultRobot());
  }

  /** A fresh default cell with {@code model} as its robot, behind its port. */
  static RobotControl control(org.robotrun.robot.RobotModel model) {
    Simulation sim = DefaultCell.simulation(model);
    ControllerPort port = new ControllerPort(sim.controllers().get(0));
    STEPPERS.put(port, new CellStepper(sim));
    return port;
  }

  /** The clock of a port made by {@link #control()}: advances its whole cell. */
  static java.util.function.DoubleConsumer clock(RobotControl control) {
    CellStepper s = STEPPERS.get(control);
    if (s == null) {
      throw new IllegalStateException("not a port of RealController.control()");
    }
    return dt -> s.advance(dt);
  }
}
