package org.robotrun.ui;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;

/**
 * One Dear ImGui draw list of one frame, copied out of ImGui's memory (its vertices, indices and
 * commands), and the comparison of two such copies that tells which part of the screen a change
 * touches: the window then draws again only there (see {@link RetainedUi}). Positions and clip
 * rectangles are in ImGui's display coordinates (y down). No GL.
 */
final class DrawListCopy {
  /** Bytes per vertex (ImDrawVert: position x, y and texture u, v as floats, colour as 4 bytes). */
  static final int VERT_BYTES = 20;

  ByteBuffer vtx = ByteBuffer.allocateDirect(0).order(ByteOrder.nativeOrder());
  int vtxCount;
  ByteBuffer idx = ByteBuffer.allocateDirect(0).order(ByteOrder.nativeOrder());
  int idxCount;
  /** Bytes per index: 2 or 4, as ImGui was built. */
  int idxBytes = 2;
  int cmdCount;
  /** Per command: clip x0, y0, x1, y1. */
  float[] clip = new float[0];
  int[] texture = new int[0];
  int[] elemCount = new int[0];
  int[] idxOffset = new int[0];
  int[] vtxOffset = new int[0];

  /** Makes room for the given counts (contents kept only up to the counts set afterwards). */
  void reserve(int vertices, int indices, int indexBytes, int commands) {
    idxBytes = indexBytes;
    if (vtx.capacity() < vertices * VERT_BYTES) {
      vtx = ByteBuffer.allocateDirect(Math.max(vertices * VERT_BYTES, vtx.capacity() * 3 / 2)).order(ByteOrder.nativeOrder());
    }
    if (idx.capacity() < indices * indexBytes) {
      idx = ByteBuffer.allocateDirect(Math.max(indices * indexBytes, idx.capacity() * 3 / 2)).order(ByteOrder.nativeOrder());
    }
    if (texture.length < commands) {
      int n = Math.max(commands, texture.length * 3 / 2);
      clip = new float[4 * n];
      texture = new int[n];
      elemCount = new int[n];
      idxOffset = new int[n];
      vtxOffset = new int[n];
    }
    vtxCount = vertices;
    idxCount = indices;
    cmdCount = commands;
  }

  /** Index i as an unsigned number. */
  int index(int i) {
    return idxBytes == 2 ? Short.toUnsignedInt(idx.getShort(i * 2)) : idx.getInt(i * 4);
  }

  float x(int vertex) {
    return vtx.getFloat(vertex * VERT_BYTES);
  }

  float y(int vertex) {
    return vtx.getFloat(vertex * VERT_BYTES + 4);
  }

