package org.robotrun.program;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import org.robotrun.program.MotionRequest.Waypoint;

/**
 * Runs TP programs the way a controller does, one tick at a time: a program counter and an
 * explicit call stack (no recursion in Java), so a pendant can run (SHIFT+FWD), single-step
 * (STEP), HOLD, resume, run backward (SHIFT+BWD), and RESET an alarm (TP-LANGUAGE.md,
 * "Execution").
 *
 * <p>Time is the caller's: {@link #tick(double)} advances simulated time and runs lines until the
 * program waits (motion, WAIT), pauses, ends or alarms. Motions go to the {@link MotionPort};
 * the interpreter waits for the port to report them done. A tick that runs more than
 * {@link InterpreterSettings#instructionBudgetPerTick()} lines without waiting raises a runaway
 * alarm rather than freezing the application.
 *
 * <p>Programs are compiled once per version ({@link Compiler}); the run loop and expression
 * evaluation then allocate nothing for non-motion statements.
 *
 * <p>Semantics worth knowing (FANUC's where the language defines them): {@code /} always gives a
 * real, {@code DIV} truncates toward zero, {@code MOD} takes the sign of the dividend; integer
 * arithmetic that leaves 32 bits becomes real; a FOR loop whose start is past its end skips the
 * body, and after a completed loop the counter holds the end value; {@code WAIT cond
 * TIMEOUT,LBL[n]} jumps after {@code $WAITTMOUT}; TIMERs count simulated time on every tick;
 * {@code Skip,LBL[n]} jumps after the motion because RobotRun has no skip condition that could
 * become true; plain {@code Offset} (which needs OFFSET CONDITION) is an alarm.
 *
 * <p>Not thread-safe: one interpreter per controller, driven by the simulation thread.
 */
public final class Interpreter {

  /** Where the interpreter stands. */
  public enum State {
    /** No program running; {@link #forward()} starts the selected program at the cursor. */
    IDLE,
    /** Running or waiting (motion, WAIT). */
    RUNNING,
    /** Stopped and resumable (HOLD, PAUSE, STEP, after a backward step). */
    PAUSED,
    /**
     * Stopped by an alarm; {@link #reset()} clears it. An ABORT-severity alarm ended the program
     * (RESET leaves it IDLE); a PAUSE/STOP/SERVO one keeps it paused on the faulty line with its
     * call stack (RESET leaves it PAUSED, SHIFT+FWD re-runs that line).
     */
    ALARMED
  }

  /** Highest UFRAME / UTOOL number. */
  static final int FRAME_COUNT = 10;

  private static final int W_NONE = 0;
  private static final int W_MOTION = 1;
  private static final int W_TIME = 2;
  private static final int W_CONDITION = 3;
  private static final double TIME_EPS_SEC = 1e-9;
  private static final int MAX_SCREEN_LINES = 100;

  final ProgramStore store;
  final Registers regs;
  final MotionPort port;
  /** The vision system ({@link VisionPort#NONE} until a cell with vision sets one). */
  VisionPort vision = VisionPort.NONE;
  final InterpreterSettings settings;
  /** $WAITTMOUT in seconds: starts at the setting, a program may change it (global, as on the controller). */
  double waitTimeoutSec;
  /** The last SKIP CONDITION of this run, or null. */
  Nodes.Node skipCondition;
  /** The PR of the last OFFSET CONDITION of this run, or null. */
  Item offsetCondition;
  /** The user frame of the OFFSET CONDITION's offset, -1 for the motion's own frame. */
  int offsetConditionFrame = -1;

  private final Map<String, CompiledProgram> compiled = new HashMap<>();
  private final Frame[] frames;
  private int depth;
  /** The running frame ({@code frames[depth - 1]}), or null when idle. */
  Frame cur;

  private State state = State.IDLE;
  private boolean stepMode;
  private Alarm alarm;
  private Outcome alarmOutcome;
  /** The alarm paused the program (call stack kept) instead of ending it. */
  private boolean alarmPaused;
  private Outcome haltOutcome = Outcome.FINISHED;
  private String selected = "";
  private int cursorLine = 1;
  /**
   * After the top program ran past its last line: that program, the cursor line it was left on
   * and the index of the next line (past the end). The robot then stands at the last line's
   * point, not at the motion above the cursor, so SHIFT+BWD must start below the cursor.
   */
  private String finishedProgram;
  private int finishedCursorLine = -1;
  private int finishedNextPc = -1;

  private int waitKind = W_NONE;
  /** Line index of the statement being waited on (motion or WAIT). */
  private int waitLine;
  private long motionHandle;
  private boolean motionHeld;
  private boolean motionBackward;
  private Ops.LabelTarget motionSkip;
  /** TIME BEFORE actions of the motion in flight, not fired yet. */
  private final java.util.List<Motion.TimedAction> motionBefore = new java.util.ArrayList<>(2);
  /** TIME AFTER actions of the motion in flight, started when it is done. */
  private final java.util.List<Motion.TimedAction> motionAfter = new java.util.ArrayList<>(2);
  /** Condition monitors in force: condition program → its WHEN lines (condition node, action program). */
  private final Map<String, List<Object[]>> monitors = new java.util.LinkedHashMap<>();
  /** Action programs of monitors that fired, running beside the program. */
  private final List<Interpreter> actions = new ArrayList<>(1);
  /** TIME AFTER actions counting down: seconds left, and the action. */
  private final java.util.List<AfterTimer> afterTimers = new java.util.ArrayList<>(2);

  /** A TIME AFTER action counting down (a plain field, not a boxed double per tick). */
  private static final class AfterTimer {
    double leftSec;
    final Motion.TimedAction action;

    AfterTimer(double leftSec, Motion.TimedAction action) {
      this.leftSec = leftSec;
      this.action = action;
    }
  }
  private double waitRemainingSec;
  private double waitElapsedSec;
  private Ops.WaitConditionOp waitOp;

  /** Type of the value the last evaluated expression node returned ({@link Nodes#INT}…). */
  int kind;
  /** String value of the last node when {@code kind == STR}. */
  String str;

  /** Whether this interpreter's tick counts the shared pulses down (false under a controller). */
  private boolean ownsPulseClock = true;
  private final List<String> userScreen = new ArrayList<>();
  private String notice = "";
  private long executedLines;
  private TaskPort taskPort = TaskPort.NONE;
  /** Whether this interpreter advances the shared timers (one per controller does; other tasks do not). */
  private boolean advancesTimers = true;

