package org.robotrun.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.FloatBuffer;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.lwjgl.system.MemoryStack;
import org.robotrun.math.Transform;
import org.robotrun.sim.DrawItem;
import org.robotrun.sim.DrawShape;
import org.robotrun.sim.SceneSnapshot;

/**
 * Draws a {@link SceneSnapshot} with OpenGL 3.3 core: the floor grid, the world axes, every
 * draw item and an orientation triad in the corner, then smooths the edges (see
 * {@link AntiAliasing}). Meshes are built once per distinct shape and kept (the small scene
 * graph: shape → GPU mesh, item → model matrix and colour). Needs a current GL context on the
 * calling thread.
 */
public final class SceneRenderer implements AutoCloseable {
  private static final float[] BACKGROUND = {0.80f, 0.83f, 0.87f};
  private static final float AXIS_LENGTH = 400f;
  private static final float AXIS_THICK = 10f;

  private final ShaderProgram solid;
  private final ShaderProgram floor;
  private final GpuMesh floorQuad;
  private final GpuMesh axisBar;
  private final Map<DrawShape, GpuMesh> meshes = new HashMap<>();
  private final float[] model = new float[16];
  private final Matrix4f viewProj = new Matrix4f();
  private final Matrix4f modelMatrix = new Matrix4f();
  private final ScreenRect edges = new ScreenRect();
  private final ScreenRect gizmoEdges = new ScreenRect();
  private final OrientationGizmo gizmo = new OrientationGizmo();
  private final AntiAliasing antiAliasing;
  private final FxaaPass fxaa;

  /** A renderer with the default edge smoothing ({@link AntiAliasing#DEFAULT}). */
  public SceneRenderer() {
    this(AntiAliasing.DEFAULT);
  }

  /**
   * A renderer with the given edge smoothing. For {@link AntiAliasing#MSAA4} the caller's
   * framebuffer must be multisampled; this class only does the FXAA post pass itself.
   */
  public SceneRenderer(AntiAliasing antiAliasing) {
    this.antiAliasing = antiAliasing;
    fxaa = new FxaaPass();
    solid = ShaderProgram.load("solid");
    floor = ShaderProgram.load("floor");
    floorQuad = GpuMesh.upload(new MeshData(
        new float[] {
          -20000, -20000, 0, 0, 0, 1,
          20000, -20000, 0, 0, 0, 1,
          20000, 20000, 0, 0, 0, 1,
          -20000, 20000, 0, 0, 0, 1
        },
        new int[] {0, 1, 2, 0, 2, 3}));
    axisBar = GpuMesh.upload(MeshFactory.box(1, 1, 1, 0));
  }

  /** Renders into the currently bound framebuffer of the given size (pixels). */
  public void render(SceneSnapshot scene, OrbitCamera camera, int width, int height) {
    draw(scene, camera.viewProjection(width, height), camera.eye(), camera.viewRect(width, height), width, height);
    gizmo.draw(solid, axisBar, camera, width, height, gizmoEdges);
    if (antiAliasing == AntiAliasing.FXAA) {
      // Two rectangles, not their union: the corner and the robot are usually far apart.
      fxaa.apply(edges, width, height);
      fxaa.apply(gizmoEdges, width, height);
    }
  }

  /**
   * Renders the scene as seen through any camera (a vision camera): {@code viewProj} maps the cell
   * (mm) to clip space, {@code eye} is the camera's position; the whole framebuffer, no orientation
   * triad.
   */
  public void render(SceneSnapshot scene, Matrix4f viewProj, Vector3f eye, int width, int height) {
    draw(scene, viewProj, eye, new int[] {0, 0, width, height}, width, height);
    if (antiAliasing == AntiAliasing.FXAA) {
      fxaa.apply(edges, width, height);
    }
  }

  // ---- The window's retained drawing: a layer of what stands still, the moving items over it ----

