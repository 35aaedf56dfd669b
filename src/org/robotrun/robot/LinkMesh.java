package org.robotrun.robot;

import java.util.Arrays;

/**
 * A display mesh attached to a link, in the link's frame (mm): what the renderer draws for the
 * link instead of its shapes (which stay the collision bodies). Imported robots have these.
 *
 * @param key identifies the mesh for the renderer's cache (e.g. the file it came from)
 * @param triangles 9 floats per triangle (three corners x, y, z), mm, link frame; copied in, and
 *     shared (not copied) out so that drawing a frame does not copy meshes: never write to it
 * @param color a colour role ("body", "joint", "base", "flange") or "#rrggbb"
 */
public record LinkMesh(String key, float[] triangles, String color) {
  public LinkMesh {
    if (triangles.length == 0 || triangles.length % 9 != 0) {
      throw new IllegalArgumentException("a link mesh needs 9 floats per triangle, got " + triangles.length);
    }
    triangles = triangles.clone();
  }

  /** Number of triangles. */
  public int triangleCount() {
    return triangles.length / 9;
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof LinkMesh m && m.key.equals(key) && m.color.equals(color) && Arrays.equals(m.triangles, triangles);
  }

  @Override
  public int hashCode() {
    return key.hashCode();
  }

  @Override
  public String toString() {
    return "LinkMesh[" + key + ", " + triangleCount() + " triangles, " + color + "]";
  }
}
