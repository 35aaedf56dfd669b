package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.RobotModel;
import org.junit.jupiter.api.Test;

/** Joint, linear and circular moves, checked tick by tick on the recorded joints and TCP. */
class MotionRunnerTest {
  static final RobotModel MODEL = RobotDefinitions.defaultRobot();
  static final MotionLimits LIMITS = MotionLimits.forModel(MODEL);
  static final double DT = 0.004;
  static final Transform TOOL = Transform.translation(0, 0, 100);
  /** Tool pointing down in front of the arm (kinematic joints, rad). */
  static final double[] HOME = {0, 0, 0, 0, Math.toRadians(-90), 0};

  /** Records events; the trace is the joints after every tick. */
  static final class Recorder implements MotionListener {
    final List<String> events = new ArrayList<>();
    MotionFault fault;

    @Override
    public void moveStarted(long tag, double t) {
      events.add("start " + tag);
    }

    @Override
    public void moveFinished(long tag, double t) {
      events.add("end " + tag);
    }

    @Override
    public void moveFailed(long tag, MotionFault f) {
      events.add("fail " + tag);
      fault = f;
    }
  }

  static List<double[]> run(MotionRunner r, int maxTicks) {
    List<double[]> trace = new ArrayList<>();
    trace.add(r.joints());
    for (int i = 0; i < maxTicks && !r.idle(); i++) {
      r.tick(DT);
      trace.add(r.joints());
    }
    return trace;
  }

  static Transform tcp(double[] q) {
    return ForwardKinematics.flangePoseInWorld(MODEL, q).compose(TOOL);
  }

  @Test
  void jointMoveArrivesTogetherWithinSpeedAndAccelerationLimits() {
    double[] target = {Math.toRadians(60), Math.toRadians(20), Math.toRadians(-10), Math.toRadians(90),
        Math.toRadians(-40), Math.toRadians(120)};
    Recorder rec = new Recorder();
    MotionRunner r = new MotionRunner(MODEL, LIMITS, HOME, rec);
    r.enqueue(new MoveRequest.Joint(target, Speed.percent(100), Termination.fine(), 1, 1));
    List<double[]> trace = run(r, 10_000);
    assertThat(rec.events).containsExactly("start 1", "end 1");
    double[] last = trace.get(trace.size() - 1);
    for (int j = 0; j < 6; j++) {
      assertThat(last[j]).isCloseTo(target[j], org.assertj.core.data.Offset.offset(1e-12));
    }
    // Every joint is the same fraction of its way at every tick: they start and arrive together.
    for (double[] q : trace) {
      double u0 = (q[0] - HOME[0]) / (target[0] - HOME[0]);
      for (int j = 1; j < 6; j++) {
        assertThat((q[j] - HOME[j]) / (target[j] - HOME[j])).isCloseTo(u0, org.assertj.core.data.Offset.offset(1e-9));
      }
    }
    // Finite differences of the trace stay within the limits (tolerance: rounding, 1e-6 relative).
    double[] prevV = new double[6];
    for (int k = 1; k < trace.size(); k++) {
      for (int j = 0; j < 6; j++) {
        double v = (trace.get(k)[j] - trace.get(k - 1)[j]) / DT;
        assertThat(Math.abs(v)).isLessThanOrEqualTo(LIMITS.jointSpeed(j) * (1 + 1e-6));
        assertThat(Math.abs(v - prevV[j]) / DT).isLessThanOrEqualTo(LIMITS.jointAccel(j) * (1 + 1e-6));
        prevV[j] = v;
      }
    }
  }

  @Test
  void linearMoveStaysOnTheLineAtTheCommandedSpeed() {
    Transform start = tcp(HOME);
    Transform target = Xyzwpr.fromTransform(start).toTransform();
    target = Transform.translation(0, 250, -150).compose(target.withTranslation(0, 0, 0))
        .withTranslation(start.x() - 50, start.y() + 250, start.z() - 150);
    target = Transform.rotation(0, 0, 1, Math.toRadians(30)).compose(target.withTranslation(0, 0, 0))
        .withTranslation(target.x(), target.y(), target.z());
    Recorder rec = new Recorder();
    MotionRunner r = new MotionRunner(MODEL, LIMITS, HOME, rec);
    r.enqueue(new MoveRequest.Linear(target, TOOL, Speed.mmPerSec(500), Termination.fine(), 1, 7));
    List<double[]> trace = run(r, 10_000);
    assertThat(rec.events).containsExactly("start 7", "end 7");
    Vec3 a = start.translationVector();
    Vec3 dir = target.translationVector().minus(a).normalized();
    double maxDev = 0;
    double prevAngle = -1;
    List<Double> speeds = new ArrayList<>();
    Vec3 prev = a;
    for (double[] q : trace) {
      Transform x = tcp(q);
      Vec3 p = x.translationVector();
      Vec3 d = p.minus(a);
      maxDev = Math.max(maxDev, d.minus(dir.times(d.dot(dir))).norm());
      double angle = start.rotationAngleTo(x);
      assertThat(angle).isGreaterThanOrEqualTo(prevAngle - 1e-9);
      prevAngle = angle;
      speeds.add(p.distanceTo(prev) / DT);
      prev = p;
    }
    // Deviation from the straight line at every tick (mm).
    assertThat(maxDev).isLessThanOrEqualTo(0.1);
    // The plateau: at least 50 ticks (0.2 s) within 1% of 500 mm/s, none above.
    assertThat(speeds.stream().filter(v -> Math.abs(v - 500) <= 5).count()).isGreaterThan(50);
    assertThat(speeds.stream().mapToDouble(Double::doubleValue).max().orElseThrow()).isLessThanOrEqualTo(505);
    Transform end = tcp(trace.get(trace.size() - 1));
    assertThat(end.distanceTo(target)).isLessThan(0.01);
    assertThat(end.rotationAngleTo(target)).isLessThan(1e-5);
  }

