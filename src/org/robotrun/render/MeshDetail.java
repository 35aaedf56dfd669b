package org.robotrun.render;

import org.joml.Matrix4f;

/**
 * How finely the window divides a round shape (a cylinder, a rounded box's edges) by its size on
 * screen: into as few segments as keep every point of the divided outline within
 * {@link #MAX_ERROR_PX} of a pixel of the true curve. A circle of radius r divided into n
 * segments strays at most r·(1 − cos(π/n)) from the true circle (between the segment's ends its
 * chord runs inside), so a cylinder 24 px wide on screen needs 24 segments where the full mesh
 * has 48, and a rim rounded over 3 px needs 2 per quarter circle where the full mesh has 5. On a
 * software renderer every triangle costs: the moving arm's small, finely divided shapes were most
 * of a jog frame's CPU (docs/architecture.md). Pictures written by {@code robotrun render} keep the
 * full meshes. Pure: no GL.
 */
final class MeshDetail {
  /** The most a divided outline may stray from the true curve, in pixels. */
  static final double MAX_ERROR_PX = 0.25;
  /** The segment counts around a cylinder to choose from, coarsest first; the last is the full mesh's. */
  static final int[] CYLINDER_STEPS = {12, 16, 24, 32, MeshFactory.CYLINDER_SEGMENTS};

  private MeshDetail() {}

  /** Segments around a cylinder whose radius spans {@code radiusPx} pixels on screen. */
  static int cylinderSegments(double radiusPx) {
    for (int n : CYLINDER_STEPS) {
      if (radiusPx * (1 - Math.cos(Math.PI / n)) <= MAX_ERROR_PX) {
        return n;
      }
    }
    return MeshFactory.CYLINDER_SEGMENTS;
  }

  /** Segments along a quarter circle (a rounded edge) whose radius spans {@code radiusPx} pixels. */
  static int roundSegments(double radiusPx) {
    for (int k = 1; k < MeshFactory.ROUND_SEGMENTS; k++) {
      if (radiusPx * (1 - Math.cos(Math.PI / (4.0 * k))) <= MAX_ERROR_PX) {
        return k;
      }
    }
    return MeshFactory.ROUND_SEGMENTS;
  }

  /**
   * The most pixels one millimetre spans anywhere within the sphere of {@code radiusMm} around the
   * point (x, y, z) (world, mm), seen through {@code viewProj} in a viewport of width × height
   * pixels: the projection's largest stretch at the point, made larger as the sphere's nearest
   * point is nearer the eye. Infinite when the sphere reaches the eye's plane (full detail then).
   */
  static double pixelsPerMm(Matrix4f viewProj, float x, float y, float z, double radiusMm, int width, int height) {
    Matrix4f m = viewProj;
    // clip coordinates of the point
    double cx = m.m00() * x + m.m10() * y + m.m20() * z + m.m30();
    double cy = m.m01() * x + m.m11() * y + m.m21() * z + m.m31();
    double cw = m.m03() * x + m.m13() * y + m.m23() * z + m.m33();
    // how fast w changes with the position: the sphere's nearest point has w smaller by up to radius · |∇w|
    double gw = Math.sqrt(m.m03() * m.m03() + m.m13() * m.m13() + m.m23() * m.m23());
    double nearW = cw - radiusMm * gw;
    if (!(cw > 0) || !(nearW > 0.05 * cw)) {
      return Double.POSITIVE_INFINITY;
    }
    // the Jacobian of the pixel position (x, y) with respect to the world position: 2 rows of 3
    double sx = width / 2.0, sy = height / 2.0;
    double[] jx = {
      sx * (m.m00() * cw - cx * m.m03()) / (cw * cw),
      sx * (m.m10() * cw - cx * m.m13()) / (cw * cw),
      sx * (m.m20() * cw - cx * m.m23()) / (cw * cw)};
    double[] jy = {
      sy * (m.m01() * cw - cy * m.m03()) / (cw * cw),
      sy * (m.m11() * cw - cy * m.m13()) / (cw * cw),
      sy * (m.m21() * cw - cy * m.m23()) / (cw * cw)};
    // its largest singular value: the square root of J·Jᵀ's larger eigenvalue
    double a = dot(jx, jx), b = dot(jx, jy), c = dot(jy, jy);
    double largest = (a + c) / 2 + Math.sqrt((a - c) * (a - c) / 4 + b * b);
    // nearer the eye a millimetre spans more: the stretch goes as 1/w
    return Math.sqrt(largest) * cw / nearW;
  }

  private static double dot(double[] p, double[] q) {
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
  }
}
