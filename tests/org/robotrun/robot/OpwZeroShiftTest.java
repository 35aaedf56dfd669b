package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * An arm whose joint i reads zero at another angle is the same machine: a file may put a joint's
 * zero anywhere (a URDF's joint origin turned about the joint's own axis by θ, its limits moved by
 * −θ), and the arm at q' = q − θ (joint i only) stands exactly where the original stands at q. So
 * OPW must still be derived (docs/kinematics.md: parameters from the chain, whatever its zero
 * pose), exact, its forward kinematics must be the chain's (at q' = 0 and at the test poses), and
 * the closed form must give for each pose every one of the original's solutions with joint i
 * less θ, each reaching the pose inside the limits. The shifts put the wrist
 * centre behind J2, the forearm pointing back, the wrist turned and the flange turned at q = 0:
 * zero poses no library arm has, each a branch of the derivation's frame choice.
 */
class OpwZeroShiftTest {

  /** Joint i's zero moved: X_PJ turned about the joint's axis by θ, limits moved by −θ. */
  static RobotModel shifted(RobotModel m, int i, double theta) {
    List<JointSpec> js = new ArrayList<>(m.joints());
    JointSpec j = js.get(i);
    Vec3 a = j.axis();
    js.set(i, new JointSpec(j.name(), j.X_PJ().compose(Transform.rotation(a.x(), a.y(), a.z(), theta)), a,
        j.lowerRad() - theta, j.upperRad() - theta, j.maxSpeedRadPerSec()));
    return RobotModel.fromChain(m.id() + "-zero" + (i + 1), m.displayName(), js, m.X_6F(), m.X_WB(), m.links(),
        m.coupledJ3());
  }

  @ParameterizedTest
  @ValueSource(strings = {"lrmate200id", "m20ia", "r2000ic165f"})
  void aJointWhoseZeroIsElsewhereIsTheSameArm(String id) {
    RobotModel m = RobotDefinitions.load(id);
    OpwParameters p = m.opw().orElseThrow();
    ClosedFormIk ik = new ClosedFormIk(m);
    List<double[]> qs = IkSolverContractTest.samples(m, 520 + id.length(), 2);
    // Each joint alone, then J4 and J5 together (J5 turned 0.7 rad as well: the J6 axis then
    // lies off the forearm at q = 0, so J4's zero counts in the wrist's frame).
    for (int i = 0; i < 7; i++) {
      for (double theta : new double[] {Math.PI / 2, -Math.PI / 2, Math.PI, 0.4}) {
        double[] shift = new double[6];
        if (i < 6) {
          shift[i] = theta;
        } else {
          shift[3] = theta;
          shift[4] = 0.7;
        }
        RobotModel s = m;
        for (int j = 0; j < 6; j++) {
          if (shift[j] != 0) {
            s = shifted(s, j, shift[j]);
          }
        }
        String what = String.format("%s, zeros moved %s rad", id, java.util.Arrays.toString(shift));
        OpwParameters ps = s.opw().orElseThrow(() -> new AssertionError(what + ": no closed form"));
        assertThat(ps.approximate()).as(what).isFalse();
        assertThat(IkSolver.forModel(s).kind()).isEqualTo(ClosedFormIk.KIND);
        Transform atZero = ForwardKinematics.flangePoseInBase(s, new double[6]);
        assertThat(OpwDerivation.forward(ps, new double[6]).distanceTo(atZero)).as(what).isLessThan(1e-6);
        ClosedFormIk iks = new ClosedFormIk(s);
        for (double[] q : qs) {
          Transform X = ForwardKinematics.flangePoseInBase(m, q);
          double[] qsh = q.clone();
          for (int j = 0; j < 6; j++) {
            qsh[j] -= shift[j];
          }
          assertThat(ForwardKinematics.flangePoseInBase(s, qsh).distanceTo(X)).as("%s: FK", what).isLessThan(1e-9);
          assertThat(OpwDerivation.forward(ps, qsh).distanceTo(X)).as("%s: OPW FK", what).isLessThan(1e-6);
          List<IkSolver.Solution> a = ik.allSolutions(X);
          List<IkSolver.Solution> b = iks.allSolutions(X);
          for (IkSolver.Solution sol : a) {
            double[] want = sol.q().clone();
            for (int j = 0; j < 6; j++) {
              want[j] -= shift[j];
            }
            if (s.firstJointOutsideLimits(want) >= 0) {
              continue;
            }
            // Modulo a turn: a shifted range may hold J2, J3 or J5 at another turn than the original's.
            assertThat(b.stream().anyMatch(o -> OffsetWristCompletenessTest.wrappedDiff(o.q(), want) < 1e-6))
                .as("%s: %s less θ", what, java.util.Arrays.toString(sol.q())).isTrue();
          }
          for (IkSolver.Solution sol : b) {
            IkSolverContractTest.reaches(s, sol.q(), X, what);
          }
        }
      }
    }
  }
}
