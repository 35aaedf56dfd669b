package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

/**
 * {@link NewtonPolish} from a start where no Newton step exists: the LR Mate at q = 0 has J4 and
 * J6 on one line through the flange (J5 = 0), so two Jacobian columns are equal and the matrix is
 * exactly singular (checked here element by element). From there it cannot step, so it only
 * judges the start, as its comment says: true exactly when the start is within 1e-6 mm and 1e-9
 * rad of the target, and the joints are left where they are. The targets are the start's own
 * flange pose moved by 0.5 mm only, turned by 1e-3 rad only, or moved by 1e-7 mm (within).
 */
class NewtonPolishSingularStartTest {
  static final RobotModel ARM = NewtonPolishTest.ARM;

  @Test
  void atAnExactlySingularStartItOnlyJudgesTheStart() {
    KinematicChain chain = new KinematicChain(ARM);
    double[] zero = new double[6];
    double[] jac = new double[36];
    double[] fk = new double[12];
    Jacobian.tcpJacobianInBase(chain, zero, null, jac, fk, new double[Jacobian.SCRATCH]);
    for (int r = 0; r < 6; r++) {
      assertThat(jac[6 * r + 3]).as("row %d: the J4 and J6 columns are equal", r).isEqualTo(jac[6 * r + 5]);
    }
    Transform F = ForwardKinematics.flangePoseInBase(ARM, zero);
    NewtonPolish polish = new NewtonPolish(chain);
    Transform moved = Transform.translation(0.3, -0.4, 0).compose(F);
    Transform turned = F.compose(Transform.rotation(0, 1, 0, 1e-3));
    Transform within = Transform.translation(0, 0, 1e-7).compose(F);
    assertThat(moved.distanceTo(F)).isCloseTo(0.5, org.assertj.core.api.Assertions.within(1e-12));
    assertThat(turned.distanceTo(F)).isLessThan(1e-9);
    double[] q = zero.clone();
    assertThat(polish.polish(q, NewtonPolishTest.packed(moved))).as("0.5 mm off").isFalse();
    assertThat(q).containsExactly(zero);
    assertThat(polish.polish(q, NewtonPolishTest.packed(turned))).as("1e-3 rad off").isFalse();
    assertThat(q).containsExactly(zero);
    assertThat(polish.polish(q, NewtonPolishTest.packed(within))).as("1e-7 mm off").isTrue();
    assertThat(q).containsExactly(zero);
  }
}
