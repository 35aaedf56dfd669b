package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.robotrun.collision.Body;
import org.robotrun.collision.StandardPairFilter;
import org.robotrun.control.RobotControl;
import org.robotrun.math.Vec3;

/**
 * Two rules a planted one-line fault broke without a test noticing:
 * <ul>
 *   <li>only T1 caps the TCP at 250 mm/s (docs/motion.md; the R-30iB's T2 runs a program at its
 *       programmed speed, hold-to-run only): a 1000 mm/sec L move in T2 goes faster than 250 mm/s;
 *   <li>a touchable object is exempt only from the end effector, link 7 (docs/collision.md); link 6
 *       (the flange) still collides with it.
 * </ul>
 */
class ModeSpeedAndTouchableSpecTest {
  static final double TICK = Simulation.DEFAULT_TICK_SEC;

  @Test
  void t2RunsAProgramAtItsProgrammedSpeedAboveTheT1Cap() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(MotionTimingSpecTest.program("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE", "L P[3:B] 1000mm/sec FINE"));
    c.setMode(RobotControl.Mode.T2);
    c.setDeadman(true);
    List<Vec3> tcp = new ArrayList<>();
    List<Integer> lines = new ArrayList<>();
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "TIMING", 60, s -> {
      tcp.add(c.tcpInWorld().position());
      lines.add(c.status().line());
    });
    assertThat(r.status()).as(r.alarm().map(ControllerAlarm::display).orElse("")).isEqualTo(HeadlessRun.Status.FINISHED);
    double fastestOnAB = 0;
    for (int i = 1; i < tcp.size(); i++) {
      if (lines.get(i) == 3) {
        fastestOnAB = Math.max(fastestOnAB, tcp.get(i).distanceTo(tcp.get(i - 1)) / TICK);
      }
    }
    // 270 mm at 1000 mm/s with a 0.2 s ramp (5000 mm/s²) peaks at sqrt(270 · 5000) = 1162 > 1000: it cruises at 1000
    assertThat(fastestOnAB).isGreaterThan(990).isLessThanOrEqualTo(1000 + 1e-6);
  }

  @Test
  void aTouchableObjectIsExemptFromTheEndEffectorOnly() {
    CellPairFilter f = new CellPairFilter(StandardPairFilter.nothingHeld(), Set.of("marker"));
    Body marker = Body.fixture("marker", "marker");
    assertThat(f.mayCollide(Body.robotLink("robot1", Body.TOOL_LINK, "tool"), marker)).isFalse();
    assertThat(f.mayCollide(marker, Body.robotLink("robot1", Body.TOOL_LINK, "tool"))).isFalse();
    for (int link = 1; link <= 6; link++) {
      assertThat(f.mayCollide(Body.robotLink("robot1", link, "l" + link), marker)).as("link %d", link).isTrue();
      assertThat(f.mayCollide(marker, Body.robotLink("robot1", link, "l" + link))).as("link %d", link).isTrue();
    }
  }
}
