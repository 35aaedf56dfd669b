package org.robotrun.world;

/** Whether an object stays put or can be picked up. */
public enum ObjectKind {
  /** Static: tables, fences, jigs. */
  FIXTURE,
  /** Can be picked up and placed. */
  PART
}
