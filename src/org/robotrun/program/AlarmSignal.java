package org.robotrun.program;

/**
 * Thrown inside the interpreter when a line raises an alarm; caught by the run loop, which adds
 * the program and line. Carries no stack trace: it is control flow, not a bug report.
 */
final class AlarmSignal extends RuntimeException {
  final AlarmKind kind;
  final String code;

  AlarmSignal(AlarmKind kind, String message) {
    this(kind, kind.code(), message);
  }

  AlarmSignal(AlarmKind kind, String code, String message) {
    super(message, null, false, false);
    this.kind = kind;
    this.code = code;
  }
}
