package org.robotrun.render;

import static org.lwjgl.opengl.GL33C.*;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.lwjgl.system.MemoryStack;

/**
 * A small X/Y/Z triad (red, green, blue: WORLD axes) in the bottom-left corner that turns with
 * the camera, so the view's orientation can be read even when the floor axes are hidden. Drawn
 * in its own corner viewport after the scene, with the scene's lit-solid shader and bar mesh.
 */
final class OrientationGizmo {
  /** Bar length and thickness in the gizmo's unit space (the viewport spans ±1). */
  private static final float LENGTH = 0.9f;
  private static final float THICK = 0.12f;
  private static final int MARGIN_PX = 10;

  private final Matrix4f proj = new Matrix4f();
  private final Matrix4f viewProj = new Matrix4f();
  private final Matrix4f model = new Matrix4f();
  private final float[] modelArray = new float[16];

  /** Side of the gizmo's square viewport for a framebuffer of the given size (pixels). */
  static int sizePx(int width, int height) {
    return Math.max(48, Math.min(width, height) / 7);
  }

  /**
   * Draws the triad and adds its square to {@code drawn}.
   *
   * @param solid the lit-solid program (uModel, uViewProj, uColor, uEye, light directions set)
   * @param bar a unit cube centred on the origin
   */
  void draw(ShaderProgram solid, GpuMesh bar, OrbitCamera camera, int width, int height, ScreenRect drawn) {
    draw(solid, bar, camera, width, height, drawn, null);
  }

  /** The triad's square {x0, y0, x1, y1} (pixels), or null when the view is too small for it. */
  static int[] square(OrbitCamera camera, int width, int height) {
    // in the bottom-left corner of the part of the window the scene is framed in
    int[] viewR = camera.viewRect(width, height);
    int size = sizePx(viewR[2], viewR[3]);
    if (size + 2 * MARGIN_PX > Math.min(viewR[2], viewR[3])) {
      return null;
    }
    int x0 = viewR[0] + MARGIN_PX;
    int y0 = viewR[1] + MARGIN_PX;
    return new int[] {x0, y0, x0 + size, y0 + size};
  }

  /** As {@link #draw(ShaderProgram, GpuMesh, OrbitCamera, int, int, ScreenRect)}, drawing only within {@code clip} (null: all). */
  void draw(ShaderProgram solid, GpuMesh bar, OrbitCamera camera, int width, int height, ScreenRect drawn, int[] clip) {
    int[] sq = square(camera, width, height);
    if (sq == null) {
      return;
    }
    int[] cut = clip == null ? sq : DamageRegion.intersect(sq, clip);
    if (cut == null) {
      return;
    }
    int x0 = sq[0];
    int y0 = sq[1];
    int size = sq[2] - sq[0];
    Vector3f eye = camera.eye();
    Vector3f target = camera.target();
    // The camera's rotation only: the triad sits at the centre of its own little view.
    Matrix4f view = new Matrix4f().lookAt(eye.x, eye.y, eye.z, target.x, target.y, target.z, 0, 0, 1);
    proj.setOrtho(-1f, 1f, -1f, 1f, -5f, 5f);
    viewProj.set(proj).mul(new Matrix4f().set3x3(view));
    Vector3f toEye = eye.sub(target).normalize(4f);

    glEnable(GL_SCISSOR_TEST);
    glScissor(cut[0], cut[1], cut[2] - cut[0], cut[3] - cut[1]);
    glClear(GL_DEPTH_BUFFER_BIT);
    if (clip == null) {
      glDisable(GL_SCISSOR_TEST);
    }
    glViewport(x0, y0, size, size);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    solid.use();
    try (MemoryStack stack = MemoryStack.stackPush()) {
      glUniformMatrix4fv(solid.uniform("uViewProj"), false, viewProj.get(stack.mallocFloat(16)));
    }
    glUniform3f(solid.uniform("uEye"), toEye.x, toEye.y, toEye.z);
    float h = LENGTH / 2;
    drawBar(solid, bar, h, 0, 0, LENGTH, THICK, THICK, 0.85f, 0.15f, 0.12f);
    drawBar(solid, bar, 0, h, 0, THICK, LENGTH, THICK, 0.15f, 0.65f, 0.2f);
    drawBar(solid, bar, 0, 0, h, THICK, THICK, LENGTH, 0.15f, 0.35f, 0.85f);
    drawBar(solid, bar, 0, 0, 0, 1.8f * THICK, 1.8f * THICK, 1.8f * THICK, 0.55f, 0.55f, 0.55f);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    drawn.addPixels(x0, y0, x0 + size, y0 + size);
  }

  private void drawBar(ShaderProgram solid, GpuMesh bar, float cx, float cy, float cz, float sx, float sy, float sz,
      float r, float g, float b) {
    model.translation(cx, cy, cz).scale(sx, sy, sz).get(modelArray);
    glUniformMatrix4fv(solid.uniform("uModel"), false, modelArray);
    glUniform4f(solid.uniform("uColor"), r, g, b, 1f);
    bar.draw();
  }
}
