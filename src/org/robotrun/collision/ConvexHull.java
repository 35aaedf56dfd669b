package org.robotrun.collision;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The convex hull of a point cloud in 3D (mm), for fitting collision boxes to meshes and for
 * reporting how tight they are.
 *
 * <p>Method: quickhull (Barber, Dobkin, Huhdanpaa 1996): start from a large tetrahedron found
 * from extreme points, then repeatedly add the farthest point outside a face: delete the faces
 * it sees, close the hole with a cone of faces from the horizon to the point; tolerance 1e-9 of
 * the cloud's extent. A flat or empty cloud has no hull: {@link #compute} returns an empty hull
 * (volume 0, no faces).
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
    List<int[]> faces = new Builder(xyz, eps).build(tetra, n);
    // A walk that met an edge with no face behind it (rounding in a near-degenerate cloud) gives no hull.
    return new ConvexHull(xyz, faces == null ? List.of() : faces);
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

  /** Areas of the hull's faces (mm²), in the order of {@link #faceNormals}. */
  public double[] faceAreas() {
    double[] out = new double[faces.size()];
    for (int i = 0; i < faces.size(); i++) {
      int[] f = faces.get(i);
      double[] c = cross(sub(points, f[1], f[0]), sub(points, f[2], f[0]));
      out[i] = Math.sqrt(dot(c, c)) / 2;
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

  /**
   * Quickhull-style construction: every point outside the hull waits in the outside set of one
   * face it sees; the farthest point of a face is added next, the faces it sees are found by a
   * walk over neighbouring faces (they are connected), replaced by a cone from the horizon, and
   * their waiting points move to the new faces. Faces are vertex triples, counter-clockwise seen
   * from outside; a directed edge maps to the face that holds it.
   */
  private static final class Builder {
    private final double[] p;
    private final double eps;
    private final List<int[]> faces = new ArrayList<>();
    private final List<double[]> planes = new ArrayList<>();
    private final List<Boolean> alive = new ArrayList<>();
    private final List<IntList> outside = new ArrayList<>();
    private final Map<Long, Integer> edgeFace = new HashMap<>();

    Builder(double[] p, double eps) {
      this.p = p;
      this.eps = eps;
    }

    List<int[]> build(int[] t, int n) {
      // Orient the tetrahedron's faces outward: the fourth vertex must lie behind each.
      int[][] tf = {{t[0], t[1], t[2]}, {t[0], t[3], t[1]}, {t[1], t[3], t[2]}, {t[2], t[3], t[0]}};
      int[] opposite = {t[3], t[2], t[0], t[1]};
      boolean flip = signedDistance(plane(tf[0]), opposite[0]) > 0;
      for (int[] f : tf) {
        add(flip ? new int[] {f[0], f[2], f[1]} : f);
      }
      IntList all = new IntList();
      for (int i = 0; i < n; i++) {
        if (i != t[0] && i != t[1] && i != t[2] && i != t[3]) {
          all.add(i);
        }
      }
      List<Integer> created = List.of(0, 1, 2, 3);
      assign(all, created);
      java.util.ArrayDeque<Integer> work = new java.util.ArrayDeque<>(created);
      while (!work.isEmpty()) {
        int f = work.pop();
        if (!alive.get(f) || outside.get(f).size == 0) {
          continue;
        }
        List<Integer> made = addPoint(f, farthest(f));
        if (made == null) {
          return null;
        }
        work.addAll(made);
      }
      List<int[]> out = new ArrayList<>();
      for (int i = 0; i < faces.size(); i++) {
        if (alive.get(i)) {
          out.add(faces.get(i));
        }
      }
      return out;
    }

    private int farthest(int f) {
      IntList o = outside.get(f);
      double[] pl = planes.get(f);
      int best = o.get(0);
      double bestD = signedDistance(pl, best);
      for (int k = 1; k < o.size; k++) {
        double d = signedDistance(pl, o.get(k));
        if (d > bestD) {
          bestD = d;
          best = o.get(k);
        }
      }
      return best;
    }

    /** Adds point q seen from face f; returns the new faces (null when the hull's edges are inconsistent). */
    private List<Integer> addPoint(int f, int q) {
      List<Integer> visible = new ArrayList<>(List.of(f));
      Map<Integer, Boolean> seen = new HashMap<>();
      seen.put(f, true);
      List<int[]> horizon = new ArrayList<>();
      for (int v = 0; v < visible.size(); v++) {
        int[] face = faces.get(visible.get(v));
        for (int e = 0; e < 3; e++) {
          int a = face[e], b = face[(e + 1) % 3];
          Integer g = edgeFace.get(key(b, a));
          if (g == null) {
            return null;
          }
          Boolean vis = seen.get(g);
          if (vis == null) {
            vis = signedDistance(planes.get(g), q) > eps;
            seen.put(g, vis);
            if (vis) {
              visible.add(g);
            }
          }
          if (!vis) {
            horizon.add(new int[] {a, b});
          }
        }
      }
      IntList orphans = new IntList();
      for (int v : visible) {
        alive.set(v, false);
        int[] face = faces.get(v);
        for (int e = 0; e < 3; e++) {
          edgeFace.remove(key(face[e], face[(e + 1) % 3]));
        }
        IntList o = outside.get(v);
        for (int k = 0; k < o.size; k++) {
          if (o.get(k) != q) {
            orphans.add(o.get(k));
          }
        }
        outside.set(v, new IntList());
      }
      List<Integer> made = new ArrayList<>();
      for (int[] e : horizon) {
        made.add(add(new int[] {e[0], e[1], q}));
      }
      assign(orphans, made);
      return made;
    }

    private void assign(IntList points, List<Integer> candidates) {
      for (int k = 0; k < points.size; k++) {
        int i = points.get(k);
        for (int f : candidates) {
          if (signedDistance(planes.get(f), i) > eps) {
            outside.get(f).add(i);
            break;
          }
        }
      }
    }

    private int add(int[] f) {
      int idx = faces.size();
      faces.add(f);
      planes.add(plane(f));
      alive.add(true);
      outside.add(new IntList());
      for (int e = 0; e < 3; e++) {
        edgeFace.put(key(f[e], f[(e + 1) % 3]), idx);
      }
      return idx;
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

  /** A growable list of ints. */
  private static final class IntList {
    private int[] a = new int[4];
    private int size;

    void add(int v) {
      if (size == a.length) {
        a = java.util.Arrays.copyOf(a, size * 2);
      }
      a[size++] = v;
    }

    int get(int i) {
      return a[i];
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
