package org.robotrun.app;

/**
 * An error the user can fix (bad file, bad value, missing directory). The command line prints
 * its message on one line and exits with its code; no stack trace.
 */
public final class UserError extends RuntimeException {
  private final int exitCode;

  public UserError(String message) {
    this(message, Main.EXIT_BAD_INPUT);
  }

  public UserError(String message, int exitCode) {
    super(message);
    this.exitCode = exitCode;
  }

  public int exitCode() {
    return exitCode;
  }
}
