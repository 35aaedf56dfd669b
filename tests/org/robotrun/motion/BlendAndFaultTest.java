package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/** CNT blending against FINE, and moves that cannot be followed. */
class BlendAndFaultTest {
  static final double DT = MotionRunnerTest.DT;
  static final Transform TOOL = MotionRunnerTest.TOOL;

  record Run(List<double[]> trace, MotionRunnerTest.Recorder rec) {}

  static Run corner(Termination atCorner) {
    Transform a = MotionRunnerTest.tcp(MotionRunnerTest.HOME);
    Vec3 p = a.translationVector();
    Transform b = a.withTranslation(p.x(), p.y() + 200, p.z());
    Transform c = a.withTranslation(p.x(), p.y() + 200, p.z() - 200);
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, MotionRunnerTest.HOME, rec);
    r.enqueue(new MoveRequest.Linear(b, TOOL, Speed.mmPerSec(400), atCorner, 1, 1));
    List<double[]> trace = new java.util.ArrayList<>();
    // The second move is queued as soon as the runner takes it, as the interpreter does.
    boolean queued = false;
    for (int i = 0; i < 10_000 && !(queued && r.idle()); i++) {
      if (!queued && r.acceptsMove()) {
        r.enqueue(new MoveRequest.Linear(c, TOOL, Speed.mmPerSec(400), Termination.fine(), 1, 2));
        queued = true;
      }
      r.tick(DT);
      trace.add(r.joints());
    }
    return new Run(trace, rec);
  }

  @Test
  void cnt100CutsTheCornerAndIsFasterThanFine() {
    Run fine = corner(Termination.fine());
    Run cnt = corner(Termination.cnt(100));
    Transform a = MotionRunnerTest.tcp(MotionRunnerTest.HOME);
    Vec3 corner = a.translationVector().plus(new Vec3(0, 200, 0));
    double fineClosest = Double.MAX_VALUE;
    double cntClosest = Double.MAX_VALUE;
    double maxOffPlane = 0;
    for (double[] q : fine.trace()) {
      fineClosest = Math.min(fineClosest, MotionRunnerTest.tcp(q).translationVector().distanceTo(corner));
    }
    for (double[] q : cnt.trace()) {
      Vec3 p = MotionRunnerTest.tcp(q).translationVector();
      cntClosest = Math.min(cntClosest, p.distanceTo(corner));
      // The corner's plane is x = const.
      maxOffPlane = Math.max(maxOffPlane, Math.abs(p.x() - corner.x()));
    }
    // FINE reaches the corner to 0.01 mm; CNT100 stays clear of it, in the plane, and is shorter.
    assertThat(fineClosest).isLessThan(0.01);
    assertThat(cntClosest).isGreaterThan(5);
    assertThat(maxOffPlane).isLessThan(0.01);
    assertThat(cnt.trace().size()).isLessThan(fine.trace().size() - 20);
    assertThat(cnt.rec().events).containsExactly("start 1", "start 2", "end 1", "end 2");
  }

  /** Runs the two moves, queuing the second as soon as the runner takes it; returns the joint trace. */
  static Run pair(MoveRequest first, MoveRequest second, double[] q0) {
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, rec);
    r.enqueue(first);
    List<double[]> trace = new java.util.ArrayList<>();
    trace.add(r.joints());
    boolean queued = false;
    for (int i = 0; i < 10_000 && !(queued && r.idle()); i++) {
      if (!queued && r.acceptsMove()) {
        r.enqueue(second);
        queued = true;
      }
      r.tick(DT);
      trace.add(r.joints());
    }
    return new Run(trace, rec);
  }

  @Test
  void jointMoveBlendsIntoALinearMoveWithoutStopping() {
    double[] home = MotionRunnerTest.HOME;
    double[] via = {0.5, 0.3, -0.2, 0.2, Math.toRadians(-70), 0.3};
    Transform end = MotionRunnerTest.tcp(home).withTranslation(350, -120, 40);
    Run fine = pair(new MoveRequest.Joint(via, Speed.percent(80), Termination.fine(), 1, 1),
        new MoveRequest.Linear(end, TOOL, Speed.mmPerSec(600), Termination.fine(), 1, 2), home);
    Run cnt = pair(new MoveRequest.Joint(via, Speed.percent(80), Termination.cnt(100), 1, 1),
        new MoveRequest.Linear(end, TOOL, Speed.mmPerSec(600), Termination.fine(), 1, 2), home);
    assertThat(cnt.rec().fault).isNull();
    assertThat(cnt.rec().events).containsExactly("start 1", "start 2", "end 1", "end 2");
    assertThat(cnt.trace().size()).isLessThan(fine.trace().size() - 20);
    assertThat(MotionRunnerTest.tcp(cnt.trace().get(cnt.trace().size() - 1)).distanceTo(end)).isLessThan(0.01);
    // Never at rest between the start and the end: the corner is blended, not stopped at.
    double slowest = Double.MAX_VALUE;
    List<double[]> t = cnt.trace();
    for (int k = 20; k < t.size() - 20; k++) {
      double v = MotionRunnerTest.tcp(t.get(k)).distanceTo(MotionRunnerTest.tcp(t.get(k - 1))) / DT;
      slowest = Math.min(slowest, v);
      for (int j = 0; j < 6; j++) {
        assertThat(Math.abs(t.get(k)[j] - t.get(k - 1)[j]) / DT).isLessThanOrEqualTo(
            MotionRunnerTest.LIMITS.jointSpeed(j) * (1 + 1e-6));
      }
    }
    assertThat(slowest).isGreaterThan(20);
  }

  @Test
  void linearMoveBlendsIntoAJointMoveAndEndsOnItsTarget() {
    double[] home = MotionRunnerTest.HOME;
    double[] target = {-0.6, 0.2, -0.1, -0.3, Math.toRadians(-60), -0.5};
    Transform mid = MotionRunnerTest.tcp(home).withTranslation(350, 120, 40);
    Run cnt = pair(new MoveRequest.Linear(mid, TOOL, Speed.mmPerSec(600), Termination.cnt(100), 1, 1),
        new MoveRequest.Joint(target, Speed.percent(60), Termination.fine(), 1, 2), home);
    Run fine = pair(new MoveRequest.Linear(mid, TOOL, Speed.mmPerSec(600), Termination.fine(), 1, 1),
        new MoveRequest.Joint(target, Speed.percent(60), Termination.fine(), 1, 2), home);
    assertThat(cnt.rec().fault).isNull();
    assertThat(cnt.rec().events).containsExactly("start 1", "start 2", "end 1", "end 2");
    double[] last = cnt.trace().get(cnt.trace().size() - 1);
    for (int j = 0; j < 6; j++) {
      assertThat(last[j]).isCloseTo(target[j], org.assertj.core.data.Offset.offset(1e-6));
    }
    assertThat(cnt.trace().size()).isLessThan(fine.trace().size() - 20);
  }

  @Test
  void largerCntBlendsEarlier() {
    Transform a = MotionRunnerTest.tcp(MotionRunnerTest.HOME);
    Vec3 corner = a.translationVector().plus(new Vec3(0, 200, 0));
    double prev = 0;
    for (int n : new int[] {20, 50, 100}) {
      double closest = Double.MAX_VALUE;
      for (double[] q : corner(Termination.cnt(n)).trace()) {
        closest = Math.min(closest, MotionRunnerTest.tcp(q).translationVector().distanceTo(corner));
      }
      assertThat(closest).isGreaterThan(prev);
      prev = closest;
    }
  }

  @Test
  void linearMoveThroughTheWristSingularityStopsWithAnAlarmAndFiniteJoints() {
    // Wrist straight ahead (J5 near 0), then a line that makes J4/J6 swap sides.
    double[] q0 = {0, 0, 0, 0.3, Math.toRadians(-8), 0};
    Transform start = MotionRunnerTest.tcp(q0);
    double[] q1 = {0, 0, 0, 0.3, Math.toRadians(8), 0};
    Transform end = MotionRunnerTest.tcp(q1);
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, rec);
    r.enqueue(new MoveRequest.Linear(end, TOOL, Speed.mmPerSec(100), Termination.fine(), 1, 5));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);
    assertThat(rec.fault).isNotNull();
    assertThat(rec.fault.kind()).isEqualTo(MotionFault.Kind.SINGULARITY);
    assertThat(rec.events).contains("fail 5");
    for (double[] q : trace) {
      for (double v : q) {
        assertThat(Double.isFinite(v)).isTrue();
      }
    }
    assertThat(start.distanceTo(end)).isGreaterThan(1);
  }

  @Test
  void linearMoveNearTheWristSingularitySlowsInsteadOfWhippingTheWrist() {
    // Wrist straight (J5 = 0) at q_mid; the line runs 15 mm beside that point with the orientation
    // fixed, so J5 stays a few degrees from 0 while J4 and J6 must swing about 180 degrees.
    double[] qMid = {0, 0.3, 0.2, 0, 0, 0};
    Transform mid = MotionRunnerTest.tcp(qMid);
    Transform start = mid.withTranslation(mid.x(), mid.y() - 50, mid.z() + 15);
    Transform end = mid.withTranslation(mid.x(), mid.y() + 50, mid.z() + 15);
    PoseTracker solver = new PoseTracker(MotionRunnerTest.MODEL);
    double[] q0 = {0, 0.3, 0.2, -1.57, 0.1, 1.57};
    assertThat(solver.track(q0, start, TOOL, 1e-6, 1e-9)).isTrue();
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, rec);
    r.enqueue(new MoveRequest.Linear(end, TOOL, Speed.mmPerSec(500), Termination.fine(), 1, 6));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);
    assertThat(rec.fault).isNull();
    double minJ5 = Double.MAX_VALUE;
    double maxJ4Speed = 0;
    for (int k = 1; k < trace.size(); k++) {
      for (int j = 0; j < 6; j++) {
        double v = Math.abs(trace.get(k)[j] - trace.get(k - 1)[j]) / DT;
        assertThat(v).isLessThanOrEqualTo(MotionRunnerTest.LIMITS.jointSpeed(j) * (1 + 1e-9));
      }
      minJ5 = Math.min(minJ5, Math.abs(trace.get(k)[4]));
      maxJ4Speed = Math.max(maxJ4Speed, Math.abs(trace.get(k)[3] - trace.get(k - 1)[3]) / DT);
      // On the line to 0.1 mm (the line is along WORLD y).
      Transform x = MotionRunnerTest.tcp(trace.get(k));
      assertThat(Math.hypot(x.x() - start.x(), x.z() - start.z())).isLessThanOrEqualTo(0.1);
    }
    double[] last = trace.get(trace.size() - 1);
    assertThat(MotionRunnerTest.tcp(last).distanceTo(end)).isLessThan(0.01);
    // The wrist really swung, J4 ran at its speed limit, and the move took longer than planned.
    assertThat(Math.abs(last[3] - q0[3])).isGreaterThan(Math.toRadians(120));
    assertThat(minJ5).isLessThan(Math.toRadians(10));
    assertThat(maxJ4Speed).isGreaterThan(0.9 * MotionRunnerTest.LIMITS.jointSpeed(3));
    double planned = UnitProfile.fastest(500 / 100.0, 500 / MotionLimits.LINEAR_ACCEL_TIME_SEC / 100).durationSec();
    assertThat((trace.size() - 1) * DT).isGreaterThan(planned + 10 * DT);
  }

  @Test
  void unreachableTargetIsAFaultBeforeMoving() {
    Transform a = MotionRunnerTest.tcp(MotionRunnerTest.HOME);
    Transform far = a.withTranslation(a.x() + 2000, a.y(), a.z());
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, MotionRunnerTest.HOME, rec);
    r.enqueue(new MoveRequest.Linear(far, TOOL, Speed.mmPerSec(100), Termination.fine(), 1, 9));
    List<double[]> trace = MotionRunnerTest.run(r, 1000);
    assertThat(rec.fault.kind()).isEqualTo(MotionFault.Kind.OUT_OF_REACH);
    assertThat(trace.get(trace.size() - 1)).containsExactly(MotionRunnerTest.HOME);
  }
}
