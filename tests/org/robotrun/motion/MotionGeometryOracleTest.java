package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.RobotModel;

/**
 * The motion package's building blocks against definitions: the trapezoid's rate and position from
 * constant-acceleration kinematics (v = a·t, s = a·t²/2, area under the rate = 1), circles through
 * three points laid out at known angles on a known circle in a tilted plane, and the pose tracker
 * against forward kinematics of the joints it returns.
 */
class MotionGeometryOracleTest {

  // ---- UnitProfile -----------------------------------------------------------------------------

  @Test
  void trapezoidRateIsAccelerationCruiseDeceleration() {
    // Peak 0.5/s at 1/s²: 0.5 s up, covering 0.125 each ramp, so the cruise is 0.75 / 0.5 = 1.5 s.
    UnitProfile p = UnitProfile.fastest(0.5, 1);
    assertThat(p.accelTimeSec()).isCloseTo(0.5, within(1e-15));
    assertThat(p.cruiseTimeSec()).isCloseTo(1.5, within(1e-15));
    assertThat(p.durationSec()).isCloseTo(2.5, within(1e-15));
    assertThat(p.decelStartSec()).isCloseTo(2.0, within(1e-15));
    assertThat(p.rate(-1)).isZero();
    assertThat(p.rate(0)).isZero();
    assertThat(p.rate(0.25)).isCloseTo(0.25, within(1e-15));
    assertThat(p.rate(0.49)).isCloseTo(0.49, within(1e-15));
    assertThat(p.rate(1.0)).isCloseTo(0.5, within(1e-15));
    assertThat(p.rate(1.99)).isCloseTo(0.5, within(1e-15));
    assertThat(p.rate(2.25)).isCloseTo(0.25, within(1e-15));
    assertThat(p.rate(2.49)).isCloseTo(0.01, within(1e-12));
    assertThat(p.rate(2.5)).isZero();
    assertThat(p.rate(9)).isZero();
    assertThat(p.position(0.25)).isCloseTo(0.5 * 0.25 * 0.25, within(1e-15));
    assertThat(p.position(1.0)).isCloseTo(0.125 + 0.5 * 0.5, within(1e-15));
    assertThat(p.position(2.25)).isCloseTo(1 - 0.5 * 0.25 * 0.25, within(1e-15));
    assertThat(p.position(-1)).isZero();
    assertThat(p.position(3)).isEqualTo(1);
  }

  @Test
  void positionIsTheIntegralOfTheRate() {
    // Midpoint rule on 10 000 steps; trapezoid and triangle.
    for (UnitProfile p : new UnitProfile[] {UnitProfile.fastest(0.5, 1), UnitProfile.fastest(4, 1),
        UnitProfile.forDuration(4, 1, 1), UnitProfile.fastest(0.2, 3)}) {
      int n = 10_000;
      double h = p.durationSec() / n;
      double s = 0;
      for (int k = 0; k < n; k++) {
        s += p.rate((k + 0.5) * h) * h;
        if (k % 1000 == 999) {
          assertThat(p.position((k + 1) * h)).as("%s at %d", p, k).isCloseTo(s, within(1e-6));
        }
      }
      assertThat(s).as("area under %s", p).isCloseTo(1, within(1e-6));
    }
  }

  @Test
  void tooShortForThePeakIsATriangle() {
    // v²/a = 16 > 1: the peak is √a = 1/s after 1 s, half the path at the top.
    UnitProfile p = UnitProfile.fastest(4, 1);
    assertThat(p.peakRate()).isCloseTo(1, within(1e-15));
    assertThat(p.cruiseTimeSec()).isZero();
    assertThat(p.durationSec()).isCloseTo(2, within(1e-15));
    assertThat(p.position(1)).isCloseTo(0.5, within(1e-15));
    assertThat(p.rate(1)).isCloseTo(1, within(1e-15));
    // Exactly v²/a = 1: trapezoid and triangle coincide.
    UnitProfile edge = UnitProfile.fastest(1, 1);
    assertThat(edge.durationSec()).isCloseTo(2, within(1e-15));
    assertThat(edge.cruiseTimeSec()).isCloseTo(0, within(1e-15));
    // An infinite rate limit: the triangle.
    UnitProfile free = UnitProfile.fastest(Double.POSITIVE_INFINITY, 4);
    assertThat(free.peakRate()).isCloseTo(2, within(1e-15));
    assertThat(free.durationSec()).isCloseTo(1, within(1e-15));
  }

