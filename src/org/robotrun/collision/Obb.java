package org.robotrun.collision;

import org.robotrun.math.Transform;

/**
 * An oriented bounding box B seen in a frame W (usually WORLD): its centre {@code p_WBo}
 * (mm), its half extents along its own axes (mm, ≥ 0) and the rotation {@code R_WB}
 * (row-major, columns are the box's axes in W), so {@code p_W = R_WB·p_B + p_WBo}.
 *
 * <p>Boxes are closed: two boxes that only touch overlap (see {@link SeparatingAxisTest}).
 * Held in primitive fields so the separating-axis test reads them without allocating.
 */
public record Obb(
    double cx, double cy, double cz,
    double hx, double hy, double hz,
    double r00, double r01, double r02,
    double r10, double r11, double r12,
    double r20, double r21, double r22) {

  /** Doubles per box in the flat layout used by {@link #writeTo} and the broad phase. */
  public static final int STRIDE = 15;

  public Obb {
    if (!(hx >= 0 && hy >= 0 && hz >= 0)) {
      throw new IllegalArgumentException("half extents must be >= 0, got " + hx + ", " + hy + ", " + hz);
    }
  }

  /** The box with frame {@code X_WB} (centre and axes) and the given half extents (mm). */
  public static Obb of(Transform X_WB, double hx, double hy, double hz) {
    return new Obb(X_WB.x(), X_WB.y(), X_WB.z(), hx, hy, hz,
        X_WB.r00(), X_WB.r01(), X_WB.r02(),
        X_WB.r10(), X_WB.r11(), X_WB.r12(),
        X_WB.r20(), X_WB.r21(), X_WB.r22());
  }

  /** An axis-aligned box from its centre and half extents (mm). */
  public static Obb axisAligned(double cx, double cy, double cz, double hx, double hy, double hz) {
    return new Obb(cx, cy, cz, hx, hy, hz, 1, 0, 0, 0, 1, 0, 0, 0, 1);
  }

  /** Reads box {@code index} from a flat array laid out as {@link #writeTo} writes it. */
  public static Obb readFrom(double[] flat, int index) {
    int o = index * STRIDE;
    return new Obb(flat[o], flat[o + 1], flat[o + 2], flat[o + 3], flat[o + 4], flat[o + 5],
        flat[o + 6], flat[o + 7], flat[o + 8], flat[o + 9], flat[o + 10], flat[o + 11],
        flat[o + 12], flat[o + 13], flat[o + 14]);
  }

  /** The box's frame {@code X_WB}. */
  public Transform pose() {
    return new Transform(r00, r01, r02, r10, r11, r12, r20, r21, r22, cx, cy, cz);
  }

  /**
   * Writes the box into {@code flat} at {@code index * STRIDE}: centre, half extents, then the
   * rotation row-major (the CSV column order of {@code bench collision}).
   */
  public void writeTo(double[] flat, int index) {
    int o = index * STRIDE;
    flat[o] = cx; flat[o + 1] = cy; flat[o + 2] = cz;
    flat[o + 3] = hx; flat[o + 4] = hy; flat[o + 5] = hz;
    flat[o + 6] = r00; flat[o + 7] = r01; flat[o + 8] = r02;
    flat[o + 9] = r10; flat[o + 10] = r11; flat[o + 11] = r12;
    flat[o + 12] = r20; flat[o + 13] = r21; flat[o + 14] = r22;
  }

  /** Whether this box and {@code other} overlap or touch. */
  public boolean overlaps(Obb other) {
    return SeparatingAxisTest.overlap(this, other);
  }

  /** Corner {@code i} (0..7; bit 0 picks +x, bit 1 +y, bit 2 +z) in W (mm). */
  public double[] corner(int i) {
    double sx = (i & 1) != 0 ? hx : -hx;
    double sy = (i & 2) != 0 ? hy : -hy;
    double sz = (i & 4) != 0 ? hz : -hz;
    return new double[] {
      cx + r00 * sx + r01 * sy + r02 * sz,
      cy + r10 * sx + r11 * sy + r12 * sz,
      cz + r20 * sx + r21 * sy + r22 * sz
    };
  }

  /**
   * Where a ray first meets this box (slab test in the box's frame): the ray parameter t ≥ 0
   * with {@code p = o + t·d}, or NaN when it misses. A ray starting inside hits at t = 0.
   *
   * @param ox ray origin in W (mm)
   * @param dx ray direction in W (need not be unit length)
   */
  public double rayHit(double ox, double oy, double oz, double dx, double dy, double dz) {
    // origin and direction in the box frame: R_WB transposed
    double px = ox - cx, py = oy - cy, pz = oz - cz;
    double[] o = {r00 * px + r10 * py + r20 * pz, r01 * px + r11 * py + r21 * pz, r02 * px + r12 * py + r22 * pz};
    double[] d = {r00 * dx + r10 * dy + r20 * dz, r01 * dx + r11 * dy + r21 * dz, r02 * dx + r12 * dy + r22 * dz};
    double[] h = {hx, hy, hz};
    double tMin = 0, tMax = Double.POSITIVE_INFINITY;
    for (int a = 0; a < 3; a++) {
      if (Math.abs(d[a]) < 1e-15) {
        if (Math.abs(o[a]) > h[a]) {
          return Double.NaN;
        }
        continue;
      }
      double t1 = (-h[a] - o[a]) / d[a], t2 = (h[a] - o[a]) / d[a];
      tMin = Math.max(tMin, Math.min(t1, t2));
      tMax = Math.min(tMax, Math.max(t1, t2));
      if (tMin > tMax) {
        return Double.NaN;
      }
    }
    return tMin;
  }
}
