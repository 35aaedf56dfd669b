package org.robotrun.ui;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.ByteBuffer;
import org.lwjgl.system.MemoryUtil;
import org.robotrun.render.OffscreenTarget;

/**
 * {@code ROBOTRUN_REDRAW=check}: after each frame, draws the whole frame again the plain way (the
 * scene with {@code SceneRenderer.render}, as the headless renderer does, the fills, every panel)
 * into a framebuffer of its own and compares it with the frame the window kept and drew only in
 * part. A pixel differs when a colour channel differs by more than {@link #TOLERANCE}; the count
 * goes to stderr whenever it is not zero, and the largest one when the window closes. Slow (two
 * read-backs of the window per frame): for tests and for chasing a stale picture, not for use.
 */
final class RedrawCheck implements AutoCloseable {
  /** Channel difference allowed: rounding where the same pixel is reached by another order of drawing. */
  static final int TOLERANCE = 16;

  private OffscreenTarget reference;
  private ByteBuffer shown;
  private ByteBuffer expected;
  private long frames;
  private long worst;

  /** Reads back the kept frame from framebuffer {@code kept} (0: the window's back buffer), then binds the reference to draw into. */
  void beginReference(int kept, int width, int height) {
    if (reference == null || reference.width() != width || reference.height() != height) {
      close();
      reference = new OffscreenTarget(width, height, 0);
      shown = MemoryUtil.memAlloc(width * height * 4);
      expected = MemoryUtil.memAlloc(width * height * 4);
    }
    read(kept, kept == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0, shown, width, height);
    reference.bind();
  }

  /** Reads the reference back, compares, rebinds {@code kept}; returns the number of differing pixels. */
  long endReference(int kept, int width, int height) {
    read(reference.framebuffer(), GL_COLOR_ATTACHMENT0, expected, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, kept);
    long differing = differing(shown, expected, width * height);
    frames++;
    worst = Math.max(worst, differing);
    if (differing > 0) {
      int[] b = differingBounds(shown, expected, width, height);
      System.err.println("robotrun: redraw check: frame " + frames + ": " + differing + " pixels differ from a full redraw, within x "
          + b[0] + ".." + b[2] + ", y " + b[1] + ".." + b[3] + " (from the bottom left)");
    }
    return differing;
  }

  private static void read(int framebuffer, int buffer, ByteBuffer into, int width, int height) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadBuffer(buffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, into);
  }

  /** Pixels (RGBA bytes) where a colour channel differs by more than {@link #TOLERANCE}. */
  static long differing(ByteBuffer a, ByteBuffer b, int pixels) {
    long n = 0;
    for (int p = 0; p < pixels; p++) {
      for (int c = 0; c < 3; c++) {
        int d = (a.get(4 * p + c) & 0xff) - (b.get(4 * p + c) & 0xff);
        if (d > TOLERANCE || d < -TOLERANCE) {
          n++;
          break;
        }
      }
    }
    return n;
  }

  /** The bounds {x0, y0, x1, y1} (inclusive) of the differing pixels. */
  private static int[] differingBounds(ByteBuffer a, ByteBuffer b, int width, int height) {
    int[] r = {width, height, -1, -1};
    for (int p = 0; p < width * height; p++) {
      for (int c = 0; c < 3; c++) {
        int d = (a.get(4 * p + c) & 0xff) - (b.get(4 * p + c) & 0xff);
        if (d > TOLERANCE || d < -TOLERANCE) {
          int x = p % width, y = p / width;
          r[0] = Math.min(r[0], x);
          r[1] = Math.min(r[1], y);
          r[2] = Math.max(r[2], x);
          r[3] = Math.max(r[3], y);
          break;
        }
      }
    }
    return r;
  }

  /** Prints the summary line (frames checked, most pixels differing in one frame). */
  void report() {
    System.err.println("robotrun: redraw check: " + frames + " frames, at most " + worst + " pixels differed");
  }

  @Override
  public void close() {
    if (reference != null) {
      reference.close();
      MemoryUtil.memFree(shown);
      MemoryUtil.memFree(expected);
      reference = null;
    }
  }
}
