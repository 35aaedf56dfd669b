package org.robotrun.program;

/**
 * A bad statement found by {@link TpStatementParser}: the line and what was expected. Used for
 * control flow inside the parser only (the reader turns it into a {@link Diagnostic} and moves
 * on to the next line), so it carries no stack trace.
 */
public final class TpSyntaxError extends RuntimeException {
  private final int line;

  public TpSyntaxError(int line, String message) {
    super(message, null, false, false);
    this.line = line;
  }

  public int line() {
    return line;
  }
}
