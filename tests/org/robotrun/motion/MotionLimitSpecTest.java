package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The faults docs/motion.md names for a path that cannot be followed, each met in the middle of
 * a move, and the J CNT → J corner: a joint limit reached on the way of an L move (MOTN-017), an
 * L move run straight into the wrist singularity (MOTN-023, refused before J5 comes within 1° of
 * 0), and two joint moves blended into one. Expected values come from the rules of
 * docs/motion.md and the LR Mate 200iD's data sheet (J1 ±170°, J5 ±125°, the speeds in
 * resources/robots/lrmate200id.json), not from a run.
 */
class MotionLimitSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final Transform TOOL = MotionRunnerTest.TOOL;
  /** J1's limit on the LR Mate 200iD's data sheet, degrees. */
  static final double J1_LIMIT_DEG = 170;

  static double[] deg(double... d) {
    double[] q = new double[d.length];
    for (int i = 0; i < d.length; i++) {
      q[i] = Math.toRadians(d[i]);
    }
    return q;
  }

  /**
   * Behind the arm, 20° either side of J1 = ±180°: the straight line between the two points
   * passes J1 = 180°, so a J1 that follows it must pass +170°. The line is reachable all along
   * (the chord's middle is cos 20° of the radius out), the end point is reachable from the other
   * side, so the only obstacle is J1's limit on the way.
   */
  @Test
  void linearMoveThatWouldTakeJ1PastItsLimitStopsAtTheLimitNamingJ1() {
    double[] q0 = deg(160, 10, -10, 0, -80, 0);
    double[] qEnd = deg(-160, 10, -10, 0, -80, 0);
    Transform end = MotionRunnerTest.tcp(qEnd);
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, rec);
    r.enqueue(new MoveRequest.Linear(end, TOOL, Speed.mmPerSec(300), Termination.fine(), 1, 7));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);

    assertThat(rec.events).containsExactly("start 7", "fail 7");
    assertThat(rec.fault.kind()).isEqualTo(MotionFault.Kind.JOINT_LIMIT);
    // "J1 would reach <value> deg, outside its limits -170.0..170.0 deg": the value is where the
    // refused tick would have put J1, just past the limit (at most one tick at J1's top speed).
    Matcher m = Pattern.compile("J1 would reach (-?[0-9.]+) deg, outside its limits -170\\.0\\.\\.170\\.0 deg")
        .matcher(rec.fault.message());
    assertThat(m.matches()).as(rec.fault.message()).isTrue();
    double reach = Double.parseDouble(m.group(1));
    double oneTickDeg = 450 * DT; // J1: 450 deg/s on the data sheet
    assertThat(reach).isGreaterThan(J1_LIMIT_DEG).isLessThanOrEqualTo(J1_LIMIT_DEG + oneTickDeg + 0.05);
    // The arm stopped where it was, inside the limit and close to it, on the line.
    double[] last = trace.get(trace.size() - 1);
    assertThat(Math.toDegrees(last[0])).isLessThanOrEqualTo(J1_LIMIT_DEG).isGreaterThan(J1_LIMIT_DEG - oneTickDeg);
    for (double[] q : trace) {
      assertThat(Math.toDegrees(q[0])).isLessThanOrEqualTo(J1_LIMIT_DEG);
    }
    Transform start = MotionRunnerTest.tcp(q0);
    assertThat(distanceToLine(MotionRunnerTest.tcp(last).translationVector(), start.translationVector(),
        end.translationVector())).isLessThan(0.01);
    assertThat(r.idle()).isTrue();
  }

  /** The same move the other way round: J1 runs into its lower limit, and the message says so. */
  @Test
  void theLowerLimitIsNamedWithTheValueBeyondIt() {
    double[] q0 = deg(-160, 10, -10, 0, -80, 0);
    Transform end = MotionRunnerTest.tcp(deg(160, 10, -10, 0, -80, 0));
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, rec);
    r.enqueue(new MoveRequest.Linear(end, TOOL, Speed.mmPerSec(300), Termination.fine(), 1, 8));
    MotionRunnerTest.run(r, 20_000);
    assertThat(rec.fault.kind()).isEqualTo(MotionFault.Kind.JOINT_LIMIT);
    Matcher m = Pattern.compile("J1 would reach (-[0-9.]+) deg, outside its limits -170\\.0\\.\\.170\\.0 deg")
        .matcher(rec.fault.message());
    assertThat(m.matches()).as(rec.fault.message()).isTrue();
    assertThat(Double.parseDouble(m.group(1))).isLessThan(-J1_LIMIT_DEG).isGreaterThan(-J1_LIMIT_DEG - 450 * DT - 0.05);
  }

  /**
   * An L move whose end has the wrist straight (J5 = 0, J4 and J6 in line): the move is refused
   * with the wrist-singularity alarm as J5 would come within 1° of 0, at once (not after a 0.5 s
   * crawl), and J5 never gets closer than 1°.
   */
  @Test
  void linearMoveIntoTheWristSingularityIsRefusedAsJ5ComesWithinOneDegree() {
    double[] q0 = deg(0, 10, -20, 0, -25, 0);
    double[] qStraight = deg(0, 10, -20, 0, 0, 0);
    Transform end = MotionRunnerTest.tcp(qStraight);
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, rec);
    r.enqueue(new MoveRequest.Linear(end, TOOL, Speed.mmPerSec(100), Termination.fine(), 1, 9));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);

    assertThat(rec.events).containsExactly("start 9", "fail 9");
    assertThat(rec.fault.kind()).isEqualTo(MotionFault.Kind.SINGULARITY);
    double[] last = trace.get(trace.size() - 1);
    double lastJ5 = Math.toDegrees(last[4]);
    assertThat(rec.fault.message()).startsWith("wrist singularity: J4 and J6 line up (J5 = "
        + String.format(Locale.ROOT, "%.1f", lastJ5) + " deg)");
    // Never within 1° of 0; stopped at that edge (the last tick moved J5 by well under 0.5°).
    for (double[] q : trace) {
      assertThat(Math.abs(Math.toDegrees(q[4]))).isGreaterThanOrEqualTo(1);
    }
    assertThat(Math.abs(lastJ5)).isLessThan(1.5);
    // Refused at once: in the last tick it took (the refused tick leaves the arm where it was) it
    // still moved faster than 5 % of the path's speed (a stall would crawl below that for 0.5 s).
    assertThat(trace.get(trace.size() - 2)).isEqualTo(last);
    Transform a = MotionRunnerTest.tcp(trace.get(trace.size() - 3));
    Transform b = MotionRunnerTest.tcp(last);
    double lastSpeed = a.translationVector().distanceTo(b.translationVector()) / DT;
    assertThat(lastSpeed).isGreaterThan(0.05 * 100);
  }

  /** The same line stopped short of the wrist singularity by a FINE end 3° away completes normally. */
  @Test
  void theSameLineEndingThreeDegreesShortOfTheSingularityCompletes() {
    double[] q0 = deg(0, 10, -20, 0, -25, 0);
    Transform end = MotionRunnerTest.tcp(deg(0, 10, -20, 0, -3, 0));
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, rec);
    r.enqueue(new MoveRequest.Linear(end, TOOL, Speed.mmPerSec(100), Termination.fine(), 1, 10));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);
    assertThat(rec.events).containsExactly("start 10", "end 10");
    assertThat(MotionRunnerTest.tcp(trace.get(trace.size() - 1)).distanceTo(end)).isLessThan(0.01);
  }

  /**
   * J CNT100 → J: the second joint move starts during the first one's deceleration and the two
   * add up (docs/motion.md, CNT); after the first ends, the arm goes on from where the first put
   * it, ends exactly on the second target, never stops at the corner and never outruns a joint.
   */
  @Test
  void twoJointMovesBlendIntoOneAndEndOnTheSecondTarget() {
    double[] home = MotionRunnerTest.HOME;
    double[] via = deg(40, 20, -15, 30, -60, 45);
    double[] target = deg(-30, 35, 10, -20, -100, -60);
    BlendAndFaultTest.Run cnt = BlendAndFaultTest.pair(
        new MoveRequest.Joint(via, Speed.percent(70), Termination.cnt(100), 1, 1),
        new MoveRequest.Joint(target, Speed.percent(70), Termination.fine(), 1, 2), home);
    BlendAndFaultTest.Run fine = BlendAndFaultTest.pair(
        new MoveRequest.Joint(via, Speed.percent(70), Termination.fine(), 1, 1),
        new MoveRequest.Joint(target, Speed.percent(70), Termination.fine(), 1, 2), home);
    assertThat(cnt.rec().fault).isNull();
    assertThat(cnt.rec().events).containsExactly("start 1", "start 2", "end 1", "end 2");
    List<double[]> t = cnt.trace();
    double[] last = t.get(t.size() - 1);
    for (int j = 0; j < 6; j++) {
      assertThat(last[j]).isCloseTo(target[j], offset(1e-9));
    }
    // Joint space is the blend's space: every tick within each joint's data-sheet speed, and at
    // no tick between start and end are all joints at rest.
    double slowest = Double.MAX_VALUE;
    for (int k = 1; k < t.size(); k++) {
      double fastest = 0;
      for (int j = 0; j < 6; j++) {
        double v = Math.abs(t.get(k)[j] - t.get(k - 1)[j]) / DT;
        assertThat(v).isLessThanOrEqualTo(MotionRunnerTest.LIMITS.jointSpeed(j) * (1 + 1e-6));
        fastest = Math.max(fastest, v / MotionRunnerTest.LIMITS.jointSpeed(j));
      }
      if (k > 5 && k < t.size() - 5) {
        slowest = Math.min(slowest, fastest);
      }
    }
    assertThat(slowest).isGreaterThan(0.05);
    // Blending saves time over stopping at the via point.
    assertThat(t.size()).isLessThan(fine.trace().size() - 20);
  }

  /**
   * A J CNT → J corner on one joint only, where the sum is known in closed form: J1 goes 0 → 40° →
   * 80°. Each move's displacement is added to where the first started, so the joints at every
   * tick stay on the segment between the start and the final target (J2..J6 never move).
   */
  @Test
  void aBlendOfTwoMovesOfTheSameJointStaysBetweenTheirEnds() {
    double[] home = MotionRunnerTest.HOME;
    double[] via = home.clone();
    via[0] = Math.toRadians(40);
    double[] target = home.clone();
    target[0] = Math.toRadians(80);
    BlendAndFaultTest.Run cnt = BlendAndFaultTest.pair(
        new MoveRequest.Joint(via, Speed.percent(50), Termination.cnt(100), 1, 1),
        new MoveRequest.Joint(target, Speed.percent(50), Termination.fine(), 1, 2), home);
    assertThat(cnt.rec().events).containsExactly("start 1", "start 2", "end 1", "end 2");
    double prev = home[0];
    for (double[] q : cnt.trace()) {
      assertThat(q[0]).isBetween(prev - 1e-12, target[0] + 1e-12);
      prev = q[0];
      for (int j = 1; j < 6; j++) {
        assertThat(q[j]).isEqualTo(home[j]);
      }
    }
    assertThat(prev).isCloseTo(target[0], offset(1e-12));
  }

  /**
   * Joint targets outside the limits are refused before the arm moves (docs/motion.md); a target
   * exactly on a limit is inside (a JOINT jog comes to rest exactly there, and that position must
   * run). J1, the first joint, both ways.
   */
  @Test
  void aJointTargetOnJ1sLimitRunsAndOneBeyondIsRefusedBeforeMoving() {
    for (double limit : new double[] {MotionRunnerTest.MODEL.joint(0).upperRad(), MotionRunnerTest.MODEL.joint(0).lowerRad()}) {
      double[] on = MotionRunnerTest.HOME.clone();
      on[0] = limit;
      MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
      MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, MotionRunnerTest.HOME, rec);
      r.enqueue(new MoveRequest.Joint(on, Speed.percent(100), Termination.fine(), 1, 1));
      List<double[]> trace = MotionRunnerTest.run(r, 20_000);
      assertThat(rec.events).containsExactly("start 1", "end 1");
      assertThat(trace.get(trace.size() - 1)[0]).isEqualTo(limit);

      double[] beyond = MotionRunnerTest.HOME.clone();
      beyond[0] = limit + Math.signum(limit) * Math.toRadians(5);
      MotionRunnerTest.Recorder rec2 = new MotionRunnerTest.Recorder();
      MotionRunner r2 = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, MotionRunnerTest.HOME, rec2);
      r2.enqueue(new MoveRequest.Joint(beyond, Speed.percent(100), Termination.fine(), 1, 2));
      List<double[]> trace2 = MotionRunnerTest.run(r2, 20_000);
      assertThat(rec2.events).containsExactly("fail 2");
      assertThat(rec2.fault.kind()).isEqualTo(MotionFault.Kind.JOINT_LIMIT);
      assertThat(rec2.fault.message()).isEqualTo(String.format(Locale.ROOT,
          "target J1 would reach %.1f deg, outside its limits -170.0..170.0 deg", Math.signum(limit) * 175));
      for (double[] q : trace2) {
        assertThat(q).isEqualTo(MotionRunnerTest.HOME);
      }
    }
  }

  static double distanceToLine(Vec3 p, Vec3 a, Vec3 b) {
    Vec3 d = b.minus(a);
    double u = p.minus(a).dot(d) / d.dot(d);
    return p.distanceTo(a.plus(d.times(u)));
  }
}
