package org.robotrun.program;

/**
 * The number inside brackets: direct ({@code R[5]}) or indirect through a data register
 * ({@code R[R[2]]}, {@code PR[R[i]]}, {@code LBL[R[i]]}). Also used for "n | R[i]" operands
 * such as {@code UFRAME_NUM=R[3]}.
 */
public sealed interface Index {

  /** A literal number, e.g. the 5 in {@code R[5]}. */
  record Direct(int value) implements Index {}

  /**
   * The value of data register R[register], e.g. {@code R[R[2:PTR]]}; {@code comment} is the
   * inner item comment ("" when absent), kept for lossless round trips.
   */
  record Indirect(int register, String comment) implements Index {
    public Indirect {
      java.util.Objects.requireNonNull(comment, "comment");
    }
  }

  /**
   * The value of CALL argument AR[arg], e.g. {@code R[AR[1]]}: the callee indexes with what its
   * caller passed (an alarm when the argument is missing or not an integer).
   */
  record ViaArg(int arg) implements Index {}

  static Index of(int value) {
    return new Direct(value);
  }

  static Index viaRegister(int register) {
    return new Indirect(register, "");
  }
}
