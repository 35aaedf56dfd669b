package org.robotrun.io;

/**
 * A bad statement found by {@link LsStatementParser}: the line and what was expected. Used for
 * control flow inside the parser only (the reader turns it into a {@link Diagnostic} and moves
 * on to the next line), so it carries no stack trace.
 */
final class LsSyntaxError extends RuntimeException {
  private final int line;

  LsSyntaxError(int line, String message) {
    super(message, null, false, false);
    this.line = line;
  }

  int line() {
    return line;
  }
}
