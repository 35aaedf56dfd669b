package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.program.IoKind;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/**
 * Gripping, carrying and setting down parts in scenarios/pick-and-place.json. UF[1] is the table
 * corner at (220, −350, −100) in the cell; UT[1] the finger tips. Positions to 0.5 mm.
 */
class PickAndPlaceTest {
  static final double MM = 0.5;

  /** A point of UF[1] in the cell (UF[1] is a pure translation). */
  static Vec3 cell(double x, double y, double z) {
    return new Vec3(x + 220, y - 350, z - 100);
  }

  static void assertAt(World w, String part, Vec3 p_C) {
    Transform X_CP = w.poseInCell(part);
    assertThat(X_CP.x()).as(part + " x").isCloseTo(p_C.x(), offset(MM));
    assertThat(X_CP.y()).as(part + " y").isCloseTo(p_C.y(), offset(MM));
    assertThat(X_CP.z()).as(part + " z").isCloseTo(p_C.z(), offset(MM));
    // Upright and not turned: the parts are never rotated by this program.
    assertThat(X_CP.rotationAngleTo(Transform.IDENTITY)).as(part + " rotation").isLessThan(1e-6);
  }

  @Test
  void exampleProgramPutsAllThreePartsOnTheTray() {
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    Controller c = sim.controllers().get(0);
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "PICKPLACE", 120, s -> {});
    assertThat(r.alarm()).isEmpty();
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    World w = sim.world();
    // Placed at UF[1] (130 + 50k, 530) with the finger tips 30 mm up: the part's base on the
    // tray's top (UF[1] z = 10).
    for (int k = 0; k < 3; k++) {
      String part = "part" + (k + 1);
      assertAt(w, part, cell(130 + 50 * k, 530, 10));
      assertThat(w.find(part).orElseThrow().parent()).contains("tray");
    }
    assertThat(sim.heldParts()).isEmpty();
    assertThat(sim.collisionEvents()).isEmpty();
  }

  @Test
  void releasingMidAirLeavesThePartWhereReleased() {
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    var r = CellRig.run(sim, CellRig.program(new String[] {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1",
        "L P[1] 500mm/sec FINE", "L P[2] 300mm/sec FINE",
        "  RO[1]=ON", "  WAIT RI[1]=ON",
        "L P[3] 500mm/sec FINE",
        "  RO[1]=OFF", "  WAIT RI[1]=OFF",
        "L P[4] 500mm/sec FINE", "L P[5] 500mm/sec FINE"},
        // Up past the part's top (170) before moving off sideways, or a finger would knock it.
        "120,170,80", "120,170,20", "120,170,150", "120,170,230", "200,300,230"));
    assertThat(r.alarm()).isEmpty();
    World w = sim.world();
    // Gripped with the finger tips at its mid-height (20 mm): released with them at 150.
    assertAt(w, "part1", cell(120, 170, 130));
    assertThat(w.find("part1").orElseThrow().parent()).isEmpty();
    assertThat(sim.controllers().get(0).registers().bit(IoKind.RI, CellState.INPUT_HOLDING)).isFalse();
    // The others never moved.
    assertAt(w, "part2", cell(200, 170, 0));
  }

  @Test
  void partReleasedJustAboveAFixtureIsSetOnItAndHigherStaysInTheAir() {
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    String[] lines = {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1",
        "L P[1] 500mm/sec FINE", "L P[2] 300mm/sec FINE",
        "  RO[1]=ON", "  WAIT RI[1]=ON",
        "L P[3] 500mm/sec FINE", "L P[4] 300mm/sec FINE",
        "  RO[1]=OFF", "  WAIT RI[1]=OFF",
        "L P[3] 500mm/sec FINE"};
    // 1.5 mm above the tray top: set down on it (within 2 mm).
    var r = CellRig.run(sim, CellRig.program(lines, "120,170,80", "120,170,20", "130,530,80", "130,530,31.5"));
    assertThat(r.alarm()).isEmpty();
    assertAt(sim.world(), "part1", cell(130, 530, 10));
    assertThat(sim.world().find("part1").orElseThrow().parent()).contains("tray");

    // 3 mm above: left where it is.
    Simulation sim2 = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    var r2 = CellRig.run(sim2, CellRig.program(lines, "120,170,80", "120,170,20", "130,530,80", "130,530,33"));
    assertThat(r2.alarm()).isEmpty();
    assertAt(sim2.world(), "part1", cell(130, 530, 13));
    assertThat(sim2.world().find("part1").orElseThrow().parent()).isEmpty();
  }

  @Test
  void resetScenePutsEveryPartBackWhereItStarted() {
    var sc = CellRig.scenario("pick-and-place.json");
    Simulation sim = CellRig.cell(sc);
    HeadlessRun.run(sim, sim.controllers().get(0), "PICKPLACE", 120, s -> {});
    assertThat(sim.world()).isNotEqualTo(sc.world());
    sim.resetScene();
    assertThat(sim.world()).isEqualTo(sc.world());
    for (WorldObject o : sc.world().objects()) {
      assertThat(sim.world().poseInCell(o.name())).isEqualTo(sc.world().poseInCell(o.name()));
    }
    // The cell runs again after a reset.
    var again = HeadlessRun.run(sim, sim.controllers().get(0), "PICKPLACE", 120, s -> {});
    assertThat(again.alarm()).isEmpty();
    assertAt(sim.world(), "part3", cell(230, 530, 10));
  }

  @Test
  void resetWhileHoldingDropsTheGrip() {
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    var r = CellRig.run(sim, CellRig.program(new String[] {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1",
        "L P[1] 500mm/sec FINE", "L P[2] 300mm/sec FINE",
        "  RO[1]=ON", "  WAIT RI[1]=ON", "L P[1] 500mm/sec FINE"},
        "120,170,80", "120,170,20"));
    assertThat(r.alarm()).isEmpty();
    assertThat(sim.heldParts()).containsEntry("part1", "robot1");
    sim.resetScene();
    assertThat(sim.heldParts()).isEmpty();
    sim.step();
    assertThat(sim.world().find("part1").orElseThrow().parent()).contains("table");
    assertAt(sim.world(), "part1", cell(120, 170, 0));
  }

  @Test
  void closingOnNothingReportsClosedButNotHolding() {
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    Controller c = sim.controllers().get(0);
    c.registers().setBit(IoKind.RO, CellState.OUTPUT, true);
    for (int i = 0; i < 24; i++) {
      sim.step();
    }
    assertThat(c.registers().bit(IoKind.RI, CellState.INPUT_ACTUATED)).as("after 96 ms").isFalse();
    sim.step();
    assertThat(c.registers().bit(IoKind.RI, CellState.INPUT_ACTUATED)).as("after 100 ms").isTrue();
    assertThat(c.registers().bit(IoKind.RI, CellState.INPUT_HOLDING)).isFalse();
    assertThat(sim.heldParts()).isEmpty();
  }

  @Test
  void heldPartDrivenIntoTheTableStopsTheArmAtFirstContact() {
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    var r = CellRig.run(sim, CellRig.program(new String[] {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1",
        "L P[1] 500mm/sec FINE", "L P[2] 300mm/sec FINE",
        "  RO[1]=ON", "  WAIT RI[1]=ON",
        "L P[1] 500mm/sec FINE", "L P[3] 500mm/sec FINE", "L P[4] 100mm/sec FINE"},
        "120,170,80", "120,170,20", "120,370,80", "120,370,10"));
    assertThat(r.alarm()).isPresent();
    assertThat(r.alarm().get().code()).isEqualTo(Simulation.COLLISION_ALARM);
    assertThat(r.alarm().get().line()).isEqualTo(9);
    assertThat(r.alarm().get().message()).contains("part1").contains("table");
    // The part's base (20 mm below the finger tips) stopped within one tick (0.4 mm) of the
    // table top, counting the held part's 0.5 mm clearance.
    double bottomZ = sim.world().poseInCell("part1").z();
    assertThat(bottomZ).isBetween(-100 - CellCollisions.HELD_CLEARANCE_MM - 0.4 - 1e-6, -100.0);
    assertThat(sim.heldParts()).containsEntry("part1", "robot1");
    // Stopped: more ticks move nothing.
    Transform before = sim.world().poseInCell("part1");
    for (int i = 0; i < 50; i++) {
      sim.step();
    }
    assertThat(sim.world().poseInCell("part1")).isEqualTo(before);
  }

  @Test
  void collisionsAsWarningsLetTheProgramRunThrough() {
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    sim.setCollisionAlarms(false);
    var r = CellRig.run(sim, CellRig.program(new String[] {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1",
        "L P[1] 500mm/sec FINE", "L P[2] 100mm/sec FINE", "L P[1] 500mm/sec FINE"},
        "120,370,50", "120,370,-20"));
    assertThat(r.alarm()).isEmpty();
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(sim.collisionEvents()).isNotEmpty();
    CollisionEvent first = sim.collisionEvents().get(0);
    assertThat(java.util.List.of(first.bodyA(), first.bodyB())).containsExactlyInAnyOrder("robot1/tool/finger1", "table");
  }

  @Test
  void gripperFingersCloseOverTheActuationTime() {
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    EndEffectorState s = sim.cellState().tool(0).orElseThrow();
    Controller c = sim.controllers().get(0);
    assertThat(s.fingerGapMm()).isEqualTo(70.0);
    c.registers().setBit(IoKind.RO, CellState.OUTPUT, true);
    for (int i = 0; i < 12; i++) {
      sim.step();
    }
    assertThat(s.fingerGapMm()).isCloseTo(70 * (1 - 12 * 0.004 / 0.1), offset(0.01));
    var fingers = sim.snapshot().scene().items().stream().filter(i -> i.name().startsWith("robot1/tool/finger")).toList();
    assertThat(fingers).hasSize(2);
    double gap = Math.abs(fingers.get(0).X_WS().y() - fingers.get(1).X_WS().y()) - 10;
    assertThat(gap).isCloseTo(s.fingerGapMm(), offset(1e-6));
    Optional<String> none = Optional.empty();
    assertThat(s.held().map(EndEffectorState.Held::part)).isEqualTo(none);
  }

  @Test
  void mappedToolOutputDrivesTheGripper() {
    var sc = CellRig.scenario("pick-and-place.json");
    var r0 = sc.robots().get(0);
    var mapped = new org.robotrun.world.RobotSetup(r0.name(), r0.modelId(), r0.X_CB(), r0.endEffector(), r0.initialJointsRad(),
        new org.robotrun.world.ToolIo(3, 4, 5));
    var sc2 = new org.robotrun.world.Scenario(sc.name(), sc.description(), java.util.List.of(mapped), sc.world(), sc.programs(),
        sc.mainProgram(), sc.registers(), sc.toolFrames(), sc.userFrames(), sc.camera(), sc.onCollision());
    Simulation sim = CellRig.cell(sc2);
    var r = CellRig.run(sim, CellRig.program(new String[] {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1",
        "L P[1] 500mm/sec FINE", "L P[2] 300mm/sec FINE",
        "  RO[1]=ON", "  WAIT 0.20(sec)", "  RO[3]=ON", "  WAIT RI[4]=ON", "L P[1] 500mm/sec FINE"},
        "120,170,80", "120,170,20"));
    assertThat(r.alarm()).isEmpty();
    var io = sim.controllers().get(0).registers();
    // RO[1] did nothing; RO[3] gripped, RI[4] reports it closed and RI[5] holding.
    assertThat(sim.heldParts()).containsEntry("part1", "robot1");
    assertThat(io.bit(IoKind.RI, 5)).isTrue();
    assertThat(io.bit(IoKind.RI, 1)).isFalse();
    assertThat(io.bit(IoKind.RI, 2)).isFalse();
  }

  @Test
  void theFingersCloseOnThePartsWidthAcrossThemPlusTheirClearance() {
    // part1 is a 40 mm cube, square to the fingers: they stop 40 + 2 × 0.5 mm apart (the clearance of
    // EndEffectorState.FINGER_CLEARANCE_MM on each side), not at the closed gap of 0.
    Simulation sim = CellRig.cell(CellRig.scenario("pick-and-place.json"));
    var r = CellRig.run(sim, CellRig.program(new String[] {
        "  UFRAME_NUM=1", "  UTOOL_NUM=1",
        "L P[1] 500mm/sec FINE", "L P[2] 300mm/sec FINE",
        "  RO[1]=ON", "  WAIT RI[1]=ON", "  WAIT 0.20(sec)"},
        "120,170,80", "120,170,20"));
    assertThat(r.alarm()).isEmpty();
    EndEffectorState s = sim.cellState().tool(0).orElseThrow();
    assertThat(s.held().map(EndEffectorState.Held::part)).contains("part1");
    assertThat(s.held().orElseThrow().widthMm()).isCloseTo(40, offset(1e-6));
    assertThat(s.fingerGapMm()).isCloseTo(41, offset(1e-6));
  }
}
