package org.robotrun.render;

import static org.lwjgl.opengl.GL33C.*;

/**
 * Edge smoothing as a post pass over the part of a finished frame where the solids are
 * ({@link ScreenRect}): that part is copied into a texture, then {@code shaders/fxaa.frag}
 * draws it back, blended across edges, with the scissor limited to the rectangle. The floor
 * elsewhere is left alone (its shader draws smooth grid lines), so the pass costs in
 * proportion to the robot's size on screen, not the window's.
 */
final class FxaaPass implements AutoCloseable {
  private final ShaderProgram program;
  private final int emptyVao;
  private int texture;
  private int width;
  private int height;

  FxaaPass() {
    program = ShaderProgram.load("fxaa");
    emptyVao = glGenVertexArrays();
  }

  /**
   * Smooths the rectangle of the framebuffer bound for drawing now.
   *
   * @param rect where to smooth, within a viewport of width × height pixels
   */
  void apply(ScreenRect rect, int viewportWidth, int viewportHeight) {
    if (rect.isEmpty()) {
      return;
    }
    apply(rect.x0(), rect.y0(), rect.x1(), rect.y1(), viewportWidth, viewportHeight);
  }

  /**
   * Smooths the part of the rectangle that lies within {@code clip} ({x0, y0, x1, y1}, pixels):
   * a frame drawn again only in part smooths only that part.
   */
  void apply(ScreenRect rect, int[] clip, int viewportWidth, int viewportHeight) {
    if (rect.isEmpty()) {
      return;
    }
    int[] r = DamageRegion.intersect(new int[] {rect.x0(), rect.y0(), rect.x1(), rect.y1()}, clip);
    if (r != null) {
      apply(r[0], r[1], r[2], r[3], viewportWidth, viewportHeight);
    }
  }

  private void apply(int x0, int y0, int x1, int y1, int viewportWidth, int viewportHeight) {
    if (texture == 0 || viewportWidth != width || viewportHeight != height) {
      allocate(viewportWidth, viewportHeight);
    }
    int w = x1 - x0;
    int h = y1 - y0;
    // Copy one pixel more on each side than is drawn: the blend reads the four neighbours.
    int cx0 = Math.max(0, x0 - 1);
    int cy0 = Math.max(0, y0 - 1);
    int cx1 = Math.min(width, x0 + w + 1);
    int cy1 = Math.min(height, y0 + h + 1);
    int drawFbo = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
    int readFbo = glGetInteger(GL_READ_FRAMEBUFFER_BINDING);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, drawFbo);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, cx0, cy0, cx0, cy0, cx1 - cx0, cy1 - cy0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, readFbo);

    draw(x0, y0, x1, y1, x0, y0, x1, y1, width, height);
  }

  /**
   * Draws the rectangle {@code rect} ({x0, y0, x1, y1}, pixels) of {@code source}, a texture of
   * viewportWidth × viewportHeight pixels, into the same place of the framebuffer bound for
   * drawing: smoothed where it lies within {@code smooth} (as {@link #apply} smooths), copied as
   * it is elsewhere. The smoothing reads one pixel around each pixel it smooths; the caller keeps
   * those in {@code source} too. One pass instead of a copy into this pass's texture, the pass,
   * and a copy to the framebuffer.
   */
  void drawFrom(int source, ScreenRect smooth, int[] rect, int viewportWidth, int viewportHeight) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, source);
    if (smooth.isEmpty()) {
      draw(rect[0], rect[1], rect[2], rect[3], 0, 0, 0, 0, viewportWidth, viewportHeight);
    } else {
      draw(rect[0], rect[1], rect[2], rect[3], smooth.x0(), smooth.y0(), smooth.x1(), smooth.y1(), viewportWidth, viewportHeight);
    }
  }

  /** The pass over [x0, x1) × [y0, y1), smoothing within [s0, s1) × [t0, t1), from the texture bound to unit 0. */
  private void draw(int x0, int y0, int x1, int y1, int s0, int t0, int s1, int t1, int viewportWidth, int viewportHeight) {
    glViewport(0, 0, viewportWidth, viewportHeight);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, y0, x1 - x0, y1 - y0);
    program.use();
    glUniform1i(program.uniform("uScene"), 0);
    glUniform4i(program.uniform("uSmooth"), s0, t0, s1, t1);
    glBindVertexArray(emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_SCISSOR_TEST);
    glBindTexture(GL_TEXTURE_2D, 0);
  }

  private void allocate(int w, int h) {
    glDeleteTextures(texture);
    width = w;
    height = h;
    texture = glGenTextures();
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, 0L);
    // The shader reads single texels (texelFetch); no filtering or mipmaps.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
  }

  @Override
  public void close() {
    // Deleting name 0 is a no-op in GL, so this is safe if nothing was ever smoothed.
    glDeleteTextures(texture);
    glDeleteVertexArrays(emptyVao);
    program.close();
  }
}
