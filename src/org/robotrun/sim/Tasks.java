package org.robotrun.sim;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Optional;
import org.robotrun.program.Alarm;
import org.robotrun.program.Interpreter;
import org.robotrun.program.InterpreterSettings;
import org.robotrun.program.MotionPort;
import org.robotrun.program.MotionRequest;
import org.robotrun.program.Outcome;
import org.robotrun.program.Program;
import org.robotrun.program.ProgramStore;

/**
 * The controller's other tasks: programs started by {@code RUN} beside the main one (the program
 * the pendant or the PLC started). They share the controller's registers, I/O and frames.
 *
 * <p>Rules, as on an R-30iB: a program's motion group mask ({@code DEFAULT_GROUP} in /ATTR;
 * "1,*,*,*,*" unless it says otherwise) decides whether it moves the arm. Only one running
 * program may hold group 1; a RUN of a second one fails with INTP-267 (cause PROG-040 Already
 * locked by other task). A program without a group runs beside a moving one and cannot move
 * (a motion statement alarms, SIMU-021). RUN of a program that is already running, or of one
 * that does not exist, fails with INTP-267. An alarm in a task ends that task (the controller's
 * program alarms are ABORT.L: local to the task that raised them) and shows on the pendant.
 */
public final class Tasks {
  /** Most tasks at once besides the main one (the controller's task limit is larger; RobotRun keeps it small). */
  public static final int MAX_TASKS = 8;

  private final Controller controller;
  private final ProgramStore store;
  private final InterpreterSettings settings;
  private final List<Task> tasks = new ArrayList<>();

  /** One task started by RUN. */
  public static final class Task {
    final String program;
    final Interpreter interpreter;
    final boolean motion;

    Task(String program, Interpreter interpreter, boolean motion) {
      this.program = program;
      this.interpreter = interpreter;
      this.motion = motion;
    }

    /** The program the task runs (its top program). */
    public String program() {
      return program;
    }

    /** Where it stands: the program it runs now (a CALLed one inside), its line and state. */
    public ExecutionStatus status() {
      return new ExecutionStatus(interpreter.currentProgram(), interpreter.cursorLine(), switch (interpreter.state()) {
        case IDLE -> ExecutionStatus.State.IDLE;
        case RUNNING -> ExecutionStatus.State.RUNNING;
        case PAUSED -> ExecutionStatus.State.PAUSED;
        case ALARMED -> ExecutionStatus.State.ALARMED;
      });
    }

    /** Whether it holds motion group 1. */
    public boolean holdsMotionGroup() {
      return motion;
    }
  }

  Tasks(Controller controller, ProgramStore store, InterpreterSettings settings) {
    this.controller = controller;
    this.store = store;
    this.settings = settings;
  }

  /**
   * RUN {@code program}: starts it as a task. Empty when it started, else the cause the INTP-267
   * alarm names (a start from the PLC names it under INTP-105).
   */
  public Optional<String> run(String program) {
    Optional<Program> p = store.find(program);
    if (p.isEmpty()) {
      return Optional.of("MEMO-073 Program does not exist (" + program + ")");
    }
    if (isRunning(program)) {
      return Optional.of("PROG-007 Program is already running (" + program + " is already running)");
    }
    boolean motion = p.get().usesMotionGroup();
    if (motion && groupHolder().isPresent()) {
      return Optional.of("PROG-040 Already locked by other task (" + groupHolder().get() + " holds group 1)");
    }
    if (tasks.size() >= MAX_TASKS) {
      return Optional.of("too many tasks (at most " + MAX_TASKS + " besides the main program)");
    }
    MotionPort port = motion ? controller : new NoGroupPort(controller);
    Interpreter in = new Interpreter(store, controller.registers(), port, settings);
    in.leavePulsesToCaller();
    in.setTaskPort(new org.robotrun.program.TaskPort() {
      @Override
      public Optional<String> run(String name) {
        return Tasks.this.run(name);
      }

      @Override
      public void warning(Alarm alarm) {
        controller.taskAlarm(alarm);
      }
    });
    // A RUN task finds parts with the same vision system as the main program (issue 16).
    in.setVisionPort(controller.interpreter().visionPort());
    in.setAdvancesTimers(false);
    in.select(program); // at line 1
    in.forward();
    tasks.add(new Task(program, in, motion));
    return Optional.empty();
  }

  /** The running program that holds motion group 1: the main program or a task, if any. */
  public Optional<String> groupHolder() {
    for (Task t : tasks) {
      if (t.motion) {
        return Optional.of(t.program);
      }
    }
    Interpreter main = controller.interpreter();
    // the main program holds the group when any program on its stack has it
    if (main.callDepth() > 0 && mainHoldsGroup(main)) {
      return Optional.of(main.currentProgram());
    }
    return Optional.empty();
  }

  private boolean mainHoldsGroup(Interpreter main) {
    for (String n : controller.programNames()) {
      if (main.isActive(n) && store.find(n).map(Program::usesMotionGroup).orElse(false)) {
        return true;
      }
    }
    return false;
  }

