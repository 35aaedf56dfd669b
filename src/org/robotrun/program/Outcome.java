package org.robotrun.program;

import java.util.Objects;

/**
 * What the interpreter did in one {@link Interpreter#tick(double)} (or where it stands). The
 * field-less outcomes are shared constants so a tick does not allocate.
 */
public sealed interface Outcome {
  /** A line ran and the program can go on at once (single-line execution). */
  record Continue() implements Outcome {}

  /** A motion is under way; the next tick polls the port. */
  record WaitingForMotion() implements Outcome {}

  /** A {@code WAIT cond} is not yet satisfied. */
  record WaitingOnCondition() implements Outcome {}

  /** A {@code WAIT t(sec)} has time left. */
  record WaitingOnTime() implements Outcome {}

  /** Stopped and resumable: HOLD, PAUSE, STEP, or a finished backward step. */
  record Paused() implements Outcome {}

  /** The top-level program reached END or its last line (also: nothing is running). */
  record Finished() implements Outcome {}

  /** The program stopped on an alarm; RESET clears it. */
  record Alarmed(Alarm alarm) implements Outcome {
    public Alarmed {
      Objects.requireNonNull(alarm, "alarm");
    }
  }

  Outcome CONTINUE = new Continue();
  Outcome WAITING_FOR_MOTION = new WaitingForMotion();
  Outcome WAITING_ON_CONDITION = new WaitingOnCondition();
  Outcome WAITING_ON_TIME = new WaitingOnTime();
  Outcome PAUSED = new Paused();
  Outcome FINISHED = new Finished();
}
