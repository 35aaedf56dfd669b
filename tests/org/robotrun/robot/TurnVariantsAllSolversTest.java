package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.math.Transform;

/**
 * {@link IkSolver#allSolutions} of every closed-form solver (OPW on the LR Mate, the CRX search,
 * the UR-type closed form on a UR5) lists "every solution inside the limits, each turn variant
 * separately". A robot file may give a joint up to ±1080° (three turns, docs/robots.md): with J1,
 * J4 and J6 widened to ±1080°, the listed solutions that equal the truth modulo 2π in every joint
 * must be exactly as many as the test counts itself, the product over the joints of the whole turns
 * k with q + 2πk inside that joint's limits (6 or 7 each for the widened joints, more than a fixed
 * −2..2 gives), each inside the limits.
 */
class TurnVariantsAllSolversTest {
  static final double TWO_PI = 2 * Math.PI;

  static List<String> arms() {
    return List.of("lrmate200id", "crx10ia", "ur5");
  }

  @ParameterizedTest
  @MethodSource("arms")
  void everyWholeTurnOfTheTruthInsideThreeTurnLimitsIsListedOnce(String id) {
    RobotModel m = OffsetWristTurnsTest.wide(IkSolverContractTest.arm(id));
    IkSolver ik = IkSolver.forModel(m);
    assertThat(ik.kind()).isEqualTo(IkSolverContractTest.expectedKind(id));
    for (double[] q : IkSolverContractTest.samples(m, 1080, 3)) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      long expected = 1;
      for (int j = 0; j < 6; j++) {
        int turns = 0;
        for (int k = -5; k <= 5; k++) {
          if (m.joint(j).withinLimits(q[j] + TWO_PI * k)) {
            turns++;
          }
        }
        expected *= turns;
      }
      List<IkSolver.Solution> all = ik.allSolutions(X);
      String what = id + " pose " + Arrays.toString(q);
      assertThat(expected).as(what).isGreaterThanOrEqualTo(6 * 6 * 6);
      assertThat(all.stream().filter(s -> OffsetWristCompletenessTest.wrappedDiff(s.q(), q) < 1e-6).count())
          .as(what).isEqualTo(expected);
      for (IkSolver.Solution s : all) {
        assertThat(m.firstJointOutsideLimits(s.q())).as(what).isEqualTo(-1);
      }
    }
  }
}