  @Test
  void aTimedMoveTakesItsTimeAtFullAcceleration() {
    // T = 1/v + v/a: for T = 4 s at a = 1/s², v = (4 − √12)/2.
    UnitProfile p = UnitProfile.forDuration(4, 1, 1);
    double v = (4 - Math.sqrt(12)) / 2;
    assertThat(p.peakRate()).isCloseTo(v, within(1e-12));
    assertThat(p.accel()).isEqualTo(1);
    assertThat(p.accelTimeSec()).isCloseTo(v, within(1e-12));
    assertThat(p.durationSec()).isCloseTo(4, within(1e-12));
    assertThat(p.position(4)).isEqualTo(1);
    assertThat(p.position(2)).isCloseTo(0.5, within(1e-12));
    // Shorter than the limits allow (2 s at 1/s and 1/s²), or exactly that: the fastest profile.
    assertThat(UnitProfile.forDuration(1, 1, 1)).isEqualTo(UnitProfile.fastest(1, 1));
    assertThat(UnitProfile.forDuration(2, 1, 1)).isEqualTo(UnitProfile.fastest(1, 1));
    // Just longer than the fastest: a lower peak, still exactly the asked time.
    UnitProfile slow = UnitProfile.forDuration(2.5, 1, 1);
    assertThat(slow.durationSec()).isCloseTo(2.5, within(1e-12));
    assertThat(slow.peakRate()).isLessThan(1);
  }

  @Test
  void emptyAndInvalidProfiles() {
    assertThat(UnitProfile.EMPTY.position(0)).isEqualTo(1);
    assertThat(UnitProfile.EMPTY.durationSec()).isZero();
    assertThat(UnitProfile.EMPTY.rate(0)).isZero();
    assertThatThrownBy(() -> new UnitProfile(-1, 1, 1, 1)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new UnitProfile(1, -1, 1, 1)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new UnitProfile(1, 1, -1, 1)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new UnitProfile(1, 1, 1, -1)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> new UnitProfile(Double.NaN, 1, 1, 1)).isInstanceOf(IllegalArgumentException.class);
    assertThat(new UnitProfile(0, 0, 0, 0).durationSec()).isZero();
    assertThatThrownBy(() -> UnitProfile.fastest(0, 1)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> UnitProfile.fastest(1, 0)).isInstanceOf(IllegalArgumentException.class);
    assertThatThrownBy(() -> UnitProfile.fastest(1, Double.POSITIVE_INFINITY)).isInstanceOf(IllegalArgumentException.class);
  }

  // ---- PathShape and ArcPoints ------------------------------------------------------------------

  // A circle of radius 50 about (10, 20, 30) in a plane tilted about x and z.
  static final Vec3 C = new Vec3(10, 20, 30);
  static final double R = 50;
  static final Vec3 U = new Vec3(Math.cos(0.4), Math.sin(0.4), 0);
  static final Vec3 V = new Vec3(-Math.sin(0.4) * Math.cos(0.9), Math.cos(0.4) * Math.cos(0.9), Math.sin(0.9));

  static Vec3 onCircle(double deg) {
    double a = Math.toRadians(deg);
    return C.plus(U.times(R * Math.cos(a))).plus(V.times(R * Math.sin(a)));
  }

  static void assertClose(Vec3 a, Vec3 b, double tol) {
    assertThat(a.distanceTo(b)).as("%s vs %s", a, b).isLessThan(tol);
  }