  /** The union of the commands' clip rectangles {x0, y0, x1, y1}; null when there is no command. */
  float[] clipBounds() {
    if (cmdCount == 0) {
      return null;
    }
    float[] b = {Float.MAX_VALUE, Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
    for (int c = 0; c < cmdCount; c++) {
      b[0] = Math.min(b[0], clip[4 * c]);
      b[1] = Math.min(b[1], clip[4 * c + 1]);
      b[2] = Math.max(b[2], clip[4 * c + 2]);
      b[3] = Math.max(b[3], clip[4 * c + 3]);
    }
    return b;
  }

  /**
   * Where this list draws: its drawn triangles' vertices, within its clip rectangles (a
   * rectangle {x0, y0, x1, y1}, grown by a pixel); null when it draws nothing.
   */
  float[] drawnBounds() {
    float[] c = clipBounds();
    if (c == null) {
      return null;
    }
    float[] v = triangleBounds(0, idxCount, null);
    if (v == null) {
      return null;
    }
    float[] b = {Math.max(c[0], v[0] - 1), Math.max(c[1], v[1] - 1), Math.min(c[2], v[2] + 1), Math.min(c[3], v[3] + 1)};
    return b[2] > b[0] && b[3] > b[1] ? b : null;
  }

  /** Grows {@code into} (or a new rectangle when null) by the vertices of indices [from, to); null if none. */
  private float[] triangleBounds(int from, int to, float[] into) {
    float[] b = into;
    for (int i = from; i < to; i++) {
      int v = index(i) + vtxOffsetOf(i);
      if (v < 0 || v >= vtxCount) {
        continue;
      }
      float x = x(v), y = y(v);
      if (b == null) {
        b = new float[] {x, y, x, y};
      } else {
        b[0] = Math.min(b[0], x);
        b[1] = Math.min(b[1], y);
        b[2] = Math.max(b[2], x);
        b[3] = Math.max(b[3], y);
      }
    }
    return b;
  }

  /** The base vertex of the command that draws index i (0 unless ImGui offsets vertices). */
  private int vtxOffsetOf(int i) {
    for (int c = 0; c < cmdCount; c++) {
      if (i >= idxOffset[c] && i < idxOffset[c] + elemCount[c]) {
        return vtxOffset[c];
      }
    }
    return 0;
  }

  private boolean sameVertex(DrawListCopy o, int mine, int theirs) {
    int a = mine * VERT_BYTES, b = theirs * VERT_BYTES;
    return vtx.getLong(a) == o.vtx.getLong(b) && vtx.getLong(a + 8) == o.vtx.getLong(b + 8)
        && vtx.getInt(a + 16) == o.vtx.getInt(b + 16);
  }

  /**
   * The parts of the screen that changed from {@code old} to {@code now}, each {x0, y0, x1, y1} in
   * display coordinates; empty when both draw exactly the same. When the lists share their
   * commands (clip rectangles and textures) and differ only in a run of triangles, that is the
   * run; within a run of the same length in both, only the triangles that differ count, each
   * group of neighbouring ones on its own (a changed number in a panel: its changed glyphs, and a
   * second changed number further down is a second rectangle, not one over the lines between
   * them). A run of another length is bounded as a whole. Any other change is everything either
   * list draws.
   */
  static List<float[]> changedAreas(DrawListCopy old, DrawListCopy now) {
    Object partial = partialChange(old, now);
    if (partial != WHOLE) {
      @SuppressWarnings("unchecked")
      List<float[]> areas = (List<float[]>) partial;
      return areas;
    }
    float[] all = union(old.drawnBounds(), now.drawnBounds());
    return all == null ? List.of() : List.of(all);
  }

  /** Marker: the change is not a run of triangles; the whole lists count. */
  private static final Object WHOLE = new Object();
  /** More separate rectangles than this in one list's change: their union is used instead. */
  static final int MAX_AREAS = 12;

  private static Object partialChange(DrawListCopy old, DrawListCopy now) {
    if (old.cmdCount != now.cmdCount || old.idxBytes != now.idxBytes) {
      return WHOLE;
    }
    for (int c = 0; c < now.cmdCount; c++) {
      if (old.texture[c] != now.texture[c] || old.vtxOffset[c] != 0 || now.vtxOffset[c] != 0) {
        return WHOLE;
      }
      for (int k = 0; k < 4; k++) {
        if (old.clip[4 * c + k] != now.clip[4 * c + k]) {
          return WHOLE;
        }
      }
    }
    int nv0 = old.vtxCount, nv1 = now.vtxCount;
    int minV = Math.min(nv0, nv1);
    // vertices alike from the start ...
    int p = 0;
    int mismatch = old.vtx.slice(0, nv0 * VERT_BYTES).mismatch(now.vtx.slice(0, nv1 * VERT_BYTES));
    p = mismatch < 0 ? minV : Math.min(minV, mismatch / VERT_BYTES);
    // ... and from the end
    int s = 0;
    while (s < minV - p && old.sameVertex(now, nv0 - 1 - s, nv1 - 1 - s)) {
      s++;
    }
    int ni0 = old.idxCount, ni1 = now.idxCount;
    int minI = Math.min(ni0, ni1);
    // triangles alike from the start: the same indices, of vertices alike from the start
    int pi = 0;
    while (pi < minI && old.index(pi) == now.index(pi) && old.index(pi) < p) {
      pi++;
    }
    pi -= pi % 3;
    // and from the end: indices of the vertices alike from the end, at the same distance from it
    int si = 0;
    int tail0 = nv0 - s, tail1 = nv1 - s;
    while (si < minI - pi) {
      int a = old.index(ni0 - 1 - si), b = now.index(ni1 - 1 - si);
      if (a < tail0 || b < tail1 || a - tail0 != b - tail1) {
        break;
      }
      si++;
    }
    si -= si % 3;
    if (ni0 == ni1 && pi + si == ni0 && sameCommands(old, now)) {
      return List.of();
    }
    // command boundaries in the alike parts must sit at the same place in both lists
    for (int c = 0; c < now.cmdCount; c++) {
      if (!sameBoundary(old.idxOffset[c], now.idxOffset[c], pi, si, ni0, ni1)
          || !sameBoundary(old.idxOffset[c] + old.elemCount[c], now.idxOffset[c] + now.elemCount[c], pi, si, ni0, ni1)) {
        return WHOLE;
      }
    }
    if (ni0 == ni1 && (ni0 - si - pi) % 3 == 0) {
      return changedTriangles(old, now, pi, ni0 - si);
    }
    float[] b = old.triangleBounds(pi, ni0 - si, null);
    b = now.triangleBounds(pi, ni1 - si, b);
    if (b == null) {
      // only the command split moved within the changed run, drawing nothing new: nothing to see
      return sameCommands(old, now) ? List.of() : WHOLE;
    }
    return List.of(grown(b));
  }

  /**
   * Both lists have the same number of indices: the triangle at each place in [from, to) is
   * compared with the one at the same place in the other list (its three vertices, and the
   * command that draws it, hence its clip rectangle and texture); every pixel that only
   * triangles alike at their place draw looks the same in both frames. The triangles that differ
   * are bounded in groups: a triangle joins a group it touches (a pixel apart or closer).
   */
  private static List<float[]> changedTriangles(DrawListCopy old, DrawListCopy now, int from, int to) {
    List<float[]> areas = new ArrayList<>();
    float[] all = null;
    int c0 = 0, c1 = 0;
    for (int t = from; t < to; t += 3) {
      c0 = commandAt(old, t, c0);
      c1 = commandAt(now, t, c1);
      if (c0 == c1 && old.sameVertexAt(now, t) && old.sameVertexAt(now, t + 1) && old.sameVertexAt(now, t + 2)) {
        continue;
      }
      for (float[] b : new float[][] {old.triangleBounds(t, t + 3, null), now.triangleBounds(t, t + 3, null)}) {
        if (b == null) {
          continue;
        }
        b = grown(b);
        all = union(all, b);
        join(areas, b);
      }
    }
    if (areas.size() > MAX_AREAS) {
      return List.of(all);
    }
    return areas;
  }

  /** Adds {@code b} to {@code areas}, merged with every area it touches (repeatedly: a union may reach another). */
  private static void join(List<float[]> areas, float[] b) {
    boolean merged = true;
    while (merged) {
      merged = false;
      for (int i = 0; i < areas.size(); i++) {
        float[] a = areas.get(i);
        if (a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]) {
          b = union(a, b);
          areas.remove(i);
          merged = true;
          break;
        }
      }
    }
    areas.add(b);
  }

