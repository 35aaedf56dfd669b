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
 * singular value, not from J5 = 0: a UR5 whose J5 zero is turned by 0.7 rad (its joint origin
 * turned about the J5 axis) is the same arm with J5 read 0.7 rad higher, and keeps every flag,
 * while its solutions are the original ones with J5 moved by 0.7 rad.
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
  void fIsMeasuredFromJ5sSingularValueNotFromItsZero() {
    double delta = 0.7;
    List<JointSpec> js = new ArrayList<>(UR5.joints());
    JointSpec j5 = js.get(4);
    js.set(4, new JointSpec(j5.name(), j5.X_PJ().compose(Transform.rotation(0, 0, 1, -delta)), j5.axis(),
        j5.lowerRad(), j5.upperRad(), j5.maxSpeedRadPerSec()));
    RobotModel turned = RobotModel.fromChain("ur5-j5-turned", "UR5, J5 zero turned", js, UR5.X_6F(), UR5.X_WB(),
        UR5.links(), false);
    assertThat(j5.axis()).isEqualTo(Vec3.Z);
    UrTypeIk plain = new UrTypeIk(UR5);
    UrTypeIk other = new UrTypeIk(turned);
    for (double[] q : IkSolverContractTest.samples(UR5, 611, 6)) {
      double[] qt = q.clone();
      qt[4] += delta;
      Transform X = ForwardKinematics.flangePoseInBase(UR5, q);
      assertThat(ForwardKinematics.flangePoseInBase(turned, qt).distanceTo(X)).isLessThan(1e-9);
      assertThat(other.configOf(qt)).as("q = %s", java.util.Arrays.toString(q)).isEqualTo(plain.configOf(q));
      List<double[]> a = plain.baseSolutions(X);
      List<double[]> b = other.baseSolutions(X);
      assertThat(b).hasSameSizeAs(a);
      for (double[] s : a) {
        double[] st = s.clone();
        st[4] += delta;
        assertThat(b.stream().anyMatch(o -> OffsetWristCompletenessTest.wrappedDiff(o, st) < 1e-9)).isTrue();
        assertThat(other.configOf(st).sameBranch(plain.configOf(s))).isTrue();
      }
    }
  }
}
