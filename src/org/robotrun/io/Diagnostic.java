package org.robotrun.io;

/**
 * One problem found while reading a file: where it is (file and 1-based line) and what was
 * expected. Errors make the file unusable as written; warnings flag something the reader
 * accepted but a user should look at (a stale LINE_COUNT, an ignored section).
 *
 * @param file the file name as the user gave it
 * @param line 1-based line number (1 for whole-file problems such as an empty file)
 * @param severity error or warning
 * @param message what is wrong and what was expected, fit to show a user as is
 */
public record Diagnostic(String file, int line, Severity severity, String message) {

  /** How bad a diagnostic is. */
  public enum Severity {
    ERROR,
    WARNING
  }

  public static Diagnostic error(String file, int line, String message) {
    return new Diagnostic(file, line, Severity.ERROR, message);
  }

  public static Diagnostic warning(String file, int line, String message) {
    return new Diagnostic(file, line, Severity.WARNING, message);
  }

  public boolean isError() {
    return severity == Severity.ERROR;
  }

  /** {@code file:line: message}, warnings marked as such: the form compilers use, so editors link it. */
  @Override
  public String toString() {
    return file + ":" + line + ": " + (severity == Severity.WARNING ? "warning: " : "") + message;
  }
}
