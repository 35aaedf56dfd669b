package org.robotrun.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import org.lwjgl.system.MemoryUtil;

/** A mesh uploaded to the GPU: one VAO with position (location 0) and normal (location 1). */
final class GpuMesh implements AutoCloseable {
  private final int vao;
  private final int vbo;
  private final int ebo;
  private final int indexCount;
  private final int mode;
  private final MeshBounds bounds;

  private GpuMesh(int vao, int vbo, int ebo, int indexCount, int mode, MeshBounds bounds) {
    this.vao = vao;
    this.vbo = vbo;
    this.ebo = ebo;
    this.indexCount = indexCount;
    this.mode = mode;
    this.bounds = bounds;
  }

  static GpuMesh upload(MeshData data) {
    return upload(data, GL_TRIANGLES);
  }

  static GpuMesh upload(MeshData data, int mode) {
    int vao = glGenVertexArrays();
    glBindVertexArray(vao);
    int vbo = glGenBuffers();
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    FloatBuffer fb = MemoryUtil.memAllocFloat(data.vertices().length);
    IntBuffer ib = MemoryUtil.memAllocInt(data.indices().length);
    try {
      fb.put(data.vertices()).flip();
      glBufferData(GL_ARRAY_BUFFER, fb, GL_STATIC_DRAW);
      int ebo = glGenBuffers();
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
      ib.put(data.indices()).flip();
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, ib, GL_STATIC_DRAW);
      glVertexAttribPointer(0, 3, GL_FLOAT, false, 24, 0);
      glEnableVertexAttribArray(0);
      glVertexAttribPointer(1, 3, GL_FLOAT, false, 24, 12);
      glEnableVertexAttribArray(1);
      glBindVertexArray(0);
      return new GpuMesh(vao, vbo, ebo, data.indices().length, mode, MeshBounds.of(data));
    } finally {
      MemoryUtil.memFree(fb);
      MemoryUtil.memFree(ib);
    }
  }

  /** The mesh's bounds in its own coordinates. */
  MeshBounds bounds() {
    return bounds;
  }

  void draw() {
    glBindVertexArray(vao);
    glDrawElements(mode, indexCount, GL_UNSIGNED_INT, 0);
  }

  @Override
  public void close() {
    glDeleteBuffers(vbo);
    glDeleteBuffers(ebo);
    glDeleteVertexArrays(vao);
  }
}
