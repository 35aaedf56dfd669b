package org.robotrun.sim;

/**
 * Two bodies began to touch.
 *
 * @param simTimeSec when (simulated seconds)
 * @param bodyA one body, e.g. "robot1/link5" or "robot1/tool"
 * @param bodyB the other, e.g. "table"
 */
public record CollisionEvent(double simTimeSec, String bodyA, String bodyB) {}
