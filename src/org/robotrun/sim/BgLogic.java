package org.robotrun.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robotrun.program.Alarm;
import org.robotrun.program.Instruction;
import org.robotrun.program.Interpreter;
import org.robotrun.program.InterpreterSettings;
import org.robotrun.program.Outcome;
import org.robotrun.program.Program;
import org.robotrun.program.ProgramStore;

/**
 * Background logic (MENU > SETUP > BG Logic on an R-30iB): up to {@value #SLOTS} programs without a
 * motion group that the controller runs from their first line to their end, again and again,
 * once every scan, whether or not a program runs and in every mode.
 *
 * <p>What the controller refuses in a BG program, RobotRun refuses when it is put in a slot
 * ({@link #refusal}): a motion group, and any statement that waits, moves, calls or stops —
 * motion, WAIT, CALL, RUN, PAUSE, ABORT, UALM, MESSAGE, OVERRIDE, frame and payload statements. Allowed
 * are register, I/O and flag assignments, IF/SELECT/JMP/LBL, TIMER, PULSE, comments and END.
 * The scan period is set per robot (the controller's normal mode runs every 8 ms for a short
 * program); a backward JMP that loops for ever stops the scan with the runaway alarm.
 */
public final class BgLogic {
  /** Number of BG Logic slots on the setup screen. */
  public static final int SLOTS = 8;

  private final Controller controller;
  private final ProgramStore store;
  private final InterpreterSettings settings;
  private final List<Slot> slots = new ArrayList<>();
  private double scanSec = 0.008;
  private double sinceScanSec;
  private long scans;

  /** One slot: a program and whether it runs. */
  public static final class Slot {
    final String program;
    final Interpreter interpreter;
    boolean running;
    /** The version of the program last found fit for background logic (null: none yet). */
    Program checked;

    Slot(String program, Interpreter interpreter) {
      this.program = program;
      this.interpreter = interpreter;
    }

    public String program() {
      return program;
    }

    public boolean running() {
      return running;
    }
  }

  BgLogic(Controller controller, ProgramStore store, InterpreterSettings settings) {
    this.controller = controller;
    this.store = store;
    this.settings = settings;
  }

  /**
   * Why {@code p} cannot run as background logic, or empty when it can: "line 3: WAIT is not
   * allowed in background logic".
   */
  public static Optional<String> refusal(Program p) {
    if (p.usesMotionGroup()) {
      return Optional.of(p.name() + " has motion group 1: a BG program needs DEFAULT_GROUP = *,*,*,*,*");
    }
    for (int i = 1; i <= p.lineCount(); i++) {
      String bad = forbidden(p.line(i));
      if (bad != null) {
        return Optional.of(p.name() + " line " + i + ": " + bad + " is not allowed in background logic");
      }
    }
    return Optional.empty();
  }

  private static String forbidden(Instruction in) {
    return switch (in) {
      case Instruction.AssignRegister a -> null;
      case Instruction.SetIo s -> null;
      case Instruction.Pulse p -> null;
      case Instruction.TimerSet t -> null;
      case Instruction.Label l -> null;
      case Instruction.Jump j -> null;
      case Instruction.If f -> f.branch() instanceof Instruction.Call ? "CALL" : null;
      case Instruction.IfAction f -> f.action() instanceof Instruction.AssignPosElement ? "a PR[] assignment" : null;
      case Instruction.IfThen f -> null;
      case Instruction.Else e -> null;
      case Instruction.EndIf e -> null;
      case Instruction.Select s -> s.branch() instanceof Instruction.Call ? "CALL" : null;
      case Instruction.SelectCase s -> s.branch() instanceof Instruction.Call ? "CALL" : null;
      case Instruction.SelectElse s -> s.branch() instanceof Instruction.Call ? "CALL" : null;
      case Instruction.Comment c -> null;
      case Instruction.CommentedOut c -> null;
      case Instruction.Blank b -> null;
      case Instruction.End e -> null;
      case Instruction.Move m -> "a motion statement";
      case Instruction.WaitTime w -> "WAIT";
      case Instruction.WaitCondition w -> "WAIT";
      case Instruction.Call c -> "CALL";
      case Instruction.MacroCall c -> "a macro (CALL)";
      case Instruction.Run r -> "RUN";
      case Instruction.Pause p -> "PAUSE";
      case Instruction.Abort a -> "ABORT";
      case Instruction.UserAlarm u -> "UALM";
      case Instruction.Message m -> "MESSAGE";
      case Instruction.For f -> null;
      case Instruction.EndFor e -> null;
      case Instruction.AssignPosReg a -> "a PR[] assignment";
      case Instruction.AssignPosElement a -> "a PR[] assignment";
      case Instruction.SelectFrame f -> "UFRAME_NUM/UTOOL_NUM";
      case Instruction.SetFrame f -> "UFRAME/UTOOL";
      case Instruction.Payload p -> "PAYLOAD";
      case Instruction.SetSysVar v -> "a system variable assignment";
      case Instruction.SkipCondition c -> "SKIP CONDITION";
      case Instruction.OffsetCondition c -> "OFFSET CONDITION";
      case Instruction.ToolOffsetCondition c -> "TOOL_OFFSET CONDITION";
      case Instruction.SetOverride o -> "OVERRIDE";
      case Instruction.AssignString a -> "an SR[] assignment";
      case Instruction.Monitor m -> "MONITOR";
      case Instruction.When w -> "WHEN";
      case Instruction.VisionRunFind v -> "iRVision";
      case Instruction.VisionGetOffset v -> "iRVision";
      case Instruction.VisionGetNFound v -> "iRVision";
      case Instruction.AssignFromVr v -> "vision registers VR[] in an expression";
      case Instruction.Unsupported u -> u.what();
    };
  }

