package org.robotrun.sim;

import java.util.List;
import org.robotrun.collision.CollisionWorld;
import org.robotrun.collision.Obb;
import org.robotrun.math.Vec3;

/**
 * Draw items for the collision boxes of a cell ("show boxes"): each box as a wire frame and a
 * translucent fill, green when it touches nothing at the last check, red when it touches a body
 * the rules check it against. Names are "box:" + the body's name.
 */
final class CollisionBoxDrawList {
  static final DrawItem.Color FREE_EDGE = new DrawItem.Color(0.05f, 0.55f, 0.15f, 1f);
  static final DrawItem.Color FREE_FILL = new DrawItem.Color(0.2f, 0.85f, 0.3f, 0.18f);
  static final DrawItem.Color TOUCH_EDGE = new DrawItem.Color(0.8f, 0.05f, 0.05f, 1f);
  static final DrawItem.Color TOUCH_FILL = new DrawItem.Color(0.95f, 0.15f, 0.1f, 0.35f);
  /** Boxes larger than this along any axis (the floor slab) are not drawn (mm). */
  static final double MAX_DRAWN_MM = 5000;

  private CollisionBoxDrawList() {}

  static void add(List<DrawItem> out, CollisionWorld world) {
    for (int h = 0; h < world.size(); h++) {
      Obb b = world.box(h);
      if (Math.max(b.hx(), Math.max(b.hy(), b.hz())) * 2 > MAX_DRAWN_MM) {
        continue;
      }
      boolean touching = world.isTouching(h);
      Vec3 size = new Vec3(2 * b.hx(), 2 * b.hy(), 2 * b.hz());
      String name = "box:" + world.body(h).name();
      out.add(new DrawItem(name, new DrawShape.WireBox(size), b.pose(), touching ? TOUCH_EDGE : FREE_EDGE));
      out.add(new DrawItem(name, new DrawShape.Box(size, false), b.pose(), touching ? TOUCH_FILL : FREE_FILL));
    }
  }
}
