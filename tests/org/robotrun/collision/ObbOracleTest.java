package org.robotrun.collision;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * A box's corners and its ray test against definitions computed here (issue 31): the corner is
 * the centre plus ± each half size along the box's own axes (bit 0 +x, bit 1 +y, bit 2 +z), and a
 * ray's first hit is where a point walked along the ray first lies inside the box, found by
 * stepping and bisection with the inside test |(p − c)·axis_k| ≤ h_k.
 */
class ObbOracleTest {

  static Obb randomBox(Random rnd) {
    Transform X = Transform.fromRpy(rnd.nextDouble() * 400 - 200, rnd.nextDouble() * 400 - 200, rnd.nextDouble() * 400 - 200,
        rnd.nextDouble() * 6 - 3, rnd.nextDouble() * 3 - 1.5, rnd.nextDouble() * 6 - 3);
    return Obb.of(X, 10 + 60 * rnd.nextDouble(), 10 + 60 * rnd.nextDouble(), 10 + 60 * rnd.nextDouble());
  }

  static boolean inside(Obb b, Vec3 p, double tol) {
    Transform X = b.pose();
    Vec3 d = p.minus(X.translationVector());
    return Math.abs(d.dot(X.axis(0))) <= b.hx() + tol && Math.abs(d.dot(X.axis(1))) <= b.hy() + tol
        && Math.abs(d.dot(X.axis(2))) <= b.hz() + tol;
  }

  // Method: for 30 seeded general boxes, each corner against centre + sx·hx·x + sy·hy·y + sz·hz·z.
  @Test
  void cornersAreTheCentrePlusOrMinusEachHalfSizeAlongTheBoxAxes() {
    Random rnd = new Random(21);
    for (int k = 0; k < 30; k++) {
      Obb b = randomBox(rnd);
      Transform X = b.pose();
      for (int i = 0; i < 8; i++) {
        double sx = (i & 1) != 0 ? 1 : -1, sy = (i & 2) != 0 ? 1 : -1, sz = (i & 4) != 0 ? 1 : -1;
        Vec3 e = X.translationVector().plus(X.axis(0).times(sx * b.hx())).plus(X.axis(1).times(sy * b.hy()))
            .plus(X.axis(2).times(sz * b.hz()));
        double[] c = b.corner(i);
        assertThat(new Vec3(c[0], c[1], c[2]).distanceTo(e)).as("corner %d", i).isLessThan(1e-9);
      }
    }
  }

  // Method: rays from seeded points outside each box, aimed at a seeded point inside it (hit) or
  // at a point beyond the box's bounding sphere on the far side of a plane the box does not cross
  // (miss), with unnormalised directions; the hit parameter against stepping plus bisection
  // (1e-6 of the ray's length); a ray from inside hits at 0; a ray along a face plane's direction
  // outside the slab misses.
  @Test
  void rayHitsWhereAWalkAlongTheRayFirstEntersTheBox() {
    Random rnd = new Random(22);
    int hits = 0;
    for (int k = 0; k < 60; k++) {
      Obb b = randomBox(rnd);
      Transform X = b.pose();
      double radius = Math.sqrt(b.hx() * b.hx() + b.hy() * b.hy() + b.hz() * b.hz());
      Vec3 dir = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalized();
      Vec3 origin = X.translationVector().plus(dir.times(radius + 50 + 300 * rnd.nextDouble()));
      Vec3 aim = X.apply(new Vec3((rnd.nextDouble() * 1.6 - 0.8) * b.hx(), (rnd.nextDouble() * 1.6 - 0.8) * b.hy(),
          (rnd.nextDouble() * 1.6 - 0.8) * b.hz()));
      double scale = 0.1 + 5 * rnd.nextDouble();
      Vec3 d = aim.minus(origin).times(scale);
      double t = b.rayHit(origin.x(), origin.y(), origin.z(), d.x(), d.y(), d.z());
      // Walk: the aim point (t = 1/scale) is inside; find the first inside point before it.
      double tAim = 1 / scale;
      double lo = 0, hi = tAim;
      int steps = 4000;
      for (int s = 1; s <= steps; s++) {
        double ts = tAim * s / steps;
        if (inside(b, origin.plus(d.times(ts)), 0)) {
          hi = ts;
          lo = tAim * (s - 1) / steps;
          break;
        }
      }
      for (int it = 0; it < 60; it++) {
        double mid = (lo + hi) / 2;
        if (inside(b, origin.plus(d.times(mid)), 0)) {
          hi = mid;
        } else {
          lo = mid;
        }
      }
      assertThat(t).as("box %d", k).isCloseTo(hi, within(1e-6 * tAim));
      hits++;
      // Away from the box: the ray points from the origin further out.
      assertThat(b.rayHit(origin.x(), origin.y(), origin.z(), -d.x(), -d.y(), -d.z())).isNaN();
      // From inside: 0.
      assertThat(b.rayHit(aim.x(), aim.y(), aim.z(), d.x(), d.y(), d.z())).isEqualTo(0);
      // Parallel to the box's x axis, offset beyond its y half size: misses.
      Vec3 o2 = X.apply(new Vec3(-3 * b.hx(), 1.01 * b.hy(), 0));
      Vec3 ax = X.axis(0);
      assertThat(b.rayHit(o2.x(), o2.y(), o2.z(), ax.x(), ax.y(), ax.z())).isNaN();
      Vec3 o3 = X.apply(new Vec3(-3 * b.hx(), 0.99 * b.hy(), 0.5 * b.hz()));
      assertThat(b.rayHit(o3.x(), o3.y(), o3.z(), ax.x(), ax.y(), ax.z())).isCloseTo(2 * b.hx(), within(1e-6));
    }
    assertThat(hits).isEqualTo(60);
  }
}
