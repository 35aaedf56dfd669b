package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

/**
 * How consecutive moves follow each other (docs/motion.md, "Ending a move: FINE and CNT"), with
 * every time computed here from the LR Mate 200iD's data sheet (J1 450 °/s, reached in 0.25 s,
 * so 1800 °/s²) and the 4 ms tick:
 *
 * <ul>
 *   <li>a move queued behind a FINE move is taken the tick the arm arrives: it is reported started
 *       at the instant its predecessor is reported finished, and loses no tick;
 *   <li>a move to where the arm already is, at a speed (not a time), takes no time;
 *   <li>an L → J → L corner with CNT blends at both corners even when the J is short (the second
 *       L starts at the J's blend point while the first L still decelerates), so the arm never
 *       stops: CNT between a J and an L blends as on an R-30iB;
 *   <li>a Cartesian move blending in behind a J takes no follower until the J ends, and two
 *       Cartesian moves with different tools do not blend.
 * </ul>
 */
class MotionSequenceSpecTest {
  static final double DT = MotionRunnerTest.DT;
  static final double[] HOME = MotionRunnerTest.HOME;
  static final Transform TOOL = MotionRunnerTest.TOOL;
  /** Data sheet: J1 450 °/s, reached in 0.25 s (docs/motion.md). */
  static final double J1_DEG_S = 450;
  static final double J1_DEG_S2 = J1_DEG_S / 0.25;

  /** Every event with its time. */
  static final class Clock implements MotionListener {
    final List<String> events = new ArrayList<>();
    final Map<String, Double> at = new HashMap<>();
    MotionFault fault;

    @Override
    public void moveStarted(long tag, double t) {
      events.add("start " + tag);
      at.put("start " + tag, t);
    }

    @Override
    public void moveFinished(long tag, double t) {
      events.add("end " + tag);
      at.put("end " + tag, t);
    }

    @Override
    public void moveFailed(long tag, MotionFault f) {
      events.add("fail " + tag);
      fault = f;
    }
  }

  record Run(Clock clock, List<double[]> trace, MotionRunner runner) {}

