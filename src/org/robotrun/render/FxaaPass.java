package org.robotrun.render;

import static org.lwjgl.opengl.GL33C.*;

/**
 * Edge smoothing as a post pass: the scene is drawn into this pass's own single-sample colour
 * texture and depth buffer, then one full-screen triangle copies it into the caller's
 * framebuffer through {@code shaders/fxaa.frag}. On Mesa's software renderer this costs about
 * a third of what 4x multisampling does (see {@link AntiAliasing}).
 */
final class FxaaPass implements AutoCloseable {
  private final ShaderProgram program;
  private final int emptyVao;
  private int fbo;
  private int colorTex;
  private int depthRb;
  private int width;
  private int height;
  private int previousFbo;

  FxaaPass() {
    program = ShaderProgram.load("fxaa");
    emptyVao = glGenVertexArrays();
  }

  /**
   * Remembers the framebuffer bound now (the final destination) and binds the pass's own
   * buffers of the given size for drawing the scene.
   */
  void begin(int w, int h) {
    previousFbo = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
    if (w != width || h != height || fbo == 0) {
      allocate(w, h);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  }

  /** Draws the smoothed frame into the framebuffer that was bound at {@link #begin}. */
  void end() {
    glBindFramebuffer(GL_FRAMEBUFFER, previousFbo);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    program.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, colorTex);
    glUniform1i(program.uniform("uScene"), 0);
    glBindVertexArray(emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D, 0);
  }

  private void allocate(int w, int h) {
    release();
    width = w;
    height = h;
    colorTex = glGenTextures();
    glBindTexture(GL_TEXTURE_2D, colorTex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, 0L);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    depthRb = glGenRenderbuffers();
    glBindRenderbuffer(GL_RENDERBUFFER, depthRb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    fbo = glGenFramebuffers();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colorTex, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthRb);
    int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      throw new IllegalStateException("the edge-smoothing framebuffer is incomplete (status 0x"
          + Integer.toHexString(status) + ")");
    }
  }

  private void release() {
    // Deleting name 0 is a no-op in GL, so this is safe before the first allocation.
    glDeleteFramebuffers(fbo);
    glDeleteTextures(colorTex);
    glDeleteRenderbuffers(depthRb);
    fbo = 0;
  }

  @Override
  public void close() {
    release();
    glDeleteVertexArrays(emptyVao);
    program.close();
  }
}