  /** Runs programs from {@code store} on {@code registers}, moving through {@code port}. */
  public Interpreter(ProgramStore store, Registers registers, MotionPort port, InterpreterSettings settings) {
    this.store = Objects.requireNonNull(store, "store");
    this.regs = Objects.requireNonNull(registers, "registers");
    this.port = Objects.requireNonNull(port, "port");
    this.settings = Objects.requireNonNull(settings, "settings");
    this.waitTimeoutSec = settings.waitTimeoutSec();
    this.frames = new Frame[settings.maxCallDepth()];
    for (int i = 0; i < frames.length; i++) {
      frames[i] = new Frame();
    }
  }

  // ================================================================ pendant-facing API

  /** The vision system VISION RUN_FIND reaches ({@link VisionPort#NONE} when the cell has none). */
  public VisionPort visionPort() {
    return vision;
  }

  /** Connects the vision system VISION RUN_FIND reaches. */
  public void setVisionPort(VisionPort port) {
    this.vision = Objects.requireNonNull(port, "port");
  }

  /** Where {@code RUN} sends its requests (the controller's task manager). */
  public void setTaskPort(TaskPort port) {
    this.taskPort = Objects.requireNonNull(port, "port");
  }

  TaskPort taskPort() {
    return taskPort;
  }

  /**
   * A second task of a controller shares the registers with the first, whose interpreter alone
   * advances TIMER[] each tick (otherwise they would run twice as fast).
   */
  public void setAdvancesTimers(boolean on) {
    this.advancesTimers = on;
  }

  /** Selects the program SHIFT+FWD starts, with the cursor on line 1. Only when no program is active. */
  public void select(String program) {
    requireIdle("select a program");
    selected = Objects.requireNonNull(program, "program");
    cursorLine = 1;
  }

  /** Moves the cursor (1-based line) of an idle program or of the paused current program. */
  public void setCursor(int line) {
    if (line < 1) {
      throw new IllegalArgumentException("line " + line + ": lines start at 1");
    }
    switch (state) {
      case IDLE, ALARMED -> cursorLine = line;
      case PAUSED -> {
        cancelWait();
        cur.pc = line - 1;
      }
      case RUNNING -> throw new IllegalStateException("cannot move the cursor of a running program: HOLD first");
    }
  }

  /** STEP on (one line per {@link #forward()}) or off (run continuously). */
  public void setStepMode(boolean on) {
    stepMode = on;
  }

  public boolean stepMode() {
    return stepMode;
  }

  /**
   * SHIFT+FWD: starts the selected program at the cursor when idle, or resumes a paused one
   * (a held motion continues). Does nothing while running or alarmed (RESET first).
   */
  public void forward() {
    // a notice answers the command that caused it (a BWD at the top); a new command starts clean
    notice = "";
    reload();
    switch (state) {
      case IDLE -> start();
      case PAUSED -> {
        if (structureErrorOnStack()) {
          return;
        }
        if (waitKind == W_MOTION && motionHeld) {
          port.resume(motionHandle);
          motionHeld = false;
        }
        state = State.RUNNING;
      }
      case RUNNING, ALARMED -> {
        // Nothing to do: already running, or an alarm must be reset first.
      }
    }
  }

  /** HOLD: pauses a running program; a motion in progress decelerates and stays resumable. */
  public void hold() {
    if (state != State.RUNNING) {
      return;
    }
    if (waitKind == W_MOTION && !motionHeld) {
      port.hold(motionHandle);
      motionHeld = true;
    }
    state = State.PAUSED;
  }

  /**
   * RESET: clears an alarm. The program is no longer active; the cursor stays on the alarm's
   * line of the program that raised it, so SHIFT+FWD runs on from there.
   */
  public void reset() {
    if (state == State.ALARMED) {
      state = alarmPaused ? State.PAUSED : State.IDLE;
      alarmPaused = false;
      alarm = null;
      alarmOutcome = null;
    }
  }

  /** Whether a program is on the stack: running, paused, or paused by an alarm not yet reset. */
  private boolean active() {
    return state == State.RUNNING || state == State.PAUSED || (state == State.ALARMED && alarmPaused);
  }

  /** FCTN ABORT: ends the active program (cancelling its motion); the cursor stays where it was. */
  public void abort() {
    if (active()) {
      int line = cursorLine();
      String program = cur.prog.name;
      cancelWait();
      deactivate(program, line);
      // the program is no longer active; the controller keeps the alarm shown until RESET
      alarmPaused = false;
      alarm = null;
      alarmOutcome = null;
    }
  }

  /**
   * SHIFT+BWD: one backward step. The robot is taken to stand at the target of the nearest
   * motion line above the cursor; it moves back to the motion line above that one, using the
   * motion type and speed of the line it backs out of (FINE), and the cursor lands on the line it
   * backed out of (so SHIFT+FWD re-runs it). Lines with no effect are passed over; CALL, JMP,
   * WAIT, I/O and other flow statements stop it with a {@link #notice()}.
   *
   * @return WaitingForMotion when a backward motion started, Paused when it stopped with a
   *     notice, the alarm when building the motion failed, Continue when the program is running
   *     (HOLD first; nothing happens)
   */
  public Outcome backward() {
    notice = "";
    reload();
    switch (state) {
      case RUNNING -> {
        notice = "BWD: program is running; HOLD first";
        return Outcome.CONTINUE;
      }
      case ALARMED -> {
        return alarmOutcome;
      }
      case IDLE -> {
        CompiledProgram cp = compiledOrNull(selected);
        if (cp == null) {
          notice = "BWD: no program " + selected;
          return Outcome.FINISHED;
        }
        boolean ranOffTheEnd = cp.name.equals(finishedProgram) && cursorLine == finishedCursorLine;
        push(cp, ranOffTheEnd ? finishedNextPc : Math.min(cursorLine - 1, cp.ops.length));
        finishedProgram = null;
        state = State.PAUSED;
      }
      case PAUSED -> {
        if (structureErrorOnStack()) {
          return alarmOutcome;
        }
        if (waitKind == W_MOTION) {
          // A held motion is abandoned; backing out of it returns to its start point.
          port.cancel(motionHandle);
          waitKind = W_NONE;
        } else if (waitKind != W_NONE) {
          cur.pc = waitLine;
          waitKind = W_NONE;
        }
      }
    }
    return backwardStep();
  }

