package org.robotrun.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.ByteBuffer;
import org.lwjgl.system.MemoryUtil;

/**
 * A framebuffer to render into without a window: colour and depth, read back as RGB. With more
 * than one sample the scene is drawn into multisampled buffers and resolved into the plain one;
 * with 0 or 1 it is drawn into the plain one directly.
 */
public final class OffscreenTarget implements AutoCloseable {
  private final int width;
  private final int height;
  private final int msFbo;
  private final int msColor;
  private final int msDepth;
  private final int fbo;
  private final int color;
  private final int depth;
  private final boolean multisampled;
  /** The plain buffer's colour as a texture a shader can read ({@link #colorTexture}); 0 when it is a renderbuffer. */
  private final int colorTexture;

  public OffscreenTarget(int width, int height, int samples) {
    this(width, height, samples, false);
  }

  /**
   * A target whose plain colour buffer is, when {@code readableColor}, a texture (RGBA8, read
   * unfiltered) that a later pass may read with texelFetch, so that what was drawn here can be
   * drawn on elsewhere without a copy first; a renderbuffer otherwise.
   */
  public OffscreenTarget(int width, int height, int samples, boolean readableColor) {
    this.width = width;
    this.height = height;
    multisampled = samples > 1;
    if (multisampled) {
      msFbo = glGenFramebuffers();
      glBindFramebuffer(GL_FRAMEBUFFER, msFbo);
      msColor = glGenRenderbuffers();
      glBindRenderbuffer(GL_RENDERBUFFER, msColor);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msColor);
      msDepth = glGenRenderbuffers();
      glBindRenderbuffer(GL_RENDERBUFFER, msDepth);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msDepth);
      check("multisampled");
    } else {
      msFbo = 0;
      msColor = 0;
      msDepth = 0;
    }

    fbo = glGenFramebuffers();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    if (readableColor) {
      color = 0;
      colorTexture = glGenTextures();
      glBindTexture(GL_TEXTURE_2D, colorTexture);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, 0L);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glBindTexture(GL_TEXTURE_2D, 0);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colorTexture, 0);
    } else {
      colorTexture = 0;
      color = glGenRenderbuffers();
      glBindRenderbuffer(GL_RENDERBUFFER, color);
      glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    }
    if (multisampled) {
      depth = 0;
    } else {
      // Without multisampling the scene is drawn straight into this buffer: no resolve pass.
      depth = glGenRenderbuffers();
      glBindRenderbuffer(GL_RENDERBUFFER, depth);
      glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    }
    check("resolve");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  private static void check(String which) {
    int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      throw new IllegalStateException("the " + which + " framebuffer is incomplete (status 0x"
          + Integer.toHexString(status) + ")");
    }
  }

  /** Binds the framebuffer the scene is drawn into (the multisampled one, if any). */
  public void bind() {
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled ? msFbo : fbo);
  }

  /** Resolves the samples into the plain buffer; nothing to do without multisampling. */
  public void resolve() {
    if (!multisampled) {
      return;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msFbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  /**
   * Resolves and reads the image back as RGB rows, top row first. The buffer is allocated with
   * MemoryUtil; the caller frees it with {@link MemoryUtil#memFree}.
   */
  public ByteBuffer readRgbTopDown() {
    resolve();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    ByteBuffer bottomUp = MemoryUtil.memAlloc(width * height * 3);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ByteBuffer topDown = MemoryUtil.memAlloc(width * height * 3);
    int row = width * 3;
    for (int y = 0; y < height; y++) {
      MemoryUtil.memCopy(MemoryUtil.memAddress(bottomUp) + (long) (height - 1 - y) * row,
          MemoryUtil.memAddress(topDown) + (long) y * row, row);
    }
    MemoryUtil.memFree(bottomUp);
    return topDown;
  }

  /** The plain buffer's colour texture (see the constructor's {@code readableColor}); 0 when it has none. */
  public int colorTexture() {
    return colorTexture;
  }

  /** The plain (single-sample) framebuffer's GL name. */
  public int framebuffer() {
    return fbo;
  }

  /**
   * Copies the rectangle {x0, y0, x1, y1} (pixels) of the plain buffer's colour, and its depth
   * when {@code depthToo}, into the same place of framebuffer {@code target} (0: the window), which
   * must have the same depth format. Leaves {@code target} bound for drawing.
   */
  public void copyTo(int target, int[] r, boolean depthToo) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    glBlitFramebuffer(r[0], r[1], r[2], r[3], r[0], r[1], r[2], r[3],
        GL_COLOR_BUFFER_BIT | (depthToo ? GL_DEPTH_BUFFER_BIT : 0), GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target);
  }

  public int width() {
    return width;
  }

  public int height() {
    return height;
  }

  @Override
  public void close() {
    // Deleting name 0 is ignored by GL, so the single-sample case needs no branches here.
    glDeleteFramebuffers(msFbo);
    glDeleteFramebuffers(fbo);
    glDeleteRenderbuffers(msColor);
    glDeleteRenderbuffers(msDepth);
    glDeleteRenderbuffers(color);
    glDeleteRenderbuffers(depth);
    glDeleteTextures(colorTexture);
  }
}
