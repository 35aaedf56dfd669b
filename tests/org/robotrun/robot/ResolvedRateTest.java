package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.apache.commons.math3.linear.Array2DRowRealMatrix;
import org.apache.commons.math3.linear.RealMatrix;
import org.apache.commons.math3.linear.SingularValueDecomposition;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;

class ResolvedRateTest {
  private final RobotModel robot = RobotDefinitions.defaultRobot();
  private final KinematicChain chain = new KinematicChain(robot);
  private final double[] twist = {100, -50, 20, 0.1, -0.2, 0.3};

  @Test
  void awayFromSingularitiesTheJointRatesProduceTheTwistExactly() {
    // Method: J·q̇ with the unscaled Jacobian reproduces the asked twist to 1e-9 (mm/s, rad/s).
    ResolvedRate rr = new ResolvedRate(robot);
    double[] q = {0.3, 0.4, 0.2, 0.5, -0.8, 0.1};
    double[] qDot = new double[6];
    double w = rr.step(q, twist, null, qDot);
    assertThat(rr.lastDamping()).isZero();
    assertThat(w).isGreaterThan(ResolvedRate.Settings.defaults().manipulabilityThreshold());
    double[] J = jacobian(q);
    for (int r = 0; r < 6; r++) {
      double v = 0;
      for (int c = 0; c < 6; c++) {
        v += J[r * 6 + c] * qDot[c];
      }
      assertThat(v).isCloseTo(twist[r], within(1e-9));
    }
  }

  @Test
  void nearTheWristSingularityTheStepEqualsTheSvdDampedPseudoinverse() {
    // Method: same λ, SVD form Σ σ/(σ²+λ²)·v·uᵀ from Commons Math on the scaled Jacobian; 1e-9.
    ResolvedRate rr = new ResolvedRate(robot);
    for (double q5 : new double[] {0.02, 0.005, 1e-4, 0}) {
      double[] q = {0.3, 0.4, 0.2, 0.5, q5, 0.1};
      double[] qDot = new double[6];
      rr.step(q, twist, null, qDot);
      double lambda = rr.lastDamping();
      assertThat(lambda).as("q5=%s", q5).isPositive();
      double invL = 1 / rr.settings().lengthScaleMm();
      double[] J = jacobian(q);
      double[][] js = new double[6][6];
      double[] v = new double[6];
      for (int r = 0; r < 6; r++) {
        for (int c = 0; c < 6; c++) {
          js[r][c] = J[r * 6 + c] * (r < 3 ? invL : 1);
        }
        v[r] = twist[r] * (r < 3 ? invL : 1);
      }
      SingularValueDecomposition svd = new SingularValueDecomposition(new Array2DRowRealMatrix(js));
      RealMatrix U = svd.getU(), V = svd.getV();
      double[] s = svd.getSingularValues();
      for (int c = 0; c < 6; c++) {
        double expected = 0;
        for (int k = 0; k < 6; k++) {
          double ut = 0;
          for (int r = 0; r < 6; r++) {
            ut += U.getEntry(r, k) * v[r];
          }
          expected += V.getEntry(c, k) * s[k] / (s[k] * s[k] + lambda * lambda) * ut;
        }
        assertThat(qDot[c]).as("q5=%s joint %d", q5, c).isCloseTo(expected, within(1e-9));
      }
    }
  }

  @Test
  void dampingRisesSmoothlyAndRatesStayBoundedIntoTheSingularity() {
    // Method: sweep J5 from 0.3 rad to 0; damping is continuous, non-decreasing, and |q̇| bounded.
    ResolvedRate rr = new ResolvedRate(robot);
    double prevDamping = 0;
    double prevW = Double.POSITIVE_INFINITY;
    double maxRate = 0;
    for (int i = 300; i >= 0; i--) {
      double[] q = {0.3, 0.4, 0.2, 0.5, i * 1e-3, 0.1};
      double[] qDot = new double[6];
      double w = rr.step(q, twist, null, qDot);
      assertThat(w).isLessThanOrEqualTo(prevW + 1e-12);
      assertThat(rr.lastDamping()).isGreaterThanOrEqualTo(prevDamping - 1e-15);
      // Continuous: 1 mrad of J5 moves λ by a small fraction of λmax (0.05).
      assertThat(rr.lastDamping() - prevDamping).isLessThan(5e-3);
      prevDamping = rr.lastDamping();
      prevW = w;
      for (double d : qDot) {
        maxRate = Math.max(maxRate, Math.abs(d));
      }
    }
    assertThat(prevW).isLessThan(1e-12);
    assertThat(prevDamping).isCloseTo(ResolvedRate.Settings.defaults().maxDamping(), within(1e-6));
    assertThat(maxRate).isLessThan(50);
  }

  @Test
  void toolOffsetIsHonoured() {
    // A pure rotation twist about a TCP 200 mm along flange z must leave the TCP still.
    double[] toolPacked = new double[12];
    KinematicChain.pack(org.robotrun.math.Transform.translation(0, 0, 200), toolPacked, 0);
    ResolvedRate rr = new ResolvedRate(chain, ResolvedRate.Settings.defaults());
    double[] q = {0.3, 0.4, 0.2, 0.5, -0.8, 0.1};
    double[] qDot = new double[6];
    rr.step(q, new double[] {0, 0, 0, 0, 0, 0.5}, toolPacked, qDot);
    double h = 1e-6;
    double[] q2 = q.clone();
    for (int i = 0; i < 6; i++) {
      q2[i] += h * qDot[i];
    }
    var X1 = ForwardKinematics.flangePoseInBase(robot, q).compose(org.robotrun.math.Transform.translation(0, 0, 200));
    var X2 = ForwardKinematics.flangePoseInBase(robot, q2).compose(org.robotrun.math.Transform.translation(0, 0, 200));
    assertThat(X1.distanceTo(X2) / h).isLessThan(1e-3);
    assertThat(X1.rotationAngleTo(X2) / h).isCloseTo(0.5, within(1e-4));
  }

  private double[] jacobian(double[] q) {
    double[] J = new double[36];
    Jacobian.tcpJacobianInBase(chain, q, null, J, new double[12], new double[Jacobian.SCRATCH]);
    return J;
  }
}
