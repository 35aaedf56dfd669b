package org.robotrun.math;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The math helpers against their definitions, computed here by other means (issue 31): the
 * inverse by composition, angles between rotations built about a known axis, a quaternion scaled
 * off the unit sphere, the wrap and the number grammar at their boundaries.
 */
class MathOracleTest {

  // Method: for seeded transforms with every translation component non-zero, X·X⁻¹ and X⁻¹·X
  // are the identity and X⁻¹ maps X's image of a point back to it (1e-9).
  @Test
  void theInverseUndoesTheTransformBothWays() {
    Random rnd = new Random(31);
    for (int k = 0; k < 50; k++) {
      Transform X = Transform.fromRpy(
          -800 + 1600 * rnd.nextDouble(), -800 + 1600 * rnd.nextDouble(), -800 + 1600 * rnd.nextDouble(),
          -3 + 6 * rnd.nextDouble(), -1.5 + 3 * rnd.nextDouble(), -3 + 6 * rnd.nextDouble());
      for (Transform I : new Transform[] {X.compose(X.inverse()), X.inverse().compose(X)}) {
        assertThat(I.translationVector().norm()).isLessThan(1e-9);
        assertThat(I.rotationAngleTo(Transform.IDENTITY)).isLessThan(1e-9);
      }
      Vec3 p = new Vec3(rnd.nextDouble() * 500, -rnd.nextDouble() * 500, 250);
      assertThat(X.inverse().apply(X.apply(p)).distanceTo(p)).isLessThan(1e-9);
      // The inverse's origin is where the parent's origin lies in the child frame: -Rᵀ·t.
      Vec3 t = X.translationVector();
      Vec3 expected = new Vec3(-X.axis(0).dot(t), -X.axis(1).dot(t), -X.axis(2).dot(t));
      assertThat(X.inverse().translationVector().distanceTo(expected)).isLessThan(1e-9);
    }
  }

  // Method: B = A · Rot(axis, θ) for a fixed arbitrary A and axis; the angle from A to B is θ,
  // whatever the axis, from a micro-radian (where acos alone loses digits) to a half turn; the
  // distance between origins is the Euclidean one.
  @Test
  void rotationAngleAndDistanceBetweenTwoPoses() {
    Transform A = Transform.fromRpy(10, 20, 30, 0.3, -0.7, 1.9);
    Vec3[] axes = {new Vec3(1, 0, 0), new Vec3(0, 1, 0), new Vec3(0, 0, 1), new Vec3(1, -2, 3).normalized()};
    for (Vec3 ax : axes) {
      for (double theta : new double[] {1e-6, 1e-3, 0.3, 1.0, 2.0, 3.0, Math.PI - 1e-6}) {
        Transform B = A.compose(Transform.rotation(ax.x(), ax.y(), ax.z(), theta));
        assertThat(A.rotationAngleTo(B)).as("θ=%s about %s", theta, ax).isCloseTo(theta, within(1e-9 * Math.max(1, theta)));
        assertThat(B.rotationAngleTo(A)).isCloseTo(theta, within(1e-9 * Math.max(1, theta)));
      }
    }
    assertThat(A.rotationAngleTo(A)).isCloseTo(0, within(1e-12));
    Transform C = Transform.translation(13, -4, 7).compose(A);
    assertThat(A.distanceTo(C)).isCloseTo(Math.sqrt(13 * 13 + 4 * 4 + 7 * 7), within(1e-9));
    assertThat(C.distanceTo(A)).isCloseTo(Math.sqrt(234), within(1e-9));
  }

