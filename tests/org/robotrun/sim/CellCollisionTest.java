package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.program.IoKind;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.World;

/** Contact at the first tick, and the process tool's trace. */
class CellCollisionTest {

  @Test
  void armDrivenIntoTheTableStopsAtTheFirstTickOfContact() {
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    Controller c = sim.controllers().get(0);
    c.saveProgram(CellRig.program(new String[] {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1", "L P[1] 500mm/sec FINE", "L P[2] 250mm/sec FINE"},
        "120,370,50", "120,370,-40"));
    c.run("TEST", 1, true);
    // The finger tips are the TCP; the table top is at z = -100 in the cell (= WORLD here).
    double tableTop = -100;
    List<Double> tcpZ = new ArrayList<>();
    while (!c.hasActiveAlarm() && sim.timeSec() < 20) {
      sim.step();
      tcpZ.add(c.tcpInWorld().z());
    }
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly(Simulation.COLLISION_ALARM);
    int n = tcpZ.size();
    assertThat(tcpZ.get(n - 1)).as("tip at the alarm tick").isLessThanOrEqualTo(tableTop + 1e-6);
    assertThat(tcpZ.get(n - 2)).as("tip one tick earlier").isGreaterThan(tableTop + 1e-6);
    // The arm stays where it stopped: nothing moves through the table.
    double stopped = c.tcpInWorld().z();
    for (int i = 0; i < 100; i++) {
      sim.step();
    }
    assertThat(c.tcpInWorld().z()).isEqualTo(stopped);
    // Both fingers met the table in the same tick: two contacts, one alarm.
    assertThat(sim.collisionEvents()).extracting(e -> new java.util.TreeSet<>(List.of(e.bodyA(), e.bodyB())).toString())
        .containsExactly("[robot1/tool/finger1, table]", "[robot1/tool/finger2, table]");
  }

  static Simulation glueCell() {
    RobotSetup robot = new RobotSetup("robot1", "lrmate200id", Transform.translation(0, 0, -330), EndEffectorType.GLUEGUN,
        List.of(0.0, 0.0, 0.0, 0.0, -Math.PI / 2, 0.0));
    TreeMap<Integer, Transform> user = new TreeMap<>();
    user.put(1, Transform.IDENTITY);
    Scenario sc = new Scenario("glue", "", List.of(robot), World.empty(), List.of(), Optional.empty(), new TreeMap<>(),
        new TreeMap<>(), user, Optional.empty());
    return CellRig.cell(sc);
  }

  @Test
  void glueGunLeavesATraceOnlyWhileOn() {
    Simulation sim = glueCell();
    // UT[1] defaults to the nozzle tip, 140 mm along the flange's z.
    assertThat(sim.controllers().get(0).frames().transform(org.robotrun.program.Instruction.FrameKind.TOOL, 1))
        .isEqualTo(Transform.translation(0, 0, 140));
    var r = CellRig.run(sim, CellRig.program(new String[] {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1",
        "L P[1] 500mm/sec FINE", "  RO[1]=ON", "L P[2] 200mm/sec FINE", "  RO[1]=OFF", "L P[3] 500mm/sec FINE"},
        "400,0,0", "400,100,0", "300,100,0"));
    assertThat(r.alarm()).isEmpty();
    List<EndEffectorState.TraceSegment> trace = sim.cellState().trace(0);
    double length = trace.stream().mapToDouble(s -> s.from().distanceTo(s.to())).sum();
    // The bead runs along y from 0 to 100 (to one trace step), at the nozzle tip's height.
    assertThat(length).isBetween(100 - EndEffectorState.TRACE_STEP_MM, 100.0 + 1e-6);
    assertThat(trace).allSatisfy(s -> {
      assertThat(s.from().x()).isCloseTo(400, org.assertj.core.data.Offset.offset(1e-3));
      assertThat(s.to().z()).isCloseTo(0, org.assertj.core.data.Offset.offset(1e-3));
    });
    var beads = sim.snapshot().scene().items().stream().filter(i -> i.name().equals("robot1/trace")).toList();
    assertThat(beads.size()).isGreaterThanOrEqualTo(50);
    assertThat(sim.controllers().get(0).registers().bit(IoKind.RI, CellState.INPUT_ACTUATED)).isFalse();
    // Reset scene clears it.
    sim.resetScene();
    assertThat(sim.cellState().trace(0)).isEmpty();
  }

  @Test
  void traceIsCappedAtItsLength() {
    EndEffectorState s = new EndEffectorState("r", org.robotrun.world.EndEffectorGeometry.of(EndEffectorType.GLUEGUN));
    s.setOn(true);
    for (int i = 0; i <= EndEffectorState.MAX_TRACE_SEGMENTS + 500; i++) {
      s.extendTrace(new org.robotrun.math.Vec3(i * 3.0, 0, 0));
    }
    List<EndEffectorState.TraceSegment> t = s.trace();
    assertThat(t).hasSize(EndEffectorState.MAX_TRACE_SEGMENTS);
    // The newest are kept.
    assertThat(t.get(t.size() - 1).to().x()).isEqualTo((EndEffectorState.MAX_TRACE_SEGMENTS + 500) * 3.0);
  }

  @Test
  void suctionCupPicksThePartItSitsOnAndCarriesIt() {
    RobotSetup robot = new RobotSetup("robot1", "lrmate200id", Transform.translation(0, 0, -330), EndEffectorType.SUCTION,
        List.of(0.0, 0.0, 0.0, 0.0, -Math.PI / 2, 0.0));
    var table = org.robotrun.world.WorldObject.of("table", org.robotrun.world.ObjectKind.FIXTURE,
        new org.robotrun.world.Shape.Box(300, 300, 230), org.robotrun.world.Rgb.GREY, Transform.translation(400, 0, -330),
        Optional.empty());
    var part = org.robotrun.world.WorldObject.of("block", org.robotrun.world.ObjectKind.PART,
        new org.robotrun.world.Shape.Box(40, 40, 40), org.robotrun.world.Rgb.GREY, Transform.translation(0, 0, 230),
        Optional.of("table"));
    TreeMap<Integer, Transform> user = new TreeMap<>();
    user.put(1, Transform.IDENTITY);
    Scenario sc = new Scenario("suction", "", List.of(robot), new World(List.of(table, part)), List.of(), Optional.empty(),
        new TreeMap<>(), new TreeMap<>(), user, Optional.empty());
    Simulation sim = CellRig.cell(sc);
    // The block's top is at z = -60; the cup's face (UT[1], 110 mm out) goes onto it.
    var r = CellRig.run(sim, CellRig.program(new String[] {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1",
        "L P[1] 500mm/sec FINE", "L P[2] 200mm/sec FINE", "  RO[1]=ON", "  WAIT RI[1]=ON", "  IF RI[2]=OFF,JMP LBL[9]",
        "L P[1] 500mm/sec FINE", "L P[3] 500mm/sec FINE", "  RO[1]=OFF", "  WAIT RI[1]=OFF", "  END", "  LBL[9]",
        "  UALM[1]"},
        "400,0,0", "400,0,-60", "300,100,0"));
    assertThat(r.alarm()).isEmpty();
    Transform X_CP = sim.world().poseInCell("block");
    assertThat(X_CP.x()).isCloseTo(300, org.assertj.core.data.Offset.offset(0.5));
    assertThat(X_CP.y()).isCloseTo(100, org.assertj.core.data.Offset.offset(0.5));
    assertThat(X_CP.z()).isCloseTo(-40, org.assertj.core.data.Offset.offset(0.5));
    assertThat(sim.world().find("block").orElseThrow().parent()).isEmpty();
    assertThat(sim.collisionEvents()).isEmpty();
  }
}
