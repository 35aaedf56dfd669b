package org.robotrun.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.FloatBuffer;
import java.util.HashMap;
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
      GpuMesh mesh = meshes.computeIfAbsent(item.shape(), SceneRenderer::buildMesh);
      item.X_WS().toColumnMajor(model);
      glUniformMatrix4fv(uModel, false, model);
      if (smooth) {
        edges.addBox(viewProj, modelMatrix.set(model), mesh.bounds());
      }
      glUniform4f(uColor, c.r(), c.g(), c.b(), c.a());
      mesh.draw();
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
      case DrawShape.Box b -> MeshFactory.box(b.size().x(), b.size().y(), b.size().z(),
          b.rounded() ? 0.14 * Math.min(b.size().x(), Math.min(b.size().y(), b.size().z())) : 0);
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
    meshes.values().forEach(GpuMesh::close);
    meshes.clear();
    fxaa.close();
    floorQuad.close();
    axisBar.close();
    solid.close();
    floor.close();
  }
}
