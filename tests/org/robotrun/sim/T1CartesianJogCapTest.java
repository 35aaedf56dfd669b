package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.math.Vec3;
import org.robotrun.motion.JogState;

/**
 * T1 and a jog of two Cartesian axes at once (found moving the pendant tests to the real
 * controller, issue 23). X and Y each at 250 mm/s ask the TCP for 354 mm/s; T1 allows 250
 * (docs/motion.md, "Jog"). The controller used to shorten each tick after the jogger had moved its
 * desired pose the full way, so the desired pose ran ahead of the arm by ~100 mm a second: the
 * TCP sped up to 254 mm/s, left its line, stopped "at the edge of reach" far inside it, and would
 * have gone on moving after the keys were let go. Now the jog itself keeps to the cap.
 */
class T1CartesianJogCapTest {
  private static final double TICK = 0.004;

  @Test
  void aDiagonalWorldJogInT1KeepsTheCapAndItsLineAndStopsWithItsKeys() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.setMode(RobotControl.Mode.T1);
    c.setDeadman(true);
    c.setOverridePct(100);
    c.setCoordSystem(RobotControl.CoordSystem.WORLD);
    for (int i = 0; i < 100; i++) {
      sim.step(); // the override ramps to 100 %
    }
    Vec3 start = c.tcpInWorld().position();
    Vec3 startFlange = c.flangeInWorld();
    assertThat(c.jogKeyDown(1, +1, JogState.Press.HELD)).isInstanceOf(RobotControl.Result.Ok.class);
    assertThat(c.jogKeyDown(2, +1, JogState.Press.HELD)).isInstanceOf(RobotControl.Result.Ok.class);
    Vec3 prev = start;
    Vec3 prevFlange = startFlange;
    double fastest = 0;
    double last = 0;
    for (int i = 0; i < 250; i++) { // 1 s held: 250 mm at most, well inside the reach
      sim.step();
      Vec3 p = c.tcpInWorld().position();
      Vec3 f = c.flangeInWorld();
      last = p.distanceTo(prev) / TICK;
      fastest = Math.max(fastest, Math.max(last, f.distanceTo(prevFlange) / TICK));
      prev = p;
      prevFlange = f;
      // on its line: X and Y move alike, Z stays (docs/motion.md: the TCP does not drift off the axis)
      assertThat(p.x() - start.x()).as("tick %d", i).isCloseTo(p.y() - start.y(), offset(0.01));
      assertThat(p.z()).as("tick %d", i).isCloseTo(start.z(), offset(0.01));
    }
    assertThat(c.jogMessage()).isEmpty();
    assertThat(fastest).isLessThanOrEqualTo(250 + 1e-6);
    assertThat(last).isGreaterThan(249);
    // let go: it ramps down within 0.1 s (and a tick) and stands
    c.jogKeyUp(1, +1);
    c.jogKeyUp(2, +1);
    for (int i = 0; i < 26; i++) {
      sim.step();
    }
    Vec3 stopped = c.tcpInWorld().position();
    for (int i = 0; i < 50; i++) {
      sim.step();
    }
    assertThat(c.tcpInWorld().position().distanceTo(stopped)).isLessThan(1e-9);
  }
}
