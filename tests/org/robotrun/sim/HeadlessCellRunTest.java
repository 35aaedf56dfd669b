package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;
import static org.robotrun.sim.TaskProgs.program;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.World;

/**
 * A headless run of a cell of several robots (docs/run-report.md, "Several robots"): every
 * program starts in the same tick; the run ends when every program has ended and every arm is at
 * rest (the cell's cycle time is the last robot's end), or at the first alarm on any robot (the
 * robots still running are "stopped"), or at a time limit (every robot still running gets RUN-001,
 * or RUN-002 for the caller's stop, naming its own program and line); a PAUSE resumes at once; a
 * refused start names the robot.
 */
class HeadlessCellRunTest {
  private static final List<Double> HOME = List.of(0.0, 0.0, 0.0, 0.0, Math.toRadians(-90), 0.0);
  private static final double TICK = Simulation.DEFAULT_TICK_SEC;

  /** Two robots 2 m apart, faceplates: they never meet. */
  private static Simulation cell() {
    RobotSetup a = new RobotSetup("robot1", "lrmate200id", Transform.translation(0, 0, -330), EndEffectorType.FACEPLATE,
        HOME);
    RobotSetup b = new RobotSetup("robot2", "lrmate200id", Transform.translation(2000, 0, -330),
        EndEffectorType.FACEPLATE, HOME);
    Scenario sc = new Scenario("two", "", List.of(a, b), World.empty(), List.of(), Optional.empty(), new TreeMap<>(),
        new TreeMap<>(), new TreeMap<>(), Optional.empty());
    return ScenarioCell.build(sc, RobotDefinitions::load, TICK);
  }

  private static Map<Controller, String> both(Simulation sim, String p1, String p2) {
    Map<Controller, String> m = new LinkedHashMap<>();
    m.put(sim.controllers().get(0), p1);
    m.put(sim.controllers().get(1), p2);
    return m;
  }

  @Test
  void theCellEndsWhenTheLastRobotEndsAndEachRobotHasItsOwnCycleTime() {
    Simulation sim = cell();
    Controller a = sim.controllers().get(0);
    Controller b = sim.controllers().get(1);
    a.saveProgram(program("SHORT", false, "WAIT 0.20(sec)", "PAUSE", "R[1]=1"));
    b.saveProgram(program("LONG", false, "WAIT 0.40(sec)"));
    HeadlessRun.CellResult r = HeadlessRun.runCell(sim, both(sim, "SHORT", "LONG"), 10, s -> {}, () -> false, "");
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(r.alarm()).isEmpty();
    assertThat(r.robots()).extracting(HeadlessRun.RobotResult::robot).containsExactly("robot1", "robot2");
    assertThat(r.robots()).extracting(HeadlessRun.RobotResult::program).containsExactly("SHORT", "LONG");
    assertThat(r.robots()).extracting(HeadlessRun.RobotResult::status)
        .containsExactly(HeadlessRun.RobotStatus.FINISHED, HeadlessRun.RobotStatus.FINISHED);
    // the PAUSE resumed at once: SHORT ran to its end
    assertThat(a.registers().number(1)).isEqualTo(1);
    assertThat(r.robots().get(0).cycleTimeSec()).isBetween(0.2, 0.2 + 3 * TICK);
    assertThat(r.robots().get(1).cycleTimeSec()).isBetween(0.4, 0.4 + 3 * TICK);
    assertThat(r.cycleTimeSec()).isEqualTo(r.robots().get(1).cycleTimeSec());
    assertThat(r.robots()).allMatch(x -> x.busyTimeSec() == 0);
    assertThat(r.ticks()).isEqualTo(sim.ticks());
    assertThat(r.simTimeSec()).isCloseTo(sim.timeSec(), within(1e-12));
    // PROGRUN of the robot that ended last is off in the report's registers
    assertThat(b.uop().uo(Uop.PROGRUN)).isFalse();
  }

  @Test
  void aMovingArmCountsAsBusyAndTheRunWaitsUntilItIsAtRest() {
    Simulation sim = cell();
    Controller a = sim.controllers().get(0);
    a.saveProgram(ControllerTest.jointProgram("MOVE", "J P[2] 20% FINE", new double[] {0, 0, 0, 0, -90, 0},
        new double[] {20, 0, 0, 0, -90, 0}));
    Map<Controller, String> one = new LinkedHashMap<>();
    one.put(a, "MOVE");
    HeadlessRun.CellResult r = HeadlessRun.runCell(sim, one, 10, s -> {}, () -> false, "");
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(a.currentJoints().element(1)).isCloseTo(20, within(1e-6));
    assertThat(r.robots()).hasSize(1);
    double busy = r.robots().get(0).busyTimeSec();
    assertThat(busy).isPositive().isLessThanOrEqualTo(r.cycleTimeSec());
    // 20 deg of J1 at 20 % of its 450 deg/s: at least 0.222 s of motion
    assertThat(busy).isGreaterThanOrEqualTo(20.0 / (0.2 * 450) - TICK);
  }