  /** The command that draws index i, searching on from command {@code from} (-1: none). */
  private static int commandAt(DrawListCopy l, int i, int from) {
    for (int c = Math.max(0, from); c < l.cmdCount; c++) {
      if (i >= l.idxOffset[c] && i < l.idxOffset[c] + l.elemCount[c]) {
        return c;
      }
    }
    for (int c = 0; c < Math.min(Math.max(0, from), l.cmdCount); c++) {
      if (i >= l.idxOffset[c] && i < l.idxOffset[c] + l.elemCount[c]) {
        return c;
      }
    }
    return -1;
  }

  /** Whether index i draws the same vertex (position, texture coordinate, colour) in both lists. */
  private boolean sameVertexAt(DrawListCopy o, int i) {
    int a = index(i), b = o.index(i);
    if (a >= vtxCount || b >= o.vtxCount) {
      return false;
    }
    return sameVertex(o, a, b);
  }

  /** A bounds rectangle grown by a pixel each side (smoothed edges reach that far). */
  private static float[] grown(float[] b) {
    return new float[] {b[0] - 1, b[1] - 1, b[2] + 1, b[3] + 1};
  }

  private static boolean sameBoundary(int b0, int b1, int pi, int si, int ni0, int ni1) {
    if (b0 <= pi || b1 <= pi) {
      return b0 == b1;
    }
    if (ni0 - b0 <= si || ni1 - b1 <= si) {
      return ni0 - b0 == ni1 - b1;
    }
    return true;
  }

  private static boolean sameCommands(DrawListCopy old, DrawListCopy now) {
    for (int c = 0; c < now.cmdCount; c++) {
      if (old.idxOffset[c] != now.idxOffset[c] || old.elemCount[c] != now.elemCount[c]) {
        return false;
      }
    }
    return true;
  }

  static float[] union(float[] a, float[] b) {
    if (a == null) {
      return b;
    }
    if (b == null) {
      return a;
    }
    return new float[] {Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[2], b[2]), Math.max(a[3], b[3])};
  }
}
