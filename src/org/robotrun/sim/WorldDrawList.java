package org.robotrun.sim;

import java.util.List;
import org.robotrun.math.Transform;
import org.robotrun.world.Rgb;
import org.robotrun.world.Shape;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/** Fills draw items for a cell's fixtures and parts, in the cell frame. */
public final class WorldDrawList {
  private WorldDrawList() {}

  /** One item per object, named by the object. */
  public static void addWorld(List<DrawItem> out, World world) {
    for (WorldObject o : world.objects()) {
      Transform X_CO = world.poseInCell(o.name());
      DrawItem.Color color = colorOf(o.colour());
      switch (o.shape()) {
        // Boxes and cylinders stand on their origin; draw shapes are centred.
        case Shape.Box b -> out.add(new DrawItem(o.name(),
            new DrawShape.Box(new org.robotrun.math.Vec3(b.lengthMm(), b.widthMm(), b.heightMm()), false),
            X_CO.compose(Transform.translation(0, 0, b.heightMm() / 2)), color));
        case Shape.Cylinder c -> out.add(new DrawItem(o.name(), new DrawShape.Cylinder(c.radiusMm(), c.heightMm()),
            X_CO.compose(Transform.translation(0, 0, c.heightMm() / 2)), color));
        case Shape.Mesh m -> out.add(new DrawItem(o.name(),
            new DrawShape.Mesh(m.file() + "@" + m.scale(), m.mesh().corners()), X_CO, color));
      }
    }
  }

  static DrawItem.Color colorOf(Rgb c) {
    return DrawItem.Color.rgb(c.red() / 255.0, c.green() / 255.0, c.blue() / 255.0);
  }
}
