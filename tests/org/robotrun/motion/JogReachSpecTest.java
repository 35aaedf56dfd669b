package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.robot.IkResult;

/**
 * A WORLD jog out to the edge of reach (docs/motion.md, Jog: near a singularity a Cartesian jog
 * slows down rather than outrun a joint, and stops itself with a message when it would have to
 * crawl below 5 % of its speed, never with a jump). The arm stretches as the TCP goes out along
 * WORLD +X at the tool-down height of {@link MotionReachSpecTest}; the edge is found by bisection
 * with the arm's solver. The jog keeps its line, slows below 250 mm/s as the elbow straightens,
 * and stops with "stopped: singularity or edge of reach" within reach and within a millimetre of
 * the edge; the key goes off.
 */
class JogReachSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final Transform TOOL = MotionRunnerTest.TOOL;

  @Test
  void aWorldJogOutToTheEdgeOfReachSlowsAndStopsThereWithAMessage() {
    double edge = MotionReachSpecTest.edgeX();
    Transform start = MotionReachSpecTest.DOWN.withTranslation(edge - 60, 0, MotionReachSpecTest.Z);
    double[] q = ((IkResult.Solved) MotionReachSpecTest.solve(start)).q();
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    JogState keys = new JogState();
    keys.keyDown(0, +1, JogState.Press.HELD);
    JogResult r = new JogResult.Moving();
    List<double[]> trace = new ArrayList<>();
    trace.add(q.clone());
    for (int k = 0; k < 5_000 && r instanceof JogResult.Moving; k++) {
      r = jog.tick(q, keys, JogFrame.WORLD, 1, TOOL, Transform.IDENTITY, DT);
      trace.add(q.clone());
    }
    assertThat(r).isInstanceOf(JogResult.Stopped.class);
    assertThat(((JogResult.Stopped) r).message()).isEqualTo("stopped: singularity or edge of reach");
    assertThat(keys.anyOn()).isFalse();
    MotionSequenceSpecTest.withinJointSpeeds(trace);
    double fastest = 0;
    for (int k = 1; k < trace.size(); k++) {
      Transform p = MotionRunnerTest.tcp(trace.get(k));
      // On its line: y, z and the orientation unchanged.
      assertThat(p.y()).isCloseTo(0, offset(0.01));
      assertThat(p.z()).isCloseTo(MotionReachSpecTest.Z, offset(0.01));
      assertThat(p.rotationAngleTo(start)).isLessThan(1e-4);
      double v = p.distanceTo(MotionRunnerTest.tcp(trace.get(k - 1))) / DT;
      // 250 mm/s, give or take the jog tracker's 0.001 mm a tick at each end of the step (0.5 mm/s).
      assertThat(v).isLessThanOrEqualTo(250.5);
      fastest = Math.max(fastest, v);
    }
    // It got up to 250 mm/s (0.1 s ramp, 60 mm of room), then slowed: the last tick crawled.
    assertThat(fastest).isGreaterThan(249);
    int n = trace.size();
    double last = MotionRunnerTest.tcp(trace.get(n - 1)).distanceTo(MotionRunnerTest.tcp(trace.get(n - 2))) / DT;
    assertThat(last).isLessThan(0.5 * 250);
    double x = MotionRunnerTest.tcp(q).x();
    assertThat(x).isLessThanOrEqualTo(edge + 1e-6).isGreaterThan(edge - 1);
  }
}
