package org.robotrun.program;

import java.util.Objects;

/**
 * An alarm that stopped a program, as the pendant shows it: {@code SIMU-001 (MAIN, 7) Divide by
 * zero: R[3] is 0}.
 *
 * @param kind which fault
 * @param code FANUC-style code: {@code kind.code()}, or the motion port's own code for MOTION
 * @param program the program whose line raised it
 * @param line the 1-based line number
 * @param message what happened, naming the item involved
 */
public record Alarm(AlarmKind kind, String code, String program, int line, String message) {
  public Alarm {
    Objects.requireNonNull(kind, "kind");
    Objects.requireNonNull(code, "code");
    Objects.requireNonNull(program, "program");
    Objects.requireNonNull(message, "message");
  }

  /** The pendant's one-line form: {@code CODE (PROGRAM, line) message}. */
  public String display() {
    return code + " (" + program + ", " + line + ") " + message;
  }
}
