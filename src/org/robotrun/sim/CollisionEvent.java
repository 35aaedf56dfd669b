package org.robotrun.sim;

/**
 * Two bodies began to touch.
 *
 * @param simTimeSec when (simulated seconds)
 * @param bodyA one body's id, e.g. "robot1/link5#1" or "robot1/tool" (for tools: the run report's {@code a})
 * @param bodyB the other's, e.g. "table"
 * @param nameA body A as a student knows it, e.g. "robot1 J5 wrist" ({@link BodyNames})
 * @param nameB body B as a student knows it
 */
public record CollisionEvent(double simTimeSec, String bodyA, String bodyB, String nameA, String nameB) {
  /** An event whose bodies are shown by their ids. */
  public CollisionEvent(double simTimeSec, String bodyA, String bodyB) {
    this(simTimeSec, bodyA, bodyB, bodyA, bodyB);
  }
}