  // Method: a unit quaternion for 100° about (1, 2, 2)/3 scaled by 3 and by -0.25: canonical()
  // gives back the unit one, w ≥ 0, and the same matrix; the zero quaternion is refused.
  @Test
  void canonicalScalesToUnitLengthAndPositiveW() {
    double half = Math.toRadians(50);
    Quaternion unit = new Quaternion(Math.cos(half), Math.sin(half) / 3, 2 * Math.sin(half) / 3, 2 * Math.sin(half) / 3);
    for (double s : new double[] {3, -0.25, 1}) {
      Quaternion q = new Quaternion(s * unit.w(), s * unit.x(), s * unit.y(), s * unit.z()).canonical();
      assertThat(q.w()).isCloseTo(unit.w(), within(1e-12));
      assertThat(q.x()).isCloseTo(unit.x(), within(1e-12));
      assertThat(q.y()).isCloseTo(unit.y(), within(1e-12));
      assertThat(q.z()).isCloseTo(unit.z(), within(1e-12));
    }
    Transform R = new Quaternion(-3 * unit.w(), -3 * unit.x(), -3 * unit.y(), -3 * unit.z()).toTransform(1, 2, 3);
    Transform expected = Transform.rotation(1 / 3.0, 2 / 3.0, 2 / 3.0, Math.toRadians(100));
    assertThat(R.rotationAngleTo(expected)).isLessThan(1e-12);
    assertThat(R.translationVector().distanceTo(new Vec3(1, 2, 3))).isLessThan(1e-12);
    assertThatThrownBy(() -> new Quaternion(0, 0, 0, 0).canonical()).isInstanceOf(ArithmeticException.class);
  }

  // Method: XYZWPR in degrees against the radians it holds, and its position; a pose at the
  // gimbal (P = 90°) keeps its matrix (W is folded into R).
  @Test
  void xyzwprDegreesPositionAndGimbal() {
    Xyzwpr a = Xyzwpr.ofDegrees(1, 2, 3, 10, -20, 170);
    assertThat(a.wDeg()).isCloseTo(10, within(1e-12));
    assertThat(a.pDeg()).isCloseTo(-20, within(1e-12));
    assertThat(a.rDeg()).isCloseTo(170, within(1e-12));
    assertThat(a.position()).isEqualTo(new Vec3(1, 2, 3));
    Transform gimbal = Xyzwpr.ofDegrees(0, 0, 0, 30, 90, 50).toTransform();
    Xyzwpr back = Xyzwpr.fromTransform(gimbal);
    assertThat(back.w()).isZero();
    assertThat(back.pDeg()).isCloseTo(90, within(1e-9));
    assertThat(back.toTransform().rotationAngleTo(gimbal)).isLessThan(1e-9);
  }

  // Method: (-π, π] by definition: π stays π, -π becomes π, odd multiples of π land on π, and
  // an angle k·2π away from a in (-π, π) comes back to a; arrays convert element by element.
  @Test
  void wrapPiAndArrayConversions() {
    assertThat(Angles.wrapPi(Math.PI)).isEqualTo(Math.PI);
    assertThat(Angles.wrapPi(-Math.PI)).isCloseTo(Math.PI, within(1e-15));
    assertThat(Angles.wrapPi(3 * Math.PI)).isCloseTo(Math.PI, within(1e-12));
    assertThat(Angles.wrapPi(-3 * Math.PI)).isCloseTo(Math.PI, within(1e-12));
    for (double a : new double[] {-3.1, -1, 0, 0.5, 3.1}) {
      for (int k = -3; k <= 3; k++) {
        assertThat(Angles.wrapPi(a + 2 * Math.PI * k)).isCloseTo(a, within(1e-12));
      }
    }
    assertThat(Angles.toDegrees(new double[] {Math.PI, -Math.PI / 2, 0})).containsExactly(new double[] {180, -90, 0}, within(1e-12));
    assertThat(Angles.toRadians(new double[] {180, -90, 0})).containsExactly(new double[] {Math.PI, -Math.PI / 2, 0}, within(1e-15));
  }

