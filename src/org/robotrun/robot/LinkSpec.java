package org.robotrun.robot;

import java.util.List;

/**
 * A rigid link: its name, the shapes that make up its body (collision, and display when it has
 * no meshes) and its display meshes, all in the link frame.
 */
public record LinkSpec(String name, List<LinkShape> shapes, List<LinkMesh> meshes) {
  public LinkSpec {
    shapes = List.copyOf(shapes);
    meshes = List.copyOf(meshes);
  }

  /** A link drawn from its shapes. */
  public LinkSpec(String name, List<LinkShape> shapes) {
    this(name, shapes, List.of());
  }
}
