package org.robotrun.collision;

/** Two body names, unordered: {@code new BodyPair("a", "b")} equals {@code new BodyPair("b", "a")}. */
public record BodyPair(String first, String second) {
  public BodyPair {
    if (first.compareTo(second) > 0) {
      String t = first;
      first = second;
      second = t;
    }
  }

  /** The pair of two bodies' names. */
  public static BodyPair of(Body a, Body b) {
    return new BodyPair(a.name(), b.name());
  }
}
