package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The numeric solver's orientation error is the rotation vector of R_d·Rᵀ (NumericIk's class
 * comment: {@code log(R_d·Rᵀ)}), also at a half turn, where the angle is π and the axis comes from
 * the symmetric part of the matrix. A start that differs from the target's joints only by half a
 * turn of J6 (the flange origin on the J6 axis, so no position error) then has an error of π
 * about the J6 axis, which the J6 column of the Jacobian undoes: the first attempt, from the
 * caller's start, converges (within its 20 iterations, Settings.defaults), with the J6 axis
 * mostly along base x, y or z and off the other two (both signs), so every case of the axis
 * extraction is met. A wrong axis would send the first attempt astray and leave it to the
 * restarts.
 */
class NumericIkHalfTurnTest {
  static final RobotModel LRMATE = NumericIkSpecTest.LRMATE;

  @Test
  void aStartHalfATurnOfJ6AwayConvergesInTheFirstAttempt() {
    double[][] targets = {
      {0.3, -0.2, 0.4, -0.3, 1.2, 0.2},
      {0.3, 0.1, -0.1, 0.2, -1.2, 0.2},
      {1.87, 0.1, -0.1, 0.2, -1.2, 0.2},
      {1.87, -0.2, 0.4, -0.3, 1.2, 0.2},
      {0.3, 0.1, -0.1, 0.2, -0.3, 0.2},
      {0.3, 0.1, -0.1, 0.2, 0.6, 0.2},
    };
    boolean[] dominant = new boolean[3];
    NumericIk ik = new NumericIk(LRMATE);
    for (double[] q : targets) {
      Transform X = ForwardKinematics.flangePoseInBase(LRMATE, q);
      Vec3 j6 = X.axis(0);
      double[] c = {Math.abs(j6.x()), Math.abs(j6.y()), Math.abs(j6.z())};
      int big = c[0] >= c[1] && c[0] >= c[2] ? 0 : c[1] >= c[2] ? 1 : 2;
      dominant[big] = true;
      assertThat(Math.min(c[(big + 1) % 3], c[(big + 2) % 3])).as("J6 axis %s off the other base axes", j6).isGreaterThan(0.1);
      double[] start = q.clone();
      start[5] += Math.PI;
      Transform S = ForwardKinematics.flangePoseInBase(LRMATE, start);
      assertThat(S.distanceTo(X)).isLessThan(1e-9);
      assertThat(S.rotationAngleTo(X)).isCloseTo(Math.PI, org.assertj.core.api.Assertions.within(1e-9));
      IkResult r = ik.solve(X, start);
      NumericIkSpecTest.exact(LRMATE, r, X, 1e-6, 1e-9, "half a turn of J6 from " + Arrays.toString(q));
      assertThat(((IkResult.Solved) r).iterations()).as("iterations from %s", Arrays.toString(start))
          .isLessThanOrEqualTo(NumericIk.Settings.defaults().iterationsPerAttempt());
    }
    assertThat(dominant).containsOnly(true);
  }
}
