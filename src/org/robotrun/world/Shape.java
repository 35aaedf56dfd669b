package org.robotrun.world;

import java.nio.file.Path;
import org.robotrun.collision.Obb;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The solid of a world object, in the object's own frame O (mm). Boxes and cylinders stand on
 * their origin: O is the centre of the bottom face with z up, so an object posed at a table's
 * top height rests on the table. A mesh keeps the coordinates of its STL file (scaled).
 */
public sealed interface Shape {

  /** The box bounding the shape, in the object's frame. */
  LocalBox boundingBox();

  /** The collision box of an object with this shape posed at {@code X_WO}. */
  default Obb collisionBox(Transform X_WO) {
    return boundingBox().inWorld(X_WO);
  }

  /** A box: length along x, width along y, height along z (mm, all > 0). */
  record Box(double lengthMm, double widthMm, double heightMm) implements Shape {
    public Box {
      requirePositive("length", lengthMm);
      requirePositive("width", widthMm);
      requirePositive("height", heightMm);
    }

    @Override
    public LocalBox boundingBox() {
      return new LocalBox(Transform.translation(0, 0, heightMm / 2), lengthMm / 2, widthMm / 2, heightMm / 2);
    }
  }

  /** A cylinder standing on its base, axis along z (mm, both > 0). */
  record Cylinder(double radiusMm, double heightMm) implements Shape {
    public Cylinder {
      requirePositive("radius", radiusMm);
      requirePositive("height", heightMm);
    }

    @Override
    public LocalBox boundingBox() {
      return new LocalBox(Transform.translation(0, 0, heightMm / 2), radiusMm, radiusMm, heightMm / 2);
    }
  }

  /**
   * A triangle mesh read from an STL file.
   *
   * @param file the STL file (absolute; scenario files store it relative to themselves)
   * @param scale factor applied to the file's coordinates to get mm (e.g. 1000 for metres)
   * @param mesh the triangles, already scaled (mm)
   */
  record Mesh(Path file, double scale, TriangleMesh mesh) implements Shape {
    public Mesh {
      requirePositive("scale", scale);
      file = file.toAbsolutePath().normalize();
    }

    @Override
    public LocalBox boundingBox() {
      Vec3 lo = mesh.min();
      Vec3 hi = mesh.max();
      return new LocalBox(Transform.translation((lo.x() + hi.x()) / 2, (lo.y() + hi.y()) / 2, (lo.z() + hi.z()) / 2),
          (hi.x() - lo.x()) / 2, (hi.y() - lo.y()) / 2, (hi.z() - lo.z()) / 2);
    }
  }

  private static void requirePositive(String what, double v) {
    if (!(v > 0) || !Double.isFinite(v)) {
      throw new IllegalArgumentException(what + " must be a finite number > 0, got " + v);
    }
  }
}
