package org.robotrun.sim;

import java.util.Optional;
import java.util.function.Consumer;

/**
 * Runs one program to its end with no window, as fast as the machine allows: selects it, starts
 * it at line 1 (SHIFT+FWD) and steps the simulation until the program has ended and the arm is
 * at rest, an alarm is active, or the time limit passes. A PAUSE resumes at once (nobody is
 * there to press SHIFT+FWD).
 */
public final class HeadlessRun {
  /** Alarm code reported when the time limit ends the run. */
  public static final String TIME_LIMIT_CODE = "RUN-001";

  /** Alarm code reported when the caller's real-time limit ends the run ({@code --max-wall-seconds}). */
  public static final String WALL_LIMIT_CODE = "RUN-002";

  /** Ticks between two questions to the caller's stop check (about 1 s of simulated time). */
  private static final int STOP_CHECK_TICKS = 250;

  private HeadlessRun() {}

  /** How a run ended. */
  public enum Status {
    FINISHED, ALARM
  }

  /**
   * @param alarm the alarm that stopped the run (a time limit is {@link #TIME_LIMIT_CODE})
   * @param cycleTimeSec simulated seconds from start to end
   */
  public record Result(Status status, Optional<ControllerAlarm> alarm, double simTimeSec, double cycleTimeSec, long ticks) {}

  /**
   * @param afterTick called after every tick (trace rows); may be a no-op
   * @throws IllegalArgumentException if the controller refuses to start the program (the
   *     message says why: missing program, active alarm)
   */
  public static Result run(Simulation sim, Controller c, String program, double maxSimSec, Consumer<Simulation> afterTick) {
    return run(sim, c, program, maxSimSec, afterTick, () -> false, "");
  }

  /**
   * As {@link #run(Simulation, Controller, String, double, Consumer)}, and also asks {@code stop}
   * every {@value #STOP_CHECK_TICKS} ticks: when it answers true the run ends with alarm
   * {@link #WALL_LIMIT_CODE} and {@code stopReason} as its message. The simulation never reads
   * a clock itself; a caller's real-time limit only decides where a run is cut off.
   */
  public static Result run(Simulation sim, Controller c, String program, double maxSimSec, Consumer<Simulation> afterTick,
      java.util.function.BooleanSupplier stop, String stopReason) {
    CommandResult start = c.run(program, 1, true);
    if (start instanceof CommandResult.Refused r) {
      throw new IllegalArgumentException(r.reason());
    }
    double t0 = sim.timeSec();
    while (true) {
      sim.step();
      afterTick.accept(sim);
      if (c.hasActiveAlarm()) {
        return new Result(Status.ALARM, Optional.of(c.activeAlarms().get(0)), sim.timeSec(), sim.timeSec() - t0, sim.ticks());
      }
      ExecutionStatus s = c.status();
      if (s.state() == ExecutionStatus.State.IDLE && !c.busy()) {
        return new Result(Status.FINISHED, Optional.empty(), sim.timeSec(), sim.timeSec() - t0, sim.ticks());
      }
      if (s.state() == ExecutionStatus.State.PAUSED) {
        c.run(s.program(), s.line(), true);
      }
      if (sim.ticks() % STOP_CHECK_TICKS == 0 && stop.getAsBoolean()) {
        ControllerAlarm a = new ControllerAlarm(WALL_LIMIT_CODE, stopReason, s.program(), s.line(), sim.timeSec());
        return new Result(Status.ALARM, Optional.of(a), sim.timeSec(), sim.timeSec() - t0, sim.ticks());
      }
      if (sim.timeSec() - t0 >= maxSimSec) {
        ControllerAlarm a = new ControllerAlarm(TIME_LIMIT_CODE,
            String.format(java.util.Locale.ROOT, "time limit reached: the program ran %.1f s of simulated time without ending", maxSimSec),
            s.program(), s.line(), sim.timeSec());
        return new Result(Status.ALARM, Optional.of(a), sim.timeSec(), sim.timeSec() - t0, sim.ticks());
      }
    }
  }
}