  /**
   * Brings every program on the call stack up to date with the store after an edit, so what runs
   * is what the store (the pendant) shows (docs/tp-execution.md, "Editing a paused program").
   * Each program whose stored version changed is recompiled and its place carried over by
   * {@link LineMap}: the paused line (the line waited on, else the next line) keeps its identity
   * when the edit left it alone; when it was changed or deleted, the line that took its place
   * runs next (the end when none). A caller goes on just below its CALL line. A held motion or
   * WAIT whose line and positions are unchanged stays resumable; otherwise it is cancelled and
   * its line (its replacement) runs again from where the robot stands. While running, a motion
   * in flight is let finish. FOR loops in progress keep their state on kept lines. Cheap when
   * nothing changed; {@link #forward()} and {@link #backward()} call it too.
   */
  public void reload() {
    for (int i = 0; i < depth; i++) {
      Frame f = frames[i];
      CompiledProgram now = compiledOrNull(f.prog.name);
      if (now == null || now == f.prog) {
        // unchanged, or no longer stored (the controller refuses to delete an active program)
        continue;
      }
      CompiledProgram was = f.prog;
      LineMap map = LineMap.between(was.program.lines(), now.program.lines());
      int pc;
      if (i < depth - 1) {
        pc = map.returnPoint(f.pc);
      } else if (waitKind == W_NONE) {
        pc = map.position(f.pc);
      } else {
        pc = carryWait(map, was, now, f.pc);
      }
      f.remap(now, map, Math.min(pc, now.ops.length));
    }
  }

  /** The top frame's new pc when it waits (motion, WAIT) in a program just edited; see {@link #reload()}. */
  private int carryWait(LineMap map, CompiledProgram was, CompiledProgram now, int oldPc) {
    int kept = map.kept(waitLine);
    boolean positionsChanged = waitKind == W_MOTION && !was.program.positions().equals(now.program.positions());
    if (!motionBackward && kept >= 0 && !(positionsChanged && state == State.PAUSED)) {
      // the same line in the new code: the wait goes on; its label targets are the new program's
      waitLine = kept;
      if (waitKind == W_MOTION) {
        motionSkip = ((Ops.MoveOp) now.ops[kept]).skip;
      } else if (waitKind == W_CONDITION) {
        waitOp = (Ops.WaitConditionOp) now.ops[kept];
      }
      return kept + 1;
    }
    if (state == State.PAUSED || waitKind == W_CONDITION) {
      // re-run the edited line (or the one in its place) from here; a backward step starts over
      int at = motionBackward ? map.position(oldPc) : map.position(waitLine);
      cancelWait();
      return at;
    }
    // running: a motion or a timed WAIT of a changed line finishes; the program goes on after it
    motionSkip = null;
    waitLine = Math.max(0, Math.min(map.position(waitLine), now.ops.length - 1));
    return map.position(oldPc);
  }

  /** Whether a program on the stack no longer compiles (an edit broke FOR/IF/SELECT): alarms if so. */
  private boolean structureErrorOnStack() {
    for (int i = depth - 1; i >= 0; i--) {
      CompiledProgram p = frames[i].prog;
      if (p.structureError != null) {
        raise(new AlarmSignal(AlarmKind.STRUCTURE, p.structureError), p.name, p.structureErrorLine + 1);
        return true;
      }
    }
    return false;
  }

  /** Whether {@code program} is on the call stack of an active (running or paused) program. */
  public boolean isActive(String program) {
    for (int i = 0; i < depth; i++) {
      if (frames[i].prog.name.equals(program)) {
        return true;
      }
    }
    return false;
  }

  /**
   * Advances simulated time by {@code dtSec} (pulses, timers, waits) and runs the program until it
   * waits, pauses, ends or alarms.
   */
  public Outcome tick(double dtSec) {
    if (!(dtSec >= 0) || Double.isInfinite(dtSec)) {
      throw new IllegalArgumentException("dtSec must be finite and >= 0, got " + dtSec);
    }
    if (ownsPulseClock) {
      regs.advancePulses(dtSec);
    }
    if (!afterTimers.isEmpty()) {
      try {
        advanceTimedActions(dtSec);
      } catch (AlarmSignal a) {
        if (state == State.RUNNING || state == State.PAUSED) {
          return raise(a, cur.prog.name, Math.max(1, cur.pc));
        }
        // Already stopped by an alarm: the pending action is dropped, never thrown out of the tick.
        afterTimers.clear();
      }
    }
    if (advancesTimers) {
      regs.advanceTimers(dtSec);
    }
    if (state == State.RUNNING && !monitors.isEmpty()) {
      try {
        checkMonitors();
      } catch (AlarmSignal a) {
        return raise(a, cur.prog.name, waitKind != W_NONE ? waitLine + 1 : Math.max(1, cur.pc));
      }
    }
    if (!actions.isEmpty()) {
      Outcome failed = tickActions(dtSec);
      if (failed != null) {
        return failed;
      }
    }
    switch (state) {
      case IDLE -> {
        return Outcome.FINISHED;
      }
      case PAUSED -> {
        return Outcome.PAUSED;
      }
      case ALARMED -> {
        return alarmOutcome;
      }
      case RUNNING -> {
        // Below.
      }
    }
    if (waitKind != W_NONE) {
      Outcome waiting = serviceWait(dtSec);
      if (waiting != null) {
        return waiting;
      }
    }
    return runLines();
  }

  public State state() {
    return state;
  }

  /** The alarm that stopped the program, while ALARMED. */
  public Optional<Alarm> alarm() {
    return Optional.ofNullable(alarm);
  }

  /** The active program's name (the callee inside a CALL), or the selected one when idle. */
  public String currentProgram() {
    return cur != null ? cur.prog.name : selected;
  }

  /**
   * The cursor (1-based): the line being waited on, else the line the next SHIFT+FWD runs; when
   * idle or alarmed, where the program stopped or was put.
   */
  public int cursorLine() {
    if (cur == null) {
      return cursorLine;
    }
    return waitKind != W_NONE ? waitLine + 1 : cur.pc + 1;
  }

  /** Programs on the call stack (1 = top program only, 0 when idle). */
  public int callDepth() {
    return depth;
  }

  /** MESSAGE[] texts, oldest first (the user screen), at most the last 100. */
  public List<String> userScreen() {
    return Collections.unmodifiableList(userScreen);
  }

