package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.program.IoKind;

/**
 * The default cell's gripper I/O (docs/run-report.md, "Without --scenario"): RO[1] closes the
 * gripper and RI[1] reports it closed, or open, 0.1 s (25 ticks of 4 ms) after RO[1] changes; a
 * change back before that restarts the time.
 */
class SimpleGripperTest {

  /** Ticks until RI[1] equals {@code want}, at most 100. */
  private static int ticksUntil(Simulation sim, Controller c, boolean want) {
    for (int k = 1; k <= 100; k++) {
      sim.step();
      if (c.registers().bit(IoKind.RI, 1) == want) {
        return k;
      }
    }
    return -1;
  }

  @Test
  void ri1FollowsRo1AfterTheActuationTimeBothWays() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    sim.step();
    assertThat(c.registers().bit(IoKind.RI, 1)).isFalse();
    c.registers().setBit(IoKind.RO, 1, true);
    assertThat(ticksUntil(sim, c, true)).isEqualTo(25);
    for (int k = 0; k < 10; k++) {
      sim.step();
      assertThat(c.registers().bit(IoKind.RI, 1)).isTrue();
    }
    c.registers().setBit(IoKind.RO, 1, false);
    assertThat(ticksUntil(sim, c, false)).isEqualTo(25);
    // ON for 10 ticks, then OFF again: the jaws never reported closed
    c.registers().setBit(IoKind.RO, 1, true);
    for (int k = 0; k < 10; k++) {
      sim.step();
    }
    c.registers().setBit(IoKind.RO, 1, false);
    for (int k = 0; k < 40; k++) {
      sim.step();
      assertThat(c.registers().bit(IoKind.RI, 1)).isFalse();
    }
    // ON again: a full 0.1 s from this change
    c.registers().setBit(IoKind.RO, 1, true);
    assertThat(ticksUntil(sim, c, true)).isEqualTo(25);
  }
}