  /** Whether {@code program} runs now: in the main program's call stack or as a task. */
  public boolean isRunning(String program) {
    if (controller.interpreter().isActive(program)) {
      return true;
    }
    for (Task t : tasks) {
      if (t.interpreter.isActive(program)) {
        return true;
      }
    }
    return false;
  }

  /** The tasks now, in the order they started. */
  public List<Task> list() {
    return List.copyOf(tasks);
  }

  /** Whether a task is running (not paused). */
  public boolean anyRunning() {
    for (Task t : tasks) {
      if (t.interpreter.state() == Interpreter.State.RUNNING) {
        return true;
      }
    }
    return false;
  }

  /** Whether no task runs (no copy, unlike {@link #list}: asked every tick). */
  public boolean isEmpty() {
    return tasks.isEmpty();
  }

  /** Whether a task is paused. */
  public boolean anyPaused() {
    for (Task t : tasks) {
      if (t.interpreter.state() == Interpreter.State.PAUSED) {
        return true;
      }
    }
    return false;
  }

  /** Runs every task one tick; a task that ended is removed; a task's alarm is raised on the controller and ends it. */
  void tick(double dtSec) {
    // By index over the tasks there were at the start of the tick: a task's RUN adds one (it starts next tick).
    int n = tasks.size();
    int i = 0;
    while (i < n) {
      Task t = tasks.get(i);
      Outcome o = t.interpreter.tick(dtSec);
      if (o instanceof Outcome.Alarmed a) {
        Alarm al = a.alarm();
        controller.taskAlarm(al);
        t.interpreter.abort();
        tasks.remove(i);
        n--;
      } else if (t.interpreter.state() == Interpreter.State.IDLE) {
        tasks.remove(i);
        n--;
      } else {
        i++;
      }
    }
  }

  /** PAUSE of one task (the pendant's task list). */
  public boolean pause(String program) {
    for (Task t : tasks) {
      if (t.program.equals(program)) {
        t.interpreter.hold();
        return true;
      }
    }
    return false;
  }

  /** Resumes one paused task. */
  public boolean resume(String program) {
    for (Task t : tasks) {
      if (t.program.equals(program)) {
        t.interpreter.forward();
        return true;
      }
    }
    return false;
  }

  /** ABORT of one task. */
  public boolean abort(String program) {
    Iterator<Task> it = tasks.iterator();
    while (it.hasNext()) {
      Task t = it.next();
      if (t.program.equals(program)) {
        t.interpreter.abort();
        it.remove();
        return true;
      }
    }
    return false;
  }

  /** HOLD: every task pauses. */
  void holdAll() {
    for (Task t : tasks) {
      t.interpreter.hold();
    }
  }

  /** START / SHIFT+FWD after a HOLD: every paused task goes on. */
  void resumeAll() {
    for (Task t : tasks) {
      if (t.interpreter.state() == Interpreter.State.PAUSED) {
        t.interpreter.forward();
      }
    }
  }

  /** FCTN ABORT (ALL), CSTOPI: every task ends. */
  void abortAll() {
    for (Task t : tasks) {
      t.interpreter.abort();
    }
    tasks.clear();
  }

  /** A motion port for a task without a motion group: it reads frames and positions but cannot move the arm. */
  private static final class NoGroupPort implements MotionPort {
    private final MotionPort arm;

    NoGroupPort(MotionPort arm) {
      this.arm = arm;
    }

    @Override
    public Start startMotion(MotionRequest request) {
      return new Start.Rejected(org.robotrun.program.AlarmCode.SIMU_021.code(),
          "motion statement in a program without a motion group (DEFAULT_GROUP = *,*,*,*,*)");
    }

    @Override
    public Status poll(long handle) {
      return Status.FAILED;
    }

    @Override
    public Start.Rejected failure(long handle) {
      return new Start.Rejected(org.robotrun.program.AlarmCode.SIMU_021.code(), "no motion group");
    }

    @Override
    public void hold(long handle) {
    }

    @Override
    public void resume(long handle) {
    }

    @Override
    public void cancel(long handle) {
    }

    @Override
    public org.robotrun.program.Position.Cartesian currentLpos() {
      return arm.currentLpos();
    }

    @Override
    public org.robotrun.program.Position.Joint currentJpos() {
      return arm.currentJpos();
    }

    @Override
    public int activeFrame(org.robotrun.program.Instruction.FrameKind kind) {
      return arm.activeFrame(kind);
    }

    @Override
    public void selectFrame(org.robotrun.program.Instruction.FrameKind kind, int number) {
      arm.selectFrame(kind, number);
    }

    @Override
    public org.robotrun.program.Position.Cartesian frame(org.robotrun.program.Instruction.FrameKind kind, int number) {
      return arm.frame(kind, number);
    }

    @Override
    public void setFrame(org.robotrun.program.Instruction.FrameKind kind, int number,
        org.robotrun.program.Position.Cartesian value) {
      arm.setFrame(kind, number, value);
    }

    @Override
    public int overridePct() {
      return arm.overridePct();
    }

    @Override
    public void setOverridePct(int percent) {
      arm.setOverridePct(percent);
    }
  }
}