  /** The note about the last SHIFT+FWD or SHIFT+BWD (e.g. why backward execution stopped), "" when none. */
  public String notice() {
    return notice;
  }

  /** Lines executed since construction (for throughput figures). */
  public long executedLines() {
    return executedLines;
  }

  // ================================================================ run loop

  private Outcome runLines() {
    int budget = settings.instructionBudgetPerTick();
    Frame f = cur;
    int line = f.pc;
    try {
      while (true) {
        f = cur;
        line = f.pc;
        Ops.Op[] ops = f.prog.ops;
        if (line >= ops.length) {
          // Running past the last line is an END.
          if (end() != Ops.NEXT) {
            return haltOutcome;
          }
          continue;
        }
        if (--budget < 0) {
          throw new AlarmSignal(AlarmKind.RUNAWAY, "more than " + settings.instructionBudgetPerTick()
              + " lines in one tick without motion or WAIT (runaway loop)");
        }
        f.pc = line + 1;
        executedLines++;
        if (ops[line].exec(this) != Ops.NEXT) {
          return haltOutcome;
        }
        if (stepMode) {
          state = State.PAUSED;
          return Outcome.PAUSED;
        }
      }
    } catch (AlarmSignal a) {
      return raise(a, f.prog.name, line + 1);
    }
  }

  private Outcome serviceWait(double dtSec) {
    try {
      switch (waitKind) {
        case W_MOTION -> {
          switch (port.poll(motionHandle)) {
            case RUNNING -> {
              if (!motionBefore.isEmpty() && !motionHeld) {
                fireBefore(false);
              }
              if (motionSkip != null && skipCondition != null && !motionHeld && skipCondition.bool(this, "SKIP CONDITION")) {
                // The skip condition turned true: the arm stops and the program goes on with the
                // next line, without the jump (FANUC Skip,LBL[] semantics).
                port.cancel(motionHandle);
                waitKind = W_NONE;
                motionSkip = null;
                break;
              }
              return Outcome.WAITING_FOR_MOTION;
            }
            case FAILED -> {
              MotionPort.Start.Rejected why = port.failure(motionHandle);
              waitKind = W_NONE;
              throw new AlarmSignal(AlarmKind.MOTION, why.code(), why.message());
            }
            case DONE -> {
              waitKind = W_NONE;
              // CNT: done when blending starts; TIME BEFORE actions not fired yet fire now, and
              // TIME AFTER actions start counting (RobotRun's approximation of "after the point").
              fireBefore(true);
              for (Motion.TimedAction t : motionAfter) {
                afterTimers.add(new AfterTimer(t.amount(), t));
              }
              motionAfter.clear();
              if (!afterTimers.isEmpty()) {
                advanceTimedActions(0);
              }
              if (motionBackward) {
                state = State.PAUSED;
                return Outcome.PAUSED;
              }
              if (motionSkip != null) {
                cur.pc = motionSkip.line(this);
              }
            }
          }
        }
        case W_TIME -> {
          waitRemainingSec -= dtSec;
          if (waitRemainingSec > TIME_EPS_SEC) {
            return Outcome.WAITING_ON_TIME;
          }
          waitKind = W_NONE;
        }
        case W_CONDITION -> {
          waitElapsedSec += dtSec;
          if (!waitOp.condition.bool(this, "WAIT")) {
            if (waitOp.timeout == null || waitElapsedSec < waitTimeoutSec - TIME_EPS_SEC) {
              return Outcome.WAITING_ON_CONDITION;
            }
            cur.pc = waitOp.timeout.line(this);
          }
          waitKind = W_NONE;
        }
        default -> throw new IllegalStateException("wait kind " + waitKind);
      }
    } catch (AlarmSignal a) {
      waitKind = W_NONE;
      return raise(a, cur.prog.name, waitLine + 1);
    }
    if (stepMode) {
      state = State.PAUSED;
      return Outcome.PAUSED;
    }
    return null;
  }

  /**
   * Stops the program on an alarm, as its severity says (docs/alarms.md): ABORT ends it (the
   * cursor stays on the alarm's line of the program that raised it); PAUSE, STOP and SERVO keep
   * the call stack with the faulty line next, so RESET then SHIFT+FWD runs that line again.
   */
  private Outcome raise(AlarmSignal a, String program, int line) {
    cancelWait();
    alarm = new Alarm(a.kind, a.code, program, line, a.getMessage());
    alarmOutcome = new Outcome.Alarmed(alarm);
    if (pausesProgram(a) && cur != null && cur.prog.name.equals(program) && line >= 1) {
      cur.pc = Math.min(line - 1, cur.prog.ops.length);
      alarmPaused = true;
    } else {
      deactivate(program, line);
      alarmPaused = false;
    }
    state = State.ALARMED;
    return alarmOutcome;
  }

  /** Whether the alarm's severity pauses the program (PAUSE, STOP, SERVO) rather than ending it. */
  private static boolean pausesProgram(AlarmSignal a) {
    AlarmSeverity s = AlarmCode.of(a.code).map(AlarmCode::severity).orElse(a.kind.entry().severity());
    return s == AlarmSeverity.PAUSE || s == AlarmSeverity.STOP || s == AlarmSeverity.SERVO;
  }

  private void deactivate(String program, int line) {
    // What the program started ends with it: pending TIME AFTER actions, its condition monitors,
    // and the action programs they called (an abort or END never leaves one firing later).
    afterTimers.clear();
    monitors.clear();
    for (Interpreter child : actions) {
      child.abort();
    }
    actions.clear();
    for (int i = 0; i < depth; i++) {
      frames[i].prog = null;
    }
    depth = 0;
    cur = null;
    selected = program;
    cursorLine = Math.max(1, line);
    state = State.IDLE;
  }

  private void cancelWait() {
    if (waitKind == W_MOTION) {
      port.cancel(motionHandle);
    }
    motionBefore.clear();
    motionAfter.clear();
    waitKind = W_NONE;
    motionHeld = false;
  }

  private void requireIdle(String what) {
    if (active()) {
      throw new IllegalStateException("cannot " + what + " while program " + currentProgram() + " is active");
    }
  }

