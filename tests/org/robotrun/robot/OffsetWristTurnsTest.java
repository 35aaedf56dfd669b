package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * {@link IkSolver#allSolutions} on the CRX lists "every solution inside the limits, each turn
 * variant separately". A robot file may give a joint up to ±1080° (three turns, docs/robots.md),
 * so with J1, J4 and J6 at ±1080° every base solution has up to 7 variants per joint. The test
 * counts the variants itself: for each joint vector q that reaches the pose, q + 2π·(k1, k4, k6)
 * for every k with each joint inside its limits; each must be listed once, with CONFIG turn
 * numbers {@link Config#turnOf} of its own joints. And a limit is inclusive to the last bit: with
 * J2's upper limit exactly at the truth's J2, the listed solutions at that limit lie on it, not a
 * rounding beyond it.
 */
class OffsetWristTurnsTest {
  static final double TWO_PI = 2 * Math.PI;
  static final double WIDE = Math.toRadians(1080);

  static RobotModel wide(RobotModel m) {
    RobotModel w = IkSolverContractTest.narrowed(m, 0, -WIDE, WIDE);
    w = IkSolverContractTest.narrowed(w, 3, -WIDE, WIDE);
    return IkSolverContractTest.narrowed(w, 5, -WIDE, WIDE);
  }

  @Test
  void everyTurnVariantOfEverySolutionInsideThreeTurnLimitsIsListedOnce() {
    RobotModel m = wide(RobotDefinitions.load("crx10ia"));
    OffsetWristIk ik = new OffsetWristIk(m);
    for (double[] q : IkSolverContractTest.samples(m, 1080, 3)) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      List<IkSolver.Solution> all = ik.allSolutions(X);
      List<double[]> base = ik.baseSolutions(X);
      String what = "pose " + Arrays.toString(q);
      assertThat(base.stream().anyMatch(b -> OffsetWristCompletenessTest.wrappedDiff(b, q) < 1e-6)).as(what).isTrue();
      // Each listed solution as (its base solution, its turns of J1, J4 and J6).
      java.util.Map<String, Integer> listed = new java.util.HashMap<>();
      for (IkSolver.Solution s : all) {
        int b = 0;
        while (b < base.size() && OffsetWristCompletenessTest.wrappedDiff(base.get(b), s.q()) > 1e-9) {
          b++;
        }
        assertThat(b).as("%s: %s is a turn of a base solution", what, Arrays.toString(s.q())).isLessThan(base.size());
        double[] o = base.get(b);
        listed.merge(b + ":" + Math.round((s.q()[0] - o[0]) / TWO_PI) + ":" + Math.round((s.q()[3] - o[3]) / TWO_PI)
            + ":" + Math.round((s.q()[5] - o[5]) / TWO_PI), 1, Integer::sum);
      }
      // The variants the limits allow, counted here: J2, J3 and J5 (ranges under a turn) as the one
      // value or ±2π variant inside, J1, J4 and J6 every turn inside.
      java.util.Map<String, Integer> expected = new java.util.HashMap<>();
      for (int b = 0; b < base.size(); b++) {
        double[] v = base.get(b).clone();
        for (int j : new int[] {1, 2, 4}) {
          for (int k = -1; k <= 1; k++) {
            if (m.joint(j).withinLimits(base.get(b)[j] + TWO_PI * k)) {
              v[j] = base.get(b)[j] + TWO_PI * k;
            }
          }
        }
        for (int k1 = -4; k1 <= 4; k1++) {
          for (int k4 = -4; k4 <= 4; k4++) {
            for (int k6 = -4; k6 <= 4; k6++) {
              double[] w = v.clone();
              w[0] += TWO_PI * k1;
              w[3] += TWO_PI * k4;
              w[5] += TWO_PI * k6;
              if (m.firstJointOutsideLimits(w) < 0) {
                expected.put(b + ":" + k1 + ":" + k4 + ":" + k6, 1);
              }
            }
          }
        }
      }
      assertThat(listed).as("%s: every variant inside the limits, once", what).isEqualTo(expected);
      // The truth's own variants: 1080° is three turns, so J1, J4 and J6 have 6 or 7 each.
      assertThat(all.stream().filter(s -> OffsetWristCompletenessTest.wrappedDiff(s.q(), q) < 1e-6).count()).as(what)
          .isGreaterThanOrEqualTo(6 * 6 * 6);
      for (IkSolver.Solution s : all) {
        assertThat(m.firstJointOutsideLimits(s.q())).isEqualTo(-1);
        assertThat(s.config()).isEqualTo(ik.configOf(s.q()));
        assertThat(s.config().turn6()).isEqualTo(Config.turnOf(s.q()[5]));
      }
    }
  }

  @Test
  void aSolutionAtALimitIsListedOnTheLimit() {
    RobotModel crx = RobotDefinitions.load("crx10ia");
    int onLimit = 0;
    for (double[] q : IkSolverContractTest.samples(crx, 1081, 6)) {
      for (int c = 0; c < 9; c++) {
        // Joint j's upper limit exactly at the truth's value, or for J1, J4 and J6 at its next turn
        // (the listed variant q + 2π lies on the limit): the limit is inclusive, nothing beyond it.
        int j = c < 6 ? c : new int[] {0, 3, 5}[c - 6];
        double at = c < 6 ? q[j] : q[j] + TWO_PI;
        double[] want = q.clone();
        want[j] = at;
        RobotModel m = IkSolverContractTest.narrowed(crx, j, crx.joint(j).lowerRad(), at);
        OffsetWristIk ik = new OffsetWristIk(m);
        Transform X = ForwardKinematics.flangePoseInBase(m, q);
        List<IkSolver.Solution> all = ik.allSolutions(X);
        assertThat(all.stream().anyMatch(s -> IkSolverContractTest.maxDiff(s.q(), want) < 1e-6))
            .as("J%d at its upper limit %s", j + 1, Arrays.toString(want)).isTrue();
        for (IkSolver.Solution s : all) {
          assertThat(m.firstJointOutsideLimits(s.q())).as("J%d limit, listed %s", j + 1, Arrays.toString(s.q()))
              .isEqualTo(-1);
          if (s.q()[j] == at) {
            onLimit++;
          }
        }
      }
    }
    assertThat(onLimit).as("solutions listed exactly on the limit").isPositive();
  }
}
