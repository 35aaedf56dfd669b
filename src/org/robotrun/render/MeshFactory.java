package org.robotrun.render;

import java.util.Arrays;

/**
 * Generates display meshes for the primitive shapes the draw list uses. Everything is built
 * here from parameters; no mesh files are shipped.
 */
public final class MeshFactory {
  /** Segments around a cylinder (at full detail: see {@link MeshDetail} for fewer). */
  static final int CYLINDER_SEGMENTS = 48;
  /** Segments along each quarter-circle of a rounded edge (at full detail). */
  static final int ROUND_SEGMENTS = 5;

  private MeshFactory() {}

  /** A growable vertex/index buffer. */
  private static final class Builder {
    float[] v = new float[6 * 256];
    int nv;
    int[] idx = new int[3 * 256];
    int ni;

    int vertex(double x, double y, double z, double nx, double ny, double nz) {
      if ((nv + 1) * 6 > v.length) {
        v = Arrays.copyOf(v, v.length * 2);
      }
      int o = nv * 6;
      v[o] = (float) x; v[o + 1] = (float) y; v[o + 2] = (float) z;
      v[o + 3] = (float) nx; v[o + 4] = (float) ny; v[o + 5] = (float) nz;
      return nv++;
    }

    void triangle(int a, int b, int c) {
      if (ni + 3 > idx.length) {
        idx = Arrays.copyOf(idx, idx.length * 2);
      }
      idx[ni++] = a; idx[ni++] = b; idx[ni++] = c;
    }

    MeshData build() {
      return new MeshData(Arrays.copyOf(v, nv * 6), Arrays.copyOf(idx, ni));
    }
  }

  /**
   * A box with full sizes (sx, sy, sz) centred on the origin, its edges rounded with radius
   * {@code round} (0 for sharp edges).
   */
  public static MeshData box(double sx, double sy, double sz, double round) {
    return box(sx, sy, sz, round, ROUND_SEGMENTS);
  }

  /** As {@link #box(double, double, double, double)}, each quarter-circle of a rounded edge in {@code roundSegments} segments. */
  static MeshData box(double sx, double sy, double sz, double round, int roundSegments) {
    double[] h = {sx / 2, sy / 2, sz / 2};
    double r = Math.max(0, Math.min(round, Math.min(h[0], Math.min(h[1], h[2])) * 0.999));
    double[] hi = {h[0] - r, h[1] - r, h[2] - r};
    Builder b = new Builder();
    // Each face is a grid whose rows near the edges are spaced so that, projected onto the
    // rounded surface (point = clamp(p, inner box) + r·n), they sweep equal angles.
    for (int axis = 0; axis < 3; axis++) {
      for (int sign = -1; sign <= 1; sign += 2) {
        int u = (axis + 1) % 3;
        int w = (axis + 2) % 3;
        double[] us = edgeCoords(h[u], hi[u], r, roundSegments);
        double[] ws = edgeCoords(h[w], hi[w], r, roundSegments);
        int base = b.nv;
        for (double wc : ws) {
          for (double uc : us) {
            double[] p = new double[3];
            p[axis] = sign * h[axis];
            p[u] = uc;
            p[w] = wc;
            double[] q = new double[3];
            for (int k = 0; k < 3; k++) {
              q[k] = Math.max(-hi[k], Math.min(hi[k], p[k]));
            }
            double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            double nx, ny, nz;
            if (len < 1e-12) {
              nx = axis == 0 ? sign : 0; ny = axis == 1 ? sign : 0; nz = axis == 2 ? sign : 0;
            } else {
              nx = dx / len; ny = dy / len; nz = dz / len;
            }
            b.vertex(q[0] + r * nx, q[1] + r * ny, q[2] + r * nz, nx, ny, nz);
          }
        }
        int nu = us.length;
        for (int j = 0; j + 1 < ws.length; j++) {
          for (int i = 0; i + 1 < nu; i++) {
            int a = base + j * nu + i, c = a + 1, d = a + nu, e = d + 1;
            // Keep counter-clockwise winding seen from outside: (u × w) = axis direction.
            if (sign > 0) {
              b.triangle(a, c, e);
              b.triangle(a, e, d);
            } else {
              b.triangle(a, e, c);
              b.triangle(a, d, e);
            }
          }
        }
      }
    }
    return b.build();
  }

  private static double[] edgeCoords(double h, double hi, double r, int k) {
    if (r <= 0) {
      return new double[] {-h, h};
    }
    double[] out = new double[2 * (k + 1)];
    for (int i = 0; i <= k; i++) {
      double theta = Math.PI / 4 * (k - i) / k;
      out[i] = -hi - r * Math.tan(theta);
      out[out.length - 1 - i] = hi + r * Math.tan(theta);
    }
    return out;
  }

  /**
   * A cylinder along z centred on the origin with its rims rounded (radius a fraction of the
   * smaller of radius and half length), so it catches highlights like a cast housing.
   */
  public static MeshData cylinder(double radius, double length) {
    return cylinder(radius, length, CYLINDER_SEGMENTS, ROUND_SEGMENTS);
  }

