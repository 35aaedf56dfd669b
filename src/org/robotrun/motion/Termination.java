package org.robotrun.motion;

/** How a motion ends: stop at the point, or blend into the next motion. */
public sealed interface Termination {

  /** {@code FINE}: the robot stops exactly at the target before the next motion starts. */
  record Fine() implements Termination {}

  /**
   * {@code CNT n}, n in 0..100: the next motion starts while this one decelerates; it starts
   * {@code n}% of this motion's deceleration time before the end, so larger n rounds the corner
   * earlier and wider. CNT 0 does not stop to settle but does not cut the corner either.
   */
  record Cnt(int value) implements Termination {
    public Cnt {
      if (value < 0 || value > 100) {
        throw new IllegalArgumentException("CNT must be 0..100, got " + value);
      }
    }
  }

  /** FINE. */
  static Termination fine() {
    return new Fine();
  }

  /** CNT n. */
  static Termination cnt(int n) {
    return new Cnt(n);
  }
}
