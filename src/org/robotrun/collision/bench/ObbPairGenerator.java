package org.robotrun.collision.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.robotrun.collision.Obb;

/**
 * Seeded random box pairs for tests and benchmarks: a mix of general placements (about half
 * overlapping) and deliberately built contacts — face on face, vertex on face, edge across
 * edge, nested boxes, axis-aligned and quarter-turn boxes with exactly parallel edges — each
 * at a known gap: touching (0), inside the 1e-6 mm contact tolerance (1e-9 and 5e-7 mm: still
 * touching), just beyond it (3e-6 mm: apart), clearly apart (≥ 1e-3 mm) or penetrating.
 */
public final class ObbPairGenerator {

  /** What the construction guarantees about a pair. */
  public enum Expect {
    /** Overlapping, or apart by at most half the contact tolerance, by construction. */
    OVERLAP,
    /** Apart by at least 3e-6 mm (three times the contact tolerance) by construction. */
    SEPARATE,
    /** A general random placement: only a reference test can say. */
    UNKNOWN
  }

  /** How a pair was built. */
  public enum Kind { GENERAL, FACE_FACE, VERTEX_FACE, EDGE_EDGE, NESTED, PARALLEL }

  /** One generated pair. */
  public record LabeledPair(Obb a, Obb b, Kind kind, Expect expect) {}

  // Penetrations stay below the thinnest plate (1 mm), so a corner never pokes through.
  // 5e-7 and 3e-6 sit either side of the 1e-6 mm contact tolerance.
  private static final double[] GAPS_MM = {0, 0, 1e-9, -1e-9, 5e-7, 3e-6, 1e-3, 0.01, 0.5, 5, -1e-3, -0.1, -0.5};

  private final Random random;

  public ObbPairGenerator(long seed) {
    this.random = new Random(seed);
  }

