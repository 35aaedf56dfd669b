package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.robot.IkResult;

/**
 * MOTN-017 names the joint that would pass its limit, with the limits of the robot's data file
 * (resources/robots/lrmate200id.json: J3 −70..205° as the kinematic J3, which the pendant shows as
 * J2 + J3 with FANUC's coupled J3; J5 ±125°, 545 °/s), also when the joint is not J1 and the limit
 * is met in the middle of a path (docs/motion.md, "MOTN-017 a joint would pass its limit").
 */
class MotionLimitNamingSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final double J5_DEG_S = org.robotrun.DataSheet.maxSpeedsDegPerSec()[4];

  @Test
  void aJointTargetPastJ3sLimitNamesJ3AsThePendantShowsIt() {
    double[] q = MotionRunnerTest.HOME.clone();
    q[2] = Math.toRadians(210);
    MotionSequenceSpecTest.Clock clock = new MotionSequenceSpecTest.Clock();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, MotionRunnerTest.HOME, clock);
    r.enqueue(new MoveRequest.Joint(q, Speed.percent(50), Termination.fine(), 1, 3));
    r.tick(DT);
    assertThat(clock.events).containsExactly("fail 3");
    assertThat(clock.fault.kind()).isEqualTo(MotionFault.Kind.JOINT_LIMIT);
    assertThat(clock.fault.message())
        .isEqualTo("target J3 would reach 210.0 deg (J2 + J3 as the pendant shows them), outside its limits -70.0..205.0 deg");
    assertThat(r.joints()).isEqualTo(MotionRunnerTest.HOME);
  }

  @Test
  void aJointTargetPastJ5sLimitNamesJ5WithoutTheCouplingNote() {
    double[] q = MotionRunnerTest.HOME.clone();
    q[4] = Math.toRadians(-130);
    MotionSequenceSpecTest.Clock clock = new MotionSequenceSpecTest.Clock();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, MotionRunnerTest.HOME, clock);
    r.enqueue(new MoveRequest.Joint(q, Speed.percent(50), Termination.fine(), 1, 3));
    r.tick(DT);
    assertThat(clock.fault.message()).isEqualTo("target J5 would reach -130.0 deg, outside its limits -125.0..125.0 deg");
  }

  /**
   * Tool down at z = 300, the edge of what the arm can reach is J5's limit (the wrist bends back
   * to −125° before the arm is stretched): a circle through three points inside it that bulges
   * 5 mm past it stops in the middle with MOTN-017 for J5, at most one tick of J5's speed past −125°.
   */
  @Test
  void aCircleRunningJ5IntoItsLimitMidPathNamesJ5() {
    Transform down = MotionReachSpecTest.DOWN;
    double z = 300;
    double lo = 100;
    double hi = 1500;
    for (int i = 0; i < 60; i++) {
      double m = (lo + hi) / 2;
      if (MotionReachSpecTest.reachable(down.withTranslation(m, 0, z))) {
        lo = m;
      } else {
        hi = m;
      }
    }
    // Beyond the edge the solver says "joint limit", not "out of reach".
    IkResult beyond = MotionReachSpecTest.solve(down.withTranslation(lo + 1, 0, z));
    assertThat(((IkResult.Unreachable) beyond).reason()).isEqualTo(IkResult.Reason.JOINT_LIMIT);
    double xc = lo + 5 - 200;
    Transform start = down.withTranslation(xc + 200 * Math.cos(Math.toRadians(-70)), 200 * Math.sin(Math.toRadians(-70)), z);
    Transform via = down.withTranslation(xc + 200 * Math.cos(Math.toRadians(50)), 200 * Math.sin(Math.toRadians(50)), z);
    Transform end = down.withTranslation(xc + 200 * Math.cos(Math.toRadians(70)), 200 * Math.sin(Math.toRadians(70)), z);
    double[] q0 = ((IkResult.Solved) MotionReachSpecTest.solve(start)).q();
    MotionSequenceSpecTest.Clock clock = new MotionSequenceSpecTest.Clock();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, clock);
    r.enqueue(new MoveRequest.Circular(via, end, MotionRunnerTest.TOOL, Speed.mmPerSec(300), Termination.fine(), 1, 4));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);
    assertThat(clock.events).containsExactly("start 4", "fail 4");
    assertThat(clock.fault.kind()).isEqualTo(MotionFault.Kind.JOINT_LIMIT);
    Matcher m = Pattern.compile("J5 would reach (-[0-9.]+) deg, outside its limits -125.0..125.0 deg").matcher(clock.fault.message());
    assertThat(m.matches()).as(clock.fault.message()).isTrue();
    double shown = Double.parseDouble(m.group(1));
    assertThat(shown).isLessThanOrEqualTo(-124.95).isGreaterThanOrEqualTo(-125 - J5_DEG_S * DT);
    // The arm stayed inside the limit, on the circle, and got there (it moved a good part of the arc).
    double[] last = trace.get(trace.size() - 1);
    assertThat(Math.toDegrees(last[4])).isGreaterThanOrEqualTo(-125);
    Transform tcp = MotionRunnerTest.tcp(last);
    assertThat(Math.hypot(tcp.x() - xc, tcp.y())).isCloseTo(200, offset(0.01));
    assertThat(tcp.translationVector().distanceTo(start.translationVector())).isGreaterThan(100);
  }

  /**
   * A J move behind the arm (J1 150°) blending (CNT100) into an L: the L leads from the J's end,
   * found again from where the arm is, and ends on its target.
   */
  @Test
  void aLinearMoveBlendingOutOfALongJointMoveEndsOnItsTarget() {
    double[] far = {Math.toRadians(150), 0.2, -0.1, 0.4, Math.toRadians(-60), -0.3};
    Transform p = MotionRunnerTest.tcp(far);
    Transform end = p.withTranslation(p.x() + 60, p.y() - 60, p.z() - 40);
    MotionSequenceSpecTest.Run run = MotionSequenceSpecTest.run(MotionRunnerTest.HOME,
        new MoveRequest.Joint(far, Speed.percent(100), Termination.cnt(100), 1, 1),
        new MoveRequest.Linear(end, MotionRunnerTest.TOOL, Speed.mmPerSec(300), Termination.fine(), 1, 2));
    assertThat(run.clock().fault).isNull();
    assertThat(run.clock().events).containsExactly("start 1", "start 2", "end 1", "end 2");
    MotionSequenceSpecTest.withinJointSpeeds(run.trace());
    assertThat(MotionRunnerTest.tcp(run.trace().get(run.trace().size() - 1)).distanceTo(end)).isLessThan(0.01);
  }
}
