package org.robotrun.ui;

import imgui.ImDrawList;
import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.type.ImInt;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.robotrun.math.Transform;
import org.robotrun.render.CameraImage;
import org.robotrun.render.VisionCameraView;
import org.robotrun.sim.Simulation;
import org.robotrun.sim.VisionSystem;
import org.robotrun.world.VisionSetup;

/**
 * Vision in the window (issue 16): the "Vision" menu opens a camera view per vision camera (what the
 * camera sees, rendered from its pose, the parts found by the last RUN_FIND outlined with their
 * found poses written beside them), and the side panel's "Vision" section resets the cell with a
 * new placement seed. Acts on the simulation on the GUI thread, as the other panels do.
 */
public final class VisionPanel implements Workbench.MenuContributor, AutoCloseable {
  /** Title of the side panel section. */
  public static final String TITLE = "Vision";

  private final Simulation sim;
  private final Map<String, CameraImage> open = new LinkedHashMap<>();
  private final ImInt seed = new ImInt();
  private String message = "";

  /** The scene of this frame (the window's own snapshot, so a camera view does not build a second one). */
  private final java.util.function.Supplier<org.robotrun.sim.SceneSnapshot> scene;

  public VisionPanel(Simulation sim) {
    this(sim, () -> sim.snapshot().scene());
  }

  /** A panel whose camera views draw {@code scene}: the snapshot the window took for this frame. */
  public VisionPanel(Simulation sim, java.util.function.Supplier<org.robotrun.sim.SceneSnapshot> scene) {
    this.sim = sim;
    this.scene = scene;
    seed.set((int) system().setup().seed());
  }

  private VisionSystem system() {
    return sim.vision().orElseThrow();
  }

  @Override
  public void drawMenus() {
    if (ImGui.beginMenu(TITLE)) {
      for (VisionSetup.Camera c : system().setup().cameras()) {
        if (ImGui.menuItem("Camera view: " + c.name(), "", open.containsKey(c.name()))) {
          toggle(c.name());
        }
      }
      ImGui.separator();
      if (ImGui.menuItem("Reset with a new seed")) {
        reseed(system().setup().seed() + 1);
      }
      ImGui.endMenu();
    }
  }

  private void toggle(String camera) {
    CameraImage img = open.remove(camera);
    if (img != null) {
      img.close();
    } else {
      open.put(camera, new CameraImage());
    }
  }

  /** Parts placed anew from {@code s}, vision results and VR[] cleared. */
  void reseed(long s) {
    VisionSystem.reseed(sim, system().setup(), s);
    seed.set((int) s);
    message = "seed " + s + ": parts placed anew, vision registers cleared";
  }

  /** The side panel's section: the seed, Reset with it, and what each process found last. */
  public void drawContents() {
    VisionSetup setup = system().setup();
    ImGui.setNextItemWidth(Math.max(80, ImGui.getContentRegionAvailX() - ImGui.calcTextSize("seed").x - 12));
    ImGui.inputInt("seed", seed);
    if (ImGui.button("Reset with seed")) {
      reseed(seed.get());
    }
    if (ImGui.isItemHovered()) {
      Txt.tooltip("Put the parts at the places this seed gives and clear the vision registers; the same seed "
          + "gives the same places (robotrun run --seed N)");
    }
    ImGui.sameLine();
    if (ImGui.button("New seed")) {
      reseed(setup.seed() + 1);
    }
    for (VisionSetup.Process p : setup.processes()) {
      List<VisionSystem.Detection> found = system().lastFound(p.name());
      Txt.wrapped(p.name() + " (" + p.type().text() + ", " + p.camera() + "): " + found.size()
          + " found by the last RUN_FIND");
    }
    for (VisionSetup.Camera c : setup.cameras()) {
      if (ImGui.button("Camera view " + c.name())) {
        toggle(c.name());
      }
    }
    if (!message.isEmpty()) {
      Txt.wrapped(message);
    }
  }

  @Override
  public void drawPopups() {
    for (String name : List.copyOf(open.keySet())) {
      VisionSetup.Camera cam = system().setup().camera(name).orElse(null);
      if (cam == null) {
        open.remove(name).close();
        continue;
      }
      drawCameraWindow(cam, open.get(name));
    }
  }

