package org.robotrun.collision;

/**
 * Reference test for two closed boxes, independent of the separating-axis theorem: two convex
 * polyhedra intersect iff an edge of one meets the other solid (that covers a vertex inside
 * the other, an edge crossing a face, and nesting, since a nested box's edges lie inside).
 * Each of the 24 edges is clipped against the other box's slabs (Liang–Barsky) in that box's
 * frame, with the box grown by {@code tolMm} on every face: touching counts as overlap.
 */
final class BruteForceOverlap {
  private BruteForceOverlap() {}

  static boolean overlap(Obb a, Obb b, double tolMm) {
    return anyEdgeMeets(a, b, tolMm) || anyEdgeMeets(b, a, tolMm);
  }

  private static boolean anyEdgeMeets(Obb edgesOf, Obb solid, double tol) {
    double[][] p = new double[8][];
    for (int i = 0; i < 8; i++) {
      p[i] = toLocal(solid, edgesOf.corner(i));
    }
    // The 12 edges join corners whose indices differ in one bit.
    for (int i = 0; i < 8; i++) {
      for (int bit = 1; bit < 8; bit <<= 1) {
        int j = i | bit;
        if (j != i && segmentMeetsBox(p[i], p[j], solid.hx() + tol, solid.hy() + tol, solid.hz() + tol)) {
          return true;
        }
      }
    }
    return false;
  }

  private static double[] toLocal(Obb o, double[] p) {
    double dx = p[0] - o.cx(), dy = p[1] - o.cy(), dz = p[2] - o.cz();
    return new double[] {
      o.r00() * dx + o.r10() * dy + o.r20() * dz,
      o.r01() * dx + o.r11() * dy + o.r21() * dz,
      o.r02() * dx + o.r12() * dy + o.r22() * dz
    };
  }

  /** Whether the segment p→q meets the closed box |x| ≤ h (Liang–Barsky clipping). */
  static boolean segmentMeetsBox(double[] p, double[] q, double hx, double hy, double hz) {
    double[] h = {hx, hy, hz};
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 3; k++) {
      double d = q[k] - p[k];
      if (d == 0) {
        if (p[k] < -h[k] || p[k] > h[k]) {
          return false;
        }
        continue;
      }
      double ta = (-h[k] - p[k]) / d;
      double tb = (h[k] - p[k]) / d;
      t0 = Math.max(t0, Math.min(ta, tb));
      t1 = Math.min(t1, Math.max(ta, tb));
      if (t0 > t1) {
        return false;
      }
    }
    return true;
  }
}
