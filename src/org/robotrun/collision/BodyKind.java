package org.robotrun.collision;

/** What a collision body belongs to; the pair filter decides by it which pairs are checked. */
public enum BodyKind {
  /** A box of a robot link or of the end effector mounted on it. */
  ROBOT,
  /** A static object: table, fence, fixture. */
  FIXTURE,
  /** An object that can be picked up. */
  PART
}
