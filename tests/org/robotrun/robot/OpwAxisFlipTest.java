package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * A joint whose axis is written the other way round (a URDF's {@code axis="0 -1 0"} for
 * {@code "0 1 0"}) turns the arm the same way for the negated angle. So the arm with joint i's
 * axis and limits negated is the same machine: its derived OPW parameters have the same lengths
 * and that joint's sign correction flipped (OpwDerivation: signs compare each axis with OPW's
 * positive one), and the pose X has exactly the solutions of the original with joint i negated,
 * with the same elbow and arm-side flags (F/N, the sign of J5, flips with J5 itself).
 */
class OpwAxisFlipTest {

  static RobotModel flipped(RobotModel m, int i) {
    List<JointSpec> js = new ArrayList<>(m.joints());
    JointSpec j = js.get(i);
    js.set(i, new JointSpec(j.name(), j.X_PJ(), j.axis().times(-1), -j.upperRad(), -j.lowerRad(), j.maxSpeedRadPerSec()));
    return RobotModel.fromChain(m.id() + "-flip" + (i + 1), m.displayName(), js, m.X_6F(), m.X_WB(), m.links(), m.coupledJ3());
  }

  @ParameterizedTest
  @ValueSource(strings = {"lrmate200id", "m20ia"})
  void eachAxisWrittenTheOtherWayRoundIsTheSameArm(String id) {
    RobotModel m = RobotDefinitions.load(id);
    OpwParameters p = m.opw().orElseThrow();
    ClosedFormIk ik = new ClosedFormIk(m);
    List<double[]> qs = IkSolverContractTest.samples(m, 440 + id.length(), 3);
    for (int i = 0; i < 6; i++) {
      RobotModel f = flipped(m, i);
      String what = id + " with J" + (i + 1) + " flipped";
      OpwParameters pf = f.opw().orElseThrow(() -> new AssertionError(what + ": no closed form"));
      assertThat(new double[] {pf.a1(), pf.a2(), pf.b(), pf.c1(), pf.c2(), pf.c3(), pf.c4()}).as(what)
          .containsExactly(new double[] {p.a1(), p.a2(), p.b(), p.c1(), p.c2(), p.c3(), p.c4()},
              org.assertj.core.api.Assertions.within(1e-9));
      for (int k = 0; k < 6; k++) {
        assertThat(pf.sign(k)).as("%s: sign %d", what, k + 1).isEqualTo(k == i ? -p.sign(k) : p.sign(k));
      }
      ClosedFormIk fk = new ClosedFormIk(f);
      for (double[] q : qs) {
        Transform X = ForwardKinematics.flangePoseInBase(m, q);
        double[] qf = q.clone();
        qf[i] = -qf[i];
        assertThat(ForwardKinematics.flangePoseInBase(f, qf).distanceTo(X)).isLessThan(1e-9);
        List<IkSolver.Solution> a = ik.allSolutions(X);
        List<IkSolver.Solution> b = fk.allSolutions(X);
        assertThat(b).as(what).hasSameSizeAs(a);
        for (IkSolver.Solution s : a) {
          double[] sf = s.q().clone();
          sf[i] = -sf[i];
          int joint = i;
          assertThat(b.stream().anyMatch(o -> IkSolverContractTest.maxDiff(o.q(), sf) < 1e-6
              && o.config().up() == s.config().up() && o.config().top() == s.config().top()
              && o.config().flip() == (joint == 4 ? !s.config().flip() : s.config().flip())))
              .as("%s: %s mirrored", what, s.config()).isTrue();
        }
        Config cf = fk.configOf(qf);
        IkResult r = fk.solve(X, cf);
        assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) r).q(), qf)).as("%s: solve %s", what, cf).isLessThan(1e-6);
      }
    }
  }
}
