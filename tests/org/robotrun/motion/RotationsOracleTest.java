package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The rotation vector (log of SO(3)) against its definition (issue 31): the rotation by θ about a
 * unit axis a has log θ·a, for θ from 0 to π (at π, ±π·a are both right) and axes along and off
 * the frame's, including the cases where the axis's largest component is x, y or z; exp undoes log.
 */
class RotationsOracleTest {
  static final Vec3[] AXES = {new Vec3(1, 0, 0), new Vec3(0, 1, 0), new Vec3(0, 0, 1),
      new Vec3(1, 2, 3).normalized(), new Vec3(-3, 1, 0.5).normalized(), new Vec3(0.2, -2, 1).normalized(),
      new Vec3(0.5, 0.5, -3).normalized()};

  @Test
  void logOfARotationAboutAnAxisIsTheAngleTimesTheAxis() {
    double[] out = new double[3];
    for (Vec3 a : AXES) {
      for (double theta : new double[] {0, 1e-9, 1e-7, 1e-3, 0.5, 1, 2, 3, Math.PI - 1e-4, Math.PI - 1e-9, Math.PI}) {
        Transform R = Transform.rotation(a.x(), a.y(), a.z(), theta);
        Rotations.log(R.rotationRowMajor(), out);
        Vec3 v = new Vec3(out[0], out[1], out[2]);
        Vec3 expected = a.times(theta);
        double err = Math.min(v.distanceTo(expected), theta > 3 ? v.distanceTo(expected.times(-1)) : Double.POSITIVE_INFINITY);
        assertThat(err).as("θ=%s about %s: %s", theta, a, v).isLessThan(1e-6 * Math.max(theta, 1e-3));
        // exp(log R) = R, and half of it twice is all of it (1e-8 rad: within a nano-radian of a
        // half turn the axis comes from the diagonal, good to about √ε).
        Transform back = Rotations.exp(v, 1);
        assertThat(back.rotationAngleTo(R)).isLessThan(1e-8);
        Transform half = Rotations.exp(v, 0.5);
        assertThat(half.compose(half).rotationAngleTo(R)).isLessThan(1e-8);
        assertThat(back.translationVector().norm()).isZero();
      }
    }
  }

  // Method: between(A, B) turns B into A in the parent frame: exp(between(A, B))·R_B = R_A.
  @Test
  void betweenTwoPosesTurnsTheSecondIntoTheFirst() {
    Transform A = Transform.fromRpy(1, 2, 3, 0.4, -1.1, 2.6);
    for (Vec3 a : AXES) {
      for (double theta : new double[] {1e-5, 0.7, 3.0}) {
        Transform B = Transform.rotation(a.x(), a.y(), a.z(), theta).compose(A).withTranslation(9, 8, 7);
        Vec3 v = Rotations.between(A, B);
        assertThat(v.norm()).isCloseTo(theta, within(1e-9));
        assertThat(Rotations.exp(v, 1).compose(B.withTranslation(0, 0, 0)).rotationAngleTo(A)).isLessThan(1e-9);
      }
    }
  }
}
