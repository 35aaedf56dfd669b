package org.robotrun.io;

import java.util.Locale;

/**
 * One problem found while reading a file: where it is (file, 1-based line and column) and what
 * was expected. Errors make the file unusable as written; warnings flag something the reader
 * accepted but a user should look at (a stale LINE_COUNT, an ignored section).
 *
 * @param file the file name as the user gave it
 * @param line 1-based line number (1 for whole-file problems such as an empty file)
 * @param column 1-based column, 1 when the problem is the whole line
 * @param severity error or warning
 * @param kind what sort of problem: only {@link Kind#SYNTAX} errors stop a program from loading
 *     (a controller refuses such a file too); the others are reported and the line alarms
 *     when it runs, as on the controller
 * @param message what is wrong and what was expected, fit to show a user as is
 */
public record Diagnostic(String file, int line, int column, Severity severity, Kind kind, String message) {

  /** How bad a diagnostic is. */
  public enum Severity {
    ERROR,
    WARNING
  }

  /** What sort of problem (the {@code kind} of {@code check --format json}). */
  public enum Kind {
    /** Text a controller would not accept. */
    SYNTAX,
    /** A statement or form the controller has and RobotRun does not run yet. */
    UNSUPPORTED,
    /** A name or number that refers to something missing: CALL target, LBL, P[n]. */
    REFERENCE,
    /** An index or value outside the controller's range. */
    RANGE,
    /** Everything else worth a look: stale LINE_COUNT, file name, encoding. */
    STYLE;

    /** Lower-case name as JSON shows it. */
    public String jsonName() {
      return name().toLowerCase(Locale.ROOT);
    }
  }

  /** The four-field form most readers use: column 1, kind from the message. */
  public Diagnostic(String file, int line, Severity severity, String message) {
    this(file, line, 1, severity, classify(severity, message), message);
  }

  public static Diagnostic error(String file, int line, String message) {
    return new Diagnostic(file, line, Severity.ERROR, message);
  }

  public static Diagnostic warning(String file, int line, String message) {
    return new Diagnostic(file, line, Severity.WARNING, message);
  }

  /** A diagnostic of a stated kind at a column. */
  public static Diagnostic of(String file, int line, int column, Severity severity, Kind kind, String message) {
    return new Diagnostic(file, line, Math.max(1, column), severity, kind, message);
  }

  public boolean isError() {
    return severity == Severity.ERROR;
  }

  /** Whether this stops the program from loading: a syntax error (a controller refuses the file too). */
  public boolean blocksLoading() {
    return severity == Severity.ERROR && kind == Kind.SYNTAX;
  }

  /** The kind a message names, for the readers that state only a message. */
  static Kind classify(Severity severity, String message) {
    if (message.startsWith("not supported")) {
      return Kind.UNSUPPORTED;
    }
    if (message.contains("out of range") || message.contains("expected 1..") || message.contains("expected 0..")) {
      return Kind.RANGE;
    }
    if (message.contains("no program named") || message.contains("is not defined") || message.contains("/POS has no")
        || message.contains("is also defined in") || message.contains("not in the macro table")) {
      return Kind.REFERENCE;
    }
    return severity == Severity.ERROR ? Kind.SYNTAX : Kind.STYLE;
  }

  /** {@code file:line: message}, warnings marked as such: the form compilers use, so editors link it. */
  @Override
  public String toString() {
    return file + ":" + line + ": " + (severity == Severity.WARNING ? "warning: " : "") + message;
  }
}
