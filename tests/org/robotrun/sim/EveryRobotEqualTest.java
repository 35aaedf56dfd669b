package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.World;

/** A robot after the first is given and reports what the first is given and reports. */
class EveryRobotEqualTest {
  private static final List<Double> HOME = List.of(0.0, 0.0, 0.0, 0.0, Math.toRadians(-90), 0.0);

  private static Scenario twoRobots(RobotSetup second) {
    RobotSetup r1 = new RobotSetup("robot1", "lrmate200id", Transform.translation(0, 0, -330), EndEffectorType.GRIPPER, HOME);
    return new Scenario("two", "", List.of(r1, second), World.empty(), List.of(), Optional.empty(),
        new TreeMap<>(Map.of(1, 3.0)), new TreeMap<>(), new TreeMap<>(), Optional.empty());
  }

  @Test
  void theSecondRobotsRegistersAndFramesArePresetAndItsFrameOneIsActive() {
    Transform ut1 = Transform.translation(0, 0, 150);
    Transform uf2 = Transform.translation(400, -100, 0);
    RobotSetup r2 = new RobotSetup("robot2", "lrmate200id", Transform.translation(900, 0, -330), EndEffectorType.GRIPPER, HOME)
        .withPresets(new TreeMap<>(Map.of(5, 7.0, 6, 2.5)), new TreeMap<>(Map.of(1, ut1)), new TreeMap<>(Map.of(2, uf2)));
    Simulation sim = ScenarioCell.build(twoRobots(r2), RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
    Controller one = sim.controllers().get(0);
    Controller two = sim.controllers().get(1);
    assertThat(two.registers().number(5)).isEqualTo(7.0);
    assertThat(two.registers().number(6)).isEqualTo(2.5);
    // the preset UT[1] wins over the gripper's TCP, and becomes active, as on the first robot
    assertThat(two.frames().transform(FrameKind.TOOL, 1)).isEqualTo(ut1);
    assertThat(two.frames().active(FrameKind.TOOL)).isEqualTo(1);
    assertThat(two.frames().transform(FrameKind.USER, 2)).isEqualTo(uf2);
    // the top-level registers are the first robot's only
    assertThat(one.registers().number(1)).isEqualTo(3.0);
    assertThat(two.registers().number(1)).isEqualTo(0.0);
    assertThat(one.registers().number(5)).isEqualTo(0.0);
  }

  @Test
  void atTheTimeLimitEachRobotsAlarmNamesItsOwnProgramAndLine() {
    RobotSetup r2 = new RobotSetup("robot2", "lrmate200id", Transform.translation(900, 0, -330), EndEffectorType.GRIPPER, HOME);
    Simulation sim = ScenarioCell.build(twoRobots(r2), RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
    Controller one = sim.controllers().get(0);
    Controller two = sim.controllers().get(1);
    one.saveProgram(ProgramMotionTest.plain("FEEDER", "R[1]=1", "WAIT 100.00(sec)"));
    two.saveProgram(ProgramMotionTest.plain("PACKER", "R[1]=1", "R[2]=2", "WAIT 100.00(sec)"));
    Map<Controller, String> mains = new java.util.LinkedHashMap<>();
    mains.put(one, "FEEDER");
    mains.put(two, "PACKER");
    HeadlessRun.CellResult r = HeadlessRun.runCell(sim, mains, 1.0, s -> { }, () -> false, "");
    assertThat(r.robots()).hasSize(2);
    ControllerAlarm feeder = r.robots().get(0).alarm().orElseThrow();
    ControllerAlarm packer = r.robots().get(1).alarm().orElseThrow();
    assertThat(feeder.code()).isEqualTo(HeadlessRun.TIME_LIMIT_CODE);
    assertThat(packer.code()).isEqualTo(HeadlessRun.TIME_LIMIT_CODE);
    assertThat(feeder.display()).contains("(FEEDER, 2)");
    assertThat(packer.display()).contains("(PACKER, 3)");
  }
}
