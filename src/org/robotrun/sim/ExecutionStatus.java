package org.robotrun.sim;

import java.util.Objects;

/**
 * Where program execution stands, for the pendant's status line.
 *
 * @param program the program running, paused or last selected ("" when none)
 * @param line its current line (1-based; 0 when none)
 * @param state what it is doing
 */
public record ExecutionStatus(String program, int line, State state) {
  public ExecutionStatus {
    Objects.requireNonNull(program, "program");
    Objects.requireNonNull(state, "state");
  }

  /** Execution states. */
  public enum State {
    /** No program active. */
    IDLE,
    /** Running (moving, waiting or executing logic). */
    RUNNING,
    /** Stopped and resumable: HOLD, PAUSE, STEP. */
    PAUSED,
    /** Stopped by an alarm; RESET clears it. */
    ALARMED
  }
}
