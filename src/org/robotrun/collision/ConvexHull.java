package org.robotrun.collision;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;

/**
 * The convex hull of a point cloud in 3D (mm), for fitting collision boxes to meshes and for
 * reporting how tight they are.
 *
 * <p>Method: incremental construction (start from the largest tetrahedron found from extreme
 * points, then add each point outside the hull: delete the faces it sees, close the hole with a
 * cone of faces from the horizon to the point), with a tolerance of 1e-9 of the cloud's extent.
 * Points are visited in a fixed shuffled order so sorted input does not hit the quadratic case.
 * A flat or empty cloud has no hull: {@link #compute} returns an empty hull (volume 0, no faces).
 */
public final class ConvexHull {
  private final double[] points;
  private final List<int[]> faces;

  private ConvexHull(double[] points, List<int[]> faces) {
    this.points = points;
    this.faces = faces;
  }

  /** The hull of {@code xyz} (3 doubles per point, mm). */
  public static ConvexHull compute(double[] xyz) {
    int n = xyz.length / 3;
    if (n < 4) {
      return new ConvexHull(xyz, List.of());
    }
    double extent = 0;
    for (int i = 0; i < xyz.length; i++) {
      extent = Math.max(extent, Math.abs(xyz[i] - xyz[i % 3]));
    }
    double eps = Math.max(extent, 1e-12) * 1e-9;
    int[] tetra = initialTetrahedron(xyz, n, eps);
    if (tetra == null) {
      return new ConvexHull(xyz, List.of());
    }
    return new ConvexHull(xyz, new Builder(xyz, eps).build(tetra, n));
  }

  /** Whether the cloud spans a volume (at least four points not in one plane). */
  public boolean isSolid() {
    return !faces.isEmpty();
  }

  /** Enclosed volume (mm³), 0 for a flat cloud. */
  public double volume() {
    if (faces.isEmpty()) {
      return 0;
    }
    double[] c = centroidOfVertices();
    double v = 0;
    for (int[] f : faces) {
      double ax = points[3 * f[0]] - c[0], ay = points[3 * f[0] + 1] - c[1], az = points[3 * f[0] + 2] - c[2];
      double bx = points[3 * f[1]] - c[0], by = points[3 * f[1] + 1] - c[1], bz = points[3 * f[1] + 2] - c[2];
      double cx = points[3 * f[2]] - c[0], cy = points[3 * f[2] + 1] - c[1], cz = points[3 * f[2] + 2] - c[2];
      v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
    }
    return v / 6;
  }

  /** The hull's vertices, 3 doubles each (mm); empty for a flat cloud. */
  public double[] vertices() {
    Set<Integer> used = new LinkedHashSet<>();
    for (int[] f : faces) {
      used.add(f[0]);
      used.add(f[1]);
      used.add(f[2]);
    }
    double[] out = new double[used.size() * 3];
    int k = 0;
    for (int i : used) {
      out[k++] = points[3 * i];
      out[k++] = points[3 * i + 1];
      out[k++] = points[3 * i + 2];
    }
    return out;
  }

  /** Outward unit normals of the hull's faces, 3 doubles each. */
  public double[] faceNormals() {
    double[] out = new double[faces.size() * 3];
    for (int i = 0; i < faces.size(); i++) {
      double[] nrm = normal(points, faces.get(i));
      out[3 * i] = nrm[0];
      out[3 * i + 1] = nrm[1];
      out[3 * i + 2] = nrm[2];
    }
    return out;
  }

  /** Number of triangular faces. */
  public int faceCount() {
    return faces.size();
  }

  private double[] centroidOfVertices() {
    double[] v = vertices();
    double[] c = new double[3];
    for (int i = 0; i < v.length; i++) {
      c[i % 3] += v[i];
    }
    int m = v.length / 3;
    for (int i = 0; i < 3; i++) {
      c[i] /= m;
    }
    return c;
  }

  private static int[] initialTetrahedron(double[] p, int n, double eps) {
    int a = 0;
    for (int i = 1; i < n; i++) {
      if (p[3 * i] < p[3 * a]) {
        a = i;
      }
    }
    int b = -1;
    double best = eps;
    for (int i = 0; i < n; i++) {
      double d = dist2(p, a, i);
      if (d > best * best) {
        best = Math.sqrt(d);
        b = i;
      }
    }
    if (b < 0) {
      return null;
    }
    int c = -1;
    best = eps * eps;
    for (int i = 0; i < n; i++) {
      double[] cr = cross(sub(p, b, a), sub(p, i, a));
      double d = dot(cr, cr);
      if (d > best) {
        best = d;
        c = i;
      }
    }
    if (c < 0) {
      return null;
    }
    double[] nrm = cross(sub(p, b, a), sub(p, c, a));
    double len = Math.sqrt(dot(nrm, nrm));
    int d = -1;
    best = eps;
    for (int i = 0; i < n; i++) {
      double h = Math.abs(dot(nrm, sub(p, i, a))) / len;
      if (h > best) {
        best = h;
        d = i;
      }
    }
    return d < 0 ? null : new int[] {a, b, c, d};
  }

