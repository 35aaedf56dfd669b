package org.robotrun.collision;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/** Convex hulls and fitted boxes of point clouds whose answers are known in closed form. */
class BoxFitTest {

  // Method: a 400 x 300 x 200 mm box's 8 corners plus 2000 random points inside (seed 7):
  // the hull is the box. Tolerance 1e-6 relative.
  @Test
  void hullOfABoxWithPointsInsideIsTheBox() {
    Random rnd = new Random(7);
    double[] p = new double[(8 + 2000) * 3];
    for (int i = 0; i < 8; i++) {
      p[3 * i] = (i & 1) == 0 ? -200 : 200;
      p[3 * i + 1] = (i & 2) == 0 ? -150 : 150;
      p[3 * i + 2] = (i & 4) == 0 ? -100 : 100;
    }
    for (int i = 8; i < 2008; i++) {
      p[3 * i] = -200 + 400 * rnd.nextDouble();
      p[3 * i + 1] = -150 + 300 * rnd.nextDouble();
      p[3 * i + 2] = -100 + 200 * rnd.nextDouble();
    }
    ConvexHull h = ConvexHull.compute(p);
    assertThat(h.volume()).isCloseTo(400.0 * 300 * 200, within(1e-6 * 400 * 300 * 200));
    assertThat(h.vertices()).hasSize(8 * 3);
  }

  // Method: 5000 points on a sphere of radius 100 mm (all on the hull, the hard case for an
  // incremental hull); the hull volume lies just below 4/3·π·r³ and every sampled point is
  // inside every face plane (tolerance 1e-6 mm).
  @Test
  void hullOfPointsOnASphereHoldsThemAll() {
    Random rnd = new Random(11);
    int n = 5000;
    double[] p = new double[3 * n];
    for (int i = 0; i < n; i++) {
      double z = 2 * rnd.nextDouble() - 1, a = 2 * Math.PI * rnd.nextDouble(), r = Math.sqrt(1 - z * z);
      p[3 * i] = 100 * r * Math.cos(a);
      p[3 * i + 1] = 100 * r * Math.sin(a);
      p[3 * i + 2] = 100 * z;
    }
    ConvexHull h = ConvexHull.compute(p);
    double sphere = 4.0 / 3 * Math.PI * 1e6;
    assertThat(h.volume()).isLessThan(sphere).isGreaterThan(0.995 * sphere);
    assertThat(h.vertices().length / 3).isEqualTo(n);
    double[] normals = h.faceNormals();
    double[] v = h.vertices();
    for (int f = 0; f < normals.length; f += 3 * 97) {
      // The plane of face f passes through one of its vertices: every point lies behind it.
      double best = Double.NEGATIVE_INFINITY;
      for (int i = 0; i < v.length; i += 3) {
        best = Math.max(best, normals[f] * v[i] + normals[f + 1] * v[i + 1] + normals[f + 2] * v[i + 2]);
      }
      for (int i = 0; i < p.length; i += 3 * 50) {
        assertThat(normals[f] * p[i] + normals[f + 1] * p[i + 1] + normals[f + 2] * p[i + 2]).isLessThanOrEqualTo(best + 1e-6);
      }
    }
    BoxFit fit = BoxFit.fit(p);
    assertThat(fit.volume() / fit.hullVolume()).isBetween(6 / Math.PI * 0.99, 6 / Math.PI * 1.02);
  }

  // Method: a 120 x 80 x 30 mm box's corners turned by an arbitrary rotation and moved: the
  // fitted box has the same edge lengths and centre (tolerance 1e-6 mm) and box/hull = 1.
  @Test
  void aTurnedBoxIsFittedExactly() {
    Transform X = Transform.fromRpy(15, -40, 70, 0.4, -0.9, 2.1);
    double[] p = new double[8 * 3];
    for (int i = 0; i < 8; i++) {
      Vec3 c = X.apply(new Vec3((i & 1) == 0 ? -60 : 60, (i & 2) == 0 ? -40 : 40, (i & 4) == 0 ? -15 : 15));
      p[3 * i] = c.x();
      p[3 * i + 1] = c.y();
      p[3 * i + 2] = c.z();
    }
    BoxFit fit = BoxFit.fit(p);
    double[] size = {fit.size().x(), fit.size().y(), fit.size().z()};
    Arrays.sort(size);
    assertThat(size[0]).isCloseTo(30, within(1e-6));
    assertThat(size[1]).isCloseTo(80, within(1e-6));
    assertThat(size[2]).isCloseTo(120, within(1e-6));
    assertThat(fit.X_LB().translationVector().distanceTo(new Vec3(15, -40, 70))).isLessThan(1e-6);
    assertThat(fit.volume() / fit.hullVolume()).isCloseTo(1.0, within(1e-9));
  }

  // Method: a flat square plate (all points in one plane) has no hull; its box is the square,
  // MIN_THICKNESS_MM thick.
  @Test
  void aFlatCloudGetsAThinBox() {
    double[] p = {0, 0, 0, 100, 0, 0, 100, 50, 0, 0, 50, 0, 50, 25, 0};
    BoxFit fit = BoxFit.fit(p);
    assertThat(fit.hullVolume()).isZero();
    double[] size = {fit.size().x(), fit.size().y(), fit.size().z()};
    Arrays.sort(size);
    assertThat(size).containsExactly(new double[] {BoxFit.MIN_THICKNESS_MM, 50, 100}, within(1e-9));
  }
}
