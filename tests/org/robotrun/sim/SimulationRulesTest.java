package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.world.World;

/**
 * The simulation's own rules: a tick of more than 0 and at most 0.1 s, one placement per robot;
 * a contact that begins is one event (a lasting contact is not reported again), an alarm only
 * when collisions stop the robot (docs/collision.md: free play records and shows them), none at
 * all with checking off; the snapshot shows a robot without an end effector with a 20 mm bar from
 * 2 mm past the flange to its TCP, its pendant state, and the collision boxes only when asked.
 */
class SimulationRulesTest {

  private static org.robotrun.program.Program floorProgram() {
    return ControllerTest.program("FLOOR", "UFRAME_NUM=1", "UTOOL_NUM=1", "PR[1,1]=480", "PR[1,3]=(-340)", "PR[1,4]=180",
        "L PR[1] 200mm/sec FINE");
  }

  @Test
  void theTickAndThePlacementsAreChecked() {
    Controller c = DefaultCell.controller(ControllerTest.MODEL);
    List<Controller> one = List.of(c);
    List<Transform> at = List.of(Transform.IDENTITY);
    for (double bad : new double[] {0, -0.004, 0.1000001, Double.NaN}) {
      assertThatThrownBy(() -> new Simulation(one, at, World.empty(), 0, bad)).as("%s", bad)
          .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("(0, 0.1]");
    }
    assertThat(new Simulation(one, at, World.empty(), 0, 0.1).tickSec()).isEqualTo(0.1);
    assertThatThrownBy(() -> new Simulation(one, List.of(), World.empty(), 0, 0.004))
        .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("1 robots, 0 placements");
    Simulation s = new Simulation(one, at, World.empty(), 0, 0.01);
    s.step();
    s.step();
    assertThat(s.ticks()).isEqualTo(2);
    assertThat(s.timeSec()).isCloseTo(0.02, within(1e-12));
    assertThat(c.timeSec()).isCloseTo(0.02, within(1e-12));
  }

  @Test
  void withCollisionAlarmsOffAContactIsRecordedOnceAndTheProgramRunsOn() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    assertThat(sim.collisionAlarms()).isTrue();
    sim.setCollisionAlarms(false);
    assertThat(sim.collisionAlarms()).isFalse();
    c.saveProgram(floorProgram());
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "FLOOR", 60, s -> {});
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(c.activeAlarms()).isEmpty();
    // the tool went 10 mm into the floor: one contact that began, then lasted
    assertThat(c.tcpInWorld().z()).isCloseTo(-340, within(1e-3));
    assertThat(sim.collisionEvents()).hasSize(1);
    CollisionEvent e = sim.collisionEvents().get(0);
    assertThat(List.of(e.nameA(), e.nameB())).containsExactlyInAnyOrder("robot1 tool", "floor");
    assertThat(e.simTimeSec()).isPositive().isLessThanOrEqualTo(r.simTimeSec());
    for (int i = 0; i < 50; i++) {
      sim.step();
    }
    assertThat(sim.collisionEvents()).hasSize(1);
    // and it shows: the tool drawn in contact red
    DrawItem tool = sim.snapshot().scene().items().stream().filter(d -> d.name().equals("robot1/tool")).findFirst()
        .orElseThrow();
    assertThat(tool.color()).isEqualTo(Simulation.TOUCHING);
  }

  @Test
  void withCheckingOffNothingIsRecorded() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    sim.setCollisionChecking(false);
    c.saveProgram(floorProgram());
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "FLOOR", 60, s -> {});
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(sim.collisionEvents()).isEmpty();
    sim.setShowCollisionBoxes(true);
    assertThat(sim.snapshot().scene().items()).noneMatch(d -> d.name().startsWith("box:"));
    DrawItem tool = sim.snapshot().scene().items().stream().filter(d -> d.name().equals("robot1/tool")).findFirst()
        .orElseThrow();
    assertThat(tool.color()).isEqualTo(Simulation.TOOL_COLOR);
  }

  @Test
  void theSnapshotShowsTheToolBarThePendantStateAndTheBoxesWhenAsked() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.setOverridePct(35);
    sim.step();
    SimSnapshot snap = sim.snapshot();
    assertThat(snap.simTimeSec()).isEqualTo(sim.timeSec());
    assertThat(snap.scene().floorZ()).isEqualTo(c.model().X_WB().z());
    // UTOOL 1 of the default cell is a 100 mm pointer: a 20 x 20 mm bar 98 mm long, from 2 mm past the flange
    DrawItem tool = snap.scene().items().stream().filter(d -> d.name().equals("robot1/tool")).findFirst().orElseThrow();
    assertThat(tool.color()).isEqualTo(Simulation.TOOL_COLOR);
    DrawShape.Box bar = (DrawShape.Box) tool.shape();
    assertThat(bar.size().x()).isEqualTo(20.0);
    assertThat(bar.size().y()).isEqualTo(20.0);
    assertThat(bar.size().z()).isCloseTo(98, within(1e-9));
    Xyzwpr tcp = c.tcpInWorld();
    var flange = c.flangeInWorld();
    var centre = tool.X_WS().translationVector();
    // half-way between 2 mm past the flange and the TCP (the default cell's WORLD is the cell frame)
    double along = centre.distanceTo(flange);
    assertThat(along).isCloseTo(2 + 49, within(1e-6));
    assertThat(centre.distanceTo(new org.robotrun.math.Vec3(tcp.x(), tcp.y(), tcp.z()))).isCloseTo(49, within(1e-6));
    RobotState st = snap.robots().get(0);
    assertThat(st.name()).isEqualTo("robot1");
    assertThat(st.jointsDeg()).containsExactly(new double[] {0, 0, 0, 0, -90, 0}, within(1e-9));
    assertThat(st.tcpWorld().z()).isCloseTo(tcp.z(), within(1e-9));
    assertThat(st.utool()).isEqualTo(1);
    assertThat(st.uframe()).isEqualTo(1);
    assertThat(st.overridePct()).isEqualTo(35);
    assertThat(st.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    // the flange alone (UTOOL 0): no bar
    c.frames().select(FrameKind.TOOL, 0);
    sim.step();
    assertThat(sim.snapshot().scene().items()).noneMatch(d -> d.name().equals("robot1/tool"));
    assertThat(sim.snapshot().robots().get(0).utool()).isZero();
    // the collision boxes: only when asked, wire frame and fill for each, free ones green
    assertThat(sim.showCollisionBoxes()).isFalse();
    assertThat(sim.snapshot().scene().items()).noneMatch(d -> d.name().startsWith("box:"));
    sim.setShowCollisionBoxes(true);
    assertThat(sim.showCollisionBoxes()).isTrue();
    List<DrawItem> boxes = sim.snapshot().scene().items().stream().filter(d -> d.name().startsWith("box:")).toList();
    assertThat(boxes).isNotEmpty();
    assertThat(boxes.stream().filter(d -> d.shape() instanceof DrawShape.WireBox).count() * 2).isEqualTo(boxes.size());
    assertThat(boxes).noneMatch(d -> d.name().equals("box:floor")); // the 20 m floor slab is not drawn
    assertThat(boxes).allMatch(d -> d.color().equals(CollisionBoxDrawList.FREE_EDGE)
        || d.color().equals(CollisionBoxDrawList.FREE_FILL));
  }
}
