package org.robotrun.collision;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Fitted boxes against volumes known in closed form (issue 31): a box and a regular prism (a
 * meshed cylinder) turned to several rotations, flat and thin clouds, and the 2D hull the
 * face-flush search rests on. Every fit must also hold every input point.
 */
class BoxFitOracleTest {

  /** Rotations the shapes are turned to: none, one axis, quarter turns, arbitrary. */
  static final List<Transform> POSES = List.of(
      Transform.IDENTITY,
      Transform.fromRpy(0, 0, 0, 0, 0, Math.toRadians(30)),
      Transform.fromRpy(5, 6, 7, Math.PI / 2, 0, Math.PI / 2),
      Transform.fromRpy(-250, 40, 310, Math.toRadians(45), Math.toRadians(45), 0),
      Transform.fromRpy(15, -40, 70, 0.4, -0.9, 2.1),
      Transform.fromRpy(-3, 900, -12, 2.9, 1.2, -0.7));

  // Method: a 120 x 80 x 30 mm box: its 8 corners, 300 seeded points inside and 60 on its faces,
  // turned and moved by each pose; the fit is the box itself: edge lengths, centre, volume
  // 288 000 mm³ and the hull volume exact (1e-6 relative), the axes a right-handed orthonormal set.
  @Test
  void aBoxAtEveryRotationIsFittedExactly() {
    for (Transform X : POSES) {
      Random rnd = new Random(3);
      List<Vec3> local = new ArrayList<>();
      for (int i = 0; i < 8; i++) {
        local.add(new Vec3((i & 1) == 0 ? -60 : 60, (i & 2) == 0 ? -40 : 40, (i & 4) == 0 ? -15 : 15));
      }
      for (int i = 0; i < 300; i++) {
        local.add(new Vec3(-60 + 120 * rnd.nextDouble(), -40 + 80 * rnd.nextDouble(), -15 + 30 * rnd.nextDouble()));
      }
      for (int i = 0; i < 60; i++) {
        double u = rnd.nextDouble(), v = rnd.nextDouble();
        local.add(switch (i % 3) {
          case 0 -> new Vec3(i % 2 == 0 ? 60 : -60, -40 + 80 * u, -15 + 30 * v);
          case 1 -> new Vec3(-60 + 120 * u, i % 2 == 0 ? 40 : -40, -15 + 30 * v);
          default -> new Vec3(-60 + 120 * u, -40 + 80 * v, i % 2 == 0 ? 15 : -15);
        });
      }
      Collections.shuffle(local, rnd);
      double[] p = cloud(X, local);
      BoxFit fit = BoxFit.fit(p);
      String at = X.toString();
      assertThat(sortedSize(fit)).as(at).containsExactly(new double[] {30, 80, 120}, within(1e-6));
      assertThat(fit.volume()).as(at).isCloseTo(120.0 * 80 * 30, within(1e-6 * 288_000));
      assertThat(fit.hullVolume()).as(at).isCloseTo(120.0 * 80 * 30, within(1e-6 * 288_000));
      assertThat(fit.X_LB().translationVector().distanceTo(X.translationVector())).as(at).isLessThan(1e-6);
      assertOrthonormalRightHanded(fit.X_LB());
      assertHoldsEveryPoint(fit, p, 1e-6);
      // The box's axes are the shape's: each box axis is parallel to one of the shape's axes.
      for (int k = 0; k < 3; k++) {
        Vec3 a = fit.X_LB().axis(k);
        double best = 0;
        for (int m = 0; m < 3; m++) {
          best = Math.max(best, Math.abs(a.dot(X.axis(m))));
        }
        assertThat(best).as(at + " axis " + k).isCloseTo(1, within(1e-9));
      }
    }
  }