  /** The incremental construction; faces are vertex triples, counter-clockwise seen from outside. */
  private static final class Builder {
    private final double[] p;
    private final double eps;
    private final List<int[]> faces = new ArrayList<>();
    private final List<double[]> planes = new ArrayList<>();
    private final List<Boolean> alive = new ArrayList<>();

    Builder(double[] p, double eps) {
      this.p = p;
      this.eps = eps;
    }

    List<int[]> build(int[] t, int n) {
      // Orient the tetrahedron's faces outward: the fourth vertex must lie behind each.
      int[][] tf = {{t[0], t[1], t[2]}, {t[0], t[3], t[1]}, {t[1], t[3], t[2]}, {t[2], t[3], t[0]}};
      int[] opposite = {t[3], t[2], t[0], t[1]};
      for (int i = 0; i < 4; i++) {
        int[] f = tf[i];
        double[] pl = plane(f);
        if (signedDistance(pl, opposite[i]) > 0) {
          f = new int[] {f[0], f[2], f[1]};
        }
        add(f);
      }
      int[] order = new int[n];
      for (int i = 0; i < n; i++) {
        order[i] = i;
      }
      Random rnd = new Random(1);
      for (int i = n - 1; i > 0; i--) {
        int j = rnd.nextInt(i + 1);
        int tmp = order[i];
        order[i] = order[j];
        order[j] = tmp;
      }
      for (int idx : order) {
        insert(idx);
      }
      List<int[]> out = new ArrayList<>();
      for (int i = 0; i < faces.size(); i++) {
        if (alive.get(i)) {
          out.add(faces.get(i));
        }
      }
      return out;
    }

    private void insert(int q) {
      List<Integer> visible = new ArrayList<>();
      for (int i = 0; i < faces.size(); i++) {
        if (alive.get(i) && signedDistance(planes.get(i), q) > eps) {
          visible.add(i);
        }
      }
      if (visible.isEmpty()) {
        return;
      }
      // Directed edges of the visible faces; an edge whose reverse is not among them is on the horizon.
      Map<Long, int[]> edges = new HashMap<>();
      Set<Long> all = new HashSet<>();
      for (int i : visible) {
        int[] f = faces.get(i);
        for (int e = 0; e < 3; e++) {
          all.add(key(f[e], f[(e + 1) % 3]));
        }
      }
      for (int i : visible) {
        int[] f = faces.get(i);
        for (int e = 0; e < 3; e++) {
          int a = f[e], b = f[(e + 1) % 3];
          if (!all.contains(key(b, a))) {
            edges.put(key(a, b), new int[] {a, b});
          }
        }
        alive.set(i, false);
      }
      for (int[] e : edges.values()) {
        add(new int[] {e[0], e[1], q});
      }
    }

    private void add(int[] f) {
      faces.add(f);
      planes.add(plane(f));
      alive.add(true);
    }

    private double[] plane(int[] f) {
      double[] nrm = normal(p, f);
      return new double[] {nrm[0], nrm[1], nrm[2], nrm[0] * p[3 * f[0]] + nrm[1] * p[3 * f[0] + 1] + nrm[2] * p[3 * f[0] + 2]};
    }

    private double signedDistance(double[] pl, int i) {
      return pl[0] * p[3 * i] + pl[1] * p[3 * i + 1] + pl[2] * p[3 * i + 2] - pl[3];
    }

    private static long key(int a, int b) {
      return ((long) a << 32) | (b & 0xffffffffL);
    }
  }

  private static double[] normal(double[] p, int[] f) {
    double[] nrm = cross(sub(p, f[1], f[0]), sub(p, f[2], f[0]));
    double len = Math.sqrt(dot(nrm, nrm));
    if (len == 0) {
      return new double[] {0, 0, 0};
    }
    return new double[] {nrm[0] / len, nrm[1] / len, nrm[2] / len};
  }

  private static double dist2(double[] p, int i, int j) {
    double dx = p[3 * i] - p[3 * j], dy = p[3 * i + 1] - p[3 * j + 1], dz = p[3 * i + 2] - p[3 * j + 2];
    return dx * dx + dy * dy + dz * dz;
  }

  private static double[] sub(double[] p, int i, int j) {
    return new double[] {p[3 * i] - p[3 * j], p[3 * i + 1] - p[3 * j + 1], p[3 * i + 2] - p[3 * j + 2]};
  }

  private static double[] cross(double[] a, double[] b) {
    return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }

  private static double dot(double[] a, double[] b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
}
