package org.robotrun.ui;

import static org.lwjgl.glfw.GLFW.*;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiTreeNodeFlags;
import imgui.flag.ImGuiWindowFlags;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.robotrun.collision.Obb;
import org.robotrun.math.Xyzwpr;
import org.robotrun.pendant.Pendant;
import org.robotrun.render.OrbitCamera;
import org.robotrun.sim.DrawItem;
import org.robotrun.sim.SceneSnapshot;
import org.robotrun.world.CellEditor;

/**
 * The window as a student's lab bench: the main menu bar (menus from {@link MenuContributor}s,
 * then View and Help), the left column (task, robot, cell, cell editor), the 3D view and the teach
 * pendant side by side ({@link WindowLayout}), the help windows, picking and moving objects in the
 * 3D view, and the window's keyboard shortcuts. The camera frames the scene in the free middle part.
 */
public final class Workbench implements SimulatorWindow.Panels {
  /** Draws menus into the main menu bar (e.g. the workspace's File menu), left of View and Help. */
  @FunctionalInterface
  public interface MenuContributor {
    void drawMenus();

    /**
     * Draws the contributor's dialogs (modal popups), after every other window of the frame. A
     * modal begun earlier in the frame than a window appearing for the first time trips Dear
     * ImGui 1.86's assertion in Begin (FindBlockingModal skips a modal that was not active the
     * frame before) and ends the application.
     */
    default void drawPopups() {}

    /** Draws the popups, knowing where the window's parts are this frame (the view is above the first-start card). */
    default void drawPopups(WindowLayout layout) {
      drawPopups();
    }

    /**
     * Draws the popups; {@code work} answers where the robots and parts are on the screen (display
     * pixels; empty until the camera has framed the scene), for a window that should open off
     * them. Asking projects the scene: ask only when placing.
     */
    default void drawPopups(WindowLayout layout, Supplier<List<WindowLayout.Rect>> work) {
      drawPopups(layout);
    }

    /**
     * When the contributor's drawing changes by itself next (a note that expires), as
     * {@link System#nanoTime}; {@link Long#MAX_VALUE} for never. The idle window wakes then.
     */
    default long nextRedrawNanos() {
      return Long.MAX_VALUE;
    }
  }

  /** Robot status for the left column. */
  public interface RobotStatus {
    double[] pendantDeg();

    Xyzwpr flangeInWorld();

    /** The robot's model name (e.g. "FANUC CRX-10iA"); empty when unknown. */
    default String modelName() {
      return "";
    }

    /** The joints' names as the model's file gives them (J1..J6 on FANUC arms). */
    default java.util.List<String> jointNames() {
      return java.util.List.of("J1", "J2", "J3", "J4", "J5", "J6");
    }
  }

  private final OrbitCamera camera;
  private final Pendant pendant;
  private Supplier<Pendant> pendantNow;
  private final PendantPanel pendantPanel;
  private final CellPanel cellPanel;
  private final CellEditorPanel editorPanel;
  private final RobotStatus robot;
  private final String task;
  private final Supplier<SceneSnapshot> scene;
  private final float scale;
  private final HelpWindows help = new HelpWindows();
  private final List<MenuContributor> menus = new ArrayList<>();
  private final AxisHandles handles = new AxisHandles();
  private LayoutState state;
  private WindowLayout layout;
  private int framebufferW;
  private int framebufferH;
  private boolean framed;
  private Runnable onLayoutChange = () -> {};
  private int[] minimumSize = new int[0];
  private java.util.function.Consumer<int[]> onMinimumSize = m -> {};

  /** Told the least window size (display pixels, width and height) at which the whole pendant shows, when it changes. */
  public void setMinimumSizeHandler(java.util.function.Consumer<int[]> handler) {
    onMinimumSize = java.util.Objects.requireNonNull(handler, "handler");
  }

