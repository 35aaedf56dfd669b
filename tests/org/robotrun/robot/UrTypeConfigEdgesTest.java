package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The UR-type CONFIG at its edges (docs/kinematics.md, "The UR-type closed form"): the flags need
 * strictly positive margins ("U when … &gt; 0", "F when J5 is on the positive side of its singular
 * value"), so the exactly stretched elbow of the UR5 at q = 0 (J2, J3, J4 in one line) is D and
 * its exactly singular wrist (J6 in line with J2..J4) is N; a millidegree either way flips each. F is measured from J5's
 * singular value, not from J5 = 0: an arm whose joint zeros are all turned (each joint origin
 * turned about its own axis, as a URDF's origin rpy may do) is the same arm with its joints read
 * that much higher, and keeps every flag, while its solutions are the original ones moved by the
 * same amounts.
 */
class UrTypeConfigEdgesTest {
  static final RobotModel UR5 = IkSolverContractTest.ur5(Math.PI);

  @Test
  void theExactlyStretchedElbowIsDAndTheExactlySingularWristIsN() {
    UrTypeIk ur = new UrTypeIk(UR5);
    for (double[] q : new double[][] {{0, 0, 0, 0, 0, 0}, {0.3, -0.4, 0, 0.2, 0, 0.1}, {-1.2, 0.9, 0, -2.0, 0, 1.0}}) {
      if (q[0] == 0) {
        // At q = 0 every link vector of the DH UR5 lies along a base axis: the margins are exactly 0.
        Config c = ur.configOf(q);
        assertThat(c.up()).as("J3 = 0").isFalse();
        assertThat(c.flip()).as("J5 = 0").isFalse();
      }
      double[] bent = q.clone();
      bent[2] = 1e-3;
      bent[4] = 1e-3;
      double[] other = q.clone();
      other[2] = -1e-3;
      other[4] = -1e-3;
      // The usual layout: J5 = 0 lines J6 up with J2..J4, and F is J5 > 0.
      assertThat(ur.configOf(bent).flip()).isTrue();
      assertThat(ur.configOf(other).flip()).isFalse();
      assertThat(ur.configOf(bent).up()).isNotEqualTo(ur.configOf(other).up());
    }
  }

  @Test
  void turningEveryJointsZeroKeepsTheArmItsSolutionsAndItsFlags() {
    // Each joint's origin turned about its own axis by delta_i: the same arm, read delta_i higher.
    // The zero posture moves with J2 and J3 (W stays well in front at the new zero, so the T
    // orientation is unchanged); J5's singular value moves with its zero, so F is kept.
    double[] delta = {0.3, -0.4, 0.5, 0.6, 0.7, -0.8};
    for (RobotModel m : new RobotModel[] {UR5, UrTypeGeneralLayoutTest.oblique()}) {
      List<JointSpec> js = new ArrayList<>();
      for (int i = 0; i < 6; i++) {
        JointSpec j = m.joint(i);
        Vec3 a = j.axis();
        js.add(new JointSpec(j.name(), j.X_PJ().compose(Transform.rotation(a.x(), a.y(), a.z(), -delta[i])), a,
            j.lowerRad() + delta[i], j.upperRad() + delta[i], j.maxSpeedRadPerSec()));
      }
      RobotModel turned = RobotModel.fromChain(m.id() + "-zeros", "zeros turned", js, m.X_6F(), m.X_WB(), m.links(), false);
      UrTypeIk plain = new UrTypeIk(m);
      UrTypeIk other = new UrTypeIk(turned);
      for (double[] q : IkSolverContractTest.samples(m, 611, 6)) {
        double[] qt = q.clone();
        for (int i = 0; i < 6; i++) {
          qt[i] += delta[i];
        }
        String what = m.id() + " at " + java.util.Arrays.toString(q);
        Transform X = ForwardKinematics.flangePoseInBase(m, q);
        assertThat(ForwardKinematics.flangePoseInBase(turned, qt).distanceTo(X)).isLessThan(1e-9);
        Config c = plain.configOf(q);
        assertThat(other.configOf(qt)).as(what).isEqualTo(new Config(c.flip(), c.up(), c.top(),
            Config.turnOf(qt[0]), Config.turnOf(qt[3]), Config.turnOf(qt[5])));
        List<double[]> a = plain.baseSolutions(X);
        List<double[]> b = other.baseSolutions(X);
        assertThat(b).as(what).hasSameSizeAs(a);
        for (double[] s : a) {
          double[] st = s.clone();
          for (int i = 0; i < 6; i++) {
            st[i] += delta[i];
          }
          assertThat(b.stream().anyMatch(o -> OffsetWristCompletenessTest.wrappedDiff(o, st) < 1e-9)).as(what).isTrue();
          assertThat(other.configOf(st).sameBranch(plain.configOf(s))).as(what).isTrue();
        }
        IkResult near = other.solveNearest(X, qt);
        assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), qt)).as(what).isLessThan(1e-9);
      }
    }
  }
}
