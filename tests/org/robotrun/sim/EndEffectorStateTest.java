package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.world.EndEffectorGeometry;
import org.robotrun.world.EndEffectorType;

/**
 * The end effector's own state against docs/scenario-format.md: the fingers (or vacuum) take
 * 0.1 s to close and as long to open; the fingers stop on a held part at its width plus 0.5 mm
 * clearance each side, never wider than open (70 mm); a glue gun's trace is made of 2 mm
 * segments, the last 2 000 kept; reset opens it, drops the part and clears the trace.
 */
class EndEffectorStateTest {
  private static final double TICK = 0.004;

  @Test
  void closingAndOpeningTakeTheActuationTimeEach() {
    EndEffectorState s = new EndEffectorState("robot1", EndEffectorGeometry.of(EndEffectorType.GRIPPER));
    assertThat(s.settled()).isTrue();
    assertThat(s.actuate(TICK)).isFalse(); // open and commanded open: nothing moves
    s.setOn(true);
    assertThat(s.settled()).isFalse();
    int ticks = 0;
    while (!s.settled()) {
      assertThat(s.actuate(TICK)).isTrue();
      ticks++;
      assertThat(s.closedFraction()).isCloseTo(Math.min(1, ticks * TICK / 0.1), within(1e-6));
    }
    assertThat(ticks * TICK).isCloseTo(0.1, within(1e-9));
    assertThat(s.closedFraction()).isEqualTo(1.0);
    assertThat(s.actuate(TICK)).isFalse();
    // closed on nothing: the fingers meet
    assertThat(s.fingerGapMm()).isZero();
    s.setOn(false);
    ticks = 0;
    while (!s.settled()) {
      s.actuate(TICK);
      ticks++;
    }
    assertThat(ticks * TICK).isCloseTo(0.1, within(1e-9));
    assertThat(s.fingerGapMm()).isEqualTo(EndEffectorGeometry.FINGER_OPEN_GAP_MM);
  }

  @Test
  void theFingersStopOnAHeldPartAtItsWidthPlusClearanceAndNeverOpenWiderThanOpen() {
    EndEffectorState s = new EndEffectorState("robot1", EndEffectorGeometry.of(EndEffectorType.GRIPPER));
    s.setOn(true);
    s.hold(new EndEffectorState.Held("box", Transform.IDENTITY, 40));
    for (int k = 0; k < 25; k++) {
      s.actuate(TICK);
    }
    assertThat(s.fingerGapMm()).isCloseTo(40 + 2 * 0.5, within(1e-9));
    // halfway closed: halfway between open and the part
    s.setOn(false);
    s.release();
    for (int k = 0; k < 12; k++) {
      s.actuate(TICK);
    }
    double f = s.closedFraction();
    assertThat(s.fingerGapMm()).isCloseTo(70 - f * (70 - 41), within(1e-9));
    for (int k = 0; k < 13; k++) {
      s.actuate(TICK);
    }
    assertThat(s.fingerGapMm()).isEqualTo(70.0);
    // once open with nothing held, a new close goes all the way
    s.setOn(true);
    for (int k = 0; k < 25; k++) {
      s.actuate(TICK);
    }
    assertThat(s.fingerGapMm()).isZero();
    // a part wider than the open fingers: they do not move at all
    EndEffectorState w = new EndEffectorState("robot1", EndEffectorGeometry.of(EndEffectorType.GRIPPER));
    w.setOn(true);
    w.hold(new EndEffectorState.Held("wide", Transform.IDENTITY, 90));
    for (int k = 0; k < 25; k++) {
      w.actuate(TICK);
    }
    assertThat(w.fingerGapMm()).isEqualTo(70.0);
  }

  @Test
  void aTraceIsMadeOfStepsOfAtLeastTwoMillimetresAndKeepsTheLastTwoThousand() {
    EndEffectorState s = new EndEffectorState("robot1", EndEffectorGeometry.of(EndEffectorType.GLUEGUN));
    s.setOn(true);
    s.extendTrace(new Vec3(0, 0, 0));
    assertThat(s.trace()).isEmpty();
    s.extendTrace(new Vec3(1.999, 0, 0));
    assertThat(s.trace()).isEmpty();
    s.extendTrace(new Vec3(2, 0, 0));
    assertThat(s.trace()).containsExactly(new EndEffectorState.TraceSegment(new Vec3(0, 0, 0), new Vec3(2, 0, 0)));
    s.extendTrace(new Vec3(3, 0, 0));
    s.extendTrace(new Vec3(4, 0, 0));
    assertThat(s.trace()).hasSize(2);
    assertThat(s.trace().get(1)).isEqualTo(new EndEffectorState.TraceSegment(new Vec3(2, 0, 0), new Vec3(4, 0, 0)));
    // switched off and on: the bead starts again where the gun is, not joined to the last one
    s.setOn(false);
    s.setOn(true);
    s.extendTrace(new Vec3(100, 0, 0));
    s.extendTrace(new Vec3(100, 3, 0));
    assertThat(s.trace().get(2)).isEqualTo(new EndEffectorState.TraceSegment(new Vec3(100, 0, 0), new Vec3(100, 3, 0)));
    for (int k = 0; k < 2100; k++) {
      s.extendTrace(new Vec3(100, 3 + 2 * (k + 1), 0));
    }
    assertThat(s.trace()).hasSize(EndEffectorState.MAX_TRACE_SEGMENTS);
    assertThat(s.trace().get(1999).to()).isEqualTo(new Vec3(100, 3 + 2 * 2100, 0));
    assertThat(s.trace().get(0).to()).isEqualTo(new Vec3(100, 3 + 2 * 101, 0));
    s.reset();
    assertThat(s.trace()).isEmpty();
    assertThat(s.held()).isEmpty();
    s.extendTrace(new Vec3(0, 0, 0));
    s.extendTrace(new Vec3(0, 0, 5));
    assertThat(s.trace()).containsExactly(new EndEffectorState.TraceSegment(new Vec3(0, 0, 0), new Vec3(0, 0, 5)));
  }

  @Test
  void resetDropsThePartAndTheFingersCloseFullyAgain() {
    EndEffectorState s = new EndEffectorState("robot1", EndEffectorGeometry.of(EndEffectorType.GRIPPER));
    s.setOn(true);
    s.hold(new EndEffectorState.Held("box", Transform.IDENTITY, 30));
    for (int k = 0; k < 25; k++) {
      s.actuate(TICK);
    }
    assertThat(s.fingerGapMm()).isCloseTo(31, within(1e-9));
    s.reset();
    assertThat(s.held()).isEmpty();
    assertThat(s.fingerGapMm()).isZero(); // still commanded closed, on nothing now
  }
}