  private OffscreenTarget layer;
  /** Where the moving items are drawn over a copy of the layer (the same formats as the layer). */
  private OffscreenTarget work;
  private final StillLayer still = new StillLayer();
  private boolean[] inLayer = new boolean[0];
  /** The view's rectangle {x, y, w, h} when the layer was last drawn; null before. */
  private int[] layerView;
  /** Where the items left out of the layer were last drawn, {x0, y0, x1, y1}; null: nowhere. */
  private int[] lastMovingRect;
  private final ScreenRect movingEdges = new ScreenRect();
  private SceneSnapshot frameScene;
  private OrbitCamera frameCamera;
  private int frameW;
  private int frameH;
  private int[] frameView;
  private final Vector3f frameEye = new Vector3f();
  private int layerBuilds;

  /**
   * The window's frame, first step: compares the scene and camera with the last frame's and adds
   * to {@code damage} where the picture changed. The part of the scene that stands still is kept in
   * a layer (colour and depth) drawn again only when the view or one of its items changes; an item
   * that moves is left out of it and drawn over it each time, so while the arm moves only its own
   * rectangle (this frame's and the last) is damaged ({@link StillLayer} decides). Then
   * {@link #drawRegion} draws each damaged rectangle into the bound framebuffer (the window's own
   * or another with a depth buffer).
   */
  public void prepareRetained(SceneSnapshot scene, OrbitCamera camera, int width, int height, DamageRegion damage) {
    List<DrawItem> items = scene.items();
    Matrix4f vp = camera.viewProjection(width, height);
    int[] view = camera.viewRect(width, height);
    frameScene = scene;
    frameCamera = camera;
    frameW = width;
    frameH = height;
    detailW = width;
    detailH = height;
    frameView = view;
    frameEye.set(camera.eye());
    viewProj.set(vp);
    StillLayer.Plan plan = still.next(items,
        new StillLayer.View(width, height, view[0], view[1], view[2], view[3], scene.floorZ(), vp));
    inLayer = plan.inLayer();
    if (plan.rebuild()) {
      if (layerView != null) {
        damage.addXywh(layerView[0], layerView[1], layerView[2], layerView[3]);
      }
      damage.addXywh(view[0], view[1], view[2], view[3]);
      buildLayer(items, inLayer, scene.floorZ(), width, height, view);
      layerView = view;
    }
    // the items left out of the layer: where they are now
    movingEdges.reset(width, height);
    for (int i = 0; i < items.size(); i++) {
      if (!inLayer[i]) {
        DrawItem item = items.get(i);
        GpuMesh mesh = meshes.computeIfAbsent(item.shape(), SceneRenderer::buildMesh);
        item.X_WS().toColumnMajor(model);
        movingEdges.addBox(viewProj, modelMatrix.set(model), mesh.bounds());
      }
    }
    int[] now = movingEdges.isEmpty() ? null
        : new int[] {movingEdges.x0(), movingEdges.y0(), movingEdges.x1(), movingEdges.y1()};
    if (plan.movedOutside() && !plan.rebuild()) {
      int[] clipView = {view[0], view[1], view[0] + view[2], view[1] + view[3]};
      for (int[] r : new int[][] {lastMovingRect, now}) {
        int[] c = r == null ? null : DamageRegion.intersect(r, clipView);
        if (c != null) {
          damage.add(c[0], c[1], c[2], c[3]);
        }
      }
    }
    lastMovingRect = now;
  }

  /** How often the still layer has been drawn (tests, the frame log). */
  public int layerBuilds() {
    return layerBuilds;
  }

  private static boolean opaque(DrawItem item) {
    return StillLayer.opaque(item);
  }

