package org.robotrun.math;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.DoubleRange;
import org.junit.jupiter.api.Test;

class QuaternionTest {

  @Property(seed = "3", tries = 2000)
  void xyzwprQuaternionRotationRoundTrip(
      @ForAll @DoubleRange(min = -180, max = 180) double wDeg,
      @ForAll @DoubleRange(min = -90, max = 90) double pDeg,
      @ForAll @DoubleRange(min = -180, max = 180) double rDeg) {
    // Method: WPR -> quaternion -> matrix -> WPR -> matrix; same rotation to 1e-9 rad, w >= 0, |q| = 1.
    Xyzwpr pose = Xyzwpr.ofDegrees(10, 20, 30, wDeg, pDeg, rDeg);
    Quaternion q = Quaternion.fromXyzwpr(pose);
    assertThat(q.w()).isGreaterThanOrEqualTo(0);
    assertThat(q.w() * q.w() + q.x() * q.x() + q.y() * q.y() + q.z() * q.z()).isCloseTo(1, within(1e-12));
    Xyzwpr back = q.toXyzwpr(10, 20, 30);
    assertThat(back.toTransform().rotationAngleTo(pose.toTransform())).isLessThan(1e-9);
    assertThat(back.position()).isEqualTo(pose.position());
  }

  @Property(seed = "4", tries = 1000)
  void nearGimbalPosesKeepTheirRotation(
      @ForAll @DoubleRange(min = -180, max = 180) double wDeg,
      @ForAll @DoubleRange(min = 89.99, max = 90) double pAbsDeg,
      @ForAll boolean negative,
      @ForAll @DoubleRange(min = -180, max = 180) double rDeg) {
    // Method: P within 0.01 deg of ±90 deg; WPR and quaternion round trips to 1e-9 rad.
    double pDeg = negative ? -pAbsDeg : pAbsDeg;
    Transform t = Xyzwpr.ofDegrees(0, 0, 0, wDeg, pDeg, rDeg).toTransform();
    assertThat(Xyzwpr.fromTransform(t).toTransform().rotationAngleTo(t)).isLessThan(1e-9);
    assertThat(Quaternion.fromTransform(t).toTransform(0, 0, 0).rotationAngleTo(t)).isLessThan(1e-9);
  }

  @Test
  void matchesTheReferenceQuaternionsOfEveryRow() throws Exception {
    // Method: the reference CSV stores each flange rotation both as a matrix and as a unit
    // quaternion (qw >= 0, from an independent numpy implementation); agree to 1e-9.
    java.util.List<String> lines = java.nio.file.Files.readAllLines(java.nio.file.Path.of(
        getClass().getResource("/ik_targets_lrmate200id.csv").toURI()));
    java.util.List<String> header = java.util.List.of(lines.get(0).split(","));
    int r11 = header.indexOf("r11"), qw = header.indexOf("qw");
    for (String line : lines.subList(1, lines.size())) {
      String[] f = line.split(",");
      double[] m = new double[9];
      for (int i = 0; i < 9; i++) {
        m[i] = Double.parseDouble(f[r11 + i]);
      }
      Quaternion q = Quaternion.fromTransform(Transform.of(m, 0, 0, 0));
      double[] expected = new double[4];
      for (int i = 0; i < 4; i++) {
        expected[i] = Double.parseDouble(f[qw + i]);
      }
      assertThat(new double[] {q.w(), q.x(), q.y(), q.z()}).as(f[0]).containsExactly(expected, within(1e-9));
    }
  }

  @Test
  void halfTurnsConvertExactly() {
    // 180 deg about X (the tool-down W = 180) is (0, 1, 0, 0); about Z is (0, 0, 0, 1).
    Quaternion aboutX = Quaternion.fromXyzwpr(Xyzwpr.ofDegrees(0, 0, 0, 180, 0, 0));
    assertThat(aboutX.x()).isCloseTo(1, within(1e-15));
    assertThat(aboutX.w()).isCloseTo(0, within(1e-15));
    Quaternion aboutZ = Quaternion.fromXyzwpr(Xyzwpr.ofDegrees(0, 0, 0, 0, 0, 180));
    assertThat(Math.abs(aboutZ.z())).isCloseTo(1, within(1e-15));
  }

  @Test
  void ninetyDegreesAboutZMatchesTheHamiltonConvention() {
    Quaternion q = Quaternion.fromXyzwpr(Xyzwpr.ofDegrees(0, 0, 0, 0, 0, 90));
    double h = Math.sqrt(0.5);
    assertThat(new double[] {q.w(), q.x(), q.y(), q.z()}).containsExactly(new double[] {h, 0, 0, h}, within(1e-15));
  }
}
