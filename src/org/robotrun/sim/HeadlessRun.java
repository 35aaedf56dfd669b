package org.robotrun.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import org.robotrun.control.RobotControl;

/**
 * Runs one program to its end with no window, as fast as the machine allows: selects it, starts
 * it at line 1 (SHIFT+FWD) and steps the simulation until the program has ended and the arm is
 * at rest, an alarm is active, or the time limit passes. A PAUSE resumes at once (nobody is
 * there to press SHIFT+FWD).
 */
public final class HeadlessRun {
  /** Alarm code reported when the time limit ends the run. */
  public static final String TIME_LIMIT_CODE = org.robotrun.program.AlarmCode.RUN_001.code();

  /** Alarm code reported when the caller's real-time limit ends the run ({@code --max-wall-seconds}). */
  public static final String WALL_LIMIT_CODE = org.robotrun.program.AlarmCode.RUN_002.code();

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
    CellResult r = runCell(sim, new java.util.LinkedHashMap<>(java.util.Map.of(c, program)), maxSimSec, afterTick, stop,
        stopReason);
    RobotResult one = r.robots().get(0);
    return new Result(one.status() == RobotStatus.FINISHED ? Status.FINISHED : Status.ALARM, one.alarm(), r.simTimeSec(),
        r.cycleTimeSec(), r.ticks());
  }

  /** How one robot's program ended in a cell run. */
  public enum RobotStatus {
    /** The program reached its end and the arm is at rest. */
    FINISHED,
    /** An alarm stopped it (or a time limit). */
    ALARM,
    /** It was still running when another robot's alarm ended the run. */
    STOPPED
  }

  /**
   * One robot's part of a cell run.
   *
   * @param cycleTimeSec simulated seconds from the common start to this robot's end (or the run's)
   * @param busyTimeSec simulated seconds in which this robot's arm moved (ticks whose joints changed)
   */
  public record RobotResult(String robot, String program, RobotStatus status, Optional<ControllerAlarm> alarm,
      double cycleTimeSec, double busyTimeSec) {}

  /**
   * A cell run: every robot's result, in controller order.
   *
   * @param status FINISHED when every robot finished
   * @param alarm the alarm that ended the run (the first robot's in controller order when several alarm at one tick)
   * @param cycleTimeSec the cell's cycle time: from the common start to the last robot's end
   */
  public record CellResult(Status status, Optional<ControllerAlarm> alarm, double simTimeSec, double cycleTimeSec,
      long ticks, List<RobotResult> robots) {}

  /**
   * Runs several robots' programs at once in one cell, as a cell whose operator starts every
   * controller at the same tick: each program starts at line 1 (in controller order, within one
   * tick), the simulation steps every robot each tick, and the run ends when every program has
   * ended and its arm is at rest, or at the first alarm on any robot (a cell stops as a whole:
   * the robots still running are reported {@link RobotStatus#STOPPED}), or at a time limit. A
   * PAUSE resumes at once.
   *
   * @param programs controller → program to run, in the order to start them
   * @throws IllegalArgumentException if a controller refuses to start its program (the message
   *     names the robot when the cell has several and says why)
   */
  public static CellResult runCell(Simulation sim, java.util.Map<Controller, String> programs, double maxSimSec,
      Consumer<Simulation> afterTick, java.util.function.BooleanSupplier stop, String stopReason) {
    List<Controller> cs = new ArrayList<>(programs.keySet());
    int n = cs.size();
    boolean several = sim.controllers().size() > 1;
    for (Controller c : cs) {
      RobotControl.Result start = c.run(programs.get(c), 1, true);
      if (start instanceof RobotControl.Result.Refused r) {
        throw new IllegalArgumentException(several ? c.name() + ": " + r.reason() : r.reason());
      }
    }
    double t0 = sim.timeSec();
    RobotStatus[] status = new RobotStatus[n];
    @SuppressWarnings("unchecked")
    Optional<ControllerAlarm>[] alarm = new Optional[n];
    java.util.Arrays.fill(alarm, Optional.empty());
    double[] end = new double[n];
    long[] movingTicks = new long[n];
    double[][] lastQ = new double[n][];
    for (int i = 0; i < n; i++) {
      lastQ[i] = cs.get(i).jointsRad();
    }
    Optional<ControllerAlarm> cellAlarm = Optional.empty();
    CellStepper stepper = new CellStepper(sim);
    stepper.setAfterTick(afterTick);
    while (true) {
      stepper.tick();
      double t = sim.timeSec();
      int active = 0;
      for (int i = 0; i < n; i++) {
        Controller c = cs.get(i);
        double[] q = c.jointsRad();
        if (!java.util.Arrays.equals(q, lastQ[i])) {
          movingTicks[i]++;
          lastQ[i] = q;
        }
        if (status[i] != null) {
          continue;
        }
        if (c.hasActiveAlarm()) {
          status[i] = RobotStatus.ALARM;
          alarm[i] = Optional.of(c.activeAlarms().get(0));
          end[i] = t;
          if (cellAlarm.isEmpty()) {
            cellAlarm = alarm[i];
          }
          continue;
        }
        ExecutionStatus s = c.status();
        if (s.state() == ExecutionStatus.State.IDLE && !c.busy()) {
          status[i] = RobotStatus.FINISHED;
          end[i] = t;
          continue;
        }
        if (s.state() == ExecutionStatus.State.PAUSED) {
          c.run(s.program(), s.line(), true);
        }
        active++;
      }
      // A limit stops every robot still running, each with the alarm naming its own program and line.
      String limitCode = null;
      String limitText = null;
      if (active > 0 && cellAlarm.isEmpty()) {
        if (sim.ticks() % STOP_CHECK_TICKS == 0 && stop.getAsBoolean()) {
          limitCode = WALL_LIMIT_CODE;
          limitText = stopReason;
        } else if (t - t0 >= maxSimSec) {
          limitCode = TIME_LIMIT_CODE;
          limitText = String.format(java.util.Locale.ROOT,
              "time limit reached: the program ran %.1f s of simulated time without ending", maxSimSec);
        }
      }
      ControllerAlarm limit = limitCode == null ? null : limitAlarm(firstActive(cs, status), limitCode, limitText, t);
      if (active == 0 || cellAlarm.isPresent() || limit != null) {
        cs.forEach(Controller::settleOutputs);  // PROGRUN/BUSY of a robot that ended on this tick go OFF
        List<RobotResult> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
          RobotStatus st = status[i];
          Optional<ControllerAlarm> a = alarm[i];
          if (st == null) {
            // Still running: a time limit stops it with that alarm, another robot's alarm stops the cell.
            st = limit != null ? RobotStatus.ALARM : RobotStatus.STOPPED;
            a = limit == null ? Optional.empty() : Optional.of(limitAlarm(cs.get(i), limitCode, limitText, t));
            end[i] = t;
          }
          out.add(new RobotResult(cs.get(i).name(), programs.get(cs.get(i)), st, a, end[i] - t0,
              movingTicks[i] * sim.tickSec()));
        }
        Optional<ControllerAlarm> first = cellAlarm.isPresent() ? cellAlarm : Optional.ofNullable(limit);
        return new CellResult(first.isPresent() ? Status.ALARM : Status.FINISHED, first, t, t - t0, sim.ticks(),
            List.copyOf(out));
      }
    }
  }

  /** A limit's alarm on {@code c}: its program and line as they stand. */
  private static ControllerAlarm limitAlarm(Controller c, String code, String text, double t) {
    ExecutionStatus s = c.status();
    return new ControllerAlarm(code, text, s.program(), s.line(), t);
  }

  private static Controller firstActive(List<Controller> cs, RobotStatus[] status) {
    for (int i = 0; i < cs.size(); i++) {
      if (status[i] == null) {
        return cs.get(i);
      }
    }
    return cs.get(0);
  }
}
