package org.robotrun.program;

import java.util.Optional;

/**
 * A statement {@link TpStatementParser} cannot turn into a runnable instruction: either bad
 * text (a syntax error: the line and what was expected) or a form the controller has and
 * RobotRun does not run yet ({@link #unsupported()}: the reader keeps the line as an {@link
 * Instruction.Unsupported}). Used for control flow inside the parser only, so it carries no
 * stack trace.
 */
public final class TpSyntaxError extends RuntimeException {
  private final int line;
  private final int column;
  private final String unsupported;
  private final boolean runnable;

  public TpSyntaxError(int line, String message) {
    this(line, 1, message, null, false);
  }

  private TpSyntaxError(int line, int column, String message, String unsupported, boolean runnable) {
    super(message, null, false, false);
    this.line = line;
    this.column = column;
    this.unsupported = unsupported;
    this.runnable = runnable;
  }

  /** A syntax error at a column. */
  static TpSyntaxError at(int line, int column, String message) {
    return new TpSyntaxError(line, column, message, null, false);
  }

  /** A form the controller has and RobotRun does not run: {@code what} names its kind. */
  static TpSyntaxError unsupported(int line, int column, String what, boolean runnable) {
    return new TpSyntaxError(line, column, "not supported: " + what, what, runnable);
  }

  public int line() {
    return line;
  }

  /** 1-based column of the offending token. */
  public int column() {
    return column;
  }

  /** The kind of statement not supported yet, empty for a syntax error. */
  public Optional<String> unsupported() {
    return Optional.ofNullable(unsupported);
  }

  /** For an unsupported form: whether the program can run on without it (a warning, not an error). */
  public boolean runnable() {
    return runnable;
  }
}
