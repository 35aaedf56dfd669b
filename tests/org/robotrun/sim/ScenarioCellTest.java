package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.Optional;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.world.CollisionResponse;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.World;

/**
 * A cell built from a scenario (docs/scenario-format.md): UT[1] is the end effector's TCP unless
 * the scenario sets tool frame 1; frame 1 is active only where the scenario sets it; preset
 * registers keep whole numbers whole; each robot's WORLD stands where its base is placed, the
 * floor under the lowest base; {@code "onCollision": "warn"} only records contacts; initial
 * joints outside the limits are refused naming the robot.
 */
class ScenarioCellTest {
  private static final List<Double> HOME = List.of(0.0, 0.0, 0.0, 0.0, Math.toRadians(-90), 0.0);

  private static Scenario scenario(List<RobotSetup> robots, TreeMap<Integer, Double> registers,
      TreeMap<Integer, Transform> tools, TreeMap<Integer, Transform> users, CollisionResponse onCollision) {
    return new Scenario("t", "", robots, World.empty(), List.of(), Optional.empty(), registers, tools, users,
        Optional.empty(), onCollision);
  }

  private static Simulation build(Scenario sc) {
    return ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
  }

  @Test
  void utoolOneIsTheEndEffectorsTcpButNotActiveUnlessTheScenarioSetsIt() {
    RobotSetup grip = new RobotSetup("robot1", "lrmate200id", Transform.translation(0, 0, -330), EndEffectorType.GRIPPER,
        HOME);
    RobotSetup plate = new RobotSetup("robot2", "lrmate200id", Transform.translation(1000, 0, -200),
        EndEffectorType.FACEPLATE, HOME);
    Simulation sim = build(scenario(List.of(grip, plate), new TreeMap<>(), new TreeMap<>(), new TreeMap<>(),
        CollisionResponse.ALARM));
    Controller a = sim.controllers().get(0);
    Controller b = sim.controllers().get(1);
    assertThat(a.frames().transform(FrameKind.TOOL, 1).distanceTo(Transform.translation(0, 0, 120))).isLessThan(1e-12);
    assertThat(a.frames().comment(FrameKind.TOOL, 1)).contains("gripper").contains("TCP");
    assertThat(a.frames().active(FrameKind.TOOL)).isZero();
    assertThat(a.frames().active(FrameKind.USER)).isZero();
    // a faceplate's TCP is the flange: UT[1] stays as it was
    assertThat(b.frames().transform(FrameKind.TOOL, 1).distanceTo(Transform.IDENTITY)).isLessThan(1e-12);
    assertThat(b.frames().comment(FrameKind.TOOL, 1)).isEmpty();
    // each robot's WORLD sits where its base is placed (X_CW = X_CB · X_BW); the floor under the lowest base
    for (int i = 0; i < 2; i++) {
      Controller c = sim.controllers().get(i);
      Transform X_CB = i == 0 ? Transform.translation(0, 0, -330) : Transform.translation(1000, 0, -200);
      assertThat(sim.robotPlacements().get(i).compose(c.model().X_WB()).distanceTo(X_CB)).isLessThan(1e-9);
    }
    assertThat(sim.snapshot().scene().floorZ()).isEqualTo(-330.0);
    assertThat(sim.collisionAlarms()).isTrue();
    // the gripper answers RI[1] itself, not the controller's stand-in
    a.registers().setBit(org.robotrun.program.IoKind.RO, 1, true);
    for (int k = 0; k < 30; k++) {
      sim.step();
    }
    assertThat(a.registers().bit(org.robotrun.program.IoKind.RI, 1)).isTrue();
  }

  @Test
  void presetFramesAreActiveAndPresetRegistersKeepTheirType() {
    RobotSetup grip = new RobotSetup("robot1", "lrmate200id", Transform.translation(0, 0, -330), EndEffectorType.GRIPPER,
        HOME);
    TreeMap<Integer, Double> regs = new TreeMap<>();
    regs.put(1, 5.0);
    regs.put(2, 2.5);
    regs.put(3, -7.0);
    regs.put(4, 2147483647.0);  // the largest whole number an integer register holds
    regs.put(5, 2147483648.0);
    TreeMap<Integer, Transform> tools = new TreeMap<>();
    tools.put(1, Transform.translation(0, 0, 150));
    tools.put(2, Transform.translation(10, 0, 0));
    TreeMap<Integer, Transform> users = new TreeMap<>();
    users.put(1, Transform.translation(400, 0, 0));
    Simulation sim = build(scenario(List.of(grip), regs, tools, users, CollisionResponse.WARN));
    Controller c = sim.controllers().get(0);
    assertThat(c.frames().transform(FrameKind.TOOL, 1).distanceTo(Transform.translation(0, 0, 150))).isLessThan(1e-12);
    assertThat(c.frames().transform(FrameKind.TOOL, 2).distanceTo(Transform.translation(10, 0, 0))).isLessThan(1e-12);
    assertThat(c.frames().transform(FrameKind.USER, 1).distanceTo(Transform.translation(400, 0, 0))).isLessThan(1e-12);
    assertThat(c.frames().active(FrameKind.TOOL)).isEqualTo(1);
    assertThat(c.frames().active(FrameKind.USER)).isEqualTo(1);
    assertThat(c.registers().number(1)).isEqualTo(5);
    assertThat(c.registers().isInteger(1)).isTrue();
    assertThat(c.registers().number(2)).isEqualTo(2.5);
    assertThat(c.registers().isInteger(2)).isFalse();
    assertThat(c.registers().isInteger(3)).isTrue();
    assertThat(c.registers().isInteger(4)).isTrue();
    assertThat(c.registers().number(4)).isEqualTo(2147483647.0);
    assertThat(c.registers().isInteger(5)).isFalse();
    assertThat(c.registers().number(5)).isEqualTo(2147483648.0);
    assertThat(sim.collisionAlarms()).isFalse();
  }

  @Test
  void initialJointsOutsideTheLimitsAreRefusedNamingTheRobot() {
    RobotSetup bad = new RobotSetup("armA", "lrmate200id", Transform.IDENTITY, EndEffectorType.FACEPLATE,
        List.of(Math.toRadians(200), 0.0, 0.0, 0.0, 0.0, 0.0));
    assertThatThrownBy(() -> build(scenario(List.of(bad), new TreeMap<>(), new TreeMap<>(), new TreeMap<>(),
        CollisionResponse.ALARM))).isInstanceOf(IllegalArgumentException.class)
        .hasMessageStartingWith("robot armA: ").hasMessageContaining("J1");
  }
}