  private void start() {
    notice = "";
    CompiledProgram cp = compiledOrNull(selected);
    if (cp == null) {
      raise(new AlarmSignal(AlarmKind.UNKNOWN_PROGRAM, "program " + selected + " does not exist"), selected, cursorLine);
      return;
    }
    if (cp.structureError != null) {
      raise(new AlarmSignal(AlarmKind.STRUCTURE, cp.structureError), cp.name, cp.structureErrorLine + 1);
      return;
    }
    push(cp, Math.min(cursorLine - 1, cp.ops.length));
    skipCondition = null;
    offsetCondition = null;
    offsetConditionFrame = -1;
    monitors.clear();
    finishedProgram = null;
    state = State.RUNNING;
  }

  private void push(CompiledProgram cp, int pc) {
    Frame f = frames[depth];
    f.enter(cp, pc);
    depth++;
    cur = f;
  }

  private CompiledProgram compiledOrNull(String name) {
    Optional<Program> found = store.find(name);
    if (found.isEmpty()) {
      return null;
    }
    Program p = found.get();
    CompiledProgram c = compiled.get(name);
    if (c == null || c.program != p) {
      c = Compiler.compile(p);
      compiled.put(name, c);
    }
    return c;
  }

  // ================================================================ services for compiled code

  /** END, or running past the last line: return to the caller, or finish the top program. */
  int end() {
    if (depth <= 1) {
      int line = Math.max(1, Math.min(cur.pc, cur.prog.ops.length));
      boolean pastLastLine = cur.pc >= cur.prog.ops.length;
      finishedProgram = pastLastLine ? cur.prog.name : null;
      finishedCursorLine = line;
      finishedNextPc = cur.prog.ops.length;
      deactivate(cur.prog.name, line);
      haltOutcome = Outcome.FINISHED;
      return Ops.HALT;
    }
    frames[depth - 1].prog = null;
    depth--;
    cur = frames[depth - 1];
    return Ops.NEXT;
  }

  int pauseProgram() {
    state = State.PAUSED;
    haltOutcome = Outcome.PAUSED;
    return Ops.HALT;
  }

  /** CALL: evaluates the arguments in the caller, then enters the callee at line 1. */
  void call(String name, Nodes.Node[] args, int returnPc) {
    CompiledProgram cp = compiledOrNull(name);
    if (cp == null) {
      throw new AlarmSignal(AlarmKind.UNKNOWN_PROGRAM, "CALL " + name + ": no such program");
    }
    if (depth + 1 > settings.maxCallDepth()) {
      throw new AlarmSignal(AlarmKind.CALL_DEPTH,
          "CALL " + name + ": call depth would exceed " + settings.maxCallDepth());
    }
    if (cp.structureError != null) {
      throw new AlarmSignal(AlarmKind.STRUCTURE,
          "CALL " + name + ": line " + (cp.structureErrorLine + 1) + ": " + cp.structureError);
    }
    Frame callee = frames[depth];
    callee.ensureArgs(args.length);
    for (int i = 0; i < args.length; i++) {
      callee.argValue[i] = args[i].eval(this);
      callee.argKind[i] = kind;
      callee.argString[i] = kind == Nodes.STR ? str : null;
    }
    cur.pc = returnPc;
    int nargs = args.length;
    push(cp, 0);
    callee.nargs = nargs;
  }

  /** AR[i] of the running program. */
  double readArg(int i) {
    Frame f = cur;
    if (i < 1 || i > f.nargs) {
      throw new AlarmSignal(AlarmKind.BAD_INDEX,
          "AR[" + i + "]: " + f.prog.name + " was called with " + f.nargs + " argument" + (f.nargs == 1 ? "" : "s"));
    }
    kind = f.argKind[i - 1];
    if (kind == Nodes.STR) {
      str = f.argString[i - 1];
    }
    return f.argValue[i - 1];
  }

  /** R[i] = value of type {@link #kind}; ON/OFF stores 1/0, a string is a type mismatch. */
  void storeR(int i, double v) {
    switch (kind) {
      case Nodes.INT, Nodes.BOOL -> {
        regs.r[i] = v;
        regs.rIsInteger[i] = true;
      }
      case Nodes.REAL -> {
        regs.r[i] = v;
        regs.rIsInteger[i] = false;
      }
      case Nodes.STR -> {
        // R[i]=SR[j]: the string's leading number
        double n = Nodes.number(this, str, "R[" + i + "]=" + "a string");
        storeR(i, n);
      }
      default -> throw Nodes.mismatch("R[" + i + "] needs a number", kind);
    }
  }

  /** The value of R[j] used as an index ({@code R[R[j]]}, {@code LBL[R[j]]}): a whole number. */
  /** The CALL argument AR[j] as an index (R[AR[1]]): an alarm when it is missing or not a whole number. */
  int argAsIndex(int j) {
    double v = readArg(j);
    if (kind == Nodes.STR || !Nodes.isWhole(v)) {
      throw new AlarmSignal(AlarmKind.BAD_INDEX, "AR[" + j + "] is not a whole number and cannot be an index");
    }
    return (int) v;
  }

  int registerAsIndex(int j) {
    Nodes.check("R", j, Registers.R_COUNT);
    double v = regs.r[j];
    if (!Nodes.isWhole(v)) {
      throw new AlarmSignal(AlarmKind.BAD_INDEX, "R[" + j + "]=" + v + " is not a whole number and cannot be an index");
    }
    return (int) v;
  }

  LocalPosition localPosition(int n) {
    Optional<LocalPosition> p = cur.prog.program.position(n);
    if (p.isEmpty()) {
      throw new AlarmSignal(AlarmKind.UNDEFINED_POSITION, "P[" + n + "] is not in the /POS block of " + cur.prog.name);
    }
    return p.get();
  }

  int waitTime(double seconds) {
    if (seconds <= 0) {
      return Ops.NEXT;
    }
    waitKind = W_TIME;
    waitLine = cur.pc - 1;
    waitRemainingSec = seconds;
    haltOutcome = Outcome.WAITING_ON_TIME;
    return Ops.HALT;
  }

  int waitCondition(Ops.WaitConditionOp op) {
    waitKind = W_CONDITION;
    waitLine = cur.pc - 1;
    waitOp = op;
    waitElapsedSec = 0;
    haltOutcome = Outcome.WAITING_ON_CONDITION;
    return Ops.HALT;
  }

  void pulse(IoKind io, int i, double widthSec) {
    // A zero width still shows ON until the next tick. The countdown is the I/O's (Registers).
    regs.startPulse(io, i, widthSec);
  }

