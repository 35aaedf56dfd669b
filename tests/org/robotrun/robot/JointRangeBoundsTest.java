package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;

/**
 * {@link JointRange} at its edges, as its comments state: a value counts as inside when it lies
 * inside the limits or outside by no more than {@link JointRange#SLACK} (so exactly SLACK outside
 * is still inside, on either side, and a hair more is not); {@code intoLimits} takes q itself or
 * the one ±2π variant that lies inside, also for a joint whose range does not hold 0 (a joint
 * at exactly 0 must then take +2π, the only variant inside); {@code nearestTurn} gives the variant
 * nearest the reference inside the limits, or the one turn further that is inside.
 */
class JointRangeBoundsTest {
  private static final double TWO_PI = 2 * Math.PI;

  /** The default arm with joint i's limits replaced. */
  static RobotModel withLimits(int i, double lower, double upper) {
    RobotModel m = RobotDefinitions.defaultRobot();
    List<JointSpec> js = new ArrayList<>(m.joints());
    JointSpec j = js.get(i);
    js.set(i, new JointSpec(j.name(), j.X_PJ(), j.axis(), lower, upper, j.maxSpeedRadPerSec()));
    return new RobotModel(m.id(), m.displayName(), js, m.X_6F(), m.X_WB(), m.links(), m.opw(), m.coupledJ3());
  }

  @Test
  void exactlyTheSlackOutsideEitherLimitIsInsideAndAnyMoreIsNot() {
    RobotModel m = RobotDefinitions.defaultRobot();
    JointRange r = new JointRange(m);
    for (int i = 0; i < 6; i++) {
      double lo = m.joint(i).lowerRad(), hi = m.joint(i).upperRad();
      // The same arithmetic as the stated rule: lower − SLACK and upper + SLACK are the edges.
      double loEdge = lo - JointRange.SLACK, hiEdge = hi + JointRange.SLACK;
      assertThat(r.ok(loEdge, i)).as("J%d at lower − SLACK", i + 1).isTrue();
      assertThat(r.ok(hiEdge, i)).as("J%d at upper + SLACK", i + 1).isTrue();
      assertThat(r.ok(Math.nextDown(loEdge), i)).as("J%d just below lower − SLACK", i + 1).isFalse();
      assertThat(r.ok(Math.nextUp(hiEdge), i)).as("J%d just above upper + SLACK", i + 1).isFalse();
      assertThat(r.ok(lo - 0.5 * JointRange.SLACK, i)).as("J%d half the slack below", i + 1).isTrue();
      assertThat(r.ok(lo - 2 * JointRange.SLACK, i)).as("J%d twice the slack below", i + 1).isFalse();
      // Clamped onto the limit it is outside of, on either side.
      assertThat(r.clamp(loEdge, i)).isEqualTo(lo);
      assertThat(r.clamp(hiEdge, i)).isEqualTo(hi);
      assertThat(r.lower(i)).isEqualTo(lo);
      assertThat(r.upper(i)).isEqualTo(hi);
      double[] q = new double[6];
      q[i] = loEdge;
      assertThat(r.firstOutside(q)).as("J%d at the lower edge", i + 1).isEqualTo(-1);
      q[i] = Math.nextDown(loEdge);
      assertThat(r.firstOutside(q)).as("J%d past the lower edge", i + 1).isEqualTo(i);
    }
  }

  @Test
  void aJointAtZeroWhoseRangeDoesNotHoldZeroTakesTheTurnAbove() {
    // J6 limited to 30°..370°: 0 is outside, 0 + 360° inside; -10° is outside, +350° inside;
    // +10° is outside and so is 10° − 360°: left as it is.
    JointRange r = new JointRange(withLimits(5, Math.toRadians(30), Math.toRadians(370)));
    assertThat(r.intoLimits(0, 5)).isEqualTo(TWO_PI);
    assertThat(r.intoLimits(Math.toRadians(-10), 5)).isCloseTo(Math.toRadians(350), org.assertj.core.data.Offset.offset(1e-12));
    assertThat(r.intoLimits(Math.toRadians(10), 5)).isEqualTo(Math.toRadians(10));
    // And below: -370°..-30°: +10° takes -350°.
    JointRange n = new JointRange(withLimits(5, Math.toRadians(-370), Math.toRadians(-30)));
    assertThat(n.intoLimits(Math.toRadians(10), 5)).isCloseTo(Math.toRadians(-350), org.assertj.core.data.Offset.offset(1e-12));
    // A value a round-off outside the upper limit, whose other turn is far outside: onto the limit.
    double hi = Math.toRadians(-30);
    assertThat(n.intoLimits(hi + 0.5 * JointRange.SLACK, 5)).isEqualTo(hi);
  }

  @Test
  void theNearestTurnPrefersTheReferenceSideAndFallsBackOneTurnEitherWay() {
    // J6 from -100° to 500°: for q = 170° and a reference at 480°, the turn nearest the reference is
    // 530° (outside), so the one turn below, 170°, is taken; for a reference at -95° the nearest
    // turn is -190° (outside), so the turn above, 170°, is taken.
    JointRange r = new JointRange(withLimits(5, Math.toRadians(-100), Math.toRadians(500)));
    double q = Math.toRadians(170);
    assertThat(r.nearestTurn(q, Math.toRadians(480), 5)).isCloseTo(q, org.assertj.core.data.Offset.offset(1e-12));
    assertThat(r.nearestTurn(q, Math.toRadians(-95), 5)).isCloseTo(q, org.assertj.core.data.Offset.offset(1e-12));
    // Inside: the variant nearest the reference, turns included.
    double p = Math.toRadians(100);
    assertThat(r.nearestTurn(p, Math.toRadians(400), 5)).isCloseTo(p + TWO_PI, org.assertj.core.data.Offset.offset(1e-12));
    assertThat(r.nearestTurn(q - TWO_PI, Math.toRadians(200), 5)).isCloseTo(q, org.assertj.core.data.Offset.offset(1e-12));
  }

  @Test
  void theTurnsInsideAWideRangeAreCountedFromBothLimits() {
    // J6 at ±1080° (three turns): 0 has the variants -3..3 turns, 0.3 rad -3..2, -0.3 rad -2..3;
    // with limits 30°..370°, 0 has only the turn +1 and 15° none (first above last).
    JointRange r = new JointRange(withLimits(5, Math.toRadians(-1080), Math.toRadians(1080)));
    assertThat(new int[] {r.firstTurn(0, 5), r.lastTurn(0, 5)}).containsExactly(-3, 3);
    assertThat(new int[] {r.firstTurn(0.3, 5), r.lastTurn(0.3, 5)}).containsExactly(-3, 2);
    assertThat(new int[] {r.firstTurn(-0.3, 5), r.lastTurn(-0.3, 5)}).containsExactly(-2, 3);
    // A value a round-off beyond a limit still has that turn (the limit's slack).
    double hi = Math.toRadians(1080);
    assertThat(r.lastTurn(hi + 0.5 * JointRange.SLACK - TWO_PI, 5)).isEqualTo(1);
    assertThat(r.lastTurn(hi + 2 * JointRange.SLACK - TWO_PI, 5)).isEqualTo(0);
    JointRange n = new JointRange(withLimits(5, Math.toRadians(30), Math.toRadians(370)));
    assertThat(new int[] {n.firstTurn(0, 5), n.lastTurn(0, 5)}).containsExactly(1, 1);
    assertThat(n.firstTurn(Math.toRadians(15), 5)).isGreaterThan(n.lastTurn(Math.toRadians(15), 5));
  }
}
