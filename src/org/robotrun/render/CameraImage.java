package org.robotrun.render;

import static org.lwjgl.opengl.GL33C.*;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.robotrun.sim.SceneSnapshot;

/**
 * A scene drawn through a vision camera into a texture the window shows (an ImGui image). Owns
 * its own {@link SceneRenderer} (no edge smoothing: the image is small and shown as the camera
 * takes it) and a framebuffer with a colour texture and a depth buffer, resized on demand. Needs
 * the window's GL context current; restores the framebuffer and viewport it found.
 */
public final class CameraImage implements AutoCloseable {
  private SceneRenderer renderer;
  private int fbo;
  private int texture;
  private int depth;
  private int width;
  private int height;
  private long lastFrameNs;

  /**
   * Draws the scene and answers the texture's GL name. The texture's first row is the image's
   * bottom row (OpenGL's order): show it with v running from 1 to 0.
   */
  public int render(SceneSnapshot scene, Matrix4f viewProj, Vector3f eye, int w, int h) {
    long t0 = System.nanoTime();
    if (renderer == null) {
      renderer = new SceneRenderer(AntiAliasing.NONE);
    }
    if (fbo == 0 || w != width || h != height) {
      allocate(w, h);
    }
    int[] viewport = new int[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    int drawFbo = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
    int readFbo = glGetInteger(GL_READ_FRAMEBUFFER_BINDING);
    int[] scissor = new int[4];
    glGetIntegerv(GL_SCISSOR_BOX, scissor);
    boolean scissorOn = glIsEnabled(GL_SCISSOR_TEST);
    // The window's own scissor (its 3D view, or a panel's clip rectangle) must not cut the camera image.
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    renderer.render(scene, viewProj, eye, w, h);
    // The renderer leaves alpha 0 on the background and floor; the image is shown opaque.
    float[] clear = new float[4];
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    glColorMask(false, false, false, true);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(true, true, true, true);
    glClearColor(clear[0], clear[1], clear[2], clear[3]);
    if (scissorOn) {
      glEnable(GL_SCISSOR_TEST);
    }
    glScissor(scissor[0], scissor[1], scissor[2], scissor[3]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, drawFbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, readFbo);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    lastFrameNs = System.nanoTime() - t0;
    return texture;
  }

  /** CPU time of the last {@link #render} call (ns): the GL calls issued, not waited for. */
  public long lastFrameNs() {
    return lastFrameNs;
  }

  private void allocate(int w, int h) {
    freeTargets();
    width = w;
    height = h;
    texture = glGenTextures();
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, 0L);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    depth = glGenRenderbuffers();
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    int previous = glGetInteger(GL_FRAMEBUFFER_BINDING);
    fbo = glGenFramebuffers();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, previous);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      throw new IllegalStateException("camera image framebuffer incomplete: 0x" + Integer.toHexString(status));
    }
  }

  private void freeTargets() {
    glDeleteFramebuffers(fbo);
    glDeleteTextures(texture);
    glDeleteRenderbuffers(depth);
    fbo = 0;
    texture = 0;
    depth = 0;
  }

  @Override
  public void close() {
    freeTargets();
    if (renderer != null) {
      renderer.close();
    }
  }
}
