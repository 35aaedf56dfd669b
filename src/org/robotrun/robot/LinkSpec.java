package org.robotrun.robot;

import java.util.List;

/** A rigid link: its name and the shapes that make up its body, in the link frame. */
public record LinkSpec(String name, List<LinkShape> shapes) {
  public LinkSpec {
    shapes = List.copyOf(shapes);
  }
}
