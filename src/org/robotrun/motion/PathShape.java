package org.robotrun.motion;

import org.robotrun.math.Vec3;

/** The geometry of a Cartesian move's TCP path, parameterised by arc length fraction u ∈ [0, 1]. */
sealed interface PathShape {

  /** Path length (mm). */
  double lengthMm();

  /** The TCP's displacement from the path's start at fraction u (mm, WORLD). */
  Vec3 displacement(double u);

  /** A straight line from the start by {@code delta}. */
  record Line(Vec3 delta) implements PathShape {
    @Override
    public double lengthMm() {
      return delta.norm();
    }

    @Override
    public Vec3 displacement(double u) {
      return delta.times(u);
    }
  }

  /**
   * An arc of the circle with centre {@code c} and radius {@code r} in the plane spanned by the
   * unit vectors e1 (from the centre to the start) and e2, swept by {@code sweepRad} from e1
   * towards e2.
   */
  record Arc(Vec3 start, Vec3 center, double radius, Vec3 e1, Vec3 e2, double sweepRad) implements PathShape {
    @Override
    public double lengthMm() {
      return radius * sweepRad;
    }

    @Override
    public Vec3 displacement(double u) {
      double a = u * sweepRad;
      return center.plus(e1.times(radius * Math.cos(a))).plus(e2.times(radius * Math.sin(a))).minus(start);
    }

    /**
     * The arc that starts at p0, passes p1 and ends at p2, or null if the points are (nearly)
     * on one line or two coincide. Circumcentre after the vector form of the triangle's
     * circumcentre: {@code o = (|c|²·(b×c)×b + |b|²·c×(b×c)) / (2|b×c|²)}, b and c relative to p0.
     */
    static Arc through(Vec3 p0, Vec3 p1, Vec3 p2) {
      Vec3 b = p1.minus(p0);
      Vec3 c = p2.minus(p0);
      Vec3 n = b.cross(c);
      double n2 = n.dot(n);
      // Relative to the triangle's size: sin of the angle at p0 below ~1e-6 is a line.
      if (n2 <= 1e-12 * b.dot(b) * c.dot(c) || b.norm() < 1e-6 || c.norm() < 1e-6) {
        return null;
      }
      Vec3 o = n.cross(b).times(c.dot(c)).plus(c.cross(n).times(b.dot(b))).times(1 / (2 * n2));
      Vec3 center = p0.plus(o);
      double radius = o.norm();
      Vec3 e1 = o.times(-1 / radius);
      Vec3 e2 = n.normalized().cross(e1);
      Vec3 d2 = p2.minus(center);
      double sweep = Math.atan2(d2.dot(e2), d2.dot(e1));
      if (sweep <= 0) {
        sweep += 2 * Math.PI;
      }
      return new Arc(p0, center, radius, e1, e2, sweep);
    }
  }
}
