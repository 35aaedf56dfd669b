package org.robotrun.render;

import static org.lwjgl.glfw.GLFW.*;

import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;
import org.lwjgl.system.Configuration;
import org.lwjgl.system.Platform;

/**
 * An OpenGL 3.3 core context with no display: GLFW's null platform with an OSMesa context
 * (Mesa's software renderer; {@code libosmesa6} on Debian). Rendering goes into an
 * {@link OffscreenTarget}. One per thread; close it when done.
 */
public final class HeadlessGl implements AutoCloseable {
  private final long window;
  private final GLFWErrorCallback previous;

  private HeadlessGl(long window, GLFWErrorCallback previous) {
    this.window = window;
    this.previous = previous;
  }

  /**
   * Creates the context and makes it current.
   *
   * @throws GlUnavailableException when no headless OpenGL can be had, with the reason
   */
  public static HeadlessGl create() {
    if (Platform.get() != Platform.LINUX) {
      throw new GlUnavailableException("headless rendering needs Linux with Mesa (OSMesa)");
    }
    StringBuilder errors = new StringBuilder();
    GLFWErrorCallback previous = glfwSetErrorCallback((code, desc) ->
        errors.append(GLFWErrorCallback.getDescription(desc)).append("; "));
    // GL function pointers come from OSMesa itself, not from libGL.
    Configuration.OPENGL_LIBRARY_NAME.set("libOSMesa.so.8");
    glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_NULL);
    if (!glfwInit()) {
      restore(previous);
      throw new GlUnavailableException("GLFW could not start its null platform: " + errors);
    }
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_OSMESA_CONTEXT_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    long w = glfwCreateWindow(16, 16, "robotrun-headless", 0, 0);
    if (w == 0) {
      glfwTerminate();
      restore(previous);
      throw new GlUnavailableException(
          "no OSMesa OpenGL context (is libosmesa6 installed? apt-get install libosmesa6): " + errors);
    }
    glfwMakeContextCurrent(w);
    try {
      // Explicit init so the library can be loaded again by the next context in this process.
      Configuration.OPENGL_EXPLICIT_INIT.set(true);
      GL.create();
      GL.createCapabilities();
    } catch (RuntimeException | LinkageError e) {
      glfwDestroyWindow(w);
      glfwTerminate();
      restore(previous);
      throw new GlUnavailableException("OpenGL functions could not be loaded from OSMesa: " + e.getMessage());
    }
    return new HeadlessGl(w, previous);
  }

  private static void restore(GLFWErrorCallback previous) {
    GLFWErrorCallback cb = glfwSetErrorCallback(previous);
    if (cb != null) {
      cb.free();
    }
  }

  @Override
  public void close() {
    GL.setCapabilities(null);
    glfwMakeContextCurrent(0);
    glfwDestroyWindow(window);
    glfwTerminate();
    restore(previous);
    GL.destroy();
    Configuration.OPENGL_LIBRARY_NAME.set((String) null);
  }
}
