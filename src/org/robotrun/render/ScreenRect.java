package org.robotrun.render;

import org.joml.Matrix4f;
import org.joml.Vector4f;

/**
 * The pixel rectangle that a frame's solids cover, grown box by box: where the edge smoothing
 * has work to do. The floor is not added (its grid lines are smoothed in its own shader).
 * Mutable and reused every frame, so adding allocates nothing.
 */
final class ScreenRect {
  /** Pixels added on every side: the blend reads one neighbour, rasterisation may spill one. */
  private static final int MARGIN = 2;

  private final Matrix4f modelViewProj = new Matrix4f();
  private final Vector4f corner = new Vector4f();
  private int width;
  private int height;
  private float minX;
  private float minY;
  private float maxX;
  private float maxY;

  /** Empties the rectangle for a viewport of the given size (pixels). */
  void reset(int viewportWidth, int viewportHeight) {
    width = viewportWidth;
    height = viewportHeight;
    minX = Float.POSITIVE_INFINITY;
    minY = Float.POSITIVE_INFINITY;
    maxX = Float.NEGATIVE_INFINITY;
    maxY = Float.NEGATIVE_INFINITY;
  }

  /** Grows the rectangle to include the pixels [x0, x1) × [y0, y1). */
  void addPixels(int x0, int y0, int x1, int y1) {
    minX = Math.min(minX, x0);
    minY = Math.min(minY, y0);
    maxX = Math.max(maxX, x1);
    maxY = Math.max(maxY, y1);
  }

  /**
   * Grows the rectangle by a box's projection.
   *
   * @param viewProj projection times view
   * @param model the box's model matrix
   * @param b the box in model coordinates
   */
  void addBox(Matrix4f viewProj, Matrix4f model, MeshBounds b) {
    viewProj.mul(model, modelViewProj);
    for (int i = 0; i < 8; i++) {
      corner.set((i & 1) == 0 ? b.minX() : b.maxX(), (i & 2) == 0 ? b.minY() : b.maxY(),
          (i & 4) == 0 ? b.minZ() : b.maxZ(), 1f);
      modelViewProj.transform(corner);
      if (corner.w <= 1e-3f) {
        // A corner at or behind the eye projects nowhere useful: take the whole viewport.
        minX = 0;
        minY = 0;
        maxX = width;
        maxY = height;
        return;
      }
      float sx = (corner.x / corner.w * 0.5f + 0.5f) * width;
      float sy = (corner.y / corner.w * 0.5f + 0.5f) * height;
      minX = Math.min(minX, sx);
      minY = Math.min(minY, sy);
      maxX = Math.max(maxX, sx);
      maxY = Math.max(maxY, sy);
    }
  }

  boolean isEmpty() {
    return x1() <= x0() || y1() <= y0();
  }

  /** Left edge, inclusive, in pixels from the left, clamped to the viewport. */
  int x0() {
    return clamp((int) Math.floor(minX) - MARGIN, width);
  }

  /** Bottom edge, inclusive, in pixels from the bottom. */
  int y0() {
    return clamp((int) Math.floor(minY) - MARGIN, height);
  }

  /** Right edge, exclusive. */
  int x1() {
    return clamp((int) Math.ceil(maxX) + MARGIN, width);
  }

  /** Top edge, exclusive. */
  int y1() {
    return clamp((int) Math.ceil(maxY) + MARGIN, height);
  }

  private static int clamp(int v, int max) {
    return Math.max(0, Math.min(max, v));
  }
}
