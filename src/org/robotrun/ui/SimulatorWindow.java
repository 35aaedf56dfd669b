package org.robotrun.ui;

import static org.lwjgl.glfw.GLFW.*;

import imgui.ImGui;
import imgui.glfw.ImGuiImplGlfw;
import java.util.function.BooleanSupplier;
import java.util.function.IntPredicate;
import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;
import org.lwjgl.system.Configuration;
import org.lwjgl.system.Platform;
import org.robotrun.render.AntiAliasing;
import org.robotrun.render.DamageRegion;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.render.OffscreenTarget;
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
  /** Draws the panels, again only where they changed. */
  private RetainedUi ui;
  /** The frame as last drawn, kept between frames: each frame draws again only what changed, then shows it. */
  private OffscreenTarget canvas;
  private java.util.List<Fill> lastFills = java.util.List.of();
  /** ROBOTRUN_REDRAW=all: draw every pixel every frame (to compare, or should a driver mishandle the kept frame). */
  private final boolean redrawAll = redrawMode("all");
  private volatile long damagedPixels;
  /** Non-null: the back buffer keeps the frame and only changed rectangles are shown (Mesa's software renderers). */
  private SubBufferPresenter presenter;
  /** The back buffer's size when {@link #presenter} draws into it; the window was exposed: show all of it. */
  private int backW;
  private int backH;
  private volatile boolean showAll = true;
  /** Frames still to be drawn whole and swapped after the window's size changed ({@link #presenter} only). */
  private int swapFramesLeft;
  private static final int SWAP_FRAMES_AFTER_RESIZE = 3;
  /** ROBOTRUN_REDRAW=check: compare each kept frame with a full redraw (tests). */
  private final RedrawCheck check = redrawMode("check") ? new RedrawCheck() : null;

  /** Whether ROBOTRUN_REDRAW (words separated by commas: all, swap, check) names this word. */
  static boolean redrawMode(String word) {
    String v = System.getenv("ROBOTRUN_REDRAW");
    return v != null && java.util.Arrays.asList(v.trim().split("\\s*,\\s*")).contains(word);
  }
  private double lastX;
  private double lastY;
  private boolean orbiting;
  private boolean panning;
  private KeyHandler keyHandler = (key, action) -> false;
  /** Keys typed into a text field stay the field's, press and release (issue 26). */
  private final TypingKeyFilter typingFilter = new TypingKeyFilter();
  private IntPredicate charHandler = codepoint -> false;
  private Runnable focusLost = () -> {};
  private Runnable focusGained = () -> {};
  private BooleanSupplier mayClose = () -> true;
  private Runnable firstFrame = () -> {};
  private Runnable afterFrame = () -> {};
  private ShortcutHandler shortcuts = (key, mods) -> false;
  private ViewClick viewClick = (x, y) -> {};
  private ViewPress viewPress = new ViewPress() {
    @Override
    public boolean press(double x, double y) {
      return false;
    }

    @Override
    public boolean drag(double x, double y) {
      return false;
    }

    @Override
    public void release() {}
  };
  private final InputEdges mouseEdges = new InputEdges();
  private final InputEdges keyEdges = new InputEdges();
  private volatile long lastInputNanos = System.nanoTime();
  private double pressX;
  private double pressY;
  private boolean dragged;
  /** Read by other threads too (a benchmark's timer). */
  private volatile long frames;
  private float contentScale = 1f;
  /** The least window size (window coordinates), once the first frame knows it; null before. */
  private int[] minimumSize;
  /** After the last input, keep drawing this long (hover highlights, tooltips settle). */
  private static final long IDLE_AFTER_NANOS = 500_000_000L;
  /**
   * While idle, the longest sleep between two frames. Nothing on screen changes by itself while
   * idle (the simulation advances only with frames, and every timed message, save and background
   * result asks for its own wake-up: {@link #setWakeSource}, {@link #wakeFromAnyThread}); this is
   * only a safety net.
   */
  static final double IDLE_REDRAW_SEC = 60.0;
  /** When something asked to be drawn at a time ({@link System#nanoTime}); {@link Long#MAX_VALUE} for nothing. */
  private java.util.function.LongSupplier wakeSource = () -> Long.MAX_VALUE;
  /** When the last frame drawn for input, motion or a start began ({@link System#nanoTime}). */
  private volatile long lastActiveFrameNanos = System.nanoTime();
  /** The shortest time between the starts of two frames: the screen's refresh period. */
  private final long framePeriodNanos;
  private long lastFrameStart;

  /** Receives keyboard events that no panel text field wants. */
  @FunctionalInterface
  public interface KeyHandler {
    /** Returns whether the key was used. */
    boolean onKey(int glfwKey, int action);
  }

  /**
   * Opens the window.
   *
   * @param width window width in screen coordinates; 0: fit the screen it opens on (at most
   *     1280 by 800 times the monitor's content scale, never more than its work area)
   * @param height window height; 0 as for the width
   */
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
    if (System.getenv("ROBOTRUN_HIDDEN_WINDOW") != null) {
      // the launcher's class-data training run after a build: the window draws but is never shown
      glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    }
    int[] size = defaultSize(width, height);
    window = glfwCreateWindow(size[0], size[1], title, 0, 0);
    if (window == 0) {
      glfwTerminate();
      freeErrorCallback();
      throw new GlUnavailableException("could not open a window with OpenGL 3.3" + (lastError[0].isEmpty() ? "" : " (" + lastError[0] + ")")
          + ": update the graphics driver or Mesa", true);
    }
    open[0] = true;
    framePeriodNanos = Math.round(1e9 / refreshHz(glfwGetPrimaryMonitor()));
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    Configuration.OPENGL_EXPLICIT_INIT.set(true);
    GL.create();
    GL.createCapabilities();
    renderer = new SceneRenderer();
    // round shapes divided as finely as their size on screen needs (the full meshes cost most of
    // a moving frame on a software renderer); pictures keep the full meshes
    renderer.setDetailBySize(true);
    installInput();
    // ImGui chains to the callbacks installed above.
    ImGui.createContext();
    // ImGui never writes files itself: every file goes through AtomicFiles (see WindowSettings)
    ImGui.getIO().setIniFilename(null);
    ImGui.styleColorsDark();
    contentScale = uiScale(window, System.getenv("ROBOTRUN_UI_SCALE"));
    // Pixels per window coordinate: 2 on a macOS Retina screen (window sizes in points), else 1.
    int[] ww = new int[1], wh = new int[1], fbw = new int[1], fbh = new int[1];
    glfwGetWindowSize(window, ww, wh);
    glfwGetFramebufferSize(window, fbw, fbh);
    float pixelRatio = ww[0] > 0 ? Math.max(1f, fbw[0] / (float) ww[0]) : 1f;
    float raster = contentScale * pixelRatio;
    if (Math.abs(raster - 1f) > 0.01f) {
      // HiDPI (or a forced scale): the font rasterised at the screen's pixel density (sharp, not stretched), drawn at
      // the size the UI scale asks for in window coordinates, and the style's sizes to match
      var cfg = new imgui.ImFontConfig();
      cfg.setSizePixels(13f * raster);
      ImGui.getIO().getFonts().addFontDefault(cfg);
      cfg.destroy();
      ImGui.getIO().setFontGlobalScale(1f / pixelRatio);
      if (Math.abs(contentScale - 1f) > 0.01f) {
        ImGui.getStyle().scaleAllSizes(contentScale);
      }
    }
    imguiGlfw.init(window, true);
    ui = new RetainedUi();
    presenter = SubBufferPresenter.forWindow(window);
  }

  /** ROBOTRUN_UI_SCALE's value when it is a number from 0.5 to 4; empty otherwise (unset, blank, garbage). */
  static java.util.Optional<Float> forcedUiScale(String forced) {
    if (forced == null || forced.isBlank()) {
      return java.util.Optional.empty();
    }
    try {
      float f = Float.parseFloat(forced.trim());
      return f >= 0.5f && f <= 4f ? java.util.Optional.of(f) : java.util.Optional.empty();
    } catch (NumberFormatException e) {
      return java.util.Optional.empty();
    }
  }

  /**
   * How much larger than at 96 dpi the window's text and panels are drawn, in window coordinates:
   * {@code ROBOTRUN_UI_SCALE} when set (0.5 to 4; for a screen that reports no scale, or to try
   * HiDPI on an ordinary one), else the monitor's content scale divided by the pixels per window
   * coordinate (macOS counts window sizes in points, so a Retina screen's 2 is already in them).
   */
  static float uiScale(long window, String forced) {
    if (forced != null && !forced.isBlank()) {
      java.util.Optional<Float> f = forcedUiScale(forced);
      if (f.isPresent()) {
        return f.get();
      }
      System.err.println("robotrun: ROBOTRUN_UI_SCALE: expected a number from 0.5 to 4, got '"
          + org.robotrun.io.TerminalText.safe(forced) + "'; using the monitor's scale");
    }
    float[] sx = new float[1], sy = new float[1];
    glfwGetWindowContentScale(window, sx, sy);
    int[] ww = new int[1], wh = new int[1], fbw = new int[1], fbh = new int[1];
    glfwGetWindowSize(window, ww, wh);
    glfwGetFramebufferSize(window, fbw, fbh);
    float pixelRatio = ww[0] > 0 ? Math.max(1f, fbw[0] / (float) ww[0]) : 1f;
    float s = Math.max(sx[0], sy[0]) / pixelRatio;
    return Math.max(1f, Math.min(4f, s));
  }

  /** The monitor's refresh rate (Hz), 60 when it does not say or says something odd. */
  static int refreshHz(long monitor) {
    org.lwjgl.glfw.GLFWVidMode mode = monitor == 0 ? null : glfwGetVideoMode(monitor);
    int hz = mode == null ? 0 : mode.refreshRate();
    return hz >= 24 && hz <= 500 ? hz : 60;
  }

  /** The window size to open with: what was asked for, or what fits the primary monitor. */
  private static int[] defaultSize(int width, int height) {
    if (width > 0 && height > 0) {
      return new int[] {width, height};
    }
    int w = 1280, h = 800;
    long monitor = glfwGetPrimaryMonitor();
    if (monitor != 0) {
      int[] x = new int[1], y = new int[1], ww = new int[1], wh = new int[1];
      glfwGetMonitorWorkarea(monitor, x, y, ww, wh);
      float[] sx = new float[1], sy = new float[1];
      glfwGetMonitorContentScale(monitor, sx, sy);
      // macOS counts screen coordinates in points: its content scale is not applied again
      float s = Platform.get() == Platform.MACOSX ? 1f : Math.max(1f, sx[0]);
      s = forcedUiScale(System.getenv("ROBOTRUN_UI_SCALE")).orElse(s);
      if (ww[0] > 0 && wh[0] > 0) {
        // leave room for the title bar and the task bar the work area may not count
        w = Math.min(Math.round(1280 * s), ww[0]);
        h = Math.min(Math.round(800 * s), wh[0] - Math.round(40 * s));
      }
    }
    return new int[] {width > 0 ? width : Math.max(640, w), height > 0 ? height : Math.max(480, h)};
  }

  private void installInput() {
    glfwSetMouseButtonCallback(window, (w, button, action, mods) -> {
      lastInputNanos = System.nanoTime();
      boolean down = action == GLFW_PRESS;
      mouseEdges.record(button, down);
      if (down && ImGui.getIO().getWantCaptureMouse()) {
        return;
      }
      if (button == GLFW_MOUSE_BUTTON_LEFT) {
        if (down) {
          pressX = lastX;
          pressY = lastY;
          dragged = false;
        } else if (orbiting && !dragged) {
          viewClick.click(lastX, lastY);
        }
        orbiting = down && !viewPress.press(lastX, lastY);
        if (!down) {
          viewPress.release();
        }
      } else if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) {
        panning = down;
      }
    });
    glfwSetCursorPosCallback(window, (w, x, y) -> {
      lastInputNanos = System.nanoTime();
      double dx = x - lastX, dy = y - lastY;
      lastX = x;
      lastY = y;
      if (Math.abs(x - pressX) + Math.abs(y - pressY) > 4) {
        dragged = true;
      }
      if (viewPress.drag(x, y)) {
        return;
      }
      int[] ww = new int[1], wh = new int[1];
      glfwGetWindowSize(window, ww, wh);
      if (orbiting) {
        camera.orbit((float) (-dx * 0.008), (float) (dy * 0.008));
      } else if (panning && wh[0] > 0) {
        camera.pan((float) (dx / wh[0]), (float) (dy / wh[0]));
      }
    });
    glfwSetScrollCallback(window, (w, sx, sy) -> {
      lastInputNanos = System.nanoTime();
      if (!ImGui.getIO().getWantCaptureMouse()) {
        camera.zoom((float) Math.pow(0.88, sy));
      }
    });
    glfwSetKeyCallback(window, (w, key, scancode, action, mods) -> {
      lastInputNanos = System.nanoTime();
      if (action != GLFW_REPEAT) {
        keyEdges.record(key, action == GLFW_PRESS);
      }
      // Only an open text field keeps the keyboard (not a panel that merely has the focus);
      // function keys still reach the pendant then. A key held while a text field took focus
      // still stops when let go; a key typed into the field stays the field's (TypingKeyFilter).
      boolean typing = ImGui.getIO().getWantTextInput();
      if (action == GLFW_PRESS && (!typing || shortcutWhileTyping(key)) && shortcuts.onShortcut(key, mods)) {
        return;
      }
      if (!typingFilter.pass(key, action, typing)) {
        return;
      }
      if (key == GLFW_KEY_HOME && action == GLFW_PRESS) {
        camera.reset();
        return;
      }
      keyHandler.onKey(key, action);
    });
    glfwSetCharCallback(window, (w, codepoint) -> {
      lastInputNanos = System.nanoTime();
      if (!ImGui.getIO().getWantTextInput()) {
        charHandler.test(codepoint);
      }
    });
    glfwSetWindowSizeCallback(window, (w, ww, wh) -> {
      lastInputNanos = System.nanoTime();
      // without a window manager (or one that ignores the size limits) the window is put back
      if (minimumSize != null && (ww < minimumSize[0] || wh < minimumSize[1])) {
        glfwSetWindowSize(w, Math.max(ww, minimumSize[0]), Math.max(wh, minimumSize[1]));
      }
    });
    glfwSetWindowRefreshCallback(window, w -> {
      lastInputNanos = System.nanoTime();
      // uncovered, restored or resized: the window's pixels must all be shown again
      showAll = true;
    });
    // The close button asks first (unsaved work); a refusal keeps the window open.
    glfwSetWindowCloseCallback(window, w -> {
      if (!mayClose.getAsBoolean()) {
        glfwSetWindowShouldClose(w, false);
      }
    });
    // Keys held when the window loses the focus never see their release: let go of them now.
    glfwSetWindowFocusCallback(window, (w, focused) -> {
      lastInputNanos = System.nanoTime();
      if (!focused) {
        focusLost.run();
      } else {
        focusGained.run();
      }
    });
  }

  /** Draws ImGui panels; called once per frame between ImGui's newFrame and render. */
  @FunctionalInterface
  public interface Panels {
    void draw(int framebufferWidth, int framebufferHeight);

    /**
     * Opaque rectangles (display pixels) under the panels drawn in the last {@link #draw}, filled
     * by a clear before Dear ImGui draws over them: a panel whose own background is left out then
     * costs nothing under a software renderer, where blending a textured background over half the
     * window was a third of each frame.
     */
    default java.util.List<Fill> fills() {
      return java.util.List.of();
    }
  }

  /** A rectangle in display pixels filled with an opaque colour (see {@link Panels#fills}). */
  public record Fill(float x, float y, float w, float h, float r, float g, float b) {}

  /**
   * What the idle loop asks before it sleeps: the time ({@link System#nanoTime}) of the next frame
   * something needs (a message that expires, a save that is due), or {@link Long#MAX_VALUE}.
   */
  public void setWakeSource(java.util.function.LongSupplier nextWakeNanos) {
    wakeSource = nextWakeNanos;
  }

  /** When the last frame drawn for input, motion or the start began ({@link System#nanoTime}). */
  public long lastActiveFrameNanos() {
    return lastActiveFrameNanos;
  }

  /** Wakes the loop from any thread (a background save or check finished): one frame is drawn. */
  public static void wakeFromAnyThread() {
    try {
      glfwPostEmptyEvent();
    } catch (RuntimeException | LinkageError e) {
      // no window (a test, a headless run): nothing sleeps that could be woken
    }
  }

  /**
   * Whether the window's Ctrl shortcut on {@code glfwKey} works while a text field has the
   * keyboard: Ctrl+Q, Ctrl+S and Ctrl+O do (with the pendant's Type field focused, Ctrl+Q did
   * nothing); the keys a text field edits with (Ctrl+Z, Y, A, C, V, X, H) stay the field's.
   */
  static boolean shortcutWhileTyping(int glfwKey) {
    return glfwKey == GLFW_KEY_Q || glfwKey == GLFW_KEY_S || glfwKey == GLFW_KEY_O;
  }

  /**
   * How long the idle loop sleeps (seconds): until the next wake the window was asked for, at
   * least 1 ms, at most {@link #IDLE_REDRAW_SEC}.
   */
  static double idleSleepSec(long nowNanos, long nextWakeNanos) {
    if (nextWakeNanos == Long.MAX_VALUE) {
      return IDLE_REDRAW_SEC;
    }
    double sec = (nextWakeNanos - nowNanos) / 1e9;
    return Math.max(0.001, Math.min(IDLE_REDRAW_SEC, sec));
  }

  /** Runs the event and render loop until the window is closed. */
  public void run(SceneSource scene) {
    run(scene, (w, h) -> {}, () -> true);
  }

  /**
   * Runs the event and render loop, with panels over the scene, until the window is closed.
   * Quiet when idle: while {@code busy} says nothing moves and no input came for half a second,
   * the loop sleeps in {@code glfwWaitEventsTimeout} until the wake source's time (at most
   * {@link #IDLE_REDRAW_SEC}); any input, or {@link #wakeFromAnyThread}, wakes it at once.
   *
   * @param busy whether something on screen changes by itself (the arm moves, a program runs)
   */
  public void run(SceneSource scene, Panels panels, BooleanSupplier busy) {
    long start = System.nanoTime();
    long firstFrameOfRun = frames;
    int[] fw = new int[1], fh = new int[1];
    boolean moreEdges = false;
    while (!glfwWindowShouldClose(window)) {
      boolean recentInput = System.nanoTime() - lastInputNanos < IDLE_AFTER_NANOS;
      // Dear ImGui sizes a new auto-sized window in a hidden first frame: the first few frames
      // are drawn however slowly the start went, so nothing waits for the 5 s idle redraw.
      boolean starting = frames - firstFrameOfRun < 4;
      boolean active = moreEdges || recentInput || starting || busy.getAsBoolean();
      if (active) {
        lastActiveFrameNanos = System.nanoTime();
        // No faster than the screen shows frames: where the swap does not wait for the
        // display (a virtual X server, a driver with vsync off), sleep out the rest of the
        // refresh period instead of drawing frames nobody sees.
        long wait = lastFrameStart + framePeriodNanos - System.nanoTime();
        if (wait > 0) {
          java.util.concurrent.locks.LockSupport.parkNanos(wait);
        }
        glfwPollEvents();
      } else {
        glfwWaitEventsTimeout(idleSleepSec(System.nanoTime(), wakeSource.getAsLong()));
      }
      glfwGetFramebufferSize(window, fw, fh);
      if (fw[0] > 0 && fh[0] > 0) {
        long t0 = System.nanoTime();
        lastFrameStart = t0;
        SceneSnapshot snap = scene.snapshot((System.nanoTime() - start) / 1e9);
        long t1 = System.nanoTime();
        imguiGlfw.newFrame();
        // one queued edge per button and key per frame: a tap within one frame is not lost
        moreEdges = mouseEdges.apply((b, down) -> {
          if (b < 5) {
            ImGui.getIO().setMouseDown(b, down);
          }
        });
        moreEdges |= keyEdges.apply((k, down) -> {
          if (k >= 0 && k < 512) {
            ImGui.getIO().setKeysDown(k, down);
          }
        });
        ImGui.newFrame();
        // panels first: they decide the free part of the window the scene is framed in
        panels.draw(fw[0], fh[0]);
        ImGui.render();
        long t2 = System.nanoTime();
        ui.capture(ImGui.getDrawData(), fw[0], fh[0]);
        DamageRegion damage = new DamageRegion(fw[0], fh[0]);
        boolean swapping = false;
        if (presenter != null) {
          if (backW != fw[0] || backH != fh[0]) {
            backW = fw[0];
            backH = fh[0];
            swapFramesLeft = SWAP_FRAMES_AFTER_RESIZE;
          }
          // Mesa sizes the back buffer anew only after a swap: until the size has held for a
          // while, whole frames are drawn and swapped, and no rectangle is shown that the back
          // buffer might not have
          swapping = swapFramesLeft > 0;
          if (swapping) {
            damage.addAll();
          }
        } else if (canvas == null || canvas.width() != fw[0] || canvas.height() != fh[0]) {
          if (canvas != null) {
            canvas.close();
          }
          canvas = new OffscreenTarget(fw[0], fh[0], 0);
          damage.addAll();
        }
        if (redrawAll) {
          damage.addAll();
        }
        renderer.prepareRetained(snap, camera, fw[0], fh[0], damage);
        java.util.List<Fill> fills = panels.fills();
        if (!fills.equals(lastFills)) {
          for (Fill f : lastFills) {
            if (!fills.contains(f)) {
              addFill(damage, f, fw[0], fh[0]);
            }
          }
          for (Fill f : fills) {
            if (!lastFills.contains(f)) {
              addFill(damage, f, fw[0], fh[0]);
            }
          }
          lastFills = java.util.List.copyOf(fills);
        }
        ui.addDamage(damage);
        damagedPixels += damage.area();
        if (presenter != null) {
          org.lwjgl.opengl.GL30C.glBindFramebuffer(org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER, 0);
        } else {
          canvas.bind();
        }
        long uiNanos = 0;
        java.util.List<int[]> rects = damage.rects();
        for (int[] r : rects) {
          renderer.drawRegion(r);
          fill(fills, fw[0], fh[0], r);
          long u0 = System.nanoTime();
          ui.draw(r);
          uiNanos += System.nanoTime() - u0;
        }
        if (check != null && !swapping) {
          int kept = presenter != null ? 0 : canvas.framebuffer();
          check.beginReference(kept, fw[0], fh[0]);
          renderer.render(snap, camera, fw[0], fh[0]);
          int[] all = {0, 0, fw[0], fh[0]};
          fill(fills, fw[0], fh[0], all);
          ui.draw(all);
          check.endReference(kept, fw[0], fh[0]);
        }
        long t4 = System.nanoTime();
        long t3 = t4 - uiNanos;
        if (swapping) {
          glfwSwapBuffers(window);
          swapFramesLeft--;
          glfwGetFramebufferSize(window, fw, fh);
          if (fw[0] != backW || fh[0] != backH) {
            swapFramesLeft = SWAP_FRAMES_AFTER_RESIZE;
          }
        } else if (presenter != null) {
          if (showAll) {
            showAll = false;
            rects = java.util.List.of(new int[] {0, 0, fw[0], fh[0]});
          }
          for (int[] r : rects) {
            presenter.show(r);
          }
        } else {
          canvas.copyTo(0, new int[] {0, 0, fw[0], fh[0]}, false);
          glfwSwapBuffers(window);
        }
        long t5 = System.nanoTime();
        phaseNanos[0] += t1 - t0;
        phaseNanos[1] += t2 - t1;
        phaseNanos[2] += t3 - t2;
        phaseNanos[3] += t4 - t3;
        phaseNanos[4] += t5 - t4;
        frames++;
        if (frames == 1) {
          firstFrame.run();
        }
        afterFrame.run();
      } else {
        glfwWaitEventsTimeout(0.1);
      }
    }
  }

  /**
   * Makes the window ready to run again after {@link #run} ended on a close request (the next
   * session of a scenario switch or another workspace in the same window); handlers are set anew.
   */
  public SimulatorWindow reopen() {
    glfwSetWindowShouldClose(window, false);
    afterFrame = () -> {};
    firstFrame = () -> {};
    lastInputNanos = System.nanoTime();
    return this;
  }

  /** Wall time spent so far in each part of a frame (ns): simulation and scene, panels, 3D scene, panels' GL, swap. */
  private final long[] phaseNanos = new long[5];

  /** The phase names of {@link #phaseNanos()}. */
  public static final java.util.List<String> PHASES = java.util.List.of("sim", "panels", "scene", "imgui-gl", "swap");

  /** A copy of the wall time spent in each phase of all frames so far (ns), in {@link #PHASES} order (frame log). */
  public long[] phaseNanos() {
    return phaseNanos.clone();
  }

  /** Damages a fill's rectangle (display pixels) in GL pixels. */
  private static void addFill(DamageRegion damage, Fill f, int fbW, int fbH) {
    int[] p = fillPixels(f, fbW, fbH);
    damage.add(p[0], p[1], p[2], p[3]);
  }

  /** A fill's rectangle in GL pixels {x0, y0, x1, y1} (y up). */
  private static int[] fillPixels(Fill f, int fbW, int fbH) {
    float sx = fbW / Math.max(1f, ImGui.getIO().getDisplaySizeX());
    float sy = fbH / Math.max(1f, ImGui.getIO().getDisplaySizeY());
    int x0 = Math.round(f.x() * sx), x1 = Math.round((f.x() + f.w()) * sx);
    int y0 = Math.round(f.y() * sy), y1 = Math.round((f.y() + f.h()) * sy);
    return new int[] {x0, fbH - y1, x1, fbH - y0};
  }

  /** Clears each fill's rectangle, within {@code clip}, to its colour (a clear is nearly free where a blended quad is not). */
  private static void fill(java.util.List<Fill> fills, int fbW, int fbH, int[] clip) {
    if (fills.isEmpty()) {
      return;
    }
    org.lwjgl.opengl.GL11C.glEnable(org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST);
    for (Fill f : fills) {
      int[] r = DamageRegion.intersect(fillPixels(f, fbW, fbH), clip);
      if (r == null) {
        continue;
      }
      org.lwjgl.opengl.GL11C.glScissor(r[0], r[1], r[2] - r[0], r[3] - r[1]);
      org.lwjgl.opengl.GL11C.glClearColor(f.r(), f.g(), f.b(), 1f);
      org.lwjgl.opengl.GL11C.glClear(org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT);
    }
    org.lwjgl.opengl.GL11C.glDisable(org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST);
  }

  /** Runs after every frame is on screen (layout probes, tests). */
  public void setAfterFrameHandler(Runnable handler) {
    afterFrame = handler;
  }

  /** Asks the loop to end after this frame. */
  public void close(boolean unused) {
    glfwSetWindowShouldClose(window, true);
  }

  /**
   * The least size the window may be resized to (window coordinates; {@code {w, h}}). A window
   * already smaller grows to it, as far as the screen allows.
   */
  public void setMinimumSize(int[] size) {
    minimumSize = size.clone();
    glfwSetWindowSizeLimits(window, size[0], size[1], GLFW_DONT_CARE, GLFW_DONT_CARE);
    int[] w = new int[1], h = new int[1];
    glfwGetWindowSize(window, w, h);
    if (w[0] < size[0] || h[0] < size[1]) {
      glfwSetWindowSize(window, Math.max(w[0], size[0]), Math.max(h[0], size[1]));
    }
  }

  public void setTitle(String title) {
    glfwSetWindowTitle(window, title);
  }

  /**
   * Pixels drawn again so far, all frames together (each frame draws only its damaged rectangles;
   * read by a benchmark's timer thread).
   */
  public long damagedPixels() {
    return damagedPixels;
  }

  /** Frames drawn so far. */
  public long frames() {
    return frames;
  }

  /** Runs once, right after the first frame is on screen (start-up timing). */
  public void setFirstFrameHandler(Runnable handler) {
    firstFrame = handler;
  }

  /**
   * The UI scale in window coordinates (1 on an ordinary screen, 2 on a 192 dpi one on Windows or
   * Linux, 1 on a macOS Retina screen whose window coordinates are points; see {@link #uiScale}).
   */
  public float contentScale() {
    return contentScale;
  }

  /** The GLFW window handle (for the layout probe and tests). */
  public long handle() {
    return window;
  }

  /** Keyboard shortcuts of the window (Ctrl+H, Ctrl+Z ...), asked before the pendant. */
  @FunctionalInterface
  public interface ShortcutHandler {
    /** Returns whether the key press was a shortcut and is used up. */
    boolean onShortcut(int glfwKey, int mods);
  }

  public void setShortcutHandler(ShortcutHandler handler) {
    shortcuts = handler;
  }

  /** A left click (press and release without dragging) on the 3D view, in window coordinates. */
  @FunctionalInterface
  public interface ViewClick {
    void click(double x, double y);
  }

  public void setViewClickHandler(ViewClick handler) {
    viewClick = handler;
  }

  /**
   * A left-button drag that starts on something in the 3D view (an axis handle) instead of
   * orbiting the camera.
   */
  public interface ViewPress {
    /** The button went down at (x, y); returns whether this handler takes the drag. */
    boolean press(double x, double y);

    /** The mouse moved while the button is down; returns whether the drag is this handler's. */
    boolean drag(double x, double y);

    void release();
  }

  public void setViewPressHandler(ViewPress handler) {
    viewPress = handler;
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

  /** Runs when the window gets the keyboard focus back (files may have changed meanwhile). */
  public void setFocusGainedHandler(Runnable handler) {
    focusGained = handler;
  }

  /** Asked when the user closes the window; returning false keeps it open. */
  public void setCloseHandler(BooleanSupplier handler) {
    mayClose = handler;
  }

  /**
   * What the window's close button does: asks the close handler ({@link #setCloseHandler}: unsaved
   * work), then ends {@link #run} after the current frame unless it refused.
   */
  public void closeButton() {
    if (mayClose.getAsBoolean()) {
      glfwSetWindowShouldClose(window, true);
    }
  }

  /** Ends {@link #run} after the current frame, without asking the close handler. */
  public void requestClose() {
    glfwSetWindowShouldClose(window, true);
  }

  public OrbitCamera camera() {
    return camera;
  }

  @Override
  public void close() {
    ui.close();
    if (check != null) {
      check.report();
      check.close();
    }
    if (canvas != null) {
      canvas.close();
    }
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