  // Method: a regular 64-sided prism (a cylinder of radius 50 mm, 200 mm long, as a mesh has it:
  // two rings of vertices and the two cap centres), turned by each pose. The smallest enclosing
  // rectangle of a regular n-gon with n a multiple of 4 is flush with an edge, a square of side
  // 2·r·cos(π/n) (its width between opposite edges), so the box is that square times the length:
  // 2·50·cos(π/64) x the same x 200. Its hull is the prism: n/2·r²·sin(2π/n)·200. The cloud's
  // principal axes are not unique across the round section, so only the face-flush search finds it.
  @Test
  void aMeshedCylinderAtEveryRotationGetsTheFlushSquareBox() {
    int n = 64;
    double r = 50, len = 200;
    double side = 2 * r * Math.cos(Math.PI / n);
    double prism = n / 2.0 * r * r * Math.sin(2 * Math.PI / n) * len;
    for (Transform X : POSES) {
      List<Vec3> local = new ArrayList<>();
      for (int i = 0; i < n; i++) {
        double a = 2 * Math.PI * i / n + 0.013; // not lined up with the frame's axes
        local.add(new Vec3(r * Math.cos(a), r * Math.sin(a), -len / 2));
        local.add(new Vec3(r * Math.cos(a), r * Math.sin(a), len / 2));
      }
      local.add(new Vec3(0, 0, -len / 2));
      local.add(new Vec3(0, 0, len / 2));
      double[] p = cloud(X, local);
      BoxFit fit = BoxFit.fit(p);
      String at = X.toString();
      assertThat(fit.hullVolume()).as(at).isCloseTo(prism, within(1e-6 * prism));
      assertThat(sortedSize(fit)).as(at).containsExactly(new double[] {side, side, len}, within(1e-6));
      assertThat(fit.volume()).as(at).isCloseTo(side * side * len, within(1e-6 * side * side * len));
      assertThat(fit.X_LB().translationVector().distanceTo(X.translationVector())).as(at).isLessThan(1e-6);
      // The long axis is the cylinder's.
      Vec3 axis = X.axis(2);
      double along = 0;
      for (int k = 0; k < 3; k++) {
        along = Math.max(along, Math.abs(fit.X_LB().axis(k).dot(axis)));
      }
      assertThat(along).as(at).isCloseTo(1, within(1e-9));
      assertOrthonormalRightHanded(fit.X_LB());
      assertHoldsEveryPoint(fit, p, 1e-6);
    }
  }

  // Method: a flat 100 x 50 mm plate (corners, edge midpoints, a grid inside: symmetric, so its
  // principal axes are its edges) turned by each pose: no hull, and the box is the plate,
  // BoxFit.MIN_THICKNESS_MM thick, centred on it.
  @Test
  void aFlatPlateAtEveryRotationGetsItsOwnRectangle() {
    for (Transform X : POSES) {
      List<Vec3> local = new ArrayList<>();
      for (int i = 0; i <= 10; i++) {
        for (int j = 0; j <= 5; j++) {
          local.add(new Vec3(-50 + 10 * i, -25 + 10 * j, 0));
        }
      }
      double[] p = cloud(X, local);
      BoxFit fit = BoxFit.fit(p);
      String at = X.toString();
      assertThat(fit.hullVolume()).as(at).isZero();
      assertThat(sortedSize(fit)).as(at).containsExactly(new double[] {BoxFit.MIN_THICKNESS_MM, 50, 100}, within(1e-6));
      assertThat(fit.X_LB().translationVector().distanceTo(X.translationVector())).as(at).isLessThan(1e-6);
      // The thin axis is the plate's normal.
      double normal = 0;
      for (int k = 0; k < 3; k++) {
        if (Math.abs(size(fit, k) - BoxFit.MIN_THICKNESS_MM) < 1e-9) {
          normal = Math.abs(fit.X_LB().axis(k).dot(X.axis(2)));
        }
      }
      assertThat(normal).as(at).isCloseTo(1, within(1e-9));
      assertOrthonormalRightHanded(fit.X_LB());
      assertHoldsEveryPoint(fit, p, 1e-6);
    }
  }

  // Method: one point gives a MIN_THICKNESS_MM cube on it; points on one turned line give a box
  // as long as the line and MIN_THICKNESS_MM across; repeating every point of a box changes
  // nothing; no point at all is refused.
  @Test
  void degenerateCloudsAndRepeatedPoints() {
    BoxFit one = BoxFit.fit(new double[] {12, -7, 300});
    assertThat(sortedSize(one)).containsExactly(new double[] {1, 1, 1}, within(1e-12));
    assertThat(one.X_LB().translationVector().distanceTo(new Vec3(12, -7, 300))).isLessThan(1e-9);
    assertThat(one.volume()).isCloseTo(1.0, within(1e-12));

    Vec3 dir = new Vec3(2, -3, 6).normalized(); // length 7 before normalising
    double[] line = new double[3 * 5];
    for (int i = 0; i < 5; i++) {
      Vec3 q = new Vec3(100, 200, 300).plus(dir.times(35 * i));
      line[3 * i] = q.x();
      line[3 * i + 1] = q.y();
      line[3 * i + 2] = q.z();
    }
    BoxFit thin = BoxFit.fit(line);
    assertThat(sortedSize(thin)).containsExactly(new double[] {1, 1, 140}, within(1e-6));
    assertThat(thin.X_LB().translationVector().distanceTo(new Vec3(100, 200, 300).plus(dir.times(70)))).isLessThan(1e-6);

    Transform X = POSES.get(4);
    List<Vec3> corners = new ArrayList<>();
    for (int i = 0; i < 8; i++) {
      corners.add(new Vec3((i & 1) == 0 ? -60 : 60, (i & 2) == 0 ? -40 : 40, (i & 4) == 0 ? -15 : 15));
    }
    List<Vec3> thrice = new ArrayList<>();
    for (int k = 0; k < 3; k++) {
      thrice.addAll(corners);
    }
    BoxFit repeated = BoxFit.fit(cloud(X, thrice));
    assertThat(sortedSize(repeated)).containsExactly(new double[] {30, 80, 120}, within(1e-6));
    assertThat(repeated.hullVolume()).isCloseTo(288_000, within(1e-6 * 288_000));

    assertThatThrownBy(() -> BoxFit.fit(new double[0])).isInstanceOf(IllegalArgumentException.class);
  }

