package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Frame teaching against frames computed in the test (issue 31), with the test's own vector
 * arithmetic on plain arrays and the FANUC definitions (docs/kinematics.md, FrameTeaching): user
 * three-point: origin at the origin point, +X toward the X point, Y toward the Y point made
 * orthogonal to X, Z = X × Y; user four-point: the same axes from the first three points, origin
 * at the fourth; tool three-point: the TCP that puts every approach on one point, the flange's
 * orientation; tool six-point: the TCP as three-point, +X along the TCP's move to the X point and
 * the second axis (Z or Y) along the move to the third point, orthogonalised, both in the flange
 * frame at the orient origin. Points are arbitrary (not made from a frame by the product's own
 * W, P, R code), so the origin and every axis are checked element by element.
 */
class FrameTeachingOracleTest {
  static final double TOL_MM = 1e-6;
  static final double TOL = 1e-9;

  static double[] v(double x, double y, double z) {
    return new double[] {x, y, z};
  }

  static double[] sub(double[] a, double[] b) {
    return v(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  }

  static double dot(double[] a, double[] b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  static double[] scale(double[] a, double s) {
    return v(a[0] * s, a[1] * s, a[2] * s);
  }

  static double[] unit(double[] a) {
    return scale(a, 1 / Math.sqrt(dot(a, a)));
  }

  static double[] cross(double[] a, double[] b) {
    return v(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
  }

  /** Axes (columns x, y, z) from a first direction and a second made orthogonal to it. */
  static double[][] axes(double[] first, double[] second) {
    double[] x = unit(first);
    double[] s = unit(sub(second, scale(x, dot(second, x))));
    return new double[][] {x, s};
  }

  static void assertFrame(String what, Transform actual, double[] origin, double[] x, double[] y, double[] z) {
    Vec3 o = actual.translationVector();
    assertThat(o.x()).as(what + " origin x").isCloseTo(origin[0], offset(TOL_MM));
    assertThat(o.y()).as(what + " origin y").isCloseTo(origin[1], offset(TOL_MM));
    assertThat(o.z()).as(what + " origin z").isCloseTo(origin[2], offset(TOL_MM));
    double[][] want = {x, y, z};
    for (int a = 0; a < 3; a++) {
      Vec3 axis = actual.axis(a);
      double[] got = {axis.x(), axis.y(), axis.z()};
      for (int k = 0; k < 3; k++) {
        assertThat(got[k]).as("%s axis %d component %d", what, a, k).isCloseTo(want[a][k], offset(TOL));
      }
    }
  }

  static Vec3 vec(double[] a) {
    return new Vec3(a[0], a[1], a[2]);
  }

  @Test
  void userThreePointFromArbitraryPoints() {
    double[] o = v(512.3, -40.1, 77.7);
    double[] px = v(731.9, 21.4, 95.2);
    double[] py = v(498.0, 166.6, 101.3);
    double[][] xs = axes(sub(px, o), sub(py, o));
    double[] z = cross(xs[0], xs[1]);
    assertFrame("UF 3-point", FrameTeaching.userThreePoint(vec(o), vec(px), vec(py)), o, xs[0], xs[1], z);
  }

  @Test
  void userFourPointTakesItsAxesFromTheFirstThreeAndItsOriginFromTheFourth() {
    double[] oo = v(300.5, 120.0, -15.25);
    double[] px = v(455.0, 160.5, -10.0);
    double[] py = v(280.0, 310.0, 5.5);
    double[] origin = v(260.75, 95.5, -20.0);
    double[][] xs = axes(sub(px, oo), sub(py, oo));
    double[] z = cross(xs[0], xs[1]);
    assertFrame("UF 4-point", FrameTeaching.userFourPoint(vec(oo), vec(px), vec(py), vec(origin)), origin, xs[0], xs[1], z);
  }

  /** A rotation (row-major 3×3) about a unit axis by an angle, Rodrigues. */
  static double[] rot(double[] axis, double deg) {
    double[] k = unit(axis);
    double t = Math.toRadians(deg);
    double c = Math.cos(t);
    double s = Math.sin(t);
    double u = 1 - c;
    return new double[] {
        c + k[0] * k[0] * u, k[0] * k[1] * u - k[2] * s, k[0] * k[2] * u + k[1] * s,
        k[1] * k[0] * u + k[2] * s, c + k[1] * k[1] * u, k[1] * k[2] * u - k[0] * s,
        k[2] * k[0] * u - k[1] * s, k[2] * k[1] * u + k[0] * s, c + k[2] * k[2] * u};
  }

  static double[] apply(double[] r, double[] p) {
    return v(r[0] * p[0] + r[1] * p[1] + r[2] * p[2], r[3] * p[0] + r[4] * p[1] + r[5] * p[2],
        r[6] * p[0] + r[7] * p[1] + r[8] * p[2]);
  }

  static Transform flange(double[] r, double[] t) {
    return Transform.of(r, t[0], t[1], t[2]);
  }

  /** The TCP in the flange the approaches must recover, and the point they touch (world). */
  static final double[] TCP = v(23.5, -11.25, 176.0);
  static final double[] TOUCH = v(455.0, 118.0, 82.5);

  /** A flange pose of orientation r whose TCP is on the touch point. */
  static Transform approach(double[] r) {
    return flange(r, sub(TOUCH, apply(r, TCP)));
  }

  static List<Transform> approaches() {
    List<Transform> a = new ArrayList<>();
    a.add(approach(rot(v(1, 0, 0), 180)));
    a.add(approach(rot(v(0.9, 0.3, 0.1), 150)));
    a.add(approach(rot(v(0.7, -0.5, 0.3), -160)));
    a.add(approach(rot(v(0.2, 1, 0.4), 140)));
    return a;
  }

  @Test
  void toolThreePointRecoversTheTcpAndKeepsTheFlangeOrientation() {
    assertFrame("UT 3-point (3 approaches)", FrameTeaching.toolThreePoint(approaches().subList(0, 3)), TCP, v(1, 0, 0),
        v(0, 1, 0), v(0, 0, 1));
    assertFrame("UT 3-point (4 approaches)", FrameTeaching.toolThreePoint(approaches()), TCP, v(1, 0, 0), v(0, 1, 0),
        v(0, 0, 1));
  }

  @Test
  void toolSixPointXzAndXyRecoverTheAxesTheTcpWasMovedAlong() {
    double[] r0 = rot(v(0.95, 0.2, -0.1), 170);
    Transform origin = approach(r0);
    // The TCP moved (flange orientation kept) along two directions given in the flange frame at the orient origin.
    double[] xFlange = v(0.8, 0.5, -0.2);
    double[] secondFlange = v(0.1, -0.3, 0.9); // not orthogonal to x on purpose
    Transform toX = flange(r0, v(origin.x(), origin.y(), origin.z())).withTranslation(
        origin.x() + 120 * apply(r0, unit(xFlange))[0], origin.y() + 120 * apply(r0, unit(xFlange))[1],
        origin.z() + 120 * apply(r0, unit(xFlange))[2]);
    double[] sW = apply(r0, scale(secondFlange, 90));
    Transform toSecond = origin.withTranslation(origin.x() + sW[0], origin.y() + sW[1], origin.z() + sW[2]);
    double[][] xs = axes(xFlange, secondFlange);

    Transform xz = FrameTeaching.toolSixPoint(approaches().subList(0, 3), origin, toX, toSecond,
        FrameTeaching.SixPointVariant.XZ);
    // XZ: the second axis is Z; Y = Z × X.
    assertFrame("UT 6-point XZ", xz, TCP, xs[0], cross(xs[1], xs[0]), xs[1]);

    Transform xy = FrameTeaching.toolSixPoint(approaches().subList(0, 3), origin, toX, toSecond,
        FrameTeaching.SixPointVariant.XY);
    // XY: the second axis is Y; Z = X × Y.
    assertFrame("UT 6-point XY", xy, TCP, xs[0], xs[1], cross(xs[0], xs[1]));
  }
}