  /**
   * Leaves counting pulses down to the caller, who calls {@link Registers#advancePulses} once per
   * tick for every interpreter sharing these registers (the controller: its main program, RUN
   * tasks, action programs and BG Logic). A lone interpreter counts them itself.
   */
  public void leavePulsesToCaller() {
    ownsPulseClock = false;
  }

  // ================================================================ condition monitors

  /** MONITOR NAME: watches the WHEN lines of condition program NAME (again, if it fired before). */
  void monitorStart(String name) {
    Optional<Program> p = store.find(name);
    if (p.isEmpty()) {
      throw new AlarmSignal(AlarmKind.UNKNOWN_PROGRAM, "MONITOR " + name + ": no such program");
    }
    List<Object[]> whens = new ArrayList<>();
    for (Instruction in : p.get().lines()) {
      if (in instanceof Instruction.When w) {
        whens.add(new Object[] {Compiler.expr(w.condition()), w.action().program()});
      }
    }
    if (whens.isEmpty()) {
      throw new AlarmSignal(AlarmKind.BAD_VALUE, "MONITOR " + name + ": the program has no WHEN line (a condition "
          + "program holds WHEN ...,CALL ... lines)");
    }
    monitors.put(name, whens);
  }

  /** MONITOR END NAME. */
  void monitorEnd(String name) {
    monitors.remove(name);
  }

  /**
   * Tests the WHEN conditions of the monitors in force (every tick while the program runs or
   * waits). A monitor whose condition holds ends (it is one-shot: MONITOR starts it again) and
   * its action program starts beside the program.
   */
  private void checkMonitors() {
    for (java.util.Iterator<Map.Entry<String, List<Object[]>>> it = monitors.entrySet().iterator(); it.hasNext(); ) {
      Map.Entry<String, List<Object[]>> e = it.next();
      for (Object[] w : e.getValue()) {
        if (((Nodes.Node) w[0]).bool(this, "WHEN")) {
          it.remove();
          startAction((String) w[1], "WHEN ...,CALL " + w[1], "of a condition monitor", false);
          break;
        }
      }
    }
  }

  /**
   * Starts an action program (of a condition monitor, or called by a TIME/DISTANCE BEFORE/AFTER
   * option) beside the program; it may not move the robot.
   *
   * @param what the calling form, for the alarm when the program does not exist
   * @param role how the program was started, for the alarm when it moves
   */
  private Interpreter startAction(String name, String what, String role, boolean groupless) {
    Optional<Program> p = store.find(name);
    if (p.isEmpty()) {
      throw new AlarmSignal(AlarmKind.UNKNOWN_PROGRAM, what + ": no such program");
    }
    if (groupless && p.get().usesMotionGroup()) {
      // The controller refuses it at the moment of the call (INTP-129), whether or not PROG moves.
      throw new AlarmSignal(AlarmKind.CALL_GROUP, what + ": " + name + " has motion group 1; a program " + role
          + " needs DEFAULT_GROUP = *,*,*,*,*");
    }
    if (p.get().lines().stream().anyMatch(in -> in instanceof Instruction.Move)) {
      throw new AlarmSignal(AlarmKind.NOT_SUPPORTED, "not supported in RobotRun: the action program " + name
          + " " + role + " moves the robot");
    }
    Interpreter child = new Interpreter(store, regs, port, settings);
    child.ownsPulseClock = false;  // the pulses it starts count down with the caller's (shared I/O)
    child.setAdvancesTimers(false);  // TIMER[] advance once per tick, in the program that started it
    child.select(name);
    child.forward();
    actions.add(child);
    return child;
  }

  /** Runs the monitors' action programs for this tick; the first alarm in one stops the program too. */
  private Outcome tickActions(double dtSec) {
    for (java.util.Iterator<Interpreter> it = actions.iterator(); it.hasNext(); ) {
      Interpreter child = it.next();
      Outcome o = child.tick(dtSec);
      if (o instanceof Outcome.Alarmed al) {
        it.remove();
        Alarm a = al.alarm();
        if (state == State.RUNNING || state == State.PAUSED) {
          return raise(new AlarmSignal(a.kind(), a.code(), a.message()), a.program(), a.line());
        }
        alarm = a;
        alarmOutcome = al;
        state = State.ALARMED;
        return al;
      } else if (!child.active()) {
        it.remove();
      }
    }
    return null;
  }

  /** Fires the TIME/DISTANCE BEFORE actions whose moment has come, {@code leftSec} / {@code leftMm} before the point. */
  /**
   * Runs the TIME BEFORE / DISTANCE BEFORE actions that are due; the time and distance left are
   * asked of the motion only when an action needs them (the distance costs forward kinematics);
   * {@code arrived}: the motion is done, every action is due.
   */
  private void fireBefore(boolean arrived) {
    double leftSec = arrived ? 0 : Double.NaN;
    double leftMm = arrived ? 0 : Double.NaN;
    for (java.util.Iterator<Motion.TimedAction> it = motionBefore.iterator(); it.hasNext(); ) {
      Motion.TimedAction t = it.next();
      boolean due;
      if (t.when() == Motion.When.DISTANCE_BEFORE) {
        if (Double.isNaN(leftMm)) {
          leftMm = port.distanceLeftMm(motionHandle);
        }
        due = leftMm <= t.amount() + 1e-6;
      } else {
        if (Double.isNaN(leftSec)) {
          leftSec = port.timeLeftSec(motionHandle);
        }
        due = leftSec <= t.amount() + TIME_EPS_SEC;
      }
      if (due) {
        it.remove();
        runTimedAction(t);
      }
    }
  }

  private void advanceTimedActions(double dtSec) {
    for (java.util.Iterator<AfterTimer> it = afterTimers.iterator(); it.hasNext(); ) {
      AfterTimer a = it.next();
      a.leftSec -= dtSec;
      if (a.leftSec <= TIME_EPS_SEC) {
        it.remove();
        runTimedAction(a.action);
      }
    }
  }