  // Method: the 2D hull of a square's corners, its edge midpoints (collinear: not vertices) and
  // 200 seeded points inside (enough for the interior filter to run) is the 4 corners,
  // counter-clockwise, starting at the lowest-left one; of a 100-gon's vertices (every one on
  // the hull), shuffled, with its centre, the 100 vertices with the polygon's area (n/2·sin(2π/n)).
  @Test
  void theTwoDimensionalHullKeepsExactlyTheCorners() {
    Random rnd = new Random(5);
    List<double[]> pts = new ArrayList<>();
    pts.add(new double[] {-2, -1});
    pts.add(new double[] {3, -1});
    pts.add(new double[] {3, 4});
    pts.add(new double[] {-2, 4});
    pts.add(new double[] {0.5, -1});
    pts.add(new double[] {3, 1.5});
    pts.add(new double[] {0.5, 4});
    pts.add(new double[] {-2, 1.5});
    for (int i = 0; i < 200; i++) {
      pts.add(new double[] {-2 + 5 * rnd.nextDouble(), -1 + 5 * rnd.nextDouble()});
    }
    Collections.shuffle(pts, rnd);
    double[] h = BoxFit.hull2d(flat2(pts));
    assertThat(h).containsExactly(-2, -1, 3, -1, 3, 4, -2, 4);
    // Few points (no interior filter): the same answer.
    double[] small = BoxFit.hull2d(new double[] {3, 4, 0.5, 0.5, -2, -1, 3, -1, 0.5, -1, -2, 4});
    assertThat(small).containsExactly(-2, -1, 3, -1, 3, 4, -2, 4);

    int n = 100;
    List<double[]> ring = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      double a = 2 * Math.PI * i / n;
      ring.add(new double[] {10 * Math.cos(a), 10 * Math.sin(a)});
    }
    ring.add(new double[] {0, 0});
    Collections.shuffle(ring, rnd);
    double[] poly = BoxFit.hull2d(flat2(ring));
    assertThat(poly.length / 2).isEqualTo(n);
    double area = 0;
    for (int i = 0; i < n; i++) {
      int j = (i + 1) % n;
      area += poly[2 * i] * poly[2 * j + 1] - poly[2 * j] * poly[2 * i + 1];
    }
    assertThat(area / 2).isCloseTo(n / 2.0 * 100 * Math.sin(2 * Math.PI / n), within(1e-9));
  }

  static double[] cloud(Transform X, List<Vec3> local) {
    double[] p = new double[3 * local.size()];
    for (int i = 0; i < local.size(); i++) {
      Vec3 q = X.apply(local.get(i));
      p[3 * i] = q.x();
      p[3 * i + 1] = q.y();
      p[3 * i + 2] = q.z();
    }
    return p;
  }

  static double[] flat2(List<double[]> pts) {
    double[] q = new double[2 * pts.size()];
    for (int i = 0; i < pts.size(); i++) {
      q[2 * i] = pts.get(i)[0];
      q[2 * i + 1] = pts.get(i)[1];
    }
    return q;
  }

  static double size(BoxFit fit, int k) {
    return k == 0 ? fit.size().x() : k == 1 ? fit.size().y() : fit.size().z();
  }

  static double[] sortedSize(BoxFit fit) {
    double[] s = {fit.size().x(), fit.size().y(), fit.size().z()};
    Arrays.sort(s);
    return s;
  }

  /** Every point, taken into the box's frame, lies within its half sizes (plus {@code tol} mm). */
  static void assertHoldsEveryPoint(BoxFit fit, double[] p, double tol) {
    Transform X_BL = fit.X_LB().inverse();
    for (int i = 0; i < p.length; i += 3) {
      Vec3 q = X_BL.apply(new Vec3(p[i], p[i + 1], p[i + 2]));
      assertThat(Math.abs(q.x())).isLessThanOrEqualTo(fit.size().x() / 2 + tol);
      assertThat(Math.abs(q.y())).isLessThanOrEqualTo(fit.size().y() / 2 + tol);
      assertThat(Math.abs(q.z())).isLessThanOrEqualTo(fit.size().z() / 2 + tol);
    }
  }

  static void assertOrthonormalRightHanded(Transform X) {
    Vec3 x = X.axis(0), y = X.axis(1), z = X.axis(2);
    assertThat(x.dot(x)).isCloseTo(1, within(1e-9));
    assertThat(y.dot(y)).isCloseTo(1, within(1e-9));
    assertThat(x.dot(y)).isCloseTo(0, within(1e-9));
    assertThat(x.cross(y).distanceTo(z)).isLessThan(1e-9);
  }
}
