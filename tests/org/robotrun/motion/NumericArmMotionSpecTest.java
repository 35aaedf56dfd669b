package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.NumericSolver;
import org.robotrun.robot.RobotModel;

/**
 * An arm without a closed-form solver (an imported arm of unusual geometry; here the LR Mate with
 * its OPW parameters left out, so the numeric solver is chosen) moves by the same rules: an L move
 * blending (CNT) into a J move ends exactly on the J's target, the end of the L found by the
 * tracker instead of the closed form; and a circle bulging past the edge of reach stops with
 * MOTN-023, since without a closed form the runner cannot tell a point out of reach from a
 * singular one (docs/motion.md).
 */
class NumericArmMotionSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final Transform TOOL = MotionRunnerTest.TOOL;
  static final RobotModel M = MotionRunnerTest.MODEL;
  static final RobotModel NUMERIC = new RobotModel(M.id() + "-numeric", M.displayName(), M.joints(), M.X_6F(), M.X_WB(),
      M.links(), Optional.empty(), M.coupledJ3());
  static final MotionLimits LIMITS = MotionLimits.forModel(NUMERIC);

  @Test
  void theArmHasNoClosedForm() {
    assertThat(IkSolver.kindFor(NUMERIC)).isEqualTo(NumericSolver.KIND);
  }

  @Test
  void aLinearMoveBlendsIntoAJointMoveAndEndsOnItsTarget() {
    double[] home = MotionRunnerTest.HOME;
    double[] target = {-0.6, 0.2, -0.1, -0.3, Math.toRadians(-60), -0.5};
    Transform mid = MotionRunnerTest.tcp(home).withTranslation(350, 120, 40);
    MotionSequenceSpecTest.Clock clock = new MotionSequenceSpecTest.Clock();
    MotionRunner r = new MotionRunner(NUMERIC, LIMITS, home, clock);
    r.enqueue(new MoveRequest.Linear(mid, TOOL, Speed.mmPerSec(600), Termination.cnt(100), 1, 1));
    r.tick(DT);
    r.enqueue(new MoveRequest.Joint(target, Speed.percent(60), Termination.fine(), 1, 2));
    List<double[]> trace = MotionRunnerTest.run(r, 10_000);
    assertThat(clock.fault).isNull();
    assertThat(clock.events).containsExactly("start 1", "start 2", "end 1", "end 2");
    MotionSequenceSpecTest.withinJointSpeeds(trace);
    double[] last = trace.get(trace.size() - 1);
    for (int j = 0; j < 6; j++) {
      assertThat(last[j]).isCloseTo(target[j], offset(1e-6));
    }
  }

  @Test
  void aCircleBulgingPastTheReachStopsWithASingularityAlarm() {
    double xc = MotionReachSpecTest.edgeX() + 5 - MotionReachSpecTest.RADIUS;
    Transform start = MotionReachSpecTest.onCircle(xc, -70);
    double[] q0 = ((IkResult.Solved) MotionReachSpecTest.solve(start)).q();
    MotionSequenceSpecTest.Clock clock = new MotionSequenceSpecTest.Clock();
    MotionRunner r = new MotionRunner(NUMERIC, LIMITS, q0, clock);
    r.enqueue(new MoveRequest.Circular(MotionReachSpecTest.onCircle(xc, 50), MotionReachSpecTest.onCircle(xc, 70), TOOL,
        Speed.mmPerSec(300), Termination.fine(), 1, 5));
    MotionRunnerTest.run(r, 20_000);
    assertThat(clock.events).containsExactly("start 5", "fail 5");
    assertThat(clock.fault.kind()).isEqualTo(MotionFault.Kind.SINGULARITY);
    assertThat(clock.fault.message()).isEqualTo("the path passes too close to a singularity: joints would exceed their speed");
  }
}
