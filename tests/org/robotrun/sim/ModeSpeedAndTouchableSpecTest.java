package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Set;
import org.junit.jupiter.api.Test;
import org.robotrun.collision.Body;
import org.robotrun.collision.StandardPairFilter;
import org.robotrun.control.RobotControl;

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
    double fastestOnAB = MotionTimingSpecTest.runAToB(RobotControl.Mode.T2).fastestOnAB();
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
