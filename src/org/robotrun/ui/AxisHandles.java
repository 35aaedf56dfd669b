package org.robotrun.ui;

import imgui.ImDrawList;
import imgui.ImGui;
import java.util.Optional;
import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.robotrun.math.Transform;
import org.robotrun.render.OrbitCamera;
import org.robotrun.world.CellEditor;

/**
 * Three arrows (cell X red, Y green, Z blue) on the selected object in the 3D view: drag one to
 * move the object along that axis. The move is applied once, on release, as one undoable edit in
 * whole millimetres.
 */
final class AxisHandles {
  private static final float LENGTH_MM = 150;
  private static final float GRAB_PX = 8;
  private static final int[] COLOURS = {ImColor(230, 60, 50), ImColor(70, 190, 80), ImColor(70, 120, 240)};

  /** A finished drag: move {@code object} by {@code mm} along cell axis {@code axis}. */
  record Move(String object, int axis, double mm) {}

  private String object = "";
  /** Screen positions of the origin and the three arrow tips (display pixels), last frame. */
  private final float[][] screen = new float[4][2];
  private boolean visible;
  private int dragAxis = -1;
  private double startX;
  private double startY;
  private double dragMm;

  private static int ImColor(int r, int g, int b) {
    return 0xFF000000 | (b << 16) | (g << 8) | r;
  }

  void draw(OrbitCamera camera, int fbW, int fbH, float dispW, float dispH, CellEditor editor, String selected,
      WindowLayout.Rect view) {
    visible = false;
    object = selected;
    if (selected.isEmpty() || editor.world().find(selected).isEmpty()) {
      dragAxis = -1;
      return;
    }
    Transform X_CO = editor.world().poseInCell(selected);
    double ox = X_CO.x(), oy = X_CO.y(), oz = X_CO.z();
    if (dragAxis >= 0) {
      // show where the drag would put it
      if (dragAxis == 0) {
        ox += dragMm;
      } else if (dragAxis == 1) {
        oy += dragMm;
      } else {
        oz += dragMm;
      }
    }
    Matrix4f vp = camera.viewProjection(fbW, fbH);
    for (int i = 0; i < 4; i++) {
      float px = (float) ox + (i == 1 ? LENGTH_MM : 0), py = (float) oy + (i == 2 ? LENGTH_MM : 0), pz = (float) oz + (i == 3 ? LENGTH_MM : 0);
      Vector4f c = new Vector4f(px, py, pz, 1).mul(vp);
      if (c.w <= 0) {
        return;
      }
      screen[i][0] = (c.x / c.w * 0.5f + 0.5f) * dispW;
      screen[i][1] = (0.5f - c.y / c.w * 0.5f) * dispH;
    }
    visible = true;
    ImDrawList dl = ImGui.getBackgroundDrawList();
    dl.pushClipRect(view.x(), view.y(), view.right(), view.bottom());
    for (int a = 0; a < 3; a++) {
      float thick = a == dragAxis ? 5 : 3;
      dl.addLine(screen[0][0], screen[0][1], screen[a + 1][0], screen[a + 1][1], COLOURS[a], thick);
      dl.addCircleFilled(screen[a + 1][0], screen[a + 1][1], 5, COLOURS[a]);
    }
    if (dragAxis >= 0) {
      dl.addText(screen[0][0] + 8, screen[0][1] + 8, 0xFFFFFFFF, String.format(java.util.Locale.ROOT, "%+.0f mm %s", dragMm, "XYZ".charAt(dragAxis)));
    }
    dl.popClipRect();
  }

  /** A press at (x, y): takes the drag when it is on an arrow. */
  boolean press(double x, double y) {
    if (!visible) {
      return false;
    }
    for (int a = 0; a < 3; a++) {
      if (distanceToSegment(x, y, screen[0], screen[a + 1]) <= GRAB_PX) {
        dragAxis = a;
        startX = x;
        startY = y;
        dragMm = 0;
        return true;
      }
    }
    return false;
  }

  boolean drag(double x, double y) {
    if (dragAxis < 0) {
      return false;
    }
    double ax = screen[dragAxis + 1][0] - screen[0][0], ay = screen[dragAxis + 1][1] - screen[0][1];
    double len2 = ax * ax + ay * ay;
    if (len2 < 1) {
      return true;
    }
    // mouse travel along the arrow on screen, in arrow lengths, times the arrow's length in mm
    double along = ((x - startX) * ax + (y - startY) * ay) / len2;
    dragMm = Math.rint(along * LENGTH_MM);
    return true;
  }

  Optional<Move> release() {
    if (dragAxis < 0) {
      return Optional.empty();
    }
    Move m = new Move(object, dragAxis, dragMm);
    dragAxis = -1;
    return m.mm() == 0 ? Optional.empty() : Optional.of(m);
  }

  private static double distanceToSegment(double x, double y, float[] a, float[] b) {
    double dx = b[0] - a[0], dy = b[1] - a[1];
    double len2 = dx * dx + dy * dy;
    double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - a[0]) * dx + (y - a[1]) * dy) / len2));
    double px = a[0] + t * dx - x, py = a[1] + t * dy - y;
    return Math.sqrt(px * px + py * py);
  }
}