  private void drawCameraWindow(VisionSetup.Camera cam, CameraImage img) {
    float aspect = cam.widthPx() / (float) cam.heightPx();
    // First opened over the 3D view's upper left, at most a third of the window wide.
    float dw = ImGui.getIO().getDisplaySizeX();
    float ww = Math.min(520, Math.max(240, dw * 0.34f));
    ImGui.setNextWindowSize(ww, ww / aspect + 70, ImGuiCond.FirstUseEver);
    ImGui.setNextWindowPos(dw * 0.22f, 60, ImGuiCond.FirstUseEver);
    imgui.type.ImBoolean keep = new imgui.type.ImBoolean(true);
    if (ImGui.begin("Camera " + cam.name() + "##vision", keep)) {
      float availW = Math.max(32, ImGui.getContentRegionAvailX());
      float availH = Math.max(24, ImGui.getContentRegionAvailY() - ImGui.getFrameHeightWithSpacing());
      float w = Math.min(availW, availH * aspect);
      float h = w / aspect;
      // Rendered at the shown size (at most the camera's): a pixel of the camera maps to w / width of the screen.
      int rw = Math.max(16, Math.min(cam.widthPx(), Math.round(w)));
      int rh = Math.max(16, Math.round(rw / aspect));
      Transform X_CK = system().cameraPose(cam);
      int tex = img.render(system().withOutlines(scene.get(), cam.name()),
          VisionCameraView.viewProjection(cam, X_CK), VisionCameraView.eye(X_CK), rw, rh);
      float x0 = ImGui.getCursorScreenPosX();
      float y0 = ImGui.getCursorScreenPosY();
      ImGui.image(tex, w, h, 0, 1, 1, 0);
      overlay(ImGui.getWindowDrawList(), cam, x0, y0, w / cam.widthPx());
      List<VisionSystem.Detection> found = system().lastFoundBy(cam.name());
      for (VisionSetup.Process p : system().setup().processes()) {
        if (p.camera().equals(cam.name())) {
          if (ImGui.smallButton("RUN_FIND " + p.name())) {
            // As the program's VISION RUN_FIND would (for the first robot): draws from the same seeded noise.
            system().runFind(sim.controllers().get(0), p.name());
          }
          ImGui.sameLine();
        }
      }
      Txt.disabled(String.format(Locale.ROOT, "%d found   frame %.1f ms", found.size(), img.lastFrameNs() / 1e6));
      for (String t : unplaced) {
        Txt.colored(0.1f, 1f, 0.25f, 1f, t);
      }
    }
    ImGui.end();
    if (!keep.get()) {
      toggle(cam.name());
    }
  }

  /** The search window, and each found part's outline and found pose, in image pixels scaled by {@code s}. */
  private void overlay(ImDrawList dl, VisionSetup.Camera cam, float x0, float y0, float s) {
    int windowColour = ImGui.colorConvertFloat4ToU32(1f, 0.85f, 0.2f, 0.9f);
    int foundColour = ImGui.colorConvertFloat4ToU32(0.1f, 1f, 0.25f, 1f);
    int textBg = ImGui.colorConvertFloat4ToU32(0f, 0f, 0f, 0.6f);
    VisionSetup.Window win = cam.window();
    dl.addRect(x0 + (float) win.left() * s, y0 + (float) win.top() * s, x0 + (float) win.right() * s,
        y0 + (float) win.bottom() * s, windowColour, 0, 0, 1.5f);
    List<VisionSystem.Label> labels = system().labels(cam);
    float pad = 2;
    List<LabelLayout.Label> boxes = new java.util.ArrayList<>(labels.size());
    for (VisionSystem.Label l : labels) {
      double[] o = l.outline();
      for (int c = 0; c < 4; c++) {
        int d = (c + 1) % 4;
        dl.addLine(x0 + (float) o[2 * c] * s, y0 + (float) o[2 * c + 1] * s, x0 + (float) o[2 * d] * s,
            y0 + (float) o[2 * d + 1] * s, foundColour, 2f);
      }
      dl.addCircleFilled(x0 + (float) l.u() * s, y0 + (float) l.v() * s, 3, foundColour);
      double u0 = Double.MAX_VALUE, v0 = Double.MAX_VALUE, u1 = -Double.MAX_VALUE, v1 = -Double.MAX_VALUE;
      for (int c = 0; c < 4; c++) {
        u0 = Math.min(u0, o[2 * c] * s);
        v0 = Math.min(v0, o[2 * c + 1] * s);
        u1 = Math.max(u1, o[2 * c] * s);
        v1 = Math.max(v1, o[2 * c + 1] * s);
      }
      // the part's outline: its label goes beside it, on no part, where there is room
      boxes.add(new LabelLayout.Label(l.u() * s, l.v() * s, ImGui.calcTextSize(l.text()).x + 2 * pad,
          ImGui.getTextLineHeight() + 2 * pad, new LabelLayout.Box(u0, v0, u1 - u0, v1 - v0)));
    }
    // no label over another or off the image; one moved away from its part gets a leader line
    List<java.util.Optional<LabelLayout.Placed>> placed = LabelLayout.place(boxes, cam.widthPx() * s, cam.heightPx() * s,
        List.of());
    unplaced.clear();
    for (int i = 0; i < labels.size(); i++) {
      VisionSystem.Label l = labels.get(i);
      if (placed.get(i).isEmpty()) {
        unplaced.add(l.text());
        continue;
      }
      LabelLayout.Box b = placed.get(i).get().box();
      if (placed.get(i).get().leader()) {
        double[] end = b.nearestPoint(l.u() * s, l.v() * s);
        dl.addLine(x0 + (float) l.u() * s, y0 + (float) l.v() * s, x0 + (float) end[0], y0 + (float) end[1], foundColour, 1f);
      }
      dl.addRectFilled(x0 + (float) b.x(), y0 + (float) b.y(), x0 + (float) b.right(), y0 + (float) b.bottom(), textBg);
      dl.addText(x0 + (float) b.x() + pad, y0 + (float) b.y() + pad, foundColour, l.text());
    }
  }

  /** Found parts whose label found no room on the image this frame: listed under it. */
  private final List<String> unplaced = new java.util.ArrayList<>();

  @Override
  public void close() {
    open.values().forEach(CameraImage::close);
    open.clear();
  }
}
