package org.robotrun.program;

/**
 * An index outside a register or I/O table ({@code R[0]}, {@code DO[65]}): the interpreter
 * turns it into an alarm naming the line.
 */
public final class RegisterIndexException extends RuntimeException {
  private final String table;
  private final int index;
  private final int size;

  public RegisterIndexException(String table, int index, int size) {
    super(table + "[" + index + "]: index out of range (expected 1.." + size + ")");
    this.table = table;
    this.index = index;
    this.size = size;
  }

  /** The table's name: "R", "PR", "DO", "TIMER"... */
  public String table() {
    return table;
  }

  public int index() {
    return index;
  }

  /** The highest valid index. */
  public int size() {
    return size;
  }
}