  /** Queues each move as soon as the runner takes one, ticking until all are done. */
  static Run run(double[] q0, MoveRequest... moves) {
    Clock clock = new Clock();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, clock);
    ArrayDeque<MoveRequest> left = new ArrayDeque<>(List.of(moves));
    List<double[]> trace = new ArrayList<>();
    trace.add(r.joints());
    for (int i = 0; i < 20_000 && !(left.isEmpty() && r.idle()); i++) {
      if (!left.isEmpty() && r.acceptsMove()) {
        r.enqueue(left.poll());
      }
      r.tick(DT);
      trace.add(r.joints());
    }
    return new Run(clock, trace, r);
  }

  static double[] j1At(double deg) {
    double[] q = HOME.clone();
    q[0] = Math.toRadians(deg);
    return q;
  }

  static MoveRequest j1To(double deg, Speed speed, long tag) {
    return new MoveRequest.Joint(j1At(deg), speed, Termination.fine(), 1, tag);
  }

  /** A rest-to-rest J1 move of {@code deg} at 100 %: a triangle when 450 °/s is not reached. */
  static double j1Sec(double deg) {
    return deg * J1_DEG_S2 >= J1_DEG_S * J1_DEG_S ? deg / J1_DEG_S + J1_DEG_S / J1_DEG_S2 : 2 * Math.sqrt(deg / J1_DEG_S2);
  }

  /** Whole ticks a move of {@code sec} takes: it arrives in the tick its path time reaches the end. */
  static int ticks(double sec) {
    return (int) Math.ceil(sec / DT);
  }

  @Test
  void aMoveQueuedBehindAFineMoveStartsTheInstantTheArmStopsAndLosesNoTick() {
    // J1 0 -> 30°: 2·sqrt(30/1800) = 0.258 s, 65 ticks; 30 -> 90°: 2·sqrt(60/1800) = 0.365 s, 92 ticks.
    assertThat(ticks(j1Sec(30))).isEqualTo(65);
    assertThat(ticks(j1Sec(60))).isEqualTo(92);
    Run run = run(HOME, j1To(30, Speed.percent(100), 1), j1To(90, Speed.percent(100), 2));
    Clock c = run.clock();
    assertThat(c.fault).isNull();
    // FINE: the second move starts only once the first has ended...
    assertThat(c.events).containsExactly("start 1", "end 1", "start 2", "end 2");
    // ... at the same instant (the tick the arm arrives), and its own profile from there, to the tick.
    assertThat(c.at.get("end 1")).isCloseTo(ticks(j1Sec(30)) * DT, offset(1e-9));
    assertThat(c.at.get("start 2")).isEqualTo(c.at.get("end 1"));
    assertThat(c.at.get("end 2") - c.at.get("start 2")).isCloseTo(ticks(j1Sec(60)) * DT, offset(1e-9));
    assertThat(run.runner().timeSec()).isCloseTo((ticks(j1Sec(30)) + ticks(j1Sec(60))) * DT, offset(1e-9));
    // The arm was exactly on the first target at that instant (FINE), and ends on the second.
    double[] atCorner = run.trace().get(ticks(j1Sec(30)));
    assertThat(atCorner[0]).isCloseTo(Math.toRadians(30), offset(1e-12));
    assertThat(run.trace().get(run.trace().size() - 1)[0]).isCloseTo(Math.toRadians(90), offset(1e-12));
  }

  @Test
  void theRunnerTakesTheNextMoveTheTickAFineMoveEnds() {
    Clock clock = new Clock();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, HOME, clock);
    r.enqueue(j1To(30, Speed.percent(100), 1));
    r.tick(DT);
    r.enqueue(j1To(60, Speed.percent(100), 2));
    for (int i = 1; i < ticks(j1Sec(30)); i++) {
      assertThat(r.acceptsMove()).isFalse();
      r.tick(DT);
    }
    // The tick move 1 arrives, move 2 runs and the queue is free for a third.
    assertThat(clock.events).containsExactly("start 1", "end 1", "start 2");
    assertThat(r.activeTags()).containsExactly(2L);
    assertThat(r.acceptsMove()).isTrue();
  }

  @Test
  void aMoveToWhereTheArmIsAtASpeedTakesNoTime() {
    // 0 -> 30° (65 ticks), then J to 30° again at 50 % (no distance: no time), then 30 -> 70° (40°: 75 ticks).
    assertThat(ticks(j1Sec(40))).isEqualTo(75);
    Run run = run(HOME, j1To(30, Speed.percent(100), 1), j1To(30, Speed.percent(50), 2), j1To(70, Speed.percent(100), 3));
    Clock c = run.clock();
    assertThat(c.fault).isNull();
    assertThat(c.events).containsExactly("start 1", "end 1", "start 2", "end 2", "start 3", "end 3");
    assertThat(c.at.get("start 2")).isEqualTo(c.at.get("end 1"));
    assertThat(c.at.get("end 2")).isEqualTo(c.at.get("start 2"));
    // The whole chain takes what the two real moves take: the empty move cost no tick.
    assertThat(c.at.get("end 3")).isCloseTo((ticks(j1Sec(30)) + ticks(j1Sec(40))) * DT, offset(1e-9));
  }

  /** The TCP speed (mm/s) of each tick of a trace. */
  static List<Double> tcpSpeeds(List<double[]> trace) {
    List<Double> v = new ArrayList<>();
    for (int k = 1; k < trace.size(); k++) {
      v.add(MotionRunnerTest.tcp(trace.get(k)).distanceTo(MotionRunnerTest.tcp(trace.get(k - 1))) / DT);
    }
    return v;
  }

  static void withinJointSpeeds(List<double[]> trace) {
    for (int k = 1; k < trace.size(); k++) {
      for (int j = 0; j < 6; j++) {
        assertThat(Math.abs(trace.get(k)[j] - trace.get(k - 1)[j]) / DT).as("J%d at tick %d", j + 1, k)
            .isLessThanOrEqualTo(MotionRunnerTest.LIMITS.jointSpeed(j) * (1 + 1e-6));
      }
    }
  }

  /** The joints at the TCP pose {@code X_WT}, reached by an L move from HOME. */
  static double[] jointsAt(Transform X_WT) {
    Run r = run(HOME, new MoveRequest.Linear(X_WT, TOOL, Speed.mmPerSec(500), Termination.fine(), 1, 99));
    assertThat(r.clock().fault).isNull();
    return r.trace().get(r.trace().size() - 1);
  }

  @Test
  void anLJLCornerWithCntBlendsAtBothCornersEvenWithAShortJ() {
    Transform a = MotionRunnerTest.tcp(HOME).withTranslation(350, -120, 40);
    Transform b = MotionRunnerTest.tcp(HOME).withTranslation(350, 120, 40);
    double[] qa = jointsAt(a);
    double[] qb = jointsAt(b);
    for (double jDeg : new double[] {1, 5, 20}) {
      // L to B (CNT100), a J turning J1 by jDeg from B's joints (CNT100), an L 200 mm up and out (FINE).
      double[] qj = qb.clone();
      qj[0] += Math.toRadians(jDeg);
      Transform c = MotionRunnerTest.tcp(qj).withTranslation(350, 200, 200);
      MoveRequest l1 = new MoveRequest.Linear(b, TOOL, Speed.mmPerSec(500), Termination.cnt(100), 1, 1);
      MoveRequest j = new MoveRequest.Joint(qj, Speed.percent(100), Termination.cnt(100), 1, 2);
      MoveRequest l3 = new MoveRequest.Linear(c, TOOL, Speed.mmPerSec(500), Termination.fine(), 1, 3);
      Run cnt = run(qa, l1, j, l3);
      assertThat(cnt.clock().fault).as("J of %s deg", jDeg).isNull();
      // The second L starts before the first has ended: both corners blend.
      assertThat(cnt.clock().events).as("J of %s deg", jDeg)
          .containsExactly("start 1", "start 2", "start 3", "end 1", "end 2", "end 3");
      withinJointSpeeds(cnt.trace());
      assertThat(MotionRunnerTest.tcp(cnt.trace().get(cnt.trace().size() - 1)).distanceTo(c)).isLessThan(0.01);
      // Never at rest between the first L's speed-up and the last L's slow-down (0.2 s each at ACC100):
      // not below a tenth of the 500 mm/s anywhere in between.
      List<Double> v = tcpSpeeds(cnt.trace());
      int ramp = (int) Math.ceil(0.2 / DT);
      for (int k = ramp; k < v.size() - ramp; k++) {
        assertThat(v.get(k)).as("TCP speed at tick %d with a J of %s deg", k, jDeg).isGreaterThan(50);
      }
      // And sooner than stopping at the corners.
      Run fine = run(qa, new MoveRequest.Linear(b, TOOL, Speed.mmPerSec(500), Termination.fine(), 1, 1),
          new MoveRequest.Joint(qj, Speed.percent(100), Termination.fine(), 1, 2), l3);
      assertThat(cnt.trace().size()).isLessThan(fine.trace().size() - ramp);
    }
  }

  @Test
  void aLinearMoveBlendingBehindAJointMoveTakesNoFollowerUntilTheJointMoveEnds() {
    // J (CNT100) to a point, a 5 mm L (CNT100) from there, another L (FINE): the short L rides behind
    // the J in joint space and ends before it; the last L waits for the J to end and starts from
    // there (docs/motion.md: the one deliberate stop in a CNT chain, J -> short L -> L).
    double[] via = {0.5, 0.3, -0.2, 0.2, Math.toRadians(-70), 0.3};
    Transform p = MotionRunnerTest.tcp(via);
    Transform short1 = p.withTranslation(p.x(), p.y() + 5, p.z());
    Transform end = p.withTranslation(p.x() - 150, p.y() + 5, p.z());
    Run run = run(HOME, new MoveRequest.Joint(via, Speed.percent(80), Termination.cnt(100), 1, 1),
        new MoveRequest.Linear(short1, TOOL, Speed.mmPerSec(500), Termination.cnt(100), 1, 2),
        new MoveRequest.Linear(end, TOOL, Speed.mmPerSec(500), Termination.fine(), 1, 3));
    assertThat(run.clock().fault).isNull();
    assertThat(run.clock().events).containsExactly("start 1", "start 2", "end 1", "end 2", "start 3", "end 3");
    assertThat(run.clock().at.get("start 3")).isEqualTo(run.clock().at.get("end 1"));
    withinJointSpeeds(run.trace());
    assertThat(MotionRunnerTest.tcp(run.trace().get(run.trace().size() - 1)).distanceTo(end)).isLessThan(0.01);
  }

  @Test
  void twoLinearMovesWithDifferentToolsDoNotBlend() {
    Transform a = MotionRunnerTest.tcp(HOME).withTranslation(350, -120, 40);
    Transform b = MotionRunnerTest.tcp(HOME).withTranslation(350, 120, 40);
    Transform otherTool = Transform.translation(0, 0, 150);
    Transform bOther = b.withTranslation(350, 120, 100);
    Run run = run(jointsAt(a), new MoveRequest.Linear(b, TOOL, Speed.mmPerSec(500), Termination.cnt(100), 1, 1),
        new MoveRequest.Linear(bOther, otherTool, Speed.mmPerSec(500), Termination.fine(), 1, 2));
    assertThat(run.clock().fault).isNull();
    // The first move ends (and the arm stops on B) before the second starts.
    assertThat(run.clock().events).containsExactly("start 1", "end 1", "start 2", "end 2");
    assertThat(run.clock().at.get("start 2")).isEqualTo(run.clock().at.get("end 1"));
    double[] last = run.trace().get(run.trace().size() - 1);
    assertThat(org.robotrun.robot.ForwardKinematics.flangePoseInWorld(MotionRunnerTest.MODEL, last).compose(otherTool)
        .distanceTo(bOther)).isLessThan(0.01);
  }
}
