package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * Resolved-rate steps on the LR Mate mounted at a slant (MountedArmInvarianceTest's mount: J1's
 * axis along no base axis, so every row of the Jacobian has a part from J1). Away from the
 * singularities the joint rates must give the asked TCP twist exactly: measured here by central
 * differences of {@link ForwardKinematics} (linear velocity of the flange origin, angular
 * velocity from R(q + h·q̇)·R(q − h·q̇)ᵀ). Near the wrist singularity the step is damped, and it
 * returns the manipulability it reports.
 */
class ResolvedRateMountedTest {

  @Test
  void theJointRatesGiveTheAskedTwistOnASlantedMount() {
    RobotModel m = MountedArmInvarianceTest.mounted(RobotDefinitions.load("lrmate200id"), MountedArmInvarianceTest.MOUNT);
    ResolvedRate rr = new ResolvedRate(m);
    double[] q = {0.3, 0.2, -0.4, 0.5, -0.9, 1.1};
    double[] twist = {10, -20, 5, 0.1, 0.05, -0.2};
    double[] qDot = new double[6];
    double w = rr.step(q, twist, null, qDot);
    assertThat(rr.lastDamping()).isZero();
    assertThat(w).isEqualTo(rr.lastManipulability()).isGreaterThan(rr.settings().manipulabilityThreshold());
    double h = 1e-6;
    double[] qa = q.clone(), qb = q.clone();
    for (int i = 0; i < 6; i++) {
      qa[i] += h * qDot[i];
      qb[i] -= h * qDot[i];
    }
    Transform a = ForwardKinematics.flangePoseInBase(m, qa), b = ForwardKinematics.flangePoseInBase(m, qb);
    double[] v = {(a.x() - b.x()) / (2 * h), (a.y() - b.y()) / (2 * h), (a.z() - b.z()) / (2 * h)};
    double[] r = a.compose(b.inverse()).rotationRowMajor();
    double[] omega = {0.5 * (r[7] - r[5]) / (2 * h), 0.5 * (r[2] - r[6]) / (2 * h), 0.5 * (r[3] - r[1]) / (2 * h)};
    for (int k = 0; k < 3; k++) {
      assertThat(v[k]).as("v%d", k).isCloseTo(twist[k], org.assertj.core.api.Assertions.within(1e-4));
      assertThat(omega[k]).as("w%d", k).isCloseTo(twist[3 + k], org.assertj.core.api.Assertions.within(1e-6));
    }
  }

  @Test
  void nearTheWristSingularityTheDampedStepReturnsItsManipulability() {
    RobotModel m = RobotDefinitions.load("lrmate200id");
    ResolvedRate rr = new ResolvedRate(m);
    double[] q = {0.3, 0.2, -0.4, 0.5, 1e-4, 1.1};
    double[] qDot = new double[6];
    double w = rr.step(q, new double[] {10, 0, 0, 0, 0, 0}, null, qDot);
    assertThat(rr.lastDamping()).isPositive();
    assertThat(w).isEqualTo(rr.lastManipulability()).isPositive().isLessThan(rr.settings().manipulabilityThreshold());
  }
}