  /**
   * The action of a TIME BEFORE/AFTER or DISTANCE BEFORE option (an alarm in it is the motion
   * line's alarm): an output, or a CALL whose program starts now beside the program, as the
   * controller runs it (in parallel with the motion; it may not move the robot).
   */
  private void runTimedAction(Motion.TimedAction t) {
    Ops.Op op = switch (t.action()) {
      case Instruction.SetIo s -> new Ops.SetIoOp(s.kind(), new Nodes.Idx(s.port().index()), Compiler.expr(s.value()));
      case Instruction.Pulse p -> new Ops.PulseOp(p.kind(), new Nodes.Idx(p.port().index()), p.widthSec());
      case Instruction.Call c -> {
        Interpreter child = startAction(c.program(), t.when().label() + " ...,CALL " + c.program(),
            "called by " + t.when().label(), true);
        // The program starts at the computed moment: its lines up to its first wait run now.
        Outcome o = child.tick(0);
        if (o instanceof Outcome.Alarmed al) {
          actions.remove(child);
          throw new AlarmSignal(al.alarm().kind(), al.alarm().code(), al.alarm().message());
        }
        yield null;
      }
      default -> throw new IllegalStateException("timed action " + t.action());
    };
    if (op != null) {
      op.exec(this);
    }
  }

  void message(String text) {
    if (userScreen.size() == MAX_SCREEN_LINES) {
      userScreen.remove(0);
    }
    userScreen.add(text);
  }

  // ================================================================ motion

  /** Issues a forward motion line (the current line), then waits for it. */
  int startMotion(Ops.MoveOp op, boolean backward, MotionRequest request) {
    MotionRequest req = request != null ? request : request(op.move, cur.pc - 1);
    MotionPort.Start s = port.startMotion(req);
    return switch (s) {
      case MotionPort.Start.Rejected r -> throw new AlarmSignal(AlarmKind.MOTION, r.code(), r.message());
      case MotionPort.Start.Started st -> {
        waitKind = W_MOTION;
        waitLine = backward ? req.line() - 1 : cur.pc - 1;
        motionHandle = st.handle();
        motionHeld = false;
        motionBackward = backward;
        motionSkip = backward ? null : op.skip;
        motionBefore.clear();
        motionAfter.clear();
        if (!backward) {
          for (Motion.Option o : op.move.options()) {
            if (o instanceof Motion.TimedAction t) {
              (t.when() == Motion.When.TIME_AFTER ? motionAfter : motionBefore).add(t);
            }
          }
        }
        haltOutcome = Outcome.WAITING_FOR_MOTION;
        yield Ops.HALT;
      }
    };
  }

  /** Resolves a motion line into a request: positions, register speeds, CNT, offsets. */
  private MotionRequest request(Instruction.Move mv, int lineIndex) {
    int uf = port.activeFrame(Instruction.FrameKind.USER);
    int ut = port.activeFrame(Instruction.FrameKind.TOOL);
    Waypoint first = waypoint(mv.target(), uf, ut);
    Optional<Waypoint> via = Optional.empty();
    Waypoint target = first;
    if (mv.circularEnd().isPresent()) {
      via = Optional.of(first);
      target = waypoint(mv.circularEnd().get(), uf, ut);
    }
    double speed = switch (mv.speed().value()) {
      case Motion.SpeedConst c -> c.value();
      case Motion.SpeedRegister r -> registerNumber(r.register(), "speed");
    };
    if (!mv.speed().unit().fits(mv.type())) {
      throw new AlarmSignal(AlarmKind.BAD_VALUE, "speed unit " + mv.speed().unit() + " does not fit a " + mv.type() + " motion");
    }
    if (!(speed > 0)) {
      throw new AlarmSignal(AlarmKind.BAD_VALUE, "speed " + speed + " must be greater than 0");
    }
    boolean fine = false;
    int cnt = switch (mv.termination()) {
      case Motion.Fine f -> {
        fine = true;
        yield 0;
      }
      case Motion.Cnt c -> c.value();
      case Motion.CntRegister r -> {
        double v = registerNumber(r.register(), "CNT");
        if (!Nodes.isWhole(v)) {
          throw new AlarmSignal(AlarmKind.TYPE_MISMATCH, "CNT needs an integer, got " + v);
        }
        yield (int) v;
      }
    };
    if (cnt < 0 || cnt > 100) {
      throw new AlarmSignal(AlarmKind.BAD_VALUE, "CNT" + cnt + ": expected 0..100");
    }
    if (stepMode) {
      // In STEP each motion line stops at its point, so CNT runs as FINE (as on the controller).
      fine = true;
      cnt = 0;
    }
    Optional<Position> offset = Optional.empty();
    Optional<Position> toolOffset = Optional.empty();
    int acc = 100;
    boolean wjnt = false;
    boolean inc = false;
    Nodes.Idx voffset = null;
    for (Motion.Option o : mv.options()) {
      switch (o) {
        case Motion.Offset x -> {
          if (offsetCondition == null) {
            throw new AlarmSignal(AlarmKind.UNDEFINED_POSITION, "Offset needs an OFFSET CONDITION PR[i] before it (or write Offset,PR[i])");
          }
          offset = Optional.of(offsetConditionFrame < 0 ? positionRegister(offsetCondition)
              : offsetFromFrame(positionRegister(offsetCondition), offsetConditionFrame));
        }
        case Motion.OffsetPr x -> offset = Optional.of(positionRegister(x.register()));
        case Motion.ToolOffsetPr x -> toolOffset = Optional.of(positionRegister(x.register()));
        case Motion.Acc x -> {
          if (x.percent() < 0 || x.percent() > 150) {
            throw new AlarmSignal(AlarmKind.BAD_VALUE, "ACC" + x.percent() + ": expected 0..150");
          }
          acc = x.percent();
        }
        case Motion.Skip x -> {
          // Handled after the motion (see MoveOp.skip).
        }
        case Motion.Wjnt x -> wjnt = true;
        case Motion.Inc x -> inc = true;
        case Motion.VisionOffset x -> voffset = new Nodes.Idx(x.vr().index());
        case Motion.RawOption x -> {
          // not run yet: check reported it
        }
        case Motion.TimedAction x -> {
          // Fired while the motion runs (see serviceWait).
        }
      }
    }
    if (voffset != null) {
      Nodes.Idx vr = voffset;
      target = VisionOps.offset(this, vr, target);
      via = via.map(v -> VisionOps.offset(this, vr, v));
    }
    return new MotionRequest(mv.type(), target, via, speed, mv.speed().unit(), fine, cnt, offset, toolOffset, acc, wjnt,
        inc, false, cur.prog.name, lineIndex + 1);
  }

  private double registerNumber(Item register, String what) {
    int i = Nodes.check("R", new Nodes.Idx(register.index()).resolve(this), Registers.R_COUNT);
    return regs.r[i];
  }

