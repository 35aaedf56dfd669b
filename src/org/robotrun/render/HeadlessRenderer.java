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
   * Draws one frame and writes it as a PNG.
   *
   * @throws java.io.UncheckedIOException when the file cannot be written
   */
  public void renderPng(SceneSnapshot scene, OrbitCamera camera, Path out) {
    target.bind();
    renderer.render(scene, camera, target.width(), target.height());
    ByteBuffer px = target.readRgbTopDown();
    try {
      if (!STBImageWrite.stbi_write_png(out.toString(), target.width(), target.height(), 3, px, target.width() * 3)) {
        throw new java.io.UncheckedIOException(new java.io.IOException("could not write " + out));
      }
    } finally {
      MemoryUtil.memFree(px);
    }
  }

  @Override
  public void close() {
    target.close();
    renderer.close();
    gl.close();
  }
}