  @Test
  void arcThroughThreePointsIsTheirCircle() {
    PathShape.Arc arc = PathShape.Arc.through(onCircle(0), onCircle(100), onCircle(250));
    assertThat(arc).isNotNull();
    assertClose(arc.center(), C, 1e-9);
    assertThat(arc.radius()).isCloseTo(R, within(1e-9));
    assertThat(arc.sweepRad()).isCloseTo(Math.toRadians(250), within(1e-12));
    assertThat(arc.lengthMm()).isCloseTo(R * Math.toRadians(250), within(1e-9));
    assertClose(arc.e1(), U, 1e-12);
    assertClose(arc.e2(), V, 1e-12);
    for (int k = 0; k <= 10; k++) {
      double u = k / 10.0;
      assertClose(arc.displacement(u), onCircle(250 * u).minus(onCircle(0)), 1e-9);
    }
    // The other way round the same circle: V turns to −V, the sweep is 360° − 110°... from p0 at 0°
    // through −100° to −250° (= 110°): 250° again, now clockwise seen along U×V.
    PathShape.Arc back = PathShape.Arc.through(onCircle(0), onCircle(-100), onCircle(-250));
    assertClose(back.e2(), V.times(-1), 1e-12);
    assertThat(back.sweepRad()).isCloseTo(Math.toRadians(250), within(1e-12));
    // A short arc: 30° of the circle.
    PathShape.Arc shortArc = PathShape.Arc.through(onCircle(40), onCircle(50), onCircle(70));
    assertThat(shortArc.sweepRad()).isCloseTo(Math.toRadians(30), within(1e-12));
    assertThat(shortArc.start()).isEqualTo(onCircle(40));
    assertClose(shortArc.displacement(1), onCircle(70).minus(onCircle(40)), 1e-9);
  }

  @Test
  void pointsOnALineOrTogetherMakeNoArc() {
    Vec3 a = new Vec3(1, 2, 3);
    Vec3 d = new Vec3(3, -4, 12);
    assertThat(PathShape.Arc.through(a, a.plus(d), a.plus(d.times(2.5)))).isNull();
    assertThat(PathShape.Arc.through(a, a.plus(d), a.plus(d.times(-1)))).isNull();
    assertThat(PathShape.Arc.through(a, a, a.plus(d))).isNull();
    assertThat(PathShape.Arc.through(a, a.plus(d), a)).isNull();
    // Not quite a line (the third point 1e-3 of the length off it, sin ≈ 6e-5): still a circle.
    Vec3 off = new Vec3(12, 3, 0).times(1e-3 / 13);
    PathShape.Arc flat = PathShape.Arc.through(a, a.plus(d), a.plus(d.times(2)).plus(off));
    assertThat(flat).isNotNull();
    assertThat(flat.radius()).isGreaterThan(1e3);
    assertThat(ArcPoints.continuationVia(a, a.plus(d), a.plus(d.times(3)))).isEmpty();
  }

  @Test
  void aLineIsItsDeltaScaled() {
    PathShape.Line line = new PathShape.Line(new Vec3(3, 4, 12));
    assertThat(line.lengthMm()).isEqualTo(13);
    assertClose(line.displacement(0.25), new Vec3(0.75, 1, 3), 1e-15);
  }

  @Test
  void continuationViaIsHalfwayAlongTheRestOfTheArc() {
    // p1 at 100°, p2 at 250°: the via is at 175°.
    Optional<Vec3> via = ArcPoints.continuationVia(onCircle(0), onCircle(100), onCircle(250));
    assertThat(via).isPresent();
    assertClose(via.get(), onCircle(175), 1e-9);
    // p1 beyond 180° (its atan2 angle is negative): p1 at 200°, p2 at 300° → 250°.
    assertClose(ArcPoints.continuationVia(onCircle(0), onCircle(200), onCircle(300)).orElseThrow(), onCircle(250), 1e-9);
    // Short: 10°, 20° → 15°.
    assertClose(ArcPoints.continuationVia(onCircle(0), onCircle(10), onCircle(20)).orElseThrow(), onCircle(15), 1e-9);
  }

  // ---- PoseTracker -----------------------------------------------------------------------------

  static final RobotModel MODEL = RobotDefinitions.defaultRobot();