  /**
   * An offset expressed in user frame {@code j} (OFFSET CONDITION PR[i],UFRAME[j]) as the same
   * displacement in the active user frame u, where the motion's target is: O_u = F_u^-1 F_j O F_j^-1 F_u
   * (frame 0 is the world). With j = u this is the offset itself.
   */
  private Position offsetFromFrame(Position offset, int j) {
    if (!(offset instanceof Position.Cartesian oc)) {
      throw new AlarmSignal(AlarmKind.TYPE_MISMATCH, "OFFSET CONDITION ...,UFRAME[" + j + "] needs a Cartesian PR");
    }
    int u = port.activeFrame(Instruction.FrameKind.USER);
    if (u == j) {
      return offset;
    }
    org.robotrun.math.Transform fj = userFrame(j);
    org.robotrun.math.Transform fu = userFrame(u);
    org.robotrun.math.Transform o = oc.toXyzwpr().toTransform();
    org.robotrun.math.Transform ou = fu.inverse().compose(fj).compose(o).compose(fj.inverse()).compose(fu);
    return Position.Cartesian.of(org.robotrun.math.Xyzwpr.fromTransform(ou), oc.config());
  }

  private org.robotrun.math.Transform userFrame(int n) {
    return n == 0 ? org.robotrun.math.Transform.IDENTITY
        : port.frame(Instruction.FrameKind.USER, n).toXyzwpr().toTransform();
  }

  private Position positionRegister(Item register) {
    int i = Nodes.check("PR", new Nodes.Idx(register.index()).resolve(this), Registers.PR_COUNT);
    return regs.pr[i];
  }

  private Waypoint waypoint(Motion.Target target, int activeUf, int activeUt) {
    return switch (target) {
      case Motion.Local l -> {
        LocalPosition p = localPosition(l.number());
        yield new Waypoint(itemName("P", l.number(), l.comment()), p.position(), p.userFrame(), p.toolFrame());
      }
      case Motion.Register r -> {
        int i = Nodes.check("PR", new Nodes.Idx(r.register().index()).resolve(this), Registers.PR_COUNT);
        yield new Waypoint(itemName("PR", i, r.register().comment()), regs.pr[i], activeUf, activeUt);
      }
    };
  }

  private static String itemName(String table, int n, String comment) {
    return table + "[" + n + (comment.isEmpty() ? "" : ":" + comment) + "]";
  }

  private Outcome backwardStep() {
    CompiledProgram p = cur.prog;
    int c = cur.pc;
    int m1 = motionAbove(p, c);
    if (m1 < 0) {
      return backwardStopped(m1, c);
    }
    int m0 = motionAbove(p, m1);
    if (m0 < 0) {
      // The robot already stands at the first motion's point: the cursor stays.
      return backwardStopped(m0, m1);
    }
    for (int line : new int[] {m0, m1}) {
      if (p.program.line(line + 1) instanceof Instruction.Move mv
          && mv.options().stream().anyMatch(o -> o instanceof Motion.Inc)) {
        notice = "BWD stopped at line " + (line + 1) + ": an INC motion cannot run backward";
        return Outcome.PAUSED;
      }
    }
    Instruction.Move back = (Instruction.Move) p.program.line(m1 + 1);
    try {
      MotionRequest to = request((Instruction.Move) p.program.line(m0 + 1), m0);
      MotionRequest from = request(back, m1);
      Motion.Type type = back.type();
      MotionRequest req = new MotionRequest(type, to.target(), type == Motion.Type.C ? from.via() : Optional.empty(),
          from.speed(), from.speedUnit(), true, 0, to.offset(), to.toolOffset(), from.accPercent(), from.wristJoint(),
          false, true, p.name, m0 + 1);
      cur.pc = m1;
      state = State.RUNNING;
      notice = "";
      return startMotion(null, true, req) == Ops.HALT ? haltOutcome : Outcome.PAUSED;
    } catch (AlarmSignal a) {
      return raise(a, p.name, m0 + 1);
    }
  }

  /**
   * The nearest motion line index above line index {@code below}: -1 when none (top reached),
   * or -2 - k when line k blocks backward execution.
   */
  private static int motionAbove(CompiledProgram p, int below) {
    for (int k = Math.min(below, p.ops.length) - 1; k >= 0; k--) {
      if (p.motion[k]) {
        return k;
      }
      if (!p.backwardBlocker[k].isEmpty()) {
        return -2 - k;
      }
    }
    return -1;
  }

  private Outcome backwardStopped(int code, int from) {
    if (code == -1) {
      notice = "BWD: top of program reached above line " + (from + 1);
    } else {
      int k = -2 - code;
      notice = "BWD stopped at line " + (k + 1) + ": " + cur.prog.backwardBlocker[k] + " cannot run backward";
    }
    return Outcome.PAUSED;
  }

  /** One program on the call stack; slots are reused so a CALL does not allocate. */
  static final class Frame {
    CompiledProgram prog;
    /** Index of the next line to run. */
    int pc;
    int nargs;
    double[] argValue = new double[0];
    int[] argKind = new int[0];
    String[] argString = new String[0];
    /** Per FOR line: the counter register while the loop runs (0 = not running), and its end value. */
    int[] forReg = new int[0];
    int[] forEnd = new int[0];

    void enter(CompiledProgram p, int startPc) {
      prog = p;
      pc = startPc;
      nargs = 0;
      int n = p.ops.length;
      if (forReg.length < n) {
        forReg = new int[n];
        forEnd = new int[n];
      } else {
        java.util.Arrays.fill(forReg, 0, n, 0);
      }
    }

    /** Switches to an edited version of the program at {@code newPc}, carrying running FOR loops over. */
    void remap(CompiledProgram p, LineMap map, int newPc) {
      int n = p.ops.length;
      int[] reg = new int[Math.max(n, forReg.length)];
      int[] end = new int[reg.length];
      int oldN = prog.ops.length;
      for (int i = 0; i < oldN; i++) {
        int k = map.kept(i);
        if (forReg[i] != 0 && k >= 0) {
          reg[k] = forReg[i];
          end[k] = forEnd[i];
        }
      }
      forReg = reg;
      forEnd = end;
      prog = p;
      pc = newPc;
    }

    void ensureArgs(int n) {
      if (argValue.length < n) {
        argValue = new double[n];
        argKind = new int[n];
        argString = new String[n];
      }
    }
  }
}
