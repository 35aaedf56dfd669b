package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The numeric solver's quick rejection (docs/kinematics.md, "Unreachable targets": for an arm
 * without the closed form, a reach sphere around J2 before any restart). No point of the arm is
 * farther from the circle that J2's origin sweeps about the J1 axis than the sum of the offsets
 * from J2 on, flange included: the bound is worked out here from the link poses at q = 0, for the
 * oblique test arm as built, on a wall and turned about an oblique axis and moved, and for the
 * CRX-10iA (no closed form) on that oblique mount, and written with every link frame turned and
 * slid along its joint axis (ReframedChainInvarianceTest), so the J1 axis need not be the base's
 * z axis nor J2 level with J1's origin.
 * <ul>
 *   <li>a target beyond the bound is OUT_OF_REACH at once, its message giving the distance and
 *       the bound computed here;
 *   <li>the targets made by FK inside the limits that lie closest to the bound (the most
 *       stretched of 4000 random joint vectors) are never called out of reach: solved from home,
 *       with the error FK measures.
 * </ul>
 * A reach test made about the base's z axis instead of J1's turned such targets away on the
 * oblique mount ("1133 mm from the shoulder, beyond the 1083 mm reach").
 */
class NumericIkReachTest {

  static Stream<String> mounts() {
    return Stream.of("as built", "wall", "oblique", "crx oblique", "rewritten");
  }

  static RobotModel arm(String mount) {
    RobotModel m = KinematicChainOracleTest.obliqueArm();
    return switch (mount) {
      case "wall" -> MountedArmInvarianceTest.mounted(m, Transform.translation(0, 300, 500).compose(Transform.rotation(1, 0, 0, Math.PI / 2)));
      case "oblique" -> MountedArmInvarianceTest.mounted(m, MountedArmInvarianceTest.MOUNT);
      case "rewritten" -> ReframedChainInvarianceTest.rewritten(m, new ReframedChainInvarianceTest.Rewrite(
          ReframedChainInvarianceTest.BASE, Transform.IDENTITY, 29, new int[] {1, 1, 1, 1, 1, 1}));
      case "crx oblique" -> MountedArmInvarianceTest.mounted(org.robotrun.io.RobotDefinitions.load("crx10ia"),
          MountedArmInvarianceTest.MOUNT);
      default -> m;
    };
  }

  /** The reach bound (mm): the offsets from J2 on, flange included. */
  static double bound(RobotModel m) {
    double r = m.X_6F().translationVector().norm();
    for (int i = 2; i < 6; i++) {
      r += m.joint(i).X_PJ().translationVector().norm();
    }
    return r;
  }

  /** Distance (mm) of p from the circle J2's origin sweeps about the J1 axis, from the link poses at q = 0. */
  static double fromShoulderCircle(RobotModel m, Vec3 p) {
    Transform[] L = ForwardKinematics.linkPosesInBase(m, new double[6]);
    Vec3 o = L[1].translationVector();
    Vec3 a = L[1].rotate(m.joint(0).axis()).normalized();
    Vec3 s = L[2].translationVector().minus(o);
    Vec3 v = p.minus(o);
    double sAlong = s.dot(a), vAlong = v.dot(a);
    double sOff = s.minus(a.times(sAlong)).norm(), vOff = v.minus(a.times(vAlong)).norm();
    return Math.hypot(vOff - sOff, vAlong - sAlong);
  }

  @ParameterizedTest
  @MethodSource("mounts")
  void aTargetBeyondTheReachBoundIsRefusedWithItsDistance(String mount) {
    RobotModel m = arm(mount);
    assertThat(m.opw()).isEmpty();
    Transform[] L = ForwardKinematics.linkPosesInBase(m, new double[6]);
    Vec3 o = L[1].translationVector();
    Vec3 a = L[1].rotate(m.joint(0).axis()).normalized();
    Vec3 s = L[2].translationVector();
    Vec3 off = s.minus(o).minus(a.times(s.minus(o).dot(a)));
    // Out from the J1 axis toward J2 (any way out when J2 sits on the axis, as on the CRX).
    Vec3 side = off.norm() > 1e-6 ? off.normalized() : a.cross(Math.abs(a.x()) < 0.9 ? Vec3.X : Vec3.Y).normalized();
    double r = bound(m);
    NumericIk ik = new NumericIk(m);
    // Beyond the bound: along the J1 axis over the shoulder, and out sideways from it.
    for (Vec3 p : new Vec3[] {s.plus(a.times(r + 40)), s.plus(side.times(r + 25.3)), s.minus(a.times(r + 60)).plus(side.times(30))}) {
      Transform X = Transform.translation(p.x(), p.y(), p.z());
      double d = fromShoulderCircle(m, p);
      assertThat(d).isGreaterThan(r + 20);
      IkResult res = ik.solve(X, new double[6]);
      assertThat(res).as("%s: %s", mount, p).isInstanceOf(IkResult.Unreachable.class);
      IkResult.Unreachable u = (IkResult.Unreachable) res;
      assertThat(u.reason()).isEqualTo(IkResult.Reason.OUT_OF_REACH);
      assertThat(u.message()).as(mount).isEqualTo(String.format(Locale.ROOT,
          "position (%.1f, %.1f, %.1f) mm is %.0f mm from the shoulder, beyond the %.0f mm reach", p.x(), p.y(), p.z(), d, r));
    }
  }

  @ParameterizedTest
  @MethodSource("mounts")
  void theMostStretchedReachableTargetsAreSolvedNotRefused(String mount) {
    RobotModel m = arm(mount);
    Random rnd = new Random(77);
    List<double[]> qs = new ArrayList<>();
    java.util.Map<double[], Double> reach = new java.util.IdentityHashMap<>();
    for (int k = 0; k < 4000; k++) {
      double[] q = NumericIkSpecTest.random(m, rnd);
      qs.add(q);
      reach.put(q, fromShoulderCircle(m, ForwardKinematics.flangePoseInBase(m, q).translationVector()));
    }
    qs.sort(Comparator.comparingDouble((double[] q) -> reach.get(q)).reversed());
    double r = bound(m);
    NumericIk ik = new NumericIk(m);
    for (double[] q : qs.subList(0, 6)) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      assertThat(fromShoulderCircle(m, X.translationVector())).isLessThanOrEqualTo(r);
      IkResult res = ik.solve(X, new double[6]);
      assertThat(res).as("%s: target of %s", mount, java.util.Arrays.toString(q)).isInstanceOf(IkResult.Solved.class);
      IkResult.Solved sv = (IkResult.Solved) res;
      Transform got = ForwardKinematics.flangePoseInBase(m, sv.q());
      assertThat(got.distanceTo(X)).isLessThan(1e-6);
      assertThat(sv.positionErrorMm()).isCloseTo(got.distanceTo(X), org.assertj.core.api.Assertions.within(1e-9));
      assertThat(sv.orientationErrorRad()).isLessThan(1e-9);
    }
  }
}
