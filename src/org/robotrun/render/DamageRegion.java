package org.robotrun.render;

import java.util.ArrayList;
import java.util.List;

/**
 * The part of a frame that must be drawn again: a few pixel rectangles within a framebuffer of a
 * given size (GL's pixel coordinates: x from the left, y from the bottom, lower edges inclusive,
 * upper edges exclusive). Rectangles that touch, or whose union wastes little, are merged, and
 * there are never more than {@link #MAX_RECTS}, so a frame draws its layers a bounded number of
 * times. Pure bookkeeping: no GL.
 */
public final class DamageRegion {
  /** At most this many rectangles; more are merged, the pair whose union adds least first. */
  public static final int MAX_RECTS = 4;
  /** Two rectangles are merged when their union is at most this many pixels larger than both. */
  private static final long MERGE_SLACK_PX = 64 * 64;

  private final int width;
  private final int height;
  private final List<int[]> rects = new ArrayList<>();

  /** An empty region within a framebuffer of width × height pixels. */
  public DamageRegion(int width, int height) {
    this.width = Math.max(0, width);
    this.height = Math.max(0, height);
  }

  /** Adds [x0, x1) × [y0, y1), clipped to the framebuffer; an empty rectangle adds nothing. */
  public DamageRegion add(int x0, int y0, int x1, int y1) {
    int[] r = {clamp(x0, width), clamp(y0, height), clamp(x1, width), clamp(y1, height)};
    if (r[2] <= r[0] || r[3] <= r[1]) {
      return this;
    }
    // fold it into every rectangle it should join, repeatedly (a union may now reach another)
    boolean merged = true;
    while (merged) {
      merged = false;
      for (int i = 0; i < rects.size(); i++) {
        int[] o = rects.get(i);
        if (shouldMerge(o, r)) {
          r = union(o, r);
          rects.remove(i);
          merged = true;
          break;
        }
      }
    }
    rects.add(r);
    while (rects.size() > MAX_RECTS) {
      mergeCheapestPair();
    }
    return this;
  }

  /** Adds a rectangle given as x, y, width, height (GL's viewport and scissor form). */
  public DamageRegion addXywh(int x, int y, int w, int h) {
    return add(x, y, x + w, y + h);
  }

  /** Adds the whole framebuffer. */
  public DamageRegion addAll() {
    return add(0, 0, width, height);
  }

  /** Adds every rectangle of another region. */
  public DamageRegion addAll(DamageRegion other) {
    for (int[] r : other.rects) {
      add(r[0], r[1], r[2], r[3]);
    }
    return this;
  }

  public boolean isEmpty() {
    return rects.isEmpty();
  }

  /** The rectangles as {x0, y0, x1, y1} (copies); they never overlap (overlapping ones are merged). */
  public List<int[]> rects() {
    List<int[]> out = new ArrayList<>(rects.size());
    for (int[] r : rects) {
      out.add(r.clone());
    }
    return out;
  }

  /** Pixels covered, counting an overlap of two rectangles twice (as drawing them does). */
  public long area() {
    long a = 0;
    for (int[] r : rects) {
      a += area(r);
    }
    return a;
  }

  /** Whether [x0, x1) × [y0, y1) meets some rectangle of this region. */
  public boolean intersects(int x0, int y0, int x1, int y1) {
    for (int[] r : rects) {
      if (x0 < r[2] && r[0] < x1 && y0 < r[3] && r[1] < y1) {
        return true;
      }
    }
    return false;
  }

  /** The intersection of two {x0, y0, x1, y1} rectangles, or null when they do not meet. */
  public static int[] intersect(int[] a, int[] b) {
    int[] r = {Math.max(a[0], b[0]), Math.max(a[1], b[1]), Math.min(a[2], b[2]), Math.min(a[3], b[3])};
    return r[2] > r[0] && r[3] > r[1] ? r : null;
  }

  private static boolean shouldMerge(int[] a, int[] b) {
    boolean touch = a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
    return touch || area(union(a, b)) - area(a) - area(b) <= MERGE_SLACK_PX;
  }

  private void mergeCheapestPair() {
    int bi = 0, bj = 1;
    long best = Long.MAX_VALUE;
    for (int i = 0; i < rects.size(); i++) {
      for (int j = i + 1; j < rects.size(); j++) {
        long cost = area(union(rects.get(i), rects.get(j))) - area(rects.get(i)) - area(rects.get(j));
        if (cost < best) {
          best = cost;
          bi = i;
          bj = j;
        }
      }
    }
    int[] u = union(rects.get(bi), rects.get(bj));
    rects.remove(bj);
    rects.remove(bi);
    // the union may now touch another rectangle: add it the ordinary way
    add(u[0], u[1], u[2], u[3]);
  }

  private static int[] union(int[] a, int[] b) {
    return new int[] {Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[2], b[2]), Math.max(a[3], b[3])};
  }

  private static long area(int[] r) {
    return (long) (r[2] - r[0]) * (r[3] - r[1]);
  }

  private static int clamp(int v, int max) {
    return Math.max(0, Math.min(max, v));
  }
}
