package org.robotrun.ui;

import static org.lwjgl.glfw.GLFW.*;

import imgui.ImGui;
import imgui.gl3.ImGuiImplGl3;
import imgui.glfw.ImGuiImplGlfw;
import java.util.function.IntPredicate;
import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;
import org.lwjgl.system.Configuration;
import org.lwjgl.system.Platform;
import org.robotrun.render.AntiAliasing;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.render.OrbitCamera;
import org.robotrun.render.SceneRenderer;
import org.robotrun.sim.SceneSnapshot;

/**
 * The desktop window: a GLFW window with an OpenGL 3.3 core context showing the cell. The mouse
 * moves the camera (left drag orbits, right or middle drag pans, wheel zooms); Home resets the
 * view. Other keys go to a {@link KeyHandler} (the pendant keyboard). Panels (the pendant, status) are Dear ImGui windows drawn
 * over the scene; while the mouse is over a panel the camera ignores it.
 */
public final class SimulatorWindow implements AutoCloseable {
  /** Supplies the scene to draw each frame. */
  @FunctionalInterface
  public interface SceneSource {
    SceneSnapshot snapshot(double wallSeconds);
  }

  private final long window;
  private final OrbitCamera camera = new OrbitCamera();
  private final SceneRenderer renderer;
  private final ImGuiImplGlfw imguiGlfw = new ImGuiImplGlfw();
  private final ImGuiImplGl3 imguiGl3 = new ImGuiImplGl3();
  private double lastX;
  private double lastY;
  private boolean orbiting;
  private boolean panning;
  private KeyHandler keyHandler = (key, action) -> false;
  private IntPredicate charHandler = codepoint -> false;
  private Runnable focusLost = () -> {};
  private int frameLimit;

  /** Receives keyboard events that no panel text field wants. */
  @FunctionalInterface
  public interface KeyHandler {
    /** Returns whether the key was used. */
    boolean onKey(int glfwKey, int action);
  }

  public SimulatorWindow(String title, int width, int height) {
    // One line per GLFW error, never LWJGL's stack-trace print; the last one goes into the
    // message when the window cannot open.
    String[] lastError = {""};
    boolean[] open = {false};
    GLFWErrorCallback.create((code, description) -> {
      lastError[0] = GLFWErrorCallback.getDescription(description);
      if (open[0]) {
        System.err.println("robotrun: GLFW: " + lastError[0]);
      }
    }).set();
    if (!glfwInit()) {
      freeErrorCallback();
      throw new GlUnavailableException("GLFW could not start" + (lastError[0].isEmpty() ? "" : " (" + lastError[0] + ")")
          + ": is there a display? try 'robotrun render' for headless use");
    }
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    if (Platform.get() == Platform.MACOSX) {
      glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    }
    glfwWindowHint(GLFW_SAMPLES, AntiAliasing.DEFAULT.samples());
    window = glfwCreateWindow(width, height, title, 0, 0);
    if (window == 0) {
      glfwTerminate();
      freeErrorCallback();
      throw new GlUnavailableException("could not open a window with OpenGL 3.3" + (lastError[0].isEmpty() ? "" : " (" + lastError[0] + ")")
          + ": update the graphics driver or Mesa", true);
    }
    open[0] = true;
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    Configuration.OPENGL_EXPLICIT_INIT.set(true);
    GL.create();
    GL.createCapabilities();
    renderer = new SceneRenderer();
    installInput();
    // ImGui chains to the callbacks installed above.
    ImGui.createContext();
    ImGui.getIO().setIniFilename(null);
    ImGui.styleColorsDark();
    imguiGlfw.init(window, true);
    imguiGl3.init("#version 330 core");
  }

