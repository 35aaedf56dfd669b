package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.motion.MotionLimits;

/** The control port tells the pendant each robot's own maximum TCP speed, as its model gives it. */
class ControllerPortSpeedLimitTest {
  @Test
  void eachRobotsPortReportsItsModelsMaximumTcpSpeed() {
    for (String id : RobotDefinitions.LIBRARY) {
      var model = RobotDefinitions.load(id);
      Controller c = DefaultCell.simulation(model).controllers().get(0);
      double expected = id.startsWith("crx") ? 1000 : 2000;
      assertThat(new ControllerPort(c).maxLinearSpeedMmPerSec()).as(id).isEqualTo(expected);
      // the planner limits a linear move to the same speed
      assertThat(MotionLimits.forModel(model).linearMaxSpeedMmPerSec()).as(id).isEqualTo(expected);
    }
  }
}
