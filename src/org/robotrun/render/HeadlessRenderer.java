package org.robotrun.render;

import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.lwjgl.stb.STBImageWrite;
import org.lwjgl.system.MemoryUtil;
import org.robotrun.sim.SceneSnapshot;

/** Renders snapshots to images with no display (see {@link HeadlessGl}). */
public final class HeadlessRenderer implements AutoCloseable {
  private final HeadlessGl gl;
  private final SceneRenderer renderer;
  private final OffscreenTarget target;

  /** A renderer with the default edge smoothing, as the window uses. */
  public HeadlessRenderer(int width, int height) {
    this(width, height, AntiAliasing.DEFAULT);
  }

  /** A renderer with the given edge smoothing. */
  public HeadlessRenderer(int width, int height, AntiAliasing antiAliasing) {
    gl = HeadlessGl.create();
    try {
      renderer = new SceneRenderer(antiAliasing);
      target = new OffscreenTarget(width, height, antiAliasing.samples());
    } catch (RuntimeException e) {
      gl.close();
      throw e;
    }
  }

  /** Draws one frame into the offscreen target and waits until the GPU is done. */
  public void renderFrame(SceneSnapshot scene, OrbitCamera camera) {
    target.bind();
    renderer.render(scene, camera, target.width(), target.height());
    target.resolve();
    org.lwjgl.opengl.GL33C.glFinish();
  }

  /** Draws one frame and returns its pixels as RGB, top row first (width·height·3 bytes). */
  public byte[] renderRgb(SceneSnapshot scene, OrbitCamera camera) {
    target.bind();
    renderer.render(scene, camera, target.width(), target.height());
    ByteBuffer px = target.readRgbTopDown();
    try {
      byte[] out = new byte[px.remaining()];
      px.get(out);
      return out;
    } finally {
      MemoryUtil.memFree(px);
    }
  }

  /**
   * Draws one frame and writes it as a PNG: encoded in memory, then written through
   * {@link org.robotrun.io.AtomicFiles}, so an old picture is replaced whole or not at all.
   *
   * @throws java.io.UncheckedIOException when the file cannot be written
   */
  public void renderPng(SceneSnapshot scene, OrbitCamera camera, Path out) {
    target.bind();
    renderer.render(scene, camera, target.width(), target.height());
    ByteBuffer px = target.readRgbTopDown();
    byte[] png;
    try {
      png = encodePng(px, target.width(), target.height());
    } finally {
      MemoryUtil.memFree(px);
    }
    try {
      org.robotrun.io.AtomicFiles.write(out, png);
    } catch (java.io.IOException e) {
      throw new java.io.UncheckedIOException(e);
    }
  }

  /**
   * Draws the scene through any camera ({@link SceneRenderer#render(SceneSnapshot, org.joml.Matrix4f,
   * org.joml.Vector3f, int, int)}) and writes it as a PNG, as {@link #renderPng(SceneSnapshot, OrbitCamera, Path)}.
   */
  public void renderPng(SceneSnapshot scene, org.joml.Matrix4f viewProj, org.joml.Vector3f eye, Path out) {
    target.bind();
    renderer.render(scene, viewProj, eye, target.width(), target.height());
    writePng(out);
  }

  /** Draws the scene through any camera and waits until the GPU is done (benchmarks). */
  public void renderFrame(SceneSnapshot scene, org.joml.Matrix4f viewProj, org.joml.Vector3f eye) {
    target.bind();
    renderer.render(scene, viewProj, eye, target.width(), target.height());
    target.resolve();
    org.lwjgl.opengl.GL33C.glFinish();
  }

  private void writePng(Path out) {
    ByteBuffer px = target.readRgbTopDown();
    byte[] png;
    try {
      png = encodePng(px, target.width(), target.height());
    } finally {
      MemoryUtil.memFree(px);
    }
    try {
      org.robotrun.io.AtomicFiles.write(out, png);
    } catch (java.io.IOException e) {
      throw new java.io.UncheckedIOException(e);
    }
  }

  /** PNG bytes of tightly packed RGB pixels, top row first (stb_image_write, to memory). */
  static byte[] encodePng(ByteBuffer rgb, int width, int height) {
    java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream(width * height);
    try (org.lwjgl.stb.STBIWriteCallback sink = org.lwjgl.stb.STBIWriteCallback.create((context, data, size) -> {
      ByteBuffer chunk = org.lwjgl.stb.STBIWriteCallback.getData(data, size);
      byte[] b = new byte[size];
      chunk.get(b);
      bytes.write(b, 0, size);
    })) {
      if (!STBImageWrite.stbi_write_png_to_func(sink, 0L, width, height, 3, rgb, width * 3)) {
        throw new java.io.UncheckedIOException(new java.io.IOException("could not encode the PNG"));
      }
    }
    return bytes.toByteArray();
  }

  @Override
  public void close() {
    target.close();
    renderer.close();
    gl.close();
  }
}
