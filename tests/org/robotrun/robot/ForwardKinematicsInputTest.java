package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;

/** FK of a joint vector that is not six values long is refused with the count, not cut to six. */
class ForwardKinematicsInputTest {
  @Test
  void sevenJointValuesAreRefused() {
    RobotModel m = RobotDefinitions.defaultRobot();
    assertThatThrownBy(() -> ForwardKinematics.linkPosesInBase(m, new double[7]))
        .isInstanceOf(IllegalArgumentException.class).hasMessage("expected 6 joint values, got 7");
  }
}