  @Test
  void trackerLandsOnThePoseForwardKinematicsGives() {
    PoseTracker tracker = new PoseTracker(MODEL);
    double[] goal = {0.3, 0.2, -0.1, 0.5, -0.8, 1.0};
    Transform X_FT = Transform.rotation(1, 0, 0, 0.3).withTranslation(10, -20, 150);
    Transform target = ForwardKinematics.flangePoseInWorld(MODEL, goal).compose(X_FT);
    double[] q = goal.clone();
    for (int i = 0; i < 6; i++) {
      q[i] += (i % 2 == 0 ? 0.01 : -0.008);
    }
    assertThat(tracker.track(q, target, X_FT, 1e-3, 1e-6)).isTrue();
    Transform reached = ForwardKinematics.flangePoseInWorld(MODEL, q).compose(X_FT);
    assertThat(reached.distanceTo(target)).isLessThan(1e-6);
    assertThat(reached.rotationAngleTo(target)).isLessThan(1e-9);
    assertThat(tracker.positionErrorMm()).isLessThan(1e-6).isCloseTo(reached.distanceTo(target), within(1e-6));
    assertThat(tracker.rotationErrorRad()).isLessThan(1e-9);
    assertThat(tracker.lastIterations()).isBetween(1, PoseTracker.MAX_ITERATIONS);
    for (int i = 0; i < 6; i++) {
      assertThat(q[i]).isCloseTo(goal[i], within(1e-6));
    }
    // Already there: no step at all.
    double[] again = goal.clone();
    assertThat(tracker.track(again, target, X_FT, 1e-3, 1e-6)).isTrue();
    assertThat(tracker.lastIterations()).isZero();
    assertThat(again).containsExactly(goal);
    assertThat(tracker.chain().withinLimits(goal)).isTrue();
  }

  @Test
  void trackerReportsAPoseOutOfReachAsMissed() {
    PoseTracker tracker = new PoseTracker(MODEL);
    double[] q = {0.3, 0.2, -0.1, 0.5, -0.8, 1.0};
    Transform far = ForwardKinematics.flangePoseInWorld(MODEL, q).compose(Transform.translation(0, 0, 0));
    far = far.withTranslation(far.x() + 3000, far.y(), far.z());
    assertThat(tracker.track(q, far, Transform.IDENTITY, 0.01, 1e-4)).isFalse();
    assertThat(tracker.lastIterations()).isEqualTo(PoseTracker.MAX_ITERATIONS);
    assertThat(tracker.positionErrorMm()).isGreaterThan(0.01);
    Transform reached = ForwardKinematics.flangePoseInWorld(MODEL, q);
    assertThat(tracker.positionErrorMm()).isCloseTo(reached.distanceTo(far), within(1e-6));
    // Only the orientation asked differently (10°): tolerance in rad respected either way.
    double[] q2 = {0.3, 0.2, -0.1, 0.5, -0.8, 1.0};
    Transform turned = ForwardKinematics.flangePoseInWorld(MODEL, q2).compose(Transform.rotation(0, 0, 1, Math.toRadians(10)));
    assertThat(tracker.track(q2, turned, Transform.IDENTITY, 0.01, 1e-4)).isTrue();
    // lrmate200id.json: J6 turns about −x of link 6 and the flange (rpy 180, −90, 0) has its z along
    // +x, so turning the flange +10° about its z is J6 − 10°, the other joints unchanged.
    assertThat(q2[5]).isCloseTo(1.0 - Math.toRadians(10), within(1e-6));
    assertThat(q2[0]).isCloseTo(0.3, within(1e-6));
    assertThat(q2[4]).isCloseTo(-0.8, within(1e-6));
  }

  @Test
  void manipulabilityFallsTowardsTheWristSingularity() {
    PoseTracker tracker = new PoseTracker(MODEL);
    double[] bent = {0, 0.2, -0.1, 0.3, -1.0, 0.2};
    double[] straight = {0, 0.2, -0.1, 0.3, -1e-3, 0.2};
    double[] q = bent.clone();
    q[0] += 0.01;
    tracker.track(q, ForwardKinematics.flangePoseInWorld(MODEL, bent), Transform.IDENTITY, 0.01, 1e-4);
    double wide = tracker.manipulability();
    q = straight.clone();
    q[0] += 0.01;
    tracker.track(q, ForwardKinematics.flangePoseInWorld(MODEL, straight), Transform.IDENTITY, 0.01, 1e-4);
    assertThat(wide).isGreaterThan(0);
    assertThat(tracker.manipulability()).isLessThan(wide * 0.01);
  }
}
