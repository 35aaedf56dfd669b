package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.math.Vec3;
import org.robotrun.motion.JogState;

/**
 * The override scales a jog on the controller, not only in the jogger (docs/motion.md, "Jog":
 * JOINT at 25 % of the data-sheet joint speed, WORLD at 250 mm/s, each times the override, reached
 * in 0.1 s). Measured on the real controller in T2 (no 250 mm/s cap): a key held for T seconds and
 * let go covers exactly speed × T (the 0.1 s ramp up loses what the 0.1 s ramp down gives back),
 * within a tick or two. The joint speed is the data sheet's (J1 450 °/s,
 * resources/robots/lrmate200id.json, read by {@link org.robotrun.DataSheet}).
 */
class JogOverrideOnControllerTest {
  static final double TICK = Simulation.DEFAULT_TICK_SEC;
  static final double J1_DEG_S = org.robotrun.DataSheet.maxSpeedsDegPerSec()[0];

  static Controller controller(Simulation sim, int overridePct, RobotControl.CoordSystem coord) {
    Controller c = sim.controllers().get(0);
    c.setMode(RobotControl.Mode.T2);
    c.setDeadman(true);
    c.setOverridePct(overridePct);
    c.setCoordSystem(coord);
    for (int i = 0; i < 10; i++) {
      sim.step();
    }
    return c;
  }

  /** Holds the key for {@code holdSec}, lets it go and waits until the arm is at rest. */
  static void holdAndRelease(Simulation sim, Controller c, int axis, double holdSec) {
    assertThat(c.jogKeyDown(axis, +1, JogState.Press.HELD)).isInstanceOf(RobotControl.Result.Ok.class);
    int ticks = (int) Math.round(holdSec / TICK);
    for (int i = 0; i < ticks; i++) {
      sim.step();
    }
    c.jogKeyUp(axis, +1);
    for (int i = 0; i < 100; i++) {
      sim.step();
    }
  }

  @Test
  void aJointJogAtEveryOverrideCoversTheOverriddenSpeedTimesTheHoldTime() {
    for (int pct : new int[] {10, 50, 100}) {
      Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
      Controller c = controller(sim, pct, RobotControl.CoordSystem.JOINT);
      double before = c.currentJoints().j1Deg();
      holdAndRelease(sim, c, 1, 0.4);
      double moved = c.currentJoints().j1Deg() - before;
      double expected = 0.25 * J1_DEG_S * pct / 100.0 * 0.4;
      double tickDeg = 0.25 * J1_DEG_S * pct / 100.0 * TICK;
      assertThat(moved).as("J1 jog at %d %%", pct).isBetween(expected - 2 * tickDeg, expected + 2 * tickDeg);
    }
  }

  @Test
  void aWorldJogAtThirtyPercentMovesTheTcpAtSeventyFiveMillimetresASecond() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = controller(sim, 30, RobotControl.CoordSystem.WORLD);
    Vec3 before = c.tcpInWorld().position();
    holdAndRelease(sim, c, 1, 0.4);
    Vec3 after = c.tcpInWorld().position();
    double expected = 250 * 0.30 * 0.4; // 30 mm
    double tickMm = 250 * 0.30 * TICK;
    assertThat(after.x() - before.x()).isBetween(expected - 2 * tickMm, expected + 2 * tickMm);
    assertThat(Math.hypot(after.y() - before.y(), after.z() - before.z())).isLessThan(0.01);
  }
}