  private void installInput() {
    glfwSetMouseButtonCallback(window, (w, button, action, mods) -> {
      boolean down = action == GLFW_PRESS;
      if (down && ImGui.getIO().getWantCaptureMouse()) {
        return;
      }
      if (button == GLFW_MOUSE_BUTTON_LEFT) {
        orbiting = down;
      } else if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) {
        panning = down;
      }
    });
    glfwSetCursorPosCallback(window, (w, x, y) -> {
      double dx = x - lastX, dy = y - lastY;
      lastX = x;
      lastY = y;
      int[] ww = new int[1], wh = new int[1];
      glfwGetWindowSize(window, ww, wh);
      if (orbiting) {
        camera.orbit((float) (-dx * 0.008), (float) (dy * 0.008));
      } else if (panning && wh[0] > 0) {
        camera.pan((float) (dx / wh[0]), (float) (dy / wh[0]));
      }
    });
    glfwSetScrollCallback(window, (w, sx, sy) -> {
      if (!ImGui.getIO().getWantCaptureMouse()) {
        camera.zoom((float) Math.pow(0.88, sy));
      }
    });
    glfwSetKeyCallback(window, (w, key, scancode, action, mods) -> {
      // Releases always go through, so a key held while a text field took focus still stops.
      if (action != GLFW_RELEASE && ImGui.getIO().getWantCaptureKeyboard()) {
        return;
      }
      if (key == GLFW_KEY_HOME && action == GLFW_PRESS) {
        camera.reset();
        return;
      }
      keyHandler.onKey(key, action);
    });
    glfwSetCharCallback(window, (w, codepoint) -> {
      if (!ImGui.getIO().getWantCaptureKeyboard()) {
        charHandler.test(codepoint);
      }
    });
    // Keys held when the window loses the focus never see their release: let go of them now.
    glfwSetWindowFocusCallback(window, (w, focused) -> {
      if (!focused) {
        focusLost.run();
      }
    });
  }

  /** Draws ImGui panels; called once per frame between ImGui's newFrame and render. */
  @FunctionalInterface
  public interface Panels {
    void draw(int framebufferWidth, int framebufferHeight);
  }

  /** Runs the event and render loop until the window is closed. */
  public void run(SceneSource scene) {
    run(scene, (w, h) -> {});
  }

  /** Runs the event and render loop, with panels over the scene, until the window is closed. */
  public void run(SceneSource scene, Panels panels) {
    long start = System.nanoTime();
    int[] fw = new int[1], fh = new int[1];
    while (!glfwWindowShouldClose(window)) {
      glfwPollEvents();
      glfwGetFramebufferSize(window, fw, fh);
      if (fw[0] > 0 && fh[0] > 0) {
        renderer.render(scene.snapshot((System.nanoTime() - start) / 1e9), camera, fw[0], fh[0]);
        imguiGlfw.newFrame();
        ImGui.newFrame();
        panels.draw(fw[0], fh[0]);
        ImGui.render();
        imguiGl3.renderDrawData(ImGui.getDrawData());
        glfwSwapBuffers(window);
        if (frameLimit > 0 && --frameLimit == 0) {
          glfwSetWindowShouldClose(window, true);
        }
      } else {
        glfwWaitEventsTimeout(0.1);
      }
    }
  }

  /** Closes the window after this many drawn frames (0: when the user closes it); for start-up timing and the packaging's training run. */
  public void setFrameLimit(int frames) {
    frameLimit = frames;
  }

  public void setKeyHandler(KeyHandler handler) {
    keyHandler = handler;
  }

  /** Receives typed characters (Unicode code points) that no panel text field wants. */
  public void setCharHandler(IntPredicate handler) {
    charHandler = handler;
  }

  /** Runs when the window loses the keyboard focus. */
  public void setFocusLostHandler(Runnable handler) {
    focusLost = handler;
  }

  public OrbitCamera camera() {
    return camera;
  }

  @Override
  public void close() {
    imguiGl3.dispose();
    imguiGlfw.dispose();
    ImGui.destroyContext();
    renderer.close();
    GL.setCapabilities(null);
    glfwDestroyWindow(window);
    glfwTerminate();
    GL.destroy();
    freeErrorCallback();
  }

  private static void freeErrorCallback() {
    GLFWErrorCallback cb = glfwSetErrorCallback(null);
    if (cb != null) {
      cb.free();
    }
  }
}
