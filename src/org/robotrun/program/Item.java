package org.robotrun.program;

import java.util.Objects;

/**
 * A reference to one numbered item (register, I/O port, timer, position…) with its optional
 * item comment: {@code R[1:COUNT]} is {@code Item(Direct(1), "COUNT")}. The comment is ""
 * when absent; it does not change meaning, it is only kept so a round trip is lossless.
 */
public record Item(Index index, String comment) {
  public Item {
    Objects.requireNonNull(index, "index");
    Objects.requireNonNull(comment, "comment");
  }

  /** {@code [n]} without a comment. */
  public static Item of(int n) {
    return new Item(new Index.Direct(n), "");
  }

  /** {@code [n:comment]}. */
  public static Item of(int n, String comment) {
    return new Item(new Index.Direct(n), comment);
  }
}
