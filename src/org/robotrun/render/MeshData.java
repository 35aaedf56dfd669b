package org.robotrun.render;

/**
 * Triangle mesh data ready for upload: interleaved position (mm) and unit normal per vertex,
 * six floats each, and triangle indices.
 */
public record MeshData(float[] vertices, int[] indices) {
  public int vertexCount() {
    return vertices.length / 6;
  }

  public int triangleCount() {
    return indices.length / 3;
  }
}
