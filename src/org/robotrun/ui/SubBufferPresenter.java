package org.robotrun.ui;

import org.lwjgl.glfw.GLFWNativeGLX;
import org.lwjgl.glfw.GLFWNativeX11;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GLX14;
import org.lwjgl.system.JNI;
import org.lwjgl.system.Platform;

/**
 * Shows only the changed rectangles of the window's back buffer, never swapping it, through GLX's
 * {@code GLX_MESA_copy_sub_buffer} ({@code glXCopySubBufferMESA}: copies a rectangle of the back
 * buffer to the window and leaves the back buffer as it was). The back buffer then keeps the last
 * frame, so a frame draws again only what changed and shows only that: no copy of the whole window
 * per frame, which on Mesa's software renderer costs as much as drawing the panels. Used only
 * with Mesa's software renderers (llvmpipe, softpipe) under X11, where this matters and where the
 * back buffer is memory of this process; elsewhere the window keeps its frame in a framebuffer of
 * its own and swaps.
 */
final class SubBufferPresenter {
  private final long display;
  private final long drawable;
  private final long copySubBuffer;

  private SubBufferPresenter(long display, long drawable, long copySubBuffer) {
    this.display = display;
    this.drawable = drawable;
    this.copySubBuffer = copySubBuffer;
  }

  /**
   * The presenter for a GLFW window whose context is current, or null when it does not apply (not
   * X11, not a Mesa software renderer, no extension, or {@code ROBOTRUN_REDRAW=swap}).
   */
  static SubBufferPresenter forWindow(long window) {
    if (Platform.get() != Platform.LINUX && Platform.get() != Platform.FREEBSD
        || SimulatorWindow.redrawMode("swap")) {
      return null;
    }
    try {
      String renderer = String.valueOf(GL11C.glGetString(GL11C.GL_RENDERER));
      if (!renderer.contains("llvmpipe") && !renderer.contains("softpipe")) {
        return null;
      }
      long display = GLFWNativeX11.glfwGetX11Display();
      long drawable = GLFWNativeGLX.glfwGetGLXWindow(window);
      if (display == 0 || drawable == 0) {
        return null;
      }
      String extensions = GLX14.glXQueryExtensionsString(display, 0);
      if (extensions == null || !(" " + extensions + " ").contains(" GLX_MESA_copy_sub_buffer ")) {
        return null;
      }
      long fn = GL.getFunctionProvider().getFunctionAddress("glXCopySubBufferMESA");
      return fn == 0 ? null : new SubBufferPresenter(display, drawable, fn);
    } catch (RuntimeException | LinkageError e) {
      // GLFW built without X11 (Wayland only), or GLX missing: swap as usual
      return null;
    }
  }

  /** Shows the back buffer's rectangle {x0, y0, x1, y1} (GL pixels, from the bottom left). */
  void show(int[] r) {
    // void glXCopySubBufferMESA(Display*, GLXDrawable, int x, int y, int width, int height); called
    // through an int-returning binding (the return register is simply not read)
    JNI.callPPI(display, drawable, r[0], r[1], r[2] - r[0], r[3] - r[1], copySubBuffer);
  }
}
