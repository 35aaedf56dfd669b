package org.robotrun.robot;

import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * A simple solid attached to a link, in the link's frame (mm): used to build the link's
 * display mesh and its collision boxes.
 */
public sealed interface LinkShape {

  /** Placement of the shape's centre in the link frame. */
  Transform X_LS();

  /** Display colour name: "body" (the arm's yellow), "white" (collaborative arms), "joint" (dark), "base" or "flange". */
  String color();

  /** A box with full edge lengths {@code size} (mm), centred on its pose. */
  record Box(Transform X_LS, Vec3 size, String color) implements LinkShape {}

  /** A cylinder along its local z axis, centred on its pose (mm). */
  record Cylinder(Transform X_LS, double radius, double length, String color) implements LinkShape {}
}