  // Method: the bounds are inclusive, one step beyond is out, NaN and infinities are out.
  @Test
  void poseLimitsAreInclusiveAndRejectNaN() {
    assertThat(PoseLimits.coordinateOk(PoseLimits.MAX_COORDINATE_MM)).isTrue();
    assertThat(PoseLimits.coordinateOk(-PoseLimits.MAX_COORDINATE_MM)).isTrue();
    assertThat(PoseLimits.coordinateOk(Math.nextUp(PoseLimits.MAX_COORDINATE_MM))).isFalse();
    assertThat(PoseLimits.coordinateOk(-100_000.001)).isFalse();
    assertThat(PoseLimits.coordinateOk(Double.NaN)).isFalse();
    assertThat(PoseLimits.coordinateOk(0)).isTrue();
    assertThat(PoseLimits.angleOk(PoseLimits.MAX_ANGLE_DEG)).isTrue();
    assertThat(PoseLimits.angleOk(-PoseLimits.MAX_ANGLE_DEG)).isTrue();
    assertThat(PoseLimits.angleOk(Math.nextUp(PoseLimits.MAX_ANGLE_DEG))).isFalse();
    assertThat(PoseLimits.angleOk(Double.NEGATIVE_INFINITY)).isFalse();
    assertThat(PoseLimits.angleOk(Double.NaN)).isFalse();
    assertThat(PoseLimits.angleOk(-725.5)).isTrue();
  }

  // Method: the grammar of DecimalText's Javadoc, case by case: what it takes and what it does
  // not (Java's extras, blanks, overflow, text over 400 characters).
  @Test
  void decimalGrammarTakesPlainDecimalsOnly() {
    String[] good = {"12", "-0.5", ".5", "+3.", "1e3", "1E-3", "-2.5e+10", "0", "007"};
    for (String s : good) {
      assertThat(DecimalText.isDecimal(s)).as(s).isTrue();
      assertThat(DecimalText.parse(s)).as(s).hasValue(Double.parseDouble(s));
    }
    String[] bad = {"", "NaN", "Infinity", "0x1p3", "5d", "5f", " 1", "1 ", "1e", "e3", ".", "-", "1.2.3", "1e12345"};
    for (String s : bad) {
      assertThat(DecimalText.isDecimal(s)).as(s).isFalse();
      assertThat(DecimalText.parse(s)).as(s).isEmpty();
    }
    assertThat(DecimalText.isDecimal("1e400")).isTrue();
    assertThat(DecimalText.parse("1e400")).isEmpty();
    assertThat(DecimalText.parse("-1e400")).isEmpty();
    assertThat(DecimalText.parse("1e-400")).hasValue(0.0);
    String long400 = "1".repeat(400);
    assertThat(DecimalText.isDecimal(long400)).isTrue();
    assertThat(DecimalText.isDecimal(long400 + "1")).isFalse();
    assertThat(DecimalText.tidy(-1e-12)).isEqualTo("-0.000000000001");
    assertThat(DecimalText.tidy(1e-12)).isEqualTo("0.000000000001");
    assertThat(DecimalText.tidy(-9.999999999999e-13)).isEqualTo("0");
    assertThat(DecimalText.tidy(123456.789)).isEqualTo("123456.789");
    assertThat(DecimalText.tidy(-40)).isEqualTo("-40");
  }

  // Method: the reduced-range sin/cos against Math.sin/Math.cos (both within an ulp or two of
  // the true value) up to 90 000 rad, where an error in the reduction constants shows, and at
  // and beyond the 1e5 switch-over.
  @Test
  void sinCosMatchesTheLibraryFarFromZero() {
    double[] d = new double[2];
    Random rnd = new Random(9);
    for (int i = 0; i < 2000; i++) {
      double x = (rnd.nextDouble() - 0.5) * 180_000;
      SinCos.sinCos(x, d, 0);
      assertThat(d[0]).as("sin %s", x).isCloseTo(Math.sin(x), within(1e-14));
      assertThat(d[1]).as("cos %s", x).isCloseTo(Math.cos(x), within(1e-14));
    }
    for (double x : new double[] {1e5, -1e5, 1e5 + 0.5, 3e7}) {
      SinCos.sinCos(x, d, 0);
      assertThat(d[0]).isCloseTo(Math.sin(x), within(1e-12));
      assertThat(d[1]).isCloseTo(Math.cos(x), within(1e-12));
    }
  }
}
