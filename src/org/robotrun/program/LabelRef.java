package org.robotrun.program;

import java.util.Objects;

/** A label used as a jump target: {@code LBL[10]}, {@code LBL[10:LOOP]} or {@code LBL[R[1]]}. */
public record LabelRef(Index index, String comment) {
  public LabelRef {
    Objects.requireNonNull(index, "index");
    Objects.requireNonNull(comment, "comment");
  }

  public static LabelRef of(int n) {
    return new LabelRef(new Index.Direct(n), "");
  }
}
