package org.robotrun.motion;

/** What one jog tick did. */
public sealed interface JogResult {

  /** No key on and the arm at rest. */
  record Idle() implements JogResult {}

  /** The arm moved (or is ramping). */
  record Moving() implements JogResult {}

  /**
   * The jog stopped itself at a joint limit or a singularity; every key was turned off.
   *
   * @param message for the pendant's status line
   */
  record Stopped(String message) implements JogResult {}
}
