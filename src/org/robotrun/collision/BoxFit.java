package org.robotrun.collision;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * A tight oriented box around a point cloud (mm): the collision body of a link that has only a
 * mesh.
 *
 * <p>Method: candidates are the principal axes of the hull's vertices (PCA), the cloud's own
 * axes, and, for every distinct hull face direction, that normal with the minimum-area rectangle
 * of the points projected on the face's plane (rotating calipers over their 2D hull). A minimum
 * box has a face flush with a hull face in most cases (O'Rourke 1985 shows the exact optimum
 * also covers boxes flush with two hull edges; the face-flush search is the usual practical
 * subset), trying at most {@link #MAX_DIRECTIONS} directions, those of the largest faces first.
 * The smallest candidate wins. A flat cloud gets its PCA box, at least
 * {@link #MIN_THICKNESS_MM} thick.
 *
 * @param X_LB the box's centre and axes in the cloud's frame
 * @param size full edge lengths along the box's x, y, z (mm)
 * @param hullVolume the cloud's convex hull volume (mm³), 0 when flat
 */
public record BoxFit(Transform X_LB, Vec3 size, double hullVolume) {

  /** Most hull face directions tried (the largest faces'). */
  public static final int MAX_DIRECTIONS = 64;

  /** Thickness given to the box of a flat cloud (mm), so it still collides. */
  public static final double MIN_THICKNESS_MM = 1.0;

  /** The box's volume (mm³). */
  public double volume() {
    return size.x() * size.y() * size.z();
  }

  /** Fits a box to {@code xyz} (3 doubles per point, mm; at least one point). */
  public static BoxFit fit(double[] xyz) {
    if (xyz.length < 3) {
      throw new IllegalArgumentException("no points to fit a box to");
    }
    ConvexHull hull = ConvexHull.compute(dedupe(xyz));
    double[] pts = hull.isSolid() ? hull.vertices() : xyz;
    List<double[]> candidates = new ArrayList<>();
    candidates.add(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1});
    candidates.add(pcaAxes(pts));
    if (hull.isSolid()) {
      double[] normals = hull.faceNormals();
      double[] areas = hull.faceAreas();
      // Largest faces first: a smooth mesh (a sphere's hull has tens of thousands of faces) is
      // searched over its MAX_DIRECTIONS largest distinct face directions.
      Integer[] order = new Integer[areas.length];
      for (int i = 0; i < order.length; i++) {
        order[i] = i;
      }
      Arrays.sort(order, (a, b) -> Double.compare(areas[b], areas[a]));
      Set<Long> seen = new HashSet<>();
      for (int f : order) {
        if (seen.size() >= MAX_DIRECTIONS) {
          break;
        }
        int i = 3 * f;
        double nx = normals[i], ny = normals[i + 1], nz = normals[i + 2];
        if (nx * nx + ny * ny + nz * nz < 0.5) {
          continue;
        }
        // A face and its opposite give the same box; directions within about 0.5° are one.
        if (nx < 0 || (nx == 0 && (ny < 0 || (ny == 0 && nz < 0)))) {
          nx = -nx;
          ny = -ny;
          nz = -nz;
        }
        long key = Math.round(nx * 100) * 1_000_000L + Math.round(ny * 100) * 1000L + Math.round(nz * 100);
        if (seen.add(key)) {
          candidates.add(flushAxes(pts, nx, ny, nz));
        }
      }
    }
    double[] best = null;
    double bestVolume = Double.POSITIVE_INFINITY;
    double[] bestBox = null;
    for (double[] axes : candidates) {
      double[] box = extents(pts, axes);
      double v = Math.max(box[3], MIN_THICKNESS_MM) * Math.max(box[4], MIN_THICKNESS_MM) * Math.max(box[5], MIN_THICKNESS_MM);
      if (v < bestVolume) {
        bestVolume = v;
        best = axes;
        bestBox = box;
      }
    }
    double[] a = best;
    double[] b = bestBox;
    // Centre in the cloud frame: the axes are the box's columns.
    double cx = a[0] * b[0] + a[3] * b[1] + a[6] * b[2];
    double cy = a[1] * b[0] + a[4] * b[1] + a[7] * b[2];
    double cz = a[2] * b[0] + a[5] * b[1] + a[8] * b[2];
    // Rows a[0..2], a[3..5], a[6..8] are the box axes; as columns of R they give R_LB.
    Transform X_LB = new Transform(a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8], cx, cy, cz);
    Vec3 size = new Vec3(Math.max(b[3], MIN_THICKNESS_MM), Math.max(b[4], MIN_THICKNESS_MM), Math.max(b[5], MIN_THICKNESS_MM));
    return new BoxFit(X_LB, size, hull.volume());
  }

  /**
   * The box along {@code axes} (three unit rows): its centre in axis coordinates, then its
   * three edge lengths.
   */
  private static double[] extents(double[] p, double[] axes) {
    double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
    double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
    for (int i = 0; i < p.length; i += 3) {
      for (int k = 0; k < 3; k++) {
        double d = axes[3 * k] * p[i] + axes[3 * k + 1] * p[i + 1] + axes[3 * k + 2] * p[i + 2];
        lo[k] = Math.min(lo[k], d);
        hi[k] = Math.max(hi[k], d);
      }
    }
    return new double[] {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2,
        hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  }

  /** Axes with the third along n and the first two those of the smallest rectangle around the projection. */
  private static double[] flushAxes(double[] p, double nx, double ny, double nz) {
    // An orthonormal basis (u, v) of the plane normal to n.
    double[] u = Math.abs(nx) < 0.9 ? cross(nx, ny, nz, 1, 0, 0) : cross(nx, ny, nz, 0, 1, 0);
    normalize(u);
    double[] v = cross(nx, ny, nz, u[0], u[1], u[2]);
    normalize(v);
    int m = p.length / 3;
    double[] q = new double[2 * m];
    for (int i = 0; i < m; i++) {
      q[2 * i] = u[0] * p[3 * i] + u[1] * p[3 * i + 1] + u[2] * p[3 * i + 2];
      q[2 * i + 1] = v[0] * p[3 * i] + v[1] * p[3 * i + 1] + v[2] * p[3 * i + 2];
    }
    double[] h = hull2d(q);
    // Rotating calipers, done plainly: each hull edge direction once, O(h²) for hulls of a few hundred points.
    double bestArea = Double.POSITIVE_INFINITY;
    double bestC = 1, bestS = 0;
    int k = h.length / 2;
    for (int i = 0; i < k; i++) {
      int j = (i + 1) % k;
      double ex = h[2 * j] - h[2 * i], ey = h[2 * j + 1] - h[2 * i + 1];
      double len = Math.hypot(ex, ey);
      if (len == 0) {
        continue;
      }
      double c = ex / len, s = ey / len;
      double lo1 = Double.POSITIVE_INFINITY, hi1 = Double.NEGATIVE_INFINITY;
      double lo2 = Double.POSITIVE_INFINITY, hi2 = Double.NEGATIVE_INFINITY;
      for (int t = 0; t < k; t++) {
        double a = c * h[2 * t] + s * h[2 * t + 1];
        double b = -s * h[2 * t] + c * h[2 * t + 1];
        lo1 = Math.min(lo1, a);
        hi1 = Math.max(hi1, a);
        lo2 = Math.min(lo2, b);
        hi2 = Math.max(hi2, b);
      }
      double area = (hi1 - lo1) * (hi2 - lo2);
      if (area < bestArea) {
        bestArea = area;
        bestC = c;
        bestS = s;
      }
    }
    double[] ax = {bestC * u[0] + bestS * v[0], bestC * u[1] + bestS * v[1], bestC * u[2] + bestS * v[2]};
    double[] ay = {-bestS * u[0] + bestC * v[0], -bestS * u[1] + bestC * v[1], -bestS * u[2] + bestC * v[2]};
    normalize(ax);
    normalize(ay);
    double[] az = cross(ax[0], ax[1], ax[2], ay[0], ay[1], ay[2]);
    return new double[] {ax[0], ax[1], ax[2], ay[0], ay[1], ay[2], az[0], az[1], az[2]};
  }

  /** Andrew's monotone chain: the 2D hull of {@code q} (2 doubles per point), counter-clockwise. */
  static double[] hull2d(double[] all) {
    double[] q = dropInterior(all);
    int m = q.length / 2;
    Integer[] idx = new Integer[m];
    for (int i = 0; i < m; i++) {
      idx[i] = i;
    }
    Arrays.sort(idx, (a, b) -> q[2 * a] != q[2 * b] ? Double.compare(q[2 * a], q[2 * b]) : Double.compare(q[2 * a + 1], q[2 * b + 1]));
    int[] h = new int[2 * m + 1];
    int k = 0;
    for (int i = 0; i < m; i++) {
      while (k >= 2 && turn(q, h[k - 2], h[k - 1], idx[i]) <= 0) {
        k--;
      }
      h[k++] = idx[i];
    }
    for (int i = m - 2, lower = k + 1; i >= 0; i--) {
      while (k >= lower && turn(q, h[k - 2], h[k - 1], idx[i]) <= 0) {
        k--;
      }
      h[k++] = idx[i];
    }
    int count = Math.max(1, k - 1);
    double[] out = new double[2 * count];
    for (int i = 0; i < count; i++) {
      out[2 * i] = q[2 * h[i]];
      out[2 * i + 1] = q[2 * h[i] + 1];
    }
    return out;
  }

  /**
   * Akl–Toussaint: the points extreme along eight directions span an octagon inside the hull;
   * points strictly inside it cannot be hull vertices, so the sort sees only the rest.
   */
  private static double[] dropInterior(double[] q) {
    int m = q.length / 2;
    if (m < 64) {
      return q;
    }
    double[][] dirs = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    int[] ext = new int[8];
    for (int d = 0; d < 8; d++) {
      double best = Double.NEGATIVE_INFINITY;
      for (int i = 0; i < m; i++) {
        double v = dirs[d][0] * q[2 * i] + dirs[d][1] * q[2 * i + 1];
        if (v > best) {
          best = v;
          ext[d] = i;
        }
      }
    }
    double[] kept = new double[q.length];
    int k = 0;
    for (int i = 0; i < m; i++) {
      boolean inside = true;
      for (int d = 0; d < 8 && inside; d++) {
        int a = ext[d], b = ext[(d + 1) % 8];
        // Counter-clockwise octagon: inside means strictly left of every edge that has a length.
        if (a != b && turn(q, a, b, i) <= 1e-9 * (Math.abs(q[2 * a]) + Math.abs(q[2 * a + 1]) + 1)) {
          inside = false;
        }
      }
      if (!inside) {
        kept[k++] = q[2 * i];
        kept[k++] = q[2 * i + 1];
      }
    }
    return Arrays.copyOf(kept, k);
  }

  private static double turn(double[] q, int o, int a, int b) {
    return (q[2 * a] - q[2 * o]) * (q[2 * b + 1] - q[2 * o + 1]) - (q[2 * a + 1] - q[2 * o + 1]) * (q[2 * b] - q[2 * o]);
  }

  /** Principal axes of the points (rows), from the covariance by Jacobi rotations. */
  private static double[] pcaAxes(double[] p) {
    int m = p.length / 3;
    double[] mean = new double[3];
    for (int i = 0; i < p.length; i++) {
      mean[i % 3] += p[i] / m;
    }
    double[][] c = new double[3][3];
    for (int i = 0; i < m; i++) {
      for (int r = 0; r < 3; r++) {
        for (int s = 0; s < 3; s++) {
          c[r][s] += (p[3 * i + r] - mean[r]) * (p[3 * i + s] - mean[s]);
        }
      }
    }
    double[][] v = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int sweep = 0; sweep < 50; sweep++) {
      double off = Math.abs(c[0][1]) + Math.abs(c[0][2]) + Math.abs(c[1][2]);
      if (off < 1e-12 * (Math.abs(c[0][0]) + Math.abs(c[1][1]) + Math.abs(c[2][2]) + 1e-300)) {
        break;
      }
      for (int r = 0; r < 2; r++) {
        for (int s = r + 1; s < 3; s++) {
          if (c[r][s] == 0) {
            continue;
          }
          double theta = (c[s][s] - c[r][r]) / (2 * c[r][s]);
          double t = Math.signum(theta) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
          if (theta == 0) {
            t = 1;
          }
          double cs = 1 / Math.sqrt(t * t + 1), sn = t * cs;
          for (int k = 0; k < 3; k++) {
            double a = c[k][r], b = c[k][s];
            c[k][r] = cs * a - sn * b;
            c[k][s] = sn * a + cs * b;
          }
          for (int k = 0; k < 3; k++) {
            double a = c[r][k], b = c[s][k];
            c[r][k] = cs * a - sn * b;
            c[s][k] = sn * a + cs * b;
          }
          for (int k = 0; k < 3; k++) {
            double a = v[k][r], b = v[k][s];
            v[k][r] = cs * a - sn * b;
            v[k][s] = sn * a + cs * b;
          }
        }
      }
    }
    // Eigenvectors are v's columns; make a right-handed set of rows.
    double[] x = {v[0][0], v[1][0], v[2][0]};
    double[] y = {v[0][1], v[1][1], v[2][1]};
    normalize(x);
    normalize(y);
    double[] z = cross(x[0], x[1], x[2], y[0], y[1], y[2]);
    normalize(z);
    y = cross(z[0], z[1], z[2], x[0], x[1], x[2]);
    return new double[] {x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2]};
  }

  private static double[] dedupe(double[] xyz) {
    Set<List<Double>> seen = new HashSet<>();
    double[] out = new double[xyz.length];
    int k = 0;
    for (int i = 0; i + 2 < xyz.length; i += 3) {
      if (seen.add(List.of(xyz[i], xyz[i + 1], xyz[i + 2]))) {
        out[k++] = xyz[i];
        out[k++] = xyz[i + 1];
        out[k++] = xyz[i + 2];
      }
    }
    return Arrays.copyOf(out, k);
  }

  private static double[] cross(double ax, double ay, double az, double bx, double by, double bz) {
    return new double[] {ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx};
  }

  private static void normalize(double[] a) {
    double n = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (n > 0) {
      a[0] /= n;
      a[1] /= n;
      a[2] /= n;
    }
  }
}
