package org.robotrun.sim;

import java.util.Objects;

/** Outcome of a controller command a user can have refused (run, delete, move to, jog). */
public sealed interface CommandResult {

  /** Done or started; {@code message} for the pendant's prompt line ("" when nothing to say). */
  record Ok(String message) implements CommandResult {
    public Ok {
      Objects.requireNonNull(message, "message");
    }
  }

  /** Refused; {@code reason} for the prompt line. */
  record Refused(String reason) implements CommandResult {
    public Refused {
      Objects.requireNonNull(reason, "reason");
    }
  }

  static CommandResult ok() {
    return new Ok("");
  }

  static CommandResult refused(String reason) {
    return new Refused(reason);
  }
}