  /** {@code n} pairs: 40 % general, the rest spread over the constructed kinds. */
  public List<LabeledPair> pairs(int n) {
    List<LabeledPair> out = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      int pick = random.nextInt(20);
      out.add(switch (pick) {
        case 0, 1, 2, 3, 4, 5, 6, 7 -> general();
        case 8, 9 -> faceFace();
        case 10, 11, 12 -> vertexFace();
        case 13, 14, 15 -> edgeEdge();
        case 16, 17 -> nested();
        default -> parallel();
      });
    }
    return out;
  }

  /** Random sizes and poses in a 300 mm cube: roughly half overlap. */
  public LabeledPair general() {
    Obb a = box(randomRotation(), 0, 0, 0);
    Obb b = box(randomRotation(), uniform(-150, 150), uniform(-150, 150), uniform(-150, 150));
    return new LabeledPair(a, b, Kind.GENERAL, Expect.UNKNOWN);
  }

  /** B's face lies on A's face (B turned about the common normal), at a chosen gap. */
  public LabeledPair faceFace() {
    double[] rA = randomRotation();
    Obb a = box(rA, uniform(-500, 500), uniform(-500, 500), uniform(-500, 500));
    int k = random.nextInt(3);
    double s = random.nextBoolean() ? 1 : -1;
    double[] rB = mul(rA, axisRotation(k, uniform(0, 2 * Math.PI)));
    double[] hB = {uniform(1, 100), uniform(1, 100), uniform(1, 100)};
    double gap = gap();
    double[] n = scale(column(rA, k), s);
    double lateral = 0.5 * Math.min(Math.min(ext(a, 0), ext(a, 1)), ext(a, 2));
    double[] c = add(center(a), scale(n, ext(a, k) + hB[k] + gap));
    for (int m = 0; m < 3; m++) {
      if (m != k) {
        c = add(c, scale(column(rA, m), uniform(-lateral, lateral)));
      }
    }
    return new LabeledPair(a, obb(c, hB, rB), Kind.FACE_FACE, expect(gap));
  }

  /** B's corner nearest to A sits over a point inside A's face, at a chosen gap. */
  public LabeledPair vertexFace() {
    double[] rA = randomRotation();
    Obb a = box(rA, uniform(-500, 500), uniform(-500, 500), uniform(-500, 500));
    int k = random.nextInt(3);
    double[] n = scale(column(rA, k), random.nextBoolean() ? 1 : -1);
    double[] rB = randomRotation();
    double[] hB = {uniform(1, 100), uniform(1, 100), uniform(1, 100)};
    double gap = gap();
    double[] p = add(center(a), scale(n, ext(a, k) + gap));
    for (int m = 0; m < 3; m++) {
      if (m != k) {
        p = add(p, scale(column(rA, m), uniform(-0.9, 0.9) * ext(a, m)));
      }
    }
    // B's support corner in direction -n: every axis signed against n.
    double[] corner = new double[3];
    for (int m = 0; m < 3; m++) {
      double[] bm = column(rB, m);
      corner = add(corner, scale(bm, -Math.signum(dot(n, bm)) * hB[m]));
    }
    return new LabeledPair(a, obb(sub(p, corner), hB, rB), Kind.VERTEX_FACE, expect(gap));
  }

  /** An edge of B crosses an edge of A, apart by a chosen gap along their common normal. */
  public LabeledPair edgeEdge() {
    while (true) {
      double[] rA = randomRotation();
      double[] rB = randomRotation();
      int i = random.nextInt(3);
      int j = random.nextInt(3);
      double[] cross = crossProduct(column(rA, i), column(rB, j));
      double len = Math.sqrt(dot(cross, cross));
      if (len < 0.2) {
        continue; // nearly parallel edges: the common normal is poorly defined
      }
      double[] n = scale(cross, 1 / len);
      Obb a = box(rA, uniform(-500, 500), uniform(-500, 500), uniform(-500, 500));
      double[] hB = {uniform(1, 100), uniform(1, 100), uniform(1, 100)};
      // A's edge along a_i that is extreme in +n, and B's along b_j extreme in -n.
      double[] pA = add(center(a), scale(column(rA, i), uniform(-0.8, 0.8) * ext(a, i)));
      double[] pB = scale(column(rB, j), uniform(-0.8, 0.8) * hB[j]);
      for (int m = 0; m < 3; m++) {
        if (m != i) {
          pA = add(pA, scale(column(rA, m), Math.signum(dot(n, column(rA, m))) * ext(a, m)));
        }
        if (m != j) {
          pB = add(pB, scale(column(rB, m), -Math.signum(dot(n, column(rB, m))) * hB[m]));
        }
      }
      double gap = gap();
      double[] c = sub(add(pA, scale(n, gap)), pB);
      return new LabeledPair(a, obb(c, hB, rB), Kind.EDGE_EDGE, expect(gap));
    }
  }

  /** A small box well inside a large one (either order). */
  public LabeledPair nested() {
    double[] rA = randomRotation();
    double[] hA = {uniform(50, 150), uniform(50, 150), uniform(50, 150)};
    double room = Math.min(Math.min(hA[0], hA[1]), hA[2]);
    double r = uniform(0.05, 0.45) * room;
    double h = r / Math.sqrt(3);
    Obb big = obb(new double[] {uniform(-500, 500), uniform(-500, 500), uniform(-500, 500)}, hA, rA);
    double[] off = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    double[] c = add(center(big), scale(off, (room - r) / Math.sqrt(3) * 0.99));
    Obb small = obb(c, new double[] {h * uniform(0.2, 1), h * uniform(0.2, 1), h}, randomRotation());
    return random.nextBoolean()
        ? new LabeledPair(big, small, Kind.NESTED, Expect.OVERLAP)
        : new LabeledPair(small, big, Kind.NESTED, Expect.OVERLAP);
  }

  /**
   * Boxes whose axes are parallel (B is A turned by quarter turns) (exactly parallel edges, the case the epsilon guards)
   * with integer sizes, touching or apart along a face, an edge or a corner direction.
   */
  public LabeledPair parallel() {
    // Half of them in a general orientation: B's axes are then A's up to rounding.
    double[] rA = random.nextBoolean() ? quarterTurns() : randomRotation();
    double[] rB = mul(rA, quarterTurns());
    double[] hA = {random.nextInt(1, 60), random.nextInt(1, 60), random.nextInt(1, 60)};
    double[] hB = {random.nextInt(1, 60), random.nextInt(1, 60), random.nextInt(1, 60)};
    Obb a = obb(new double[] {random.nextInt(-300, 300), random.nextInt(-300, 300), random.nextInt(-300, 300)}, hA, rA);
    Obb b0 = obb(new double[3], hB, rB);
    // B's extent along each A axis: sum of |a_m . b_q| h_q, each term 0 or h_q up to rounding.
    double gap = gap();
    int dims = random.nextInt(1, 4); // 1: face contact, 2: edge, 3: corner
    double[] c = center(a);
    for (int m = 0; m < 3; m++) {
      double[] am = column(rA, m);
      double extB = 0;
      for (int q = 0; q < 3; q++) {
        extB += Math.abs(dot(am, column(rB, q))) * hB[q];
      }
      double sign = random.nextBoolean() ? 1 : -1;
      double along = m < dims ? sign * (hA[m] + extB + gap) : random.nextInt(-(int) hA[m], (int) hA[m] + 1);
      c = add(c, scale(am, along));
    }
    Obb b = obb(c, new double[] {b0.hx(), b0.hy(), b0.hz()}, rB);
    // A gap in two or three directions at once puts the boxes apart by more, never closer.
    return new LabeledPair(a, b, Kind.PARALLEL, expect(gap));
  }

  private static Expect expect(double gap) {
    return gap <= 5e-7 ? Expect.OVERLAP : Expect.SEPARATE;
  }

  private double gap() {
    return GAPS_MM[random.nextInt(GAPS_MM.length)];
  }

  private double uniform(double lo, double hi) {
    return lo + (hi - lo) * random.nextDouble();
  }

  private Obb box(double[] r, double cx, double cy, double cz) {
    double[] h = {uniform(1, 100), uniform(1, 100), uniform(1, 100)};
    // One box in five is a thin plate, the shape that tables and grippers make.
    if (random.nextInt(5) == 0) {
      h[random.nextInt(3)] = uniform(0.5, 3);
    }
    return obb(new double[] {cx, cy, cz}, h, r);
  }

  /** Uniform random rotation (row-major) from a unit quaternion, after K. Shoemake (1992). */
  private double[] randomRotation() {
    double u1 = random.nextDouble(), u2 = random.nextDouble(), u3 = random.nextDouble();
    double a = Math.sqrt(1 - u1), b = Math.sqrt(u1);
    double x = a * Math.sin(2 * Math.PI * u2), y = a * Math.cos(2 * Math.PI * u2);
    double z = b * Math.sin(2 * Math.PI * u3), w = b * Math.cos(2 * Math.PI * u3);
    return new double[] {
      1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
      2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
      2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)
    };
  }

  /** A random signed permutation matrix with determinant +1. */
  private double[] quarterTurns() {
    int[][] perms = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    int p = random.nextInt(6);
    double[] r = new double[9];
    double det = p < 3 ? 1 : -1;
    double[] signs = new double[3];
    for (int i = 0; i < 3; i++) {
      signs[i] = random.nextBoolean() ? 1 : -1;
      det *= signs[i];
    }
    signs[2] *= det; // make it a proper rotation
    for (int i = 0; i < 3; i++) {
      r[i * 3 + perms[p][i]] = signs[i];
    }
    return r;
  }

  private static double[] axisRotation(int k, double angle) {
    double c = Math.cos(angle), s = Math.sin(angle);
    return switch (k) {
      case 0 -> new double[] {1, 0, 0, 0, c, -s, 0, s, c};
      case 1 -> new double[] {c, 0, s, 0, 1, 0, -s, 0, c};
      default -> new double[] {c, -s, 0, s, c, 0, 0, 0, 1};
    };
  }

  private static Obb obb(double[] c, double[] h, double[] r) {
    return new Obb(c[0], c[1], c[2], h[0], h[1], h[2], r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]);
  }

  private static double[] center(Obb o) {
    return new double[] {o.cx(), o.cy(), o.cz()};
  }

  private static double ext(Obb o, int k) {
    return switch (k) {
      case 0 -> o.hx();
      case 1 -> o.hy();
      default -> o.hz();
    };
  }

  private static double[] column(double[] r, int k) {
    return new double[] {r[k], r[3 + k], r[6 + k]};
  }

  private static double[] mul(double[] a, double[] b) {
    double[] out = new double[9];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        out[i * 3 + j] = a[i * 3] * b[j] + a[i * 3 + 1] * b[3 + j] + a[i * 3 + 2] * b[6 + j];
      }
    }
    return out;
  }

  private static double[] add(double[] a, double[] b) {
    return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
  }

  private static double[] sub(double[] a, double[] b) {
    return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  }

  private static double[] scale(double[] a, double s) {
    return new double[] {a[0] * s, a[1] * s, a[2] * s};
  }

  private static double dot(double[] a, double[] b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  private static double[] crossProduct(double[] a, double[] b) {
    return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
}