  @Test
  void circularMoveStaysOnTheCircle() {
    Transform start = tcp(HOME);
    Vec3 s = start.translationVector();
    Transform via = start.withTranslation(s.x() + 100, s.y() + 100, s.z());
    Transform end = start.withTranslation(s.x() + 200, s.y(), s.z());
    // Circle centre (s.x + 100, s.y, s.z), radius 100.
    Vec3 c = new Vec3(s.x() + 100, s.y(), s.z());
    Recorder rec = new Recorder();
    MotionRunner r = new MotionRunner(MODEL, LIMITS, HOME, rec);
    r.enqueue(new MoveRequest.Circular(via, end, TOOL, Speed.mmPerSec(300), Termination.fine(), 1, 3));
    List<double[]> trace = run(r, 10_000);
    assertThat(rec.events).containsExactly("start 3", "end 3");
    double maxDev = 0;
    double maxY = 0;
    for (double[] q : trace) {
      Vec3 p = tcp(q).translationVector();
      maxDev = Math.max(maxDev, Math.abs(p.distanceTo(c) - 100));
      maxDev = Math.max(maxDev, Math.abs(p.z() - s.z()));
      maxY = Math.max(maxY, p.y() - s.y());
    }
    assertThat(maxDev).isLessThanOrEqualTo(0.1);
    assertThat(maxY).isGreaterThan(99.9);
    assertThat(tcp(trace.get(trace.size() - 1)).distanceTo(end)).isLessThan(0.01);
  }

  static int ticksOf(MoveRequest m, double[] q0) {
    MotionRunner r = new MotionRunner(MODEL, LIMITS, q0, MotionListener.NONE);
    r.enqueue(m);
    return run(r, 100_000).size() - 1;
  }

  @Test
  void secondsSpeedGivesTheMoveItsDuration() {
    double[] target = {0.4, 0.1, -0.1, 0.2, Math.toRadians(-60), 0.3};
    // Duration in ticks of 4 ms, to one tick.
    assertThat(ticksOf(new MoveRequest.Joint(target, Speed.seconds(2), Termination.fine(), 1, 1), HOME))
        .isBetween(499, 501);
    Transform end = tcp(HOME).withTranslation(300, 100, 50);
    assertThat(ticksOf(new MoveRequest.Linear(end, TOOL, Speed.milliseconds(1500), Termination.fine(), 1, 1), HOME))
        .isBetween(374, 376);
  }

  @Test
  void rotationOnlyMoveTurnsAtTheCommandedDegreesPerSecondAroundAFixedTcp() {
    Transform start = tcp(HOME);
    Transform end = Transform.rotation(0, 0, 1, Math.toRadians(90)).compose(start.withTranslation(0, 0, 0))
        .withTranslation(start.x(), start.y(), start.z());
    MotionRunner r = new MotionRunner(MODEL, LIMITS, HOME, MotionListener.NONE);
    r.enqueue(new MoveRequest.Linear(end, TOOL, Speed.degPerSec(45), Termination.fine(), 1, 1));
    List<double[]> trace = run(r, 100_000);
    double maxRate = 0;
    for (int k = 1; k < trace.size(); k++) {
      assertThat(tcp(trace.get(k)).distanceTo(start)).isLessThan(0.1);
      maxRate = Math.max(maxRate, Math.toDegrees(tcp(trace.get(k)).rotationAngleTo(tcp(trace.get(k - 1)))) / DT);
    }
    // 90 degrees at 45 deg/s: 2 s plus the 0.2 s ramp; the plateau is the commanded rate (1%).
    assertThat((trace.size() - 1) * DT).isCloseTo(2.2, org.assertj.core.data.Offset.offset(0.01));
    assertThat(maxRate).isCloseTo(45, org.assertj.core.data.Offset.offset(0.45));
  }

  @Test
  void lowerAccTakesLongerAndOverrideScalesTime() {
    double[] target = {0.8, 0.2, -0.1, 0.2, Math.toRadians(-60), 0.3};
    int acc100 = ticksOf(new MoveRequest.Joint(target, Speed.percent(100), Termination.fine(), 1, 1), HOME);
    int acc50 = ticksOf(new MoveRequest.Joint(target, Speed.percent(100), Termination.fine(), 0.5, 1), HOME);
    assertThat(acc50).isGreaterThan(acc100 + 10);
    MotionRunner r = new MotionRunner(MODEL, LIMITS, HOME, MotionListener.NONE);
    r.setOverride(0.5);
    r.enqueue(new MoveRequest.Joint(target, Speed.percent(100), Termination.fine(), 1, 1));
    // At 50% override the path time runs at half rate: twice the ticks (to one tick).
    assertThat(run(r, 100_000).size() - 1).isBetween(2 * acc100 - 1, 2 * acc100 + 1);
  }
}
