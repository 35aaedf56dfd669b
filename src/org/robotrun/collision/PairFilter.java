package org.robotrun.collision;

/**
 * The exclusion rule: which pairs of bodies the collision check looks at. Must be symmetric
 * and a pure function of the two bodies: {@link CollisionWorld} asks once per pair and keeps
 * the answer until it is given a new filter (so a grip change means a new filter value).
 */
@FunctionalInterface
public interface PairFilter {
  /** Whether a contact between {@code a} and {@code b} matters. */
  boolean mayCollide(Body a, Body b);

  /** Checks every pair of different owners (boxes of one owner never collide). */
  PairFilter DIFFERENT_OWNERS = (a, b) -> !a.owner().equals(b.owner());

  /** Both rules must allow the pair. */
  default PairFilter and(PairFilter other) {
    return (a, b) -> mayCollide(a, b) && other.mayCollide(a, b);
  }
}
