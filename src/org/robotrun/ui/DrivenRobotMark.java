package org.robotrun.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robotrun.sim.DrawItem;
import org.robotrun.sim.SceneSnapshot;

/**
 * Which arm the pendant drives, shown where the eye is, in a cell of several robots: the driven
 * robot's bodies tinted toward the mark's amber in the 3D view with an amber disc around its foot, its name on a label of that colour
 * beside its base, placed off the work (parts, fixtures, the other arms), and the same name in the
 * same colour on the pendant's status line. A cell of one robot gets none of it.
 *
 * <p>The scene and label functions are pure (a draw list in, a draw list out; pixels in, a
 * rectangle out), so tests can see them.
 */
public final class DrivenRobotMark {
  private DrivenRobotMark() {}

  /** The driven robot's colour: an amber that reads on the dark 3D view and on the pendant's light LCD. */
  public static final float R = 0.95f, G = 0.55f, B = 0.05f;
  /** How far the driven robot's colours move toward {@link #R}, {@link #G}, {@link #B}. */
  public static final float TINT = 0.4f;
  /** An item covering more than this part of the view is the room (floor, table, fence), not the work. */
  static final double ROOM_FRACTION = 0.25;

  /**
   * The scene with the bodies of {@code robot} (items named {@code robot/...}) tinted; the scene
   * itself when the cell has one robot or no robot is driven ({@code robot} empty).
   */
  public static SceneSnapshot tinted(SceneSnapshot scene, String robot, int robots) {
    if (robots < 2 || robot.isEmpty()) {
      return scene;
    }
    String prefix = robot + "/";
    List<DrawItem> out = new ArrayList<>(scene.items().size() + 1);
    String baseLink = null;
    List<org.joml.Vector3f> baseCorners = new ArrayList<>();
    for (DrawItem it : scene.items()) {
      if (it.name().startsWith(prefix)) {
        if (baseLink == null) {
          baseLink = it.name();  // a robot's first item is its base link
        }
        if (it.name().equals(baseLink)) {
          SceneBounds.addCorners(it, baseCorners);
        }
        DrawItem.Color c = it.color();
        out.add(new DrawItem(it.name(), it.shape(), it.X_WS(), new DrawItem.Color(mix(c.r(), R), mix(c.g(), G),
            mix(c.b(), B), c.a())));
      } else {
        out.add(it);
      }
    }
    ring(baseCorners).ifPresent(out::add);
    return new SceneSnapshot(scene.simTimeSec(), out, scene.floorZ());
  }

  /** A flat amber disc under the base, wider than it: a ring around the robot's foot seen from above. */
  private static Optional<DrawItem> ring(List<org.joml.Vector3f> corners) {
    if (corners.isEmpty()) {
      return Optional.empty();
    }
    float x0 = Float.MAX_VALUE, y0 = Float.MAX_VALUE, z0 = Float.MAX_VALUE, x1 = -Float.MAX_VALUE, y1 = -Float.MAX_VALUE;
    for (org.joml.Vector3f c : corners) {
      x0 = Math.min(x0, c.x);
      y0 = Math.min(y0, c.y);
      z0 = Math.min(z0, c.z);
      x1 = Math.max(x1, c.x);
      y1 = Math.max(y1, c.y);
    }
    double radius = Math.max(x1 - x0, y1 - y0) / 2 * RING_SCALE + RING_MARGIN_MM;
    return Optional.of(new DrawItem(RING_NAME, new org.robotrun.sim.DrawShape.Cylinder(radius, RING_THICKNESS_MM),
        org.robotrun.math.Transform.translation((x0 + x1) / 2, (y0 + y1) / 2, z0 + RING_THICKNESS_MM / 2),
        new DrawItem.Color(R, G, B, 1f)));
  }

  /** The disc under the driven robot's base: its name in the draw list, and its size against the base's. */
  static final String RING_NAME = "driven-robot-ring";
  static final double RING_SCALE = 1.25, RING_MARGIN_MM = 40, RING_THICKNESS_MM = 3;

  private static float mix(float c, float m) {
    return c + (m - c) * TINT;
  }

  /**
   * Where the driven robot's name label goes in a view of {@code viewW} x {@code viewH} pixels:
   * beside the robot's base at {@code (baseX, baseY)}, on none of {@code work} (the screen
   * rectangles of the parts, fixtures and other arms; one that covers more than
   * {@link #ROOM_FRACTION} of the view is the room and is ignored), inside the view. Empty when
   * the base is off the view or no place is free.
   */
  public static Optional<LabelLayout.Placed> labelPlace(double baseX, double baseY, double labelW, double labelH,
      double viewW, double viewH, List<LabelLayout.Box> work) {
    if (!(baseX >= 0 && baseY >= 0 && baseX <= viewW && baseY <= viewH)) {
      return Optional.empty();
    }
    List<LabelLayout.Box> obstacles = new ArrayList<>();
    for (LabelLayout.Box b : work) {
      if (b.w() * b.h() <= ROOM_FRACTION * viewW * viewH) {
        obstacles.add(b);
      }
    }
    return LabelLayout.place(List.of(new LabelLayout.Label(baseX, baseY, labelW, labelH)), viewW, viewH, obstacles).get(0);
  }
}