  /**
   * @param editorPanel the cell editor, or null when the cell cannot be edited
   * @param task the scenario's description (the exercise)
   */
  public Workbench(OrbitCamera camera, float scale, Pendant pendant, PendantPanel pendantPanel, CellPanel cellPanel,
      CellEditorPanel editorPanel, RobotStatus robot, String task, Supplier<SceneSnapshot> scene, LayoutState state) {
    this.camera = camera;
    this.scale = scale;
    this.pendant = pendant;
    this.pendantPanel = pendantPanel;
    this.pendantNow = () -> pendant;
    this.cellPanel = cellPanel;
    this.editorPanel = editorPanel;
    this.robot = robot;
    this.task = task == null ? "" : task;
    this.scene = scene;
    this.state = state;
    help.showWelcome(!state.welcomeSeen);
  }

  /** The pendant the window drives now (a cell of several robots: the robot selector's choice). */
  public void setPendantSource(Supplier<Pendant> source) {
    pendantNow = java.util.Objects.requireNonNull(source, "source");
  }

  /** A section of the left column drawn by another part of the window (vision), after the robot's; open at first. */
  public void addSection(String title, Runnable drawContents) {
    sections.add(new Section(title, null, false, drawContents));
  }

  /** A section drawn before the robot's (the robot selector: which robot the rest is about). */
  public void addLeadSection(String title, Runnable drawContents) {
    sections.add(new Section(title, null, true, drawContents));
  }

  /** A controller panel, shown after the robot's section when {@link PanelRules} (or the View menu) says so. */
  public void addPanel(PanelRules.Panel panel, Runnable drawContents) {
    sections.add(new Section(panel.title(), panel, false, drawContents));
  }

  /** What the cell uses now, for {@link PanelRules} (asked once a frame). */
  public void setCellUse(Supplier<PanelRules.CellUse> use) {
    cellUse = java.util.Objects.requireNonNull(use, "use");
  }

  private record Section(String title, PanelRules.Panel panel, boolean lead, Runnable drawContents) {}

  private final List<Section> sections = new ArrayList<>();
  private final java.util.Map<String, Boolean> sectionOpen = new java.util.HashMap<>();
  private Supplier<PanelRules.CellUse> cellUse = () -> PanelRules.CellUse.FREE_PLAY;
  private PanelRules.CellUse use = PanelRules.CellUse.FREE_PLAY;

  /** Whether the left column shows {@code s} this frame. */
  private boolean shown(Section s) {
    return s.panel() == null || PanelRules.shown(s.panel(), use, state.panels);
  }

  /** Adds menus drawn in the main menu bar before View and Help (the File menu goes first). */
  public void addMenus(MenuContributor contributor) {
    menus.add(contributor);
  }

  public LayoutState layoutState() {
    return state;
  }

  /** Switches to another layout (a workspace opened with its own). */
  public void setLayoutState(LayoutState s) {
    state = s;
  }

  /** Runs when the student changes the layout (to save it). */
  public void setLayoutChangeHandler(Runnable r) {
    onLayoutChange = r;
  }

  /** The layout of the last frame (display pixels); null before the first frame. */
  public WindowLayout layout() {
    return layout;
  }

  public HelpWindows help() {
    return help;
  }

  public PendantPanel pendantPanel() {
    return pendantPanel;
  }

  public CellEditorPanel editorPanel() {
    return editorPanel;
  }

  // ---- input ---------------------------------------------------------------------------------

  /** The window's shortcuts: Ctrl+H key map, Ctrl+Z / Ctrl+Y (Ctrl+Shift+Z) undo / redo of cell edits. */
  public boolean onShortcut(int key, int mods) {
    boolean ctrl = (mods & (GLFW_MOD_CONTROL | GLFW_MOD_SUPER)) != 0;
    if (!ctrl) {
      return false;
    }
    if (key == GLFW_KEY_H) {
      help.toggleKeyMap();
      return true;
    }
    if (editorPanel != null && key == GLFW_KEY_Z) {
      if ((mods & GLFW_MOD_SHIFT) != 0) {
        editorPanel.redo();
      } else {
        editorPanel.undo();
      }
      return true;
    }
    if (editorPanel != null && key == GLFW_KEY_Y) {
      editorPanel.redo();
      return true;
    }
    return false;
  }