  /**
   * What a BG Logic list offers: the programs a slot would take (not in one already), and, for
   * each other program, why it is not offered (its {@link #refusal}).
   */
  public record Offer(List<String> programs, List<String> notOffered) {
    public Offer {
      programs = List.copyOf(programs);
      notOffered = List.copyOf(notOffered);
    }
  }

  /** The programs of {@code names} a BG slot can take, and why the others are missing. */
  public Offer offer(List<String> names) {
    List<String> ok = new java.util.ArrayList<>();
    List<String> why = new java.util.ArrayList<>();
    for (String n : names) {
      if (slots.stream().anyMatch(s -> s.program.equals(n))) {
        continue;
      }
      Optional<Program> p = store.find(n);
      Optional<String> bad = p.isEmpty() ? Optional.of("program " + n + " does not exist") : refusal(p.get());
      if (bad.isPresent()) {
        why.add(bad.get());
      } else {
        ok.add(n);
      }
    }
    return new Offer(ok, why);
  }

  /**
   * Puts {@code program} in the next free slot, running.
   *
   * @return why not, or empty when it is in
   */
  public Optional<String> add(String program) {
    Optional<Program> p = store.find(program);
    if (p.isEmpty()) {
      return Optional.of("program " + program + " does not exist");
    }
    Optional<String> bad = refusal(p.get());
    if (bad.isPresent()) {
      return bad;
    }
    for (Slot s : slots) {
      if (s.program.equals(program)) {
        return Optional.of(program + " is already in a BG Logic slot");
      }
    }
    if (slots.size() >= SLOTS) {
      return Optional.of("all " + SLOTS + " BG Logic slots are in use");
    }
    Interpreter in = new Interpreter(store, controller.registers(), controller, settings);
    in.leavePulsesToCaller();
    // the interpreter's task port is TaskPort.NONE unless set: a BG program cannot RUN
    in.setAdvancesTimers(false);
    Slot s = new Slot(program, in);
    s.running = true;
    slots.add(s);
    return Optional.empty();
  }

  /**
   * The scenario's slots: each program is put in a slot, running, without checking it yet (the
   * programs may load later); a slot whose program is missing or refused stops at its first scan
   * with INTP-105.
   */
  public void configure(List<String> programs) {
    slots.clear();
    for (String program : programs) {
      Interpreter in = new Interpreter(store, controller.registers(), controller, settings);
      in.leavePulsesToCaller();
      in.setAdvancesTimers(false);
      Slot s = new Slot(program, in);
      s.running = true;
      slots.add(s);
    }
  }

  /** Removes a slot's program. */
  public boolean remove(String program) {
    return slots.removeIf(s -> s.program.equals(program));
  }

  /** Starts (true) or stops (false) a slot, as F2 START / F3 STOP on the setup screen. */
  public Optional<String> setRunning(String program, boolean on) {
    for (Slot s : slots) {
      if (s.program.equals(program)) {
        if (on) {
          Optional<Program> p = store.find(program);
          if (p.isEmpty()) {
            return Optional.of("program " + program + " does not exist");
          }
          Optional<String> bad = refusal(p.get());
          if (bad.isPresent()) {
            return bad;
          }
        }
        s.running = on;
        return Optional.empty();
      }
    }
    return Optional.of(program + " is not in a BG Logic slot");
  }

  public List<Slot> slots() {
    return List.copyOf(slots);
  }

  /** Seconds between two scans (at least one tick). */
  public double scanSec() {
    return scanSec;
  }

  public void setScanSec(double seconds) {
    if (!(seconds > 0) || seconds > 1) {
      throw new IllegalArgumentException("BG Logic scan period: expected 0 < s <= 1, got " + seconds);
    }
    scanSec = seconds;
  }

  /** Scans done since the controller started. */
  public long scans() {
    return scans;
  }

  /** Advances by one tick; a scan runs when its period has passed. */
  void tick(double dtSec) {
    sinceScanSec += dtSec;
    if (sinceScanSec + 1e-9 < scanSec) {
      return;
    }
    double sinceLastScanSec = sinceScanSec;  // what the slots' PULSE outputs count down by
    sinceScanSec = 0;
    scans++;
    for (Slot s : slots) {
      if (!s.running) {
        continue;
      }
      Optional<Program> p = store.find(s.program);
      if (p.isEmpty() || p.get() != s.checked) {
        // checked once per version of the program (programs are immutable: an edit is a new one)
        Optional<String> bad = p.isEmpty() ? Optional.of("program " + s.program + " does not exist") : refusal(p.get());
        if (bad.isPresent()) {
          s.running = false;
          s.checked = null;
          controller.raiseRunFailed("BG Logic: " + bad.get());
          continue;
        }
        s.checked = p.get();
      }
      Interpreter in = s.interpreter;
      in.select(s.program); // at line 1
      in.forward();
      Outcome o = in.tick(sinceLastScanSec);
      if (o instanceof Outcome.Alarmed a) {
        Alarm al = a.alarm();
        controller.taskAlarm(al);
        in.reset();
        s.running = false;
      } else if (in.state() != Interpreter.State.IDLE) {
        // a BG program ends every scan; anything else is a fault (refused above, so it cannot happen)
        in.abort();
      }
    }
  }
}
