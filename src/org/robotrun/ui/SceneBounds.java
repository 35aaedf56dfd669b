package org.robotrun.ui;

import java.util.List;
import org.joml.Vector3f;
import org.robotrun.math.Vec3;
import org.robotrun.sim.DrawItem;
import org.robotrun.sim.DrawShape;

/** Points that bound a drawn item (the corners of its box; a mesh's vertices), in the cell (mm). */
public final class SceneBounds {
  private SceneBounds() {}

  /** Adds the bounding points of {@code item} to {@code out}. */
  public static void addCorners(DrawItem item, List<Vector3f> out) {
    switch (item.shape()) {
      case DrawShape.Box b -> box(item, b.size().x() / 2, b.size().y() / 2, b.size().z() / 2, out);
      case DrawShape.WireBox b -> box(item, b.size().x() / 2, b.size().y() / 2, b.size().z() / 2, out);
      case DrawShape.Cylinder c -> box(item, c.radius(), c.radius(), c.length() / 2, out);
      case DrawShape.Mesh m -> {
        float[] v = m.triangles();
        // every 7th vertex is plenty to bound a mesh for framing
        for (int i = 0; i + 2 < v.length; i += 21) {
          add(item, v[i], v[i + 1], v[i + 2], out);
        }
      }
    }
  }

  private static void box(DrawItem item, double hx, double hy, double hz, List<Vector3f> out) {
    for (int i = 0; i < 8; i++) {
      add(item, (i & 1) != 0 ? hx : -hx, (i & 2) != 0 ? hy : -hy, (i & 4) != 0 ? hz : -hz, out);
    }
  }

  private static void add(DrawItem item, double x, double y, double z, List<Vector3f> out) {
    Vec3 p = item.X_WS().apply(new Vec3(x, y, z));
    out.add(new Vector3f((float) p.x(), (float) p.y(), (float) p.z()));
  }
}