  @Test
  void anAlarmOnOneRobotStopsTheCellAndTheOthersAreStopped() {
    Simulation sim = cell();
    Controller a = sim.controllers().get(0);
    Controller b = sim.controllers().get(1);
    a.saveProgram(program("BAD", false, "WAIT 0.10(sec)", "R[1]=1/R[2]"));
    b.saveProgram(program("LONG", false, "WAIT 5.00(sec)"));
    HeadlessRun.CellResult r = HeadlessRun.runCell(sim, both(sim, "BAD", "LONG"), 10, s -> {}, () -> false, "");
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.ALARM);
    assertThat(r.alarm().orElseThrow().code()).isEqualTo("SIMU-001");
    assertThat(r.alarm().get().program()).isEqualTo("BAD");
    assertThat(r.robots().get(0).status()).isEqualTo(HeadlessRun.RobotStatus.ALARM);
    assertThat(r.robots().get(0).alarm()).isEqualTo(r.alarm());
    assertThat(r.robots().get(1).status()).isEqualTo(HeadlessRun.RobotStatus.STOPPED);
    assertThat(r.robots().get(1).alarm()).isEmpty();
    assertThat(r.cycleTimeSec()).isBetween(0.1, 0.1 + 3 * TICK);
    assertThat(r.robots().get(1).cycleTimeSec()).isEqualTo(r.cycleTimeSec());
  }

  @Test
  void aTimeLimitOrTheCallersStopAlarmsEveryRobotStillRunningAtItsOwnLine() {
    Simulation sim = cell();
    sim.controllers().get(0).saveProgram(program("W1", false, "R[1]=1", "WAIT 5.00(sec)"));
    sim.controllers().get(1).saveProgram(program("W2", false, "WAIT 5.00(sec)"));
    HeadlessRun.CellResult r = HeadlessRun.runCell(sim, both(sim, "W1", "W2"), 0.5, s -> {}, () -> false, "");
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.ALARM);
    assertThat(r.cycleTimeSec()).isCloseTo(0.5, within(TICK));
    ControllerAlarm a1 = r.robots().get(0).alarm().orElseThrow();
    ControllerAlarm a2 = r.robots().get(1).alarm().orElseThrow();
    assertThat(a1.code()).isEqualTo("RUN-001");
    assertThat(a1.message()).contains("0.5 s");
    assertThat(a1.program()).isEqualTo("W1");
    assertThat(a1.line()).isEqualTo(2);
    assertThat(a2.program()).isEqualTo("W2");
    assertThat(a2.line()).isEqualTo(1);
    assertThat(r.alarm().orElseThrow().program()).isEqualTo("W1"); // the first running robot's
    assertThat(r.robots()).extracting(HeadlessRun.RobotResult::status)
        .containsOnly(HeadlessRun.RobotStatus.ALARM);
    // the caller's stop, asked every 250 ticks (1 s): RUN-002 with its reason
    Simulation sim2 = cell();
    sim2.controllers().get(0).saveProgram(program("W1", false, "WAIT 5.00(sec)"));
    sim2.controllers().get(1).saveProgram(program("W2", false, "WAIT 5.00(sec)"));
    HeadlessRun.CellResult s2 = HeadlessRun.runCell(sim2, both(sim2, "W1", "W2"), 10, s -> {}, () -> true, "wall");
    assertThat(s2.alarm().orElseThrow().code()).isEqualTo("RUN-002");
    assertThat(s2.alarm().get().message()).isEqualTo("wall");
    assertThat(s2.simTimeSec()).isCloseTo(1.0, within(1e-9));
    assertThat(s2.robots().get(1).alarm().orElseThrow().code()).isEqualTo("RUN-002");
  }

  @Test
  void aRefusedStartNamesTheRobotInACellOfSeveral() {
    Simulation sim = cell();
    sim.controllers().get(0).saveProgram(program("W1", false, "R[1]=1"));
    assertThatThrownBy(() -> HeadlessRun.runCell(sim, both(sim, "W1", "GHOST"), 10, s -> {}, () -> false, ""))
        .isInstanceOf(IllegalArgumentException.class).hasMessage("robot2: no program GHOST");
    // one robot alone: no name
    Simulation one = ControllerTest.cell();
    assertThatThrownBy(() -> HeadlessRun.run(one, one.controllers().get(0), "GHOST", 10, s -> {}))
        .isInstanceOf(IllegalArgumentException.class).hasMessage("no program GHOST");
  }
}
