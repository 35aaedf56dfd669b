package org.robotrun.world;

import java.util.Optional;
import org.robotrun.math.Transform;

/**
 * A fixture or part in the cell: immutable; moving a part gives a new value.
 *
 * @param name unique in its world
 * @param kind fixture (static) or part (can be picked up)
 * @param shape the solid, in the object's frame O
 * @param colour display colour
 * @param pose {@code X_PO}: the object in its parent's frame, or in the cell when it has none (mm)
 * @param parent the fixture the pose is relative to, if any
 * @param startPose the pose the object had when the scenario was loaded ("reset scene")
 * @param startParent the parent it had then
 * @param touchable the robot's tool may touch it without a collision alarm (a marker, a pin, the
 *     point a frame is taught on; docs/collision.md); the arm's links may not
 */
public record WorldObject(
    String name,
    ObjectKind kind,
    Shape shape,
    Rgb colour,
    Transform pose,
    Optional<String> parent,
    Transform startPose,
    Optional<String> startParent,
    boolean touchable) {

  public WorldObject {
    if (name == null || name.isBlank()) {
      throw new IllegalArgumentException("an object needs a name");
    }
    if (parent.isPresent() && parent.get().equals(name)) {
      throw new IllegalArgumentException(name + " cannot be its own parent");
    }
  }

  /** An object the tool may not touch. */
  public WorldObject(String name, ObjectKind kind, Shape shape, Rgb colour, Transform pose, Optional<String> parent,
      Transform startPose, Optional<String> startParent) {
    this(name, kind, shape, colour, pose, parent, startPose, startParent, false);
  }

  /** The same object, touchable by the tool or not. */
  public WorldObject withTouchable(boolean touchable) {
    return new WorldObject(name, kind, shape, colour, pose, parent, startPose, startParent, touchable);
  }

  /** A new object at its start pose. */
  public static WorldObject of(String name, ObjectKind kind, Shape shape, Rgb colour, Transform pose, Optional<String> parent) {
    return new WorldObject(name, kind, shape, colour, pose, parent, pose, parent);
  }

  /** The same object moved: {@code pose} relative to {@code parent} (or the cell). */
  public WorldObject movedTo(Transform pose, Optional<String> parent) {
    return new WorldObject(name, kind, shape, colour, pose, parent, startPose, startParent, touchable);
  }

  /** The same object back where it started. */
  public WorldObject atStart() {
    return new WorldObject(name, kind, shape, colour, startPose, startParent, startPose, startParent, touchable);
  }
}