  /** '?' toggles the key map when no pendant entry takes text. */
  public boolean onChar(int codepoint) {
    if (codepoint == '?' && !pendantNow.get().entryOpen()) {
      help.toggleKeyMap();
      return true;
    }
    return false;
  }

  /** A click in the 3D view (window coordinates): selects the object under it (a ray against its box). */
  public void onViewClick(double x, double y) {
    if (editorPanel == null || layout == null || !layout.view().contains((float) x, (float) y)) {
      return;
    }
    float[] ray = ray(x, y);
    String best = "";
    double bestT = Double.POSITIVE_INFINITY;
    var world = editorPanel.editor().world();
    for (var o : world.objects()) {
      Obb b = world.collisionBox(o.name());
      double t = b.rayHit(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5]);
      if (!Double.isNaN(t) && t < bestT) {
        bestT = t;
        best = o.name();
      }
    }
    editorPanel.select(best);
    if (!best.isEmpty()) {
      state.editorOpen = true;
      showSidebar();
    }
  }

  /** The axis handles of the selected object take a drag that starts on them. */
  public SimulatorWindow.ViewPress viewPress() {
    return new SimulatorWindow.ViewPress() {
      @Override
      public boolean press(double x, double y) {
        return editorPanel != null && handles.press(x, y);
      }

      @Override
      public boolean drag(double x, double y) {
        return handles.drag(x, y);
      }

      @Override
      public void release() {
        handles.release().ifPresent(m -> editorPanel.report(editorPanel.editor().nudge(m.object(), m.axis(), m.mm())));
      }
    };
  }

  /** Ray through a window point: origin and direction in the cell frame (mm). */
  private float[] ray(double x, double y) {
    float fbx = framebufferW / Math.max(1f, ImGui.getIO().getDisplaySizeX());
    float fby = framebufferH / Math.max(1f, ImGui.getIO().getDisplaySizeY());
    float nx = (float) (2 * x * fbx / framebufferW - 1), ny = (float) (1 - 2 * y * fby / framebufferH);
    Matrix4f inv = camera.viewProjection(framebufferW, framebufferH).invert();
    Vector4f near = new Vector4f(nx, ny, -1, 1).mul(inv);
    Vector4f far = new Vector4f(nx, ny, 1, 1).mul(inv);
    near.div(near.w);
    far.div(far.w);
    return new float[] {near.x, near.y, near.z, far.x - near.x, far.y - near.y, far.z - near.z};
  }

  private void showSidebar() {
    if (layout != null && !layout.sidebar().visible()) {
      state.sidebarVisible = true;
    }
  }

  // ---- drawing ---------------------------------------------------------------------------------

  @Override
  public void draw(int framebufferWidth, int framebufferHeight) {
    framebufferW = framebufferWidth;
    framebufferH = framebufferHeight;
    float dw = ImGui.getIO().getDisplaySizeX(), dh = ImGui.getIO().getDisplaySizeY();
    use = cellUse.get();
    float menuH = drawMenuBar();
    layout = WindowLayout.compute(dw, dh, menuH, scale, PendantPanel.naturalWidth(), state);
    int[] min = WindowLayout.minimumSize(menuH, PendantPanel.naturalWidth(), PendantPanel.minimumHeight());
    if (!Arrays.equals(min, minimumSize)) {
      // the window may not shrink below what the pendant's keys need (the style is known from the first frame)
      minimumSize = min;
      onMinimumSize.accept(min);
    }
    // the first-start card is docked along the bottom of the 3D view: the scene is framed above it
    WindowLayout.Rect fullView = layout.view();
    float card = help.welcomeDock(fullView);
    if (card > 0) {
      layout = new WindowLayout(layout.menuBar(), layout.sidebar(),
          new WindowLayout.Rect(fullView.x(), fullView.y(), fullView.w(), fullView.h() - card), layout.pendant());
    }
    frameScene(dw, dh);
    drawSidebar(layout.sidebar());
    drawDrivenRobotLabel();
    pendantPanel.draw(layout.pendant());
    float w = pendantPanel.takeUserWidth();
    if (w > 0) {
      state.pendantWidth = w / scale;
      onLayoutChange.run();
    }
    if (editorPanel != null) {
      handles.draw(camera, framebufferW, framebufferH, dw, dh, editorPanel.editor(), editorPanel.selected(), layout.view());
    }
    drawPromptStrip();
    help.drawWelcome(fullView, layout.sidebar().visible() && state.taskOpen ? "" : task);
    help.draw(layout.view());
    if (!help.welcomeOpen() && !state.welcomeSeen) {
      state.welcomeSeen = true;
      onLayoutChange.run();
    }
    for (MenuContributor m : menus) {
      m.drawPopups(layout, this::workOnScreen);
    }
  }

  /**
   * The screen rectangles (display pixels) of each robot (all its items together) and of each
   * part or fixture that is not the room itself (one covering more than a quarter of the view,
   * the table or the floor); empty before the camera has framed the scene.
   */
  private List<WindowLayout.Rect> workOnScreen() {
    SceneSnapshot sc = lastScene != null ? lastScene : scene.get();
    WindowLayout.Rect v = layout.view();
    if (!framed || sc == null || !v.visible() || framebufferW <= 0 || framebufferH <= 0) {
      return List.of();
    }
    float dw = ImGui.getIO().getDisplaySizeX(), dh = ImGui.getIO().getDisplaySizeY();
    Matrix4f vp = camera.viewProjection(framebufferW, framebufferH);
    java.util.Map<String, float[]> boxes = new java.util.LinkedHashMap<>();
    java.util.Set<String> robots = new java.util.HashSet<>();
    List<Vector3f> pts = new ArrayList<>();
    for (DrawItem it : sc.items()) {
      if (it.name().equals(DrivenRobotMark.RING_NAME)) {
        continue;
      }
      int slash = it.name().indexOf('/');
      String key = slash > 0 ? it.name().substring(0, slash) : it.name();  // a robot's links together
      if (slash > 0) {
        robots.add(key);
      }
      pts.clear();
      SceneBounds.addCorners(it, pts);
      for (Vector3f p : pts) {
        float[] sp = project(vp, p.x, p.y, p.z, dw, dh);
        if (sp != null) {
          float[] b = boxes.computeIfAbsent(key, k -> new float[] {Float.MAX_VALUE, Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE});
          b[0] = Math.min(b[0], sp[0]);
          b[1] = Math.min(b[1], sp[1]);
          b[2] = Math.max(b[2], sp[0]);
          b[3] = Math.max(b[3], sp[1]);
        }
      }
    }
    List<WindowLayout.Rect> out = new ArrayList<>();
    for (var e : boxes.entrySet()) {
      float[] b = e.getValue();
      WindowLayout.Rect r = new WindowLayout.Rect(b[0], b[1], b[2] - b[0], b[3] - b[1]);
      if (robots.contains(e.getKey()) || r.w() * r.h() <= DrivenRobotMark.ROOM_FRACTION * v.w() * v.h()) {
        out.add(r);
      }
    }
    return out;
  }

  /**
   * When something the panels draw changes by itself next ({@link System#nanoTime}): the 3D
   * view's message strip or a menu's note expiring; {@link Long#MAX_VALUE} for nothing. The idle
   * window sleeps until then.
   */
  public long nextRedrawNanos() {
    long next = editorPanel == null ? Long.MAX_VALUE : editorPanel.stripExpiresNanos();
    for (MenuContributor m : menus) {
      next = Math.min(next, m.nextRedrawNanos());
    }
    return next;
  }

  @Override
  public List<SimulatorWindow.Fill> fills() {
    if (layout == null) {
      return List.of();
    }
    // the docked columns' backgrounds: WindowBg made opaque (the two columns never overlap the scene)
    var bg = ImGui.getStyle().getColor(imgui.flag.ImGuiCol.WindowBg);
    List<SimulatorWindow.Fill> out = new ArrayList<>(3);
    for (WindowLayout.Rect r : List.of(layout.sidebar(), layout.pendant())) {
      if (r.visible()) {
        out.add(new SimulatorWindow.Fill(r.x(), r.y(), r.w(), r.h(), bg.x, bg.y, bg.z));
      }
    }
    if (pendantPanel.lcdFill() != null) {
      out.add(pendantPanel.lcdFill());
    }
    return out;
  }

  private SceneSnapshot lastScene;

  /**
   * The frame's scene as the 3D view draws it: in a cell of several robots, the robot the pendant
   * drives tinted ({@link DrivenRobotMark}); its name label is drawn with the panels.
   */
  public SceneSnapshot marked(SceneSnapshot frameScene) {
    String driven = pendantNow.get().robotLabel();  // set only in a cell of several robots
    lastScene = frameScene;
    return DrivenRobotMark.tinted(frameScene, driven, driven.isEmpty() ? 1 : 2);
  }

  /** The driven robot's name beside its base in the 3D view, off the work (a cell of several robots only). */
  private void drawDrivenRobotLabel() {
    String driven = pendantNow.get().robotLabel();
    WindowLayout.Rect v = layout.view();
    if (driven.isEmpty() || lastScene == null || !v.visible() || framebufferW <= 0 || framebufferH <= 0) {
      return;
    }
    float dw = ImGui.getIO().getDisplaySizeX(), dh = ImGui.getIO().getDisplaySizeY();
    Matrix4f vp = camera.viewProjection(framebufferW, framebufferH);
    String prefix = driven + "/";
    float[] base = null;
    List<LabelLayout.Box> work = new ArrayList<>();
    List<Vector3f> pts = new ArrayList<>();
    for (DrawItem it : lastScene.items()) {
      if (it.name().startsWith(prefix)) {
        if (base == null) {
          // the first item of a robot is its base link
          base = project(vp, (float) it.X_WS().x(), (float) it.X_WS().y(), (float) it.X_WS().z(), dw, dh);
        }
        continue;
      }
      if (it.name().equals(DrivenRobotMark.RING_NAME)) {
        continue;  // the mark's own disc
      }
      pts.clear();
      SceneBounds.addCorners(it, pts);
      float x0 = Float.MAX_VALUE, y0 = Float.MAX_VALUE, x1 = -Float.MAX_VALUE, y1 = -Float.MAX_VALUE;
      boolean behind = false;
      for (Vector3f p : pts) {
        float[] sp = project(vp, p.x, p.y, p.z, dw, dh);
        if (sp == null) {
          behind = true;
          break;
        }
        x0 = Math.min(x0, sp[0]);
        y0 = Math.min(y0, sp[1]);
        x1 = Math.max(x1, sp[0]);
        y1 = Math.max(y1, sp[1]);
      }
      if (!behind && !pts.isEmpty()) {
        work.add(new LabelLayout.Box(x0 - v.x(), y0 - v.y(), x1 - x0, y1 - y0));
      }
    }
    if (base == null) {
      return;
    }
    float pad = 3;
    float tw = ImGui.calcTextSize(driven).x + 2 * pad, th = ImGui.getTextLineHeight() + 2 * pad;
    var place = DrivenRobotMark.labelPlace(base[0] - v.x(), base[1] - v.y(), tw, th, v.w(), v.h(), work);
    if (place.isEmpty()) {
      return;
    }
    LabelLayout.Box b = place.get().box();
    float bx = v.x() + (float) b.x(), by = v.y() + (float) b.y();
    int amber = ImGui.colorConvertFloat4ToU32(DrivenRobotMark.R, DrivenRobotMark.G, DrivenRobotMark.B, 1f);
    imgui.ImDrawList dl = ImGui.getBackgroundDrawList();
    dl.pushClipRect(v.x(), v.y(), v.right(), v.bottom());
    if (place.get().leader()) {
      double[] end = b.nearestPoint(base[0] - v.x(), base[1] - v.y());
      dl.addLine(base[0], base[1], v.x() + (float) end[0], v.y() + (float) end[1], amber, 2f);
    }
    dl.addCircleFilled(base[0], base[1], 3, amber);
    dl.addRectFilled(bx, by, bx + tw, by + th, amber, 3f);
    dl.addText(bx + pad, by + pad, ImGui.colorConvertFloat4ToU32(0.05f, 0.05f, 0.05f, 1f), driven);
    dl.popClipRect();
  }

  /** A cell point on the display (pixels), or null behind the camera. */
  private static float[] project(Matrix4f vp, float x, float y, float z, float dw, float dh) {
    Vector4f c = new Vector4f(x, y, z, 1).mul(vp);
    if (c.w <= 0) {
      return null;
    }
    return new float[] {(c.x / c.w * 0.5f + 0.5f) * dw, (0.5f - c.y / c.w * 0.5f) * dh};
  }

  /** Frames the scene in the free middle part; at the first frame, backs off until it all fits. */
  private void frameScene(float dw, float dh) {
    WindowLayout.Rect v = layout.view();
    float sx = framebufferW / Math.max(1f, dw), sy = framebufferH / Math.max(1f, dh);
    int x = Math.round(v.x() * sx), w = Math.round(v.w() * sx);
    int h = Math.round(v.h() * sy), y = framebufferH - Math.round(v.bottom() * sy);
    camera.setViewRect(x, y, w, h);
    if (!framed && w > 0 && h > 0 && help.welcomeMeasured()) {
      framed = true;
      List<Vector3f> pts = new ArrayList<>();
      for (DrawItem it : scene.get().items()) {
        SceneBounds.addCorners(it, pts);
      }
      float before = camera.distance();
      camera.fitDistance(pts, w / (float) h, 0.08f);
      if (camera.distance() < before) {
        // keep the scenario's own (wider) view when everything already fits
        camera.set(camera.target().x, camera.target().y, camera.target().z, before, camera.yaw(), camera.pitch());
      }
    }
  }

  /** Draws the main menu bar; returns its height. */
  private float drawMenuBar() {
    float h = 0;
    if (ImGui.beginMainMenuBar()) {
      h = ImGui.getWindowHeight();
      for (MenuContributor m : menus) {
        m.drawMenus();
      }
      if (ImGui.beginMenu("View")) {
        boolean sidebar = layout != null && layout.sidebar().visible();
        if (ImGui.menuItem("Side panel (task, robot, cell, editor)", "", sidebar)) {
          state.sidebarVisible = !sidebar;
          onLayoutChange.run();
        }
        if (ImGui.menuItem("Teach pendant", "", state.pendantVisible)) {
          state.pendantVisible = !state.pendantVisible;
          onLayoutChange.run();
        }
        ImGui.separator();
        if (ImGui.menuItem("Task", "", state.taskOpen)) {
          state.taskOpen = !state.taskOpen;
          showSidebar();
        }
        if (ImGui.menuItem("Robot", "", state.robotOpen)) {
          state.robotOpen = !state.robotOpen;
          showSidebar();
        }
        if (ImGui.menuItem("Cell", "", state.cellOpen)) {
          state.cellOpen = !state.cellOpen;
          showSidebar();
        }
        if (editorPanel != null && ImGui.menuItem("Cell editor", "", state.editorOpen)) {
          state.editorOpen = !state.editorOpen;
          showSidebar();
        }
        // the controller's panels: shown when the cell uses them, or as the student chose here
        boolean first = true;
        for (Section sec : sections) {
          if (sec.panel() == null) {
            continue;
          }
          if (first) {
            ImGui.separator();
            first = false;
          }
          boolean on = shown(sec);
          if (ImGui.menuItem(sec.title(), "", on)) {
            state.panels.put(sec.panel().key(), !on);
            if (!on) {
              sectionOpen.put(sec.title(), true);
              showSidebar();
            }
            onLayoutChange.run();
          }
        }
        ImGui.separator();
        if (ImGui.menuItem("Reset view", "Home")) {
          camera.reset();
          framed = false;
        }
        if (ImGui.menuItem("Reset layout")) {
          state.reset();
          onLayoutChange.run();
        }
        ImGui.endMenu();
      }
      if (ImGui.beginMenu("Help")) {
        help.menuItems();
        ImGui.endMenu();
      }
      ImGui.endMainMenuBar();
    }
    return h;
  }

  private void drawSidebar(WindowLayout.Rect r) {
    if (!r.visible()) {
      return;
    }
    ImGui.setNextWindowPos(r.x(), r.y(), ImGuiCond.Always);
    ImGui.setNextWindowSize(r.w(), r.h(), ImGuiCond.Always);
    ImGui.pushStyleColor(imgui.flag.ImGuiCol.WindowBg, 0f, 0f, 0f, 0f);  // a clear underneath (fills)
    boolean shown = ImGui.begin("##sidebar", ImGuiWindowFlags.NoTitleBar | ImGuiWindowFlags.NoMove
        | ImGuiWindowFlags.NoCollapse | ImGuiWindowFlags.NoBringToFrontOnFocus);
    ImGui.popStyleColor();
    if (shown) {
      if (Math.abs(ImGui.getWindowWidth() - r.w()) > 0.5f) {
        state.sidebarWidth = ImGui.getWindowWidth() / scale;
        onLayoutChange.run();
      }
      state.taskOpen = section("Task", state.taskOpen);
      if (state.taskOpen) {
        Txt.wrapped(task.isBlank() ? "No task: this cell is free play. Help > First steps shows how to start." : task);
      }
      drawSections(true);
      // the robot's position comes before the controller's panels
      state.robotOpen = section("Robot", state.robotOpen);
      if (state.robotOpen) {
        RobotStatusPanel.drawContents(robot.modelName(), robot.jointNames(), robot.pendantDeg(), robot.flangeInWorld());
      }
      drawSections(false);
      state.cellOpen = section("Cell", state.cellOpen);
      if (state.cellOpen) {
        cellPanel.drawContents();
      }
      if (editorPanel != null) {
        state.editorOpen = section("Cell editor", state.editorOpen);
        if (state.editorOpen) {
          editorPanel.drawContents();
        }
      } else {
        Txt.disabled("Open a scenario to edit its cell:\n  robotrun --scenario FILE.json");
      }
    }
    ImGui.end();
  }

  private void drawSections(boolean lead) {
    for (Section extra : sections) {
      if (extra.lead() != lead || !shown(extra)) {
        continue;
      }
      boolean open = section(extra.title(), sectionOpen.getOrDefault(extra.title(), true));
      sectionOpen.put(extra.title(), open);
      if (open) {
        extra.drawContents().run();
      }
    }
  }

  private static boolean section(String title, boolean open) {
    ImGui.setNextItemOpen(open, ImGuiCond.Always);
    return ImGui.collapsingHeader(title, ImGuiTreeNodeFlags.None);
  }

  /** The cell editor's last message along the bottom of the 3D view, where the student looks, while it applies. */
  private void drawPromptStrip() {
    java.util.Optional<String> shown = editorPanel == null ? java.util.Optional.empty() : editorPanel.stripMessage();
    if (shown.isEmpty()) {
      return;
    }
    WindowLayout.Rect v = layout.view();
    // centred along the bottom: the axis triad keeps the lower left corner
    ImGui.setNextWindowPos(v.x() + v.w() / 2, v.bottom() - 8, ImGuiCond.Always, 0.5f, 1f);
    ImGui.setNextWindowBgAlpha(0.85f);
    ImGui.setNextWindowSizeConstraints(0, 0, Math.max(100, v.w() - 16), ImGui.getFontSize() * 15);
    if (ImGui.begin("##editmsg", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize
        | ImGuiWindowFlags.NoFocusOnAppearing | ImGuiWindowFlags.NoNav | ImGuiWindowFlags.NoInputs)) {
      if (editorPanel.messageIsError()) {
        Txt.colored(1f, 0.55f, 0.45f, 1f, shown.get());
      } else {
        Txt.colored(0.55f, 0.9f, 0.55f, 1f, shown.get());
      }
    }
    ImGui.end();
  }

  /** Joint-value summary for idle detection. */
  static boolean same(double[] a, double[] b) {
    return Arrays.equals(a, b);
  }
}
