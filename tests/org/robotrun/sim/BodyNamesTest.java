package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.collision.Body;

/** Issue 29: collision bodies as a student knows them, not the collision world's ids. */
class BodyNamesTest {
  @Test
  void aLinkIsNamedByItsRobotAndTheJointThatMovesIt() {
    assertThat(BodyNames.of(Body.robotLink("robot1", 2, "robot1/link2#2"), "")).isEqualTo("robot1 J2 upper arm");
    assertThat(BodyNames.of(Body.robotLink("left", 0, "left/base"), "GRIPPER")).isEqualTo("left base");
    assertThat(BodyNames.of(Body.robotLink("robot2", 5, "robot2/link5#1"), "")).isEqualTo("robot2 J5 wrist");
    assertThat(BodyNames.of(Body.robotLink("robot2", 6, "robot2/link6"), "")).isEqualTo("robot2 J6 flange");
  }

  @Test
  void aToolBoxIsNamedByTheToolAndItsBoxAndObjectsKeepTheirScenarioNames() {
    assertThat(BodyNames.of(Body.robotLink("robot1", Body.TOOL_LINK, "robot1/tool/finger1"), "GRIPPER"))
        .isEqualTo("robot1 gripper finger1");
    assertThat(BodyNames.of(Body.robotLink("robot1", Body.TOOL_LINK, "robot1/tool"), "")).isEqualTo("robot1 tool");
    assertThat(BodyNames.of(Body.fixture("table", "table"), "")).isEqualTo("table");
    assertThat(BodyNames.of(Body.part("part1", "part1"), "")).isEqualTo("part1");
  }
}
