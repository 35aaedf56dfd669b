package org.robotrun.world;

import java.util.Arrays;
import org.robotrun.math.Vec3;

/**
 * A triangle soup in its own frame (mm): nine floats per triangle (three corners x, y, z), and
 * its axis-aligned bounds. Immutable: the array is copied in and only copied out.
 */
public final class TriangleMesh {
  private final float[] corners;
  private final Vec3 min;
  private final Vec3 max;

  /**
   * @param corners 9 floats per triangle, mm; must hold at least one triangle
   */
  public TriangleMesh(float[] corners) {
    if (corners.length == 0 || corners.length % 9 != 0) {
      throw new IllegalArgumentException("need 9 floats per triangle and at least one triangle, got " + corners.length);
    }
    this.corners = corners.clone();
    double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
    double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
    for (int i = 0; i < corners.length; i++) {
      lo[i % 3] = Math.min(lo[i % 3], corners[i]);
      hi[i % 3] = Math.max(hi[i % 3], corners[i]);
    }
    this.min = new Vec3(lo[0], lo[1], lo[2]);
    this.max = new Vec3(hi[0], hi[1], hi[2]);
  }

  public int triangleCount() {
    return corners.length / 9;
  }

  /** Smallest corner of the bounds (mm). */
  public Vec3 min() {
    return min;
  }

  /** Largest corner of the bounds (mm). */
  public Vec3 max() {
    return max;
  }

  /** A copy of the corners, 9 floats per triangle (mm). */
  public float[] corners() {
    return corners.clone();
  }

  /** Copies the corners into {@code dest} from {@code offset} (for uploading without a copy per frame). */
  public void copyCorners(float[] dest, int offset) {
    System.arraycopy(corners, 0, dest, offset, corners.length);
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof TriangleMesh m && Arrays.equals(corners, m.corners);
  }

  @Override
  public int hashCode() {
    return Arrays.hashCode(corners);
  }

  @Override
  public String toString() {
    return "TriangleMesh[" + triangleCount() + " triangles, " + min + " .. " + max + "]";
  }
}