  private void buildLayer(List<DrawItem> items, boolean[] keep, double floorZ, int width, int height, int[] view) {
    layerBuilds++;
    int previous = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
    if (layer == null || layer.width() != width || layer.height() != height) {
      if (layer != null) {
        layer.close();
        work.close();
      }
      layer = new OffscreenTarget(width, height, 0);
      work = new OffscreenTarget(width, height, 0, true);
    }
    layer.bind();
    glViewport(0, 0, width, height);
    // all of it: outside the view the layer is the background a full frame has there
    glDisable(GL_SCISSOR_TEST);
    glClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(view[0], view[1], view[2], view[3]);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    float floorZ32 = (float) floorZ;
    edges.reset(width, height);
    try (MemoryStack stack = MemoryStack.stackPush()) {
      var vp = viewProj.get(stack.mallocFloat(16));
      int[] u = useSolid(vp, frameEye);
      float half = AXIS_LENGTH / 2;
      drawBar(u[0], u[1], half, 0, floorZ32 + AXIS_THICK / 2, AXIS_LENGTH, AXIS_THICK, AXIS_THICK, 0.85f, 0.15f, 0.12f);
      drawBar(u[0], u[1], 0, half, floorZ32 + AXIS_THICK / 2, AXIS_THICK, AXIS_LENGTH, AXIS_THICK, 0.15f, 0.65f, 0.2f);
      for (int i = 0; i < items.size(); i++) {
        if (keep[i]) {
          drawItem(items.get(i), u[0], u[1], false);
        }
      }
      drawFloor(vp, frameEye, floorZ32);
    }
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, previous);
  }

  /**
   * Draws the rectangle {x0, y0, x1, y1} (pixels) of the frame {@link #prepareRetained} prepared
   * into the bound framebuffer: the background, the still layer's colour and depth, the items
   * left out of it, the translucent items, edge smoothing and the orientation triad, each only
   * within the rectangle. A rectangle outside the scene's view gets the background.
   */
  public void drawRegion(int[] rect) {
    int target = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
    glViewport(0, 0, frameW, frameH);
    int[] viewBox = {frameView[0], frameView[1], frameView[0] + frameView[2], frameView[1] + frameView[3]};
    int[] r = DamageRegion.intersect(rect, viewBox);
    if (r == null || !Arrays.equals(r, rect)) {
      // some of it lies outside the view: the background there (within the view, the scene's
      // pixels below replace every pixel, so a rectangle within it is not cleared first: on a
      // software renderer that clear cost as much as a copy)
      glEnable(GL_SCISSOR_TEST);
      glScissor(rect[0], rect[1], rect[2] - rect[0], rect[3] - rect[1]);
      glClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glDisable(GL_SCISSOR_TEST);
    }
    if (r == null) {
      return;
    }
    // The moving items are drawn over a copy of the layer in a buffer of the layer's own
    // formats (depth is copied only between like buffers), then only its colour goes on. The
    // copy reaches a pixel further than the rectangle: the edge smoothing of the rectangle's
    // border pixels reads their neighbours, which must be unsmoothed as in a full frame.
    int[] grown = DamageRegion.intersect(new int[] {r[0] - 1, r[1] - 1, r[2] + 1, r[3] + 1}, new int[] {0, 0, frameW, frameH});
    layer.copyTo(work.framebuffer(), grown, true);
    int[] r1 = DamageRegion.intersect(grown, viewBox);
    glEnable(GL_SCISSOR_TEST);
    glScissor(r1[0], r1[1], r1[2] - r1[0], r1[3] - r1[1]);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    List<DrawItem> items = frameScene.items();
    edges.reset(frameW, frameH);
    gizmoEdges.reset(frameW, frameH);
    try (MemoryStack stack = MemoryStack.stackPush()) {
      var vp = viewProj.get(stack.mallocFloat(16));
      int[] u = useSolid(vp, frameEye);
      for (int i = 0; i < items.size(); i++) {
        if (!inLayer[i] && opaque(items.get(i))) {
          drawItem(items.get(i), u[0], u[1], false);
        }
      }
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      glDepthMask(false);
      glDisable(GL_CULL_FACE);
      for (DrawItem item : items) {
        if (!opaque(item)) {
          drawItem(item, u[0], u[1], false);
        }
      }
      glEnable(GL_CULL_FACE);
      glDepthMask(true);
      glDisable(GL_BLEND);
    }
    glDisable(GL_SCISSOR_TEST);
    gizmo.draw(solid, axisBar, frameCamera, frameW, frameH, gizmoEdges, r1);
    if (antiAliasing != AntiAliasing.FXAA) {
      work.copyTo(target, r, false);
      glBindFramebuffer(GL_FRAMEBUFFER, target);
      return;
    }
    // every solid's edges, the still ones too: the layer keeps them unsmoothed
    float floorZ32 = (float) frameScene.floorZ();
    float half = AXIS_LENGTH / 2;
    addBarEdges(half, 0, floorZ32 + AXIS_THICK / 2, AXIS_LENGTH, AXIS_THICK, AXIS_THICK);
    addBarEdges(0, half, floorZ32 + AXIS_THICK / 2, AXIS_THICK, AXIS_LENGTH, AXIS_THICK);
    for (DrawItem item : items) {
      GpuMesh mesh = meshes.computeIfAbsent(item.shape(), SceneRenderer::buildMesh);
      item.X_WS().toColumnMajor(model);
      edges.addBox(viewProj, modelMatrix.set(model), mesh.bounds());
    }
    boolean triadHere = !gizmoEdges.isEmpty()
        && DamageRegion.intersect(new int[] {gizmoEdges.x0(), gizmoEdges.y0(), gizmoEdges.x1(), gizmoEdges.y1()}, r) != null;
    if (triadHere) {
      // the triad's smoothing reads the scene's smoothed pixels: both passes in the buffer, then a copy
      fxaa.apply(edges, r, frameW, frameH);
      fxaa.apply(gizmoEdges, r, frameW, frameH);
      work.copyTo(target, r, false);
      glBindFramebuffer(GL_FRAMEBUFFER, target);
    } else {
      // one pass straight from the buffer's colour to the target: smoothed within the solids'
      // rectangle, copied elsewhere (the pixels a full frame's pass would give)
      glBindFramebuffer(GL_FRAMEBUFFER, target);
      fxaa.drawFrom(work.colorTexture(), edges, r, frameW, frameH);
    }
  }

  private int[] useSolid(FloatBuffer vp, Vector3f eye) {
    solid.use();
    glUniformMatrix4fv(solid.uniform("uViewProj"), false, vp);
    glUniform3f(solid.uniform("uEye"), eye.x, eye.y, eye.z);
    glUniform3f(solid.uniform("uKeyDir"), 0.45f, -0.35f, 0.82f);
    glUniform3f(solid.uniform("uFillDir"), -0.6f, 0.7f, 0.3f);
    return new int[] {solid.uniform("uModel"), solid.uniform("uColor")};
  }

  private void drawItem(DrawItem item, int uModel, int uColor, boolean smooth) {
    DrawItem.Color c = item.color();
    GpuMesh mesh = meshes.computeIfAbsent(item.shape(), SceneRenderer::buildMesh);
    item.X_WS().toColumnMajor(model);
    glUniformMatrix4fv(uModel, false, model);
    if (smooth) {
      edges.addBox(viewProj, modelMatrix.set(model), mesh.bounds());
    }
    glUniform4f(uColor, c.r(), c.g(), c.b(), c.a());
    bySize(item.shape(), mesh).draw();
  }

  /**
   * Divides round shapes by their size on screen ({@link MeshDetail}) from now on: the window's
   * renderer does, so that the small shapes of an arm far from the eye cost fewer triangles.
   * Off by default: pictures ({@code robotrun render}, grading) keep the full meshes.
   */
  public void setDetailBySize(boolean on) {
    detailBySize = on;
  }

  private boolean detailBySize;
  /** The viewport the current frame is drawn in (pixels), for {@link #bySize}. */
  private int detailW;
  private int detailH;
  /** A shape divided into fewer segments than its full mesh. */
  private record Divided(DrawShape shape, int segments, int roundSegments) {}
  private final Map<Divided, GpuMesh> divided = new HashMap<>();

  /**
   * The mesh to draw for {@code shape}, placed by {@link #model} in the current frame: its full
   * mesh, or with {@link #detailBySize} one divided as finely as its size on screen needs. The
   * choice depends only on the shape, its place, the camera and the viewport, so the window's kept
   * frame and a full redraw of it choose alike. Bounds (damage, edge smoothing) stay the full mesh's.
   */
  private GpuMesh bySize(DrawShape shape, GpuMesh full) {
    if (!detailBySize) {
      return full;
    }
    Divided d;
    switch (shape) {
      case DrawShape.Cylinder cy -> {
        double ppm = MeshDetail.pixelsPerMm(viewProj, model[12], model[13], model[14],
            Math.hypot(cy.radius(), cy.length() / 2), detailW, detailH);
        d = new Divided(shape, MeshDetail.cylinderSegments(cy.radius() * ppm),
            MeshDetail.roundSegments(MeshFactory.cylinderRimRadius(cy.radius(), cy.length()) * ppm));
        if (d.segments() == MeshFactory.CYLINDER_SEGMENTS && d.roundSegments() == MeshFactory.ROUND_SEGMENTS) {
          return full;
        }
      }
      case DrawShape.Box b when b.rounded() -> {
        double half = Math.sqrt(b.size().x() * b.size().x() + b.size().y() * b.size().y() + b.size().z() * b.size().z()) / 2;
        double ppm = MeshDetail.pixelsPerMm(viewProj, model[12], model[13], model[14], half, detailW, detailH);
        d = new Divided(shape, 0, MeshDetail.roundSegments(boxRound(b) * ppm));
        if (d.roundSegments() == MeshFactory.ROUND_SEGMENTS) {
          return full;
        }
      }
      default -> {
        return full;
      }
    }
    return divided.computeIfAbsent(d, SceneRenderer::buildDivided);
  }

  private static GpuMesh buildDivided(Divided d) {
    return GpuMesh.upload(switch (d.shape()) {
      case DrawShape.Cylinder c -> MeshFactory.cylinder(c.radius(), c.length(), d.segments(), d.roundSegments());
      case DrawShape.Box b -> MeshFactory.box(b.size().x(), b.size().y(), b.size().z(), boxRound(b), d.roundSegments());
      default -> throw new IllegalArgumentException("no divided mesh for " + d.shape());
    });
  }

  /** The radius of a rounded box's edges (mm). */
  private static double boxRound(DrawShape.Box b) {
    return b.rounded() ? 0.14 * Math.min(b.size().x(), Math.min(b.size().y(), b.size().z())) : 0;
  }

  private void addBarEdges(float cx, float cy, float cz, float sx, float sy, float sz) {
    modelMatrix.translation(cx, cy, cz).scale(sx, sy, sz);
    edges.addBox(viewProj, modelMatrix, axisBar.bounds());
  }

  private void draw(SceneSnapshot scene, Matrix4f cameraViewProj, Vector3f eye, int[] view, int width, int height) {
    boolean smooth = antiAliasing == AntiAliasing.FXAA;
    edges.reset(width, height);
    gizmoEdges.reset(width, height);
    glViewport(0, 0, width, height);
    // Alpha 0: background, not a solid (see fxaa.frag); nothing blends with destination alpha.
    glClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // Draw only where the scene is framed: the window's panels cover the rest, and on a
    // software renderer every pixel of floor under them would cost as much as a visible one.
    boolean partial = view[2] < width || view[3] < height;
    if (partial) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(view[0], view[1], view[2], view[3]);
    }
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    viewProj.set(cameraViewProj);
    detailW = width;
    detailH = height;
    float floorZ = (float) scene.floorZ();

    try (MemoryStack stack = MemoryStack.stackPush()) {
      var vp = viewProj.get(stack.mallocFloat(16));

      solid.use();
      glUniformMatrix4fv(solid.uniform("uViewProj"), false, vp);
      glUniform3f(solid.uniform("uEye"), eye.x, eye.y, eye.z);
      glUniform3f(solid.uniform("uKeyDir"), 0.45f, -0.35f, 0.82f);
      glUniform3f(solid.uniform("uFillDir"), -0.6f, 0.7f, 0.3f);
      int uModel = solid.uniform("uModel");
      int uColor = solid.uniform("uColor");

      // World X (red) and Y (green) on the floor below the WORLD origin. Z is up the J1 axis,
      // inside the robot's base, so it is not drawn.
      float half = AXIS_LENGTH / 2;
      drawBar(uModel, uColor, half, 0, floorZ + AXIS_THICK / 2, AXIS_LENGTH, AXIS_THICK, AXIS_THICK, 0.85f, 0.15f, 0.12f);
      drawBar(uModel, uColor, 0, half, floorZ + AXIS_THICK / 2, AXIS_THICK, AXIS_LENGTH, AXIS_THICK, 0.15f, 0.65f, 0.2f);

      drawItems(scene, uModel, uColor, false, smooth);
      // The floor after the opaque items: the depth test then rejects its fragments behind the
      // robot before its grid shader runs (llvmpipe tests depth early), about 6% of the frame's CPU.
      drawFloor(vp, eye, floorZ);

      // Translucent items (collision boxes) last, blended over everything, without writing depth
      // so they do not hide each other.
      solid.use();
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      glDepthMask(false);
      glDisable(GL_CULL_FACE);
      drawItems(scene, uModel, uColor, true, false);
      glEnable(GL_CULL_FACE);
      glDepthMask(true);
      glDisable(GL_BLEND);
    }
    if (partial) {
      glDisable(GL_SCISSOR_TEST);
    }
  }

  private void drawItems(SceneSnapshot scene, int uModel, int uColor, boolean translucent, boolean smooth) {
    for (DrawItem item : scene.items()) {
      DrawItem.Color c = item.color();
      if ((c.a() < 1f) != translucent) {
        continue;
      }
      drawItem(item, uModel, uColor, smooth);
    }
  }

  private void drawFloor(FloatBuffer vp, Vector3f eye, float floorZ) {
    // Floor: pushed back a little in depth so the axes lying on it win.
    floor.use();
    glUniformMatrix4fv(floor.uniform("uViewProj"), false, vp);
    glUniform3f(floor.uniform("uEye"), eye.x, eye.y, eye.z);
    new Matrix4f().translation(0, 0, floorZ).get(model);
    glUniformMatrix4fv(floor.uniform("uModel"), false, model);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1f, 1f);
    glDisable(GL_CULL_FACE);
    floorQuad.draw();
    glEnable(GL_CULL_FACE);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }

  private void drawBar(int uModel, int uColor, float cx, float cy, float cz, float sx, float sy, float sz,
      float r, float g, float b) {
    modelMatrix.translation(cx, cy, cz).scale(sx, sy, sz).get(model);
    glUniformMatrix4fv(uModel, false, model);
    edges.addBox(viewProj, modelMatrix, axisBar.bounds());
    glUniform4f(uColor, r, g, b, 1f);
    axisBar.draw();
  }

  private static GpuMesh buildMesh(DrawShape shape) {
    return GpuMesh.upload(switch (shape) {
      case DrawShape.Box b -> MeshFactory.box(b.size().x(), b.size().y(), b.size().z(), boxRound(b));
      case DrawShape.Cylinder c -> MeshFactory.cylinder(c.radius(), c.length());
      case DrawShape.Mesh m -> MeshFactory.triangles(m.triangles());
      case DrawShape.WireBox w -> MeshFactory.boxEdges(w.size().x(), w.size().y(), w.size().z());
    }, shape instanceof DrawShape.WireBox ? GL_LINES : GL_TRIANGLES);
  }

  /** Number of distinct GPU meshes built so far. */
  public int meshCount() {
    return meshes.size();
  }

  /** Model matrix helper for tests and callers that place things by transform. */
  static void columnMajor(Transform t, float[] dest) {
    t.toColumnMajor(dest);
  }

  @Override
  public void close() {
    if (layer != null) {
      layer.close();
      work.close();
    }
    meshes.values().forEach(GpuMesh::close);
    meshes.clear();
    divided.values().forEach(GpuMesh::close);
    divided.clear();
    fxaa.close();
    floorQuad.close();
    axisBar.close();
    solid.close();
    floor.close();
  }
}