  /** The radius of a cylinder's rounded rims (see {@link #cylinder(double, double)}). */
  static double cylinderRimRadius(double radius, double length) {
    return Math.min(radius * 0.12, length / 2 * 0.4);
  }

  /**
   * As {@link #cylinder(double, double)}, in {@code segments} segments around and
   * {@code roundSegments} along each rim's quarter-circle.
   */
  static MeshData cylinder(double radius, double length, int segments, int roundSegments) {
    double halfLen = length / 2;
    double rr = cylinderRimRadius(radius, length);
    // Profile in (rho, z) with its outward normal, from the bottom centre to the top centre.
    int k = roundSegments;
    int n = 2 * (k + 1) + 2;
    double[] rho = new double[n], zs = new double[n], nrho = new double[n], nz = new double[n];
    int p = 0;
    rho[p] = 0; zs[p] = -halfLen; nrho[p] = 0; nz[p] = -1; p++;
    for (int i = 0; i <= k; i++) {
      double a = -Math.PI / 2 + Math.PI / 2 * i / k;
      rho[p] = radius - rr + rr * Math.cos(a); zs[p] = -halfLen + rr + rr * Math.sin(a);
      nrho[p] = Math.cos(a); nz[p] = Math.sin(a); p++;
    }
    for (int i = 0; i <= k; i++) {
      double a = Math.PI / 2 * i / k;
      rho[p] = radius - rr + rr * Math.cos(a); zs[p] = halfLen - rr + rr * Math.sin(a);
      nrho[p] = Math.cos(a); nz[p] = Math.sin(a); p++;
    }
    rho[p] = 0; zs[p] = halfLen; nrho[p] = 0; nz[p] = 1; p++;

    Builder b = new Builder();
    int seg = segments;
    for (int s = 0; s <= seg; s++) {
      double phi = 2 * Math.PI * s / seg;
      double c = Math.cos(phi), si = Math.sin(phi);
      for (int i = 0; i < n; i++) {
        b.vertex(rho[i] * c, rho[i] * si, zs[i], nrho[i] * c, nrho[i] * si, nz[i]);
      }
    }
    for (int s = 0; s < seg; s++) {
      for (int i = 0; i + 1 < n; i++) {
        int a = s * n + i, bb = a + 1, c = a + n, d = c + 1;
        // the caps' centre is one point at every angle: there each quad is one triangle (the
        // other would have no area and draw nothing)
        if (i > 0) {
          b.triangle(a, c, d);
        }
        if (i + 2 < n) {
          b.triangle(a, d, bb);
        }
      }
    }
    return b.build();
  }

  /**
   * The twelve edges of a box with full sizes (sx, sy, sz) centred on the origin, as line
   * pairs (draw with GL_LINES); normals point up so the lines are lit evenly.
   */
  public static MeshData boxEdges(double sx, double sy, double sz) {
    float[] v = new float[8 * 6];
    for (int i = 0; i < 8; i++) {
      v[i * 6] = (float) ((i & 1) != 0 ? sx / 2 : -sx / 2);
      v[i * 6 + 1] = (float) ((i & 2) != 0 ? sy / 2 : -sy / 2);
      v[i * 6 + 2] = (float) ((i & 4) != 0 ? sz / 2 : -sz / 2);
      v[i * 6 + 5] = 1;
    }
    // Corners differing in one bit are joined by an edge.
    int[] idx = new int[24];
    int n = 0;
    for (int i = 0; i < 8; i++) {
      for (int bit = 1; bit < 8; bit <<= 1) {
        if ((i & bit) == 0) {
          idx[n++] = i;
          idx[n++] = i | bit;
        }
      }
    }
    return new MeshData(v, idx);
  }

  /** A flat-shaded mesh from raw triangles (x, y, z per vertex, three vertices per triangle). */
  public static MeshData triangles(float[] xyz) {
    Builder b = new Builder();
    for (int t = 0; t + 8 < xyz.length; t += 9) {
      double ux = xyz[t + 3] - xyz[t], uy = xyz[t + 4] - xyz[t + 1], uz = xyz[t + 5] - xyz[t + 2];
      double vx = xyz[t + 6] - xyz[t], vy = xyz[t + 7] - xyz[t + 1], vz = xyz[t + 8] - xyz[t + 2];
      double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
      if (len > 0) {
        nx /= len; ny /= len; nz /= len;
      }
      int a = b.vertex(xyz[t], xyz[t + 1], xyz[t + 2], nx, ny, nz);
      int c = b.vertex(xyz[t + 3], xyz[t + 4], xyz[t + 5], nx, ny, nz);
      int d = b.vertex(xyz[t + 6], xyz[t + 7], xyz[t + 8], nx, ny, nz);
      b.triangle(a, c, d);
    }
    return b.build();
  }
}
