package org.robotrun.pendant;

import org.robotrun.sim.RobotFrameTeacher;

/** Test helper: the stand-in controller with the project's frame teaching. */
final class StandIn {
  private StandIn() {}

  static StandInRobotControl control() {
    return new StandInRobotControl(new RobotFrameTeacher()::teach);
  }
}
