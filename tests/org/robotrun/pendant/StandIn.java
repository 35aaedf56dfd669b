package org.robotrun.pendant;

import org.robotrun.sim.RobotFrameTeacher;

/**
 * Test helper: the stand-in controller with the project's frame teaching, for the tests whose
 * numbers are checked by hand on its toy kinematics and instant motions (PendantMotionAndDataTest,
 * PendantProgramTest); the others run on the real controller ({@link RealController}).
 * ControlPortContractTest runs the same cases on both.
 */
final class StandIn {
  private StandIn() {}

  static StandInRobotControl control() {
    return new StandInRobotControl(new RobotFrameTeacher()::teach);
  }
}
