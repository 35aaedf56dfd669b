package org.robotrun.world;

/**
 * What a collision does in a cell; scenario files write it in lower case ({@code "onCollision"}).
 */
public enum CollisionResponse {
  /** Stop the robot with an alarm, as a controller's collision detection does (the default). */
  ALARM,
  /** Only record and show the contact (red), for free play. */
  WARN;

  /** The name used in files. */
  public String fileName() {
    return name().toLowerCase(java.util.Locale.ROOT);
  }
}
