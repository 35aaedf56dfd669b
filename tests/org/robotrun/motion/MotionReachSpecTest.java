package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.IkSolver;

/**
 * MOTN-018 in the middle of a path (docs/alarms.md: "the target, or a point of the straight or
 * circular path, is out of the arm's reach"). A circular move whose start, via point and end are
 * all within reach but whose arc bulges past the edge of reach runs until the arm, stretched at
 * that edge, can go no further, and stops with MOTN-018 naming a point of the arc beyond the edge,
 * not with MOTN-023: near the edge the stretched elbow slows the path to a crawl first (the edge of
 * reach is itself a singular posture), and the runner then looks ahead on the path for the point
 * that cannot be reached. The edge is found here by bisection with the arm's own solver (tested in
 * the robot package against independent forward kinematics), along WORLD x at the arc's height,
 * with the tool pointing down.
 */
class MotionReachSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final Transform TOOL = MotionRunnerTest.TOOL;
  static final IkSolver IK = IkSolver.forModel(MotionRunnerTest.MODEL);
  static final Transform DOWN = MotionRunnerTest.tcp(MotionRunnerTest.HOME);
  static final double Z = 100;
  static final double RADIUS = 200;

  static IkResult solve(Transform X_WT) {
    Transform X_BF = MotionRunnerTest.MODEL.X_WB().inverse().compose(X_WT).compose(TOOL.inverse());
    return IK.solveNearest(X_BF, MotionRunnerTest.HOME);
  }

  static boolean reachable(Transform X_WT) {
    return solve(X_WT) instanceof IkResult.Solved;
  }

  /** The farthest reachable x on WORLD x at height Z, tool down. */
  static double edgeX() {
    double lo = 100;
    double hi = 1500;
    for (int i = 0; i < 60; i++) {
      double m = (lo + hi) / 2;
      if (reachable(DOWN.withTranslation(m, 0, Z))) {
        lo = m;
      } else {
        hi = m;
      }
    }
    return lo;
  }

  static Transform onCircle(double xc, double deg) {
    return DOWN.withTranslation(xc + RADIUS * Math.cos(Math.toRadians(deg)), RADIUS * Math.sin(Math.toRadians(deg)), Z);
  }

  record Outcome(MotionRunnerTest.Recorder rec, List<double[]> trace, double xc) {}

  /** C from −70° via +50° to +70° on a circle of radius 200 whose far point (0°) lies {@code bulgeMm} past the edge. */
  static Outcome arc(double bulgeMm) {
    double xc = edgeX() + bulgeMm - RADIUS;
    Transform start = onCircle(xc, -70);
    Transform via = onCircle(xc, 50);
    Transform end = onCircle(xc, 70);
    assertThat(reachable(start) && reachable(via) && reachable(end)).as("start, via and end within reach").isTrue();
    double[] q0 = ((IkResult.Solved) solve(start)).q();
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, rec);
    r.enqueue(new MoveRequest.Circular(via, end, TOOL, Speed.mmPerSec(300), Termination.fine(), 1, 5));
    return new Outcome(rec, MotionRunnerTest.run(r, 20_000), xc);
  }

  @Test
  void anArcBulgingPastTheReachStopsWithMotn018AtThePointWhereItLeaves() {
    for (double bulge : new double[] {2, 20}) {
      Outcome o = arc(bulge);
      assertThat(o.rec().events).as("bulge %s mm", bulge).containsExactly("start 5", "fail 5");
      assertThat(o.rec().fault.kind()).as(o.rec().fault.message()).isEqualTo(MotionFault.Kind.OUT_OF_REACH);
      Matcher m = Pattern.compile("the path leaves the arm's reach at \\((-?[0-9.]+), (-?[0-9.]+), (-?[0-9.]+)\\) mm")
          .matcher(o.rec().fault.message());
      assertThat(m.matches()).as(o.rec().fault.message()).isTrue();
      Vec3 named = new Vec3(Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2)), Double.parseDouble(m.group(3)));
      // The named point is on the arc, still on the way to its far point (y < 0), and out of reach.
      assertThat(Math.hypot(named.x() - o.xc(), named.y())).isCloseTo(RADIUS, offset(0.1));
      assertThat(named.z()).isCloseTo(Z, offset(0.1));
      assertThat(named.y()).isNegative();
      assertThat(reachable(DOWN.withTranslation(named.x(), named.y(), named.z()))).isFalse();
      // The arm stopped on the arc, before that point, within reach, and never went faster than its joints allow.
      Transform last = MotionRunnerTest.tcp(o.trace().get(o.trace().size() - 1));
      assertThat(Math.hypot(last.x() - o.xc(), last.y())).isCloseTo(RADIUS, offset(0.01));
      assertThat(last.z()).isCloseTo(Z, offset(0.01));
      assertThat(last.y()).isLessThan(named.y());
      assertThat(last.translationVector().distanceTo(named)).isLessThan(5);
      MotionSequenceSpecTest.withinJointSpeeds(o.trace());
    }
  }

  @Test
  void theSameArcInsideTheReachRunsThrough() {
    Outcome o = arc(-40);
    assertThat(o.rec().fault).isNull();
    assertThat(o.rec().events).containsExactly("start 5", "end 5");
    Transform last = MotionRunnerTest.tcp(o.trace().get(o.trace().size() - 1));
    assertThat(last.translationVector().distanceTo(onCircle(o.xc(), 70).translationVector())).isLessThan(0.01);
  }
}
