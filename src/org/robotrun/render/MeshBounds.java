package org.robotrun.render;

/** Axis-aligned bounds of a mesh in its own coordinates (mm). */
record MeshBounds(float minX, float minY, float minZ, float maxX, float maxY, float maxZ) {
  /** The bounds of every vertex of the mesh (an empty mesh gets a point at the origin). */
  static MeshBounds of(MeshData data) {
    float[] v = data.vertices();
    if (v.length == 0) {
      return new MeshBounds(0, 0, 0, 0, 0, 0);
    }
    float[] lo = {v[0], v[1], v[2]};
    float[] hi = {v[0], v[1], v[2]};
    for (int o = 0; o + 2 < v.length; o += 6) {
      for (int k = 0; k < 3; k++) {
        lo[k] = Math.min(lo[k], v[o + k]);
        hi[k] = Math.max(hi[k], v[o + k]);
      }
    }
    return new MeshBounds(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
  }
}
