package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import org.robotrun.io.RobotDefinitions;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.program.IoKind;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.Wiring;
import org.robotrun.world.World;

/** Two robots in one cell: wired I/O timing and robot-robot collision. */
class TwoRobotCellTest {
  private static final List<Double> HOME = List.of(0.0, 0.0, 0.0, 0.0, Math.toRadians(-90), 0.0);

  /** robot1 at the origin, robot2 900 mm away along x facing it; both with grippers; robot1.DO[10] → robot2.DI[10], robot2.DO[3] → robot1.DI[4]. */
  private static Simulation cell() {
    RobotSetup r1 = new RobotSetup("robot1", "lrmate200id", Transform.translation(0, 0, -330), EndEffectorType.GRIPPER, HOME);
    RobotSetup r2 = new RobotSetup("robot2", "lrmate200id",
        Transform.translation(900, 0, -330).compose(Transform.rotation(0, 0, 1, Math.PI)), EndEffectorType.GRIPPER, HOME);
    Wiring w = new Wiring(List.of(
        new Wiring.Wire(new Wiring.Signal("robot1", "DO", 10), new Wiring.Signal("robot2", "DI", 10)),
        new Wiring.Wire(new Wiring.Signal("robot2", "DO", 3), new Wiring.Signal("robot1", "DI", 4))));
    Scenario sc = new Scenario("two", "", List.of(r1, r2), World.empty(), List.of(), Optional.empty(), new TreeMap<>(),
        new TreeMap<>(), new TreeMap<>(), Optional.empty()).withWiring(w);
    return ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
  }

  @Test
  void eachRobotRunsItsMacrosThroughItsOwnMacroTable() {
    RobotSetup r1 = new RobotSetup("robot1", "lrmate200id", Transform.translation(0, 0, -330), EndEffectorType.GRIPPER, HOME)
        .withMacros(List.of(new RobotSetup.Macro("HAND1 OPEN", "HOPEN")));
    RobotSetup r2 = new RobotSetup("robot2", "lrmate200id", Transform.translation(900, 0, -330), EndEffectorType.GRIPPER, HOME);
    Scenario sc = new Scenario("two", "", List.of(r1, r2), World.empty(), List.of(), Optional.empty(), new TreeMap<>(),
        new TreeMap<>(), new TreeMap<>(), Optional.empty());
    Simulation sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
    for (Controller c : sim.controllers()) {
      c.saveProgram(ProgramMotionTest.plain("HOPEN", "R[1]=7"));
      c.saveProgram(ProgramMotionTest.plain("MAIN", "HAND1 OPEN", "R[2]=1"));
      c.run("MAIN", 1, true);
    }
    for (int i = 0; i < 100 && (sim.controllers().get(0).busy() || sim.controllers().get(1).busy()); i++) {
      sim.step();
    }
    Controller a = sim.controllers().get(0);
    Controller b = sim.controllers().get(1);
    assertThat(a.activeAlarms()).isEmpty();
    assertThat(a.registers().number(1)).isEqualTo(7);
    assertThat(a.registers().number(2)).isEqualTo(1);
    // robot2 has no such macro in its table
    assertThat(b.activeAlarms()).singleElement().satisfies(al -> assertThat(al.message()).contains("not in the macro table"));
    assertThat(b.registers().number(1)).isZero();
  }

  @Test
  void aWiredInputSeesItsOutputFromTheNextTickInBothDirections() {
    Simulation sim = cell();
    Controller a = sim.controllers().get(0);
    Controller b = sim.controllers().get(1);
    a.registers().setBit(IoKind.DO, 10, true);
    b.registers().setBit(IoKind.DO, 3, true);
    // Set between ticks: not seen until the tick has run.
    assertThat(b.registers().bit(IoKind.DI, 10)).isFalse();
    assertThat(a.registers().bit(IoKind.DI, 4)).isFalse();
    sim.step();
    assertThat(b.registers().bit(IoKind.DI, 10)).isTrue();
    assertThat(a.registers().bit(IoKind.DI, 4)).isTrue();
    // Unwired ports stay as they were.
    assertThat(b.registers().bit(IoKind.DI, 3)).isFalse();
    a.registers().setBit(IoKind.DO, 10, false);
    sim.step();
    assertThat(b.registers().bit(IoKind.DI, 10)).isFalse();
  }

  @Test
  void aProgramWaitingOnAWiredInputGoesOnTheTickAfterTheOtherRobotSetsIt() {
    Simulation sim = cell();
    Controller a = sim.controllers().get(0);
    Controller b = sim.controllers().get(1);
    a.saveProgram(CellRig.program(new String[] {"  WAIT 0.20(sec)", "  DO[10]=ON"}));
    b.saveProgram(CellRig.program(new String[] {"  WAIT DI[10]=ON", "  R[1]=1"}));
    long[] setAt = {-1};
    long[] seenAt = {-1};
    Map<Controller, String> programs = new LinkedHashMap<>();
    programs.put(b, "TEST");  // the waiting robot starts first: order must not matter
    programs.put(a, "TEST");
    HeadlessRun.CellResult r = HeadlessRun.runCell(sim, programs, 10, s -> {
      if (setAt[0] < 0 && a.registers().bit(IoKind.DO, 10)) {
        setAt[0] = s.ticks();
      }
      if (seenAt[0] < 0 && b.registers().number(1) == 1) {
        seenAt[0] = s.ticks();
      }
    }, () -> false, "");
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(setAt[0]).isPositive();
    assertThat(seenAt[0]).isEqualTo(setAt[0] + 1);
  }

  @Test
  void aRobotRunningIntoTheOtherStopsBothWithTheCollisionAlarmNamingBothBodies() {
    Simulation sim = cell();
    Controller a = sim.controllers().get(0);
    Controller b = sim.controllers().get(1);
    // robot2 stands at HOME with its gripper about x = 515 mm in the cell; robot1 reaches into it.
    a.saveProgram(CellRig.program(new String[] {"  UFRAME_NUM=1", "  UTOOL_NUM=1", "L P[1] 250mm/sec FINE"}, "560,0,200"));
    b.saveProgram(CellRig.program(new String[] {"  WAIT 30.00(sec)"}));
    Map<Controller, String> programs = new LinkedHashMap<>();
    programs.put(a, "TEST");
    programs.put(b, "TEST");
    HeadlessRun.CellResult r = HeadlessRun.runCell(sim, programs, 60, s -> {}, () -> false, "");
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.ALARM);
    assertThat(r.robots()).extracting(HeadlessRun.RobotResult::status)
        .containsExactly(HeadlessRun.RobotStatus.ALARM, HeadlessRun.RobotStatus.ALARM);
    for (HeadlessRun.RobotResult rr : r.robots()) {
      ControllerAlarm al = rr.alarm().orElseThrow();
      assertThat(al.code()).isEqualTo(Simulation.COLLISION_ALARM).isEqualTo("SRVO-050");
      assertThat(al.message()).containsPattern("robot1 J\\d ").containsPattern("robot2 J\\d ").doesNotContain("/");
    }
    assertThat(sim.collisionEvents()).isNotEmpty();
    // Both arms stopped: a few more ticks move neither.
    double[] qa = a.jointsRad();
    double[] qb = b.jointsRad();
    for (int i = 0; i < 50; i++) {
      sim.step();
    }
    assertThat(a.jointsRad()).containsExactly(qa);
    assertThat(b.jointsRad()).containsExactly(qb);
    assertThat(b.status().state()).isNotEqualTo(ExecutionStatus.State.RUNNING);
  }
}
