package org.robotrun.sim;

import org.robotrun.math.Vec3;

/**
 * A solid as the renderer should draw it, in its own frame (mm): the renderer turns each
 * distinct shape into a mesh once and reuses it.
 */
public sealed interface DrawShape {

  /** A box with full edge lengths {@code size}, centred on its frame; {@code rounded} softens the edges. */
  record Box(Vec3 size, boolean rounded) implements DrawShape {}

  /** The twelve edges of a box with full edge lengths {@code size}, centred on its frame, as lines. */
  record WireBox(Vec3 size) implements DrawShape {}

  /** A cylinder along local z, centred on its frame. */
  record Cylinder(double radius, double length) implements DrawShape {}

  /**
   * A triangle mesh: {@code key} identifies it (for example the STL file and scale) so the
   * renderer uploads it once; {@code triangles} holds x, y, z of three vertices per triangle.
   */
  record Mesh(String key, float[] triangles) implements DrawShape {
    @Override
    public boolean equals(Object o) {
      return o instanceof Mesh m && m.key.equals(key);
    }

    @Override
    public int hashCode() {
      return key.hashCode();
    }
  }
}
