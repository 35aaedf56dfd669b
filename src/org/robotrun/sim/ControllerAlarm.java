package org.robotrun.sim;

import java.util.Objects;

/**
 * An alarm as the controller keeps it (active list and history).
 *
 * @param code FANUC-style code, e.g. {@code MOTN-017}, {@code INTP-224}
 * @param message what happened
 * @param program program whose line raised it, "" when not from a program (jog, MOVE_TO, world)
 * @param line that line (1-based), 0 when none
 * @param simTimeSec when it was raised (simulated seconds)
 */
public record ControllerAlarm(String code, String message, String program, int line, double simTimeSec) {
  public ControllerAlarm {
    Objects.requireNonNull(code, "code");
    Objects.requireNonNull(message, "message");
    Objects.requireNonNull(program, "program");
  }

  /** The pendant's one-line form: {@code MOTN-017 (PICK, 4) J5 would reach ...}. */
  public String display() {
    String where = program.isEmpty() ? "" : " (" + program + ", " + line + ")";
    return code + where + " " + message;
  }
}
