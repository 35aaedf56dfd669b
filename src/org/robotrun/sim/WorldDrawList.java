package org.robotrun.sim;

import java.util.List;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.world.Rgb;
import org.robotrun.world.Shape;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/** Fills draw items for the fixtures and parts of a world, placed in the cell frame. */
public final class WorldDrawList {
  private WorldDrawList() {}

  public static void addWorld(List<DrawItem> out, World world) {
    for (WorldObject o : world.objects()) {
      Transform X_CO = world.poseInCell(o.name());
      out.add(new DrawItem(o.name(), shapeOf(o.shape()), X_CO.compose(shapeFrame(o.shape())), colorOf(o.colour())));
    }
  }

  /** Draw shapes are centred on their frame; boxes and cylinders stand on their object origin. */
  static Transform shapeFrame(Shape s) {
    return switch (s) {
      case Shape.Box b -> Transform.translation(0, 0, b.heightMm() / 2);
      case Shape.Cylinder c -> Transform.translation(0, 0, c.heightMm() / 2);
      case Shape.Mesh m -> Transform.IDENTITY;
    };
  }

  static DrawShape shapeOf(Shape s) {
    return switch (s) {
      case Shape.Box b -> new DrawShape.Box(new Vec3(b.lengthMm(), b.widthMm(), b.heightMm()), false);
      case Shape.Cylinder c -> new DrawShape.Cylinder(c.radiusMm(), c.heightMm());
      case Shape.Mesh m -> new DrawShape.Mesh(m.file() + "@" + m.scale(), m.mesh().corners());
    };
  }

  static DrawItem.Color colorOf(Rgb c) {
    return new DrawItem.Color(c.red() / 255f, c.green() / 255f, c.blue() / 255f, 1f);
  }
}
