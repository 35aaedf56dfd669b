package org.robotrun.control;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.Registers;

/**
 * The port between an operator's station (the teach pendant, the operator panel) and one robot's
 * controller. The pendant owns screens and keys and sends switch signals and key commands; the
 * controller owns programs, registers, frames, motion and execution, and makes every safety
 * decision (may this jog move, hold-to-run, the T1 cap, SRVO-003) itself. {@code sim.ControllerPort}
 * implements it on a {@code sim.Controller}. Time is not part of the port: the cell's stepper
 * advances the controllers, and the pendant only looks at what they report.
 *
 * <p>Units at this boundary are the pendant's: mm and degrees; joints in FANUC's coupled-J3
 * convention. Every method a user can make fail answers with a {@link Result}, never an
 * exception.
 */
public interface RobotControl {

  // ---- programs ----------------------------------------------------------------------------

  /** Names of the stored programs, alphabetical. */
  List<String> programNames();

  /** The stored program {@code name}. */
  Optional<Program> program(String name);

  /** Stores (creates or replaces) a program. */
  void saveProgram(Program program);

  /** Deletes a program; refused while it runs or is paused. */
  Result deleteProgram(String name);

  // ---- registers, I/O, comments -------------------------------------------------------------

  /** The controller's registers and I/O (live: the pendant reads and writes them). */
  Registers registers();

  /** Item comment of R[i] or PR[i] ("" when none). */
  String comment(CommentTable table, int index);

  /** Sets the item comment of R[i] or PR[i]. */
  void setComment(CommentTable table, int index, String comment);

  /** Tables whose items carry comments on the DATA screen. */
  enum CommentTable {
    R, PR
  }

  // ---- frames ------------------------------------------------------------------------------

  /** UFRAME[n] / UTOOL[n], n = 1..10 (mm, deg). */
  Position.Cartesian frame(FrameKind kind, int number);

  /** Sets UFRAME[n] / UTOOL[n] (direct entry or a taught result). */
  void setFrame(FrameKind kind, int number, Position.Cartesian value);

  /** The frame's comment ("" when none). */
  String frameComment(FrameKind kind, int number);

  /** Sets the frame's comment. */
  void setFrameComment(FrameKind kind, int number, String comment);

  /** The active user or tool frame number, 0..10 (0 = world / flange). */
  int activeFrame(FrameKind kind);

  /** Selects the active user or tool frame, 0..10. */
  void selectFrame(FrameKind kind, int number);

  /**
   * Computes a frame from recorded robot positions (the kinematics issue's methods) and, on
   * success, stores it in UTOOL[number] / UFRAME[number]. {@code points} are the recorded joint
   * positions in the order the method lists them; user-frame methods use the active tool.
   */
  TeachResult teachFrame(FrameKind kind, int number, TeachMethod method, List<Position.Joint> points);

  /** JOGFRAME[n], n = 1..5, in WORLD (mm, deg): the axes JGFRM jogs along. */
  Position.Cartesian jogFrame(int number);

  /** Sets JOGFRAME[n] (direct entry). */
  void setJogFrame(int number, Position.Cartesian value);

  /** The jog frame JGFRM uses, 1..5. */
  int activeJogFrame();

  /** Selects the jog frame JGFRM uses, 1..5. */
  void selectJogFrame(int number);

  /** Frame teaching methods (direct entry needs no points). */
  enum TeachMethod {
    TOOL_THREE_POINT(FrameKind.TOOL, "Three Point", List.of("Approach point 1", "Approach point 2", "Approach point 3")),
    TOOL_SIX_POINT_XZ(FrameKind.TOOL, "Six Point(XZ)", List.of("Approach point 1", "Approach point 2",
        "Approach point 3", "Orient Origin Point", "X Direction Point", "Z Direction Point")),
    TOOL_SIX_POINT_XY(FrameKind.TOOL, "Six Point(XY)", List.of("Approach point 1", "Approach point 2",
        "Approach point 3", "Orient Origin Point", "X Direction Point", "Y Direction Point")),
    USER_THREE_POINT(FrameKind.USER, "Three Point", List.of("Orient Origin Point", "X Direction Point",
        "Y Direction Point")),
    USER_FOUR_POINT(FrameKind.USER, "Four Point", List.of("Orient Origin Point", "X Direction Point",
        "Y Direction Point", "System Origin")),
    DIRECT_ENTRY_TOOL(FrameKind.TOOL, "Direct Entry", List.of()),
    DIRECT_ENTRY_USER(FrameKind.USER, "Direct Entry", List.of());

    private final FrameKind kind;
    private final String title;
    private final List<String> pointNames;

    TeachMethod(FrameKind kind, String title, List<String> pointNames) {
      this.kind = kind;
      this.title = title;
      this.pointNames = pointNames;
    }

    /** Which frames the method teaches. */
    public FrameKind kind() {
      return kind;
    }

    /** The name on the pendant ("Three Point"). */
    public String title() {
      return title;
    }

    /** The points to record, in order (empty for direct entry). */
    public List<String> pointNames() {
      return pointNames;
    }

    /** The methods offered for one kind of frame. */
    public static List<TeachMethod> forKind(FrameKind kind) {
      return java.util.Arrays.stream(values()).filter(m -> m.kind == kind).toList();
    }
  }

  /** Outcome of frame teaching: the frame, or why it could not be computed. */
  sealed interface TeachResult {
    /** Taught: the frame stored, with a detail line (e.g. the fit error). */
    record Taught(Position.Cartesian frame, String detail) implements TeachResult {
      public Taught {
        Objects.requireNonNull(frame, "frame");
        Objects.requireNonNull(detail, "detail");
      }
    }

    /** Not taught: the reason (points too close, collinear…). */
    record Failed(String reason) implements TeachResult {
      public Failed {
        Objects.requireNonNull(reason, "reason");
      }
    }
  }

  // ---- position ----------------------------------------------------------------------------

  /**
   * The arm's joint names, base to wrist, as its robot file gives them ("J1".."J6" for every
   * library arm; an imported URDF's own names): what the pendant labels joints with.
   */
  default List<String> jointNames() {
    return List.of("J1", "J2", "J3", "J4", "J5", "J6");
  }

  /** Whether the pendant shows J3 coupled to J2 (FANUC's convention), as the arm's model says. */
  default boolean coupledJ3() {
    return true;
  }

  /** The current joint position (deg, J3 coupled where {@link #coupledJ3()} says). */
  Position.Joint currentJoints();

  /**
   * The current TCP of tool frame {@code toolFrame} (0 = flange) in user frame
   * {@code userFrame} (0 = world), with the current configuration.
   */
  Position.Cartesian currentPose(int userFrame, int toolFrame);

  /** A Cartesian position (in the given frames) as joints, or why it is unreachable. */
  Conversion<Position.Joint> toJoints(Position.Cartesian pose, int userFrame, int toolFrame);

  /** Joints as a Cartesian position of {@code toolFrame} in {@code userFrame}. */
  Position.Cartesian toCartesian(Position.Joint joints, int userFrame, int toolFrame);

  /** A conversion that may fail (unreachable pose). */
  sealed interface Conversion<T> {
    /** Converted. */
    record Ok<T>(T value) implements Conversion<T> {}

    /** Not convertible, with the reason. */
    record Failed<T>(String reason) implements Conversion<T> {}
  }

  /**
   * Starts a joint move to {@code target} at a slow teaching speed (MOVE_TO, TOUCHUP checks),
   * taught in {@code userFrame}/{@code toolFrame} for a Cartesian target.
   */
  Result moveTo(Position target, int userFrame, int toolFrame);

  // ---- jog ---------------------------------------------------------------------------------

  /** Jog coordinate systems, in the order COORD cycles them. */
  enum CoordSystem {
    JOINT, JGFRM, WORLD, TOOL, USER
  }

  /** The jog coordinate system (COORD). */
  CoordSystem coordSystem();

  /** Selects the jog coordinate system; a change stops every jog axis. */
  void setCoordSystem(CoordSystem coord);

  /**
   * A jog key goes down: axis 1..6 (X,Y,Z,W,P,R or J1..J6), sign +1/-1, in the current
   * coordinate system. Held: the axis moves until {@link #jogKeyUp}; latched (an on-screen
   * click): the first press turns it on, a second press of the same key turns it off. Keys of
   * different axes combine. Refused, with the reason, unless the switches allow a jog (not AUTO,
   * TP ENABLE on, no E-stop, DEADMAN and SHIFT held) and the controller can (no alarm, no program
   * moving the arm).
   */
  Result jogKeyDown(int axis, int sign, boolean latched);

  /**
   * Incremental jog (override VFINE or FINE): one step of axis 1..6 by {@code sign} in the
   * current coordinate system, at once, refused as {@link #jogKeyDown} is. Step sizes as an
   * R-30iB documents them: FINE about 0.023 mm (0.001 deg for joints and rotations), VFINE about
   * 0.002 mm (0.0001 deg).
   */
  Result jogIncrement(int axis, int sign, boolean veryFine);

  /** A held jog key comes up (latched axes go on). */
  void jogKeyUp(int axis, int sign);

  /** Every jog axis off (COORD changed, HOLD). */
  void jogStop();

  // ---- the operator's switches: TP ENABLE, DEADMAN, SHIFT, the mode switch, E-stops ----------

  /** The operator panel's mode switch, as on an R-30iB. */
  enum Mode {
    /** Teach at reduced speed: TCP and flange at most 250 mm/s, hold-to-run. */
    T1,
    /** Teach at programmed speed, hold-to-run. */
    T2,
    /** Production: programs start from the operator panel with the pendant disabled; no jogging. */
    AUTO;

    /** The T1 speed limit of the TCP and the flange (mm/s). */
    public static final double T1_SPEED_MM_PER_SEC = 250;

    /** Whether a program runs only while SHIFT and DEADMAN are held. */
    public boolean holdToRun() {
      return this != AUTO;
    }
  }

  /**
   * The fastest TCP speed this robot's programs may ask for (mm/s, the controller's
   * $MRR_GRP.$SPEEDLIM for its model): the top of the mm/sec range the pendant accepts.
   */
  double maxLinearSpeedMmPerSec();

  /** Whether the pendant's TP ENABLE switch is on. */
  boolean tpEnabled();

  /**
   * TP ENABLE switched on or off. Off stops jogging and, in T1/T2, pauses a running program; the
   * UOP output TPENBL follows it (CMDENBL needs it off).
   */
  void setTpEnabled(boolean on);

  /** Whether the DEADMAN is held in its middle (enabling) position. */
  boolean deadmanHeld();

  /**
   * The DEADMAN is held or let go. Let go with TP ENABLE on: SRVO-003, the arm stops, a program
   * pauses. Answers what the prompt line says ("" when nothing).
   */
  Result setDeadman(boolean held);

  /** Whether SHIFT is held. */
  boolean shiftHeld();

  /**
   * SHIFT is held or let go. Let go: jogging stops and, in T1/T2, a running program pauses
   * (hold-to-run). Answers what the prompt line says ("" when nothing).
   */
  Result setShift(boolean held);

  /** The mode switch. */
  Mode mode();

  /** Turns the mode switch: a running program pauses, jogging stops. */
  void setMode(Mode mode);

  /**
   * An E-stop button goes down ({@code fromPendant}: the teach pendant's, SRVO-002; else the
   * operator panel's, SRVO-001): the arm stops at once, a running program pauses.
   */
  void emergencyStop(boolean fromPendant);

  /** The E-stop buttons are twisted out; the alarm stays until RESET. */
  void releaseEmergencyStop();

  /** Whether an E-stop button is pressed (RESET does nothing until it is released). */
  boolean emergencyStopped();

  // ---- execution ---------------------------------------------------------------------------

  /** Speed override, 1..100 %. */
  int overridePct();

  /** Sets the speed override, 1..100 %. */
  void setOverridePct(int percent);

  /** Single-step mode (STEP key). */
  boolean stepMode();

  /** Sets single-step mode. */
  void setStepMode(boolean on);

  /** Where a program start comes from. */
  enum StartFrom {
    /** SHIFT+FWD / SHIFT+BWD on the teach pendant (T1, T2; TP ENABLE on, DEADMAN and SHIFT held). */
    TEACH_PENDANT,
    /** CYCLE START on the operator panel (AUTO, TP ENABLE off). */
    OPERATOR_PANEL
  }

  /**
   * Whether the switches allow a start from {@code from} now (mode, TP ENABLE, E-stop, DEADMAN,
   * SHIFT), before a program is chosen: Ok, or the reason for the prompt line.
   */
  Result mayStart(StartFrom from, boolean forward);

  /**
   * SHIFT+FWD / SHIFT+BWD or CYCLE START: runs {@code program} from {@code line} forward, or
   * steps back one motion; a paused program of the same name resumes. Refused with a reason
   * ({@link #mayStart}, an active alarm, program missing, line out of range).
   */
  Result run(StartFrom from, String program, int line, boolean forward);

  /** HOLD: pauses a running program (motion decelerates). */
  void hold();

  /** FCTN ABORT: ends the program (state ABORTED). */
  void abort();

  /** RESET: clears the active alarm. */
  void reset();

  /** Where execution stands. */
  ExecutionStatus status();

  /** Execution states as the status line names them. */
  enum ExecState {
    IDLE, RUNNING, PAUSED, ABORTED
  }

  /**
   * Execution status.
   *
   * @param program the program running, paused or last run ("" when none)
   * @param line its current line (1-based; 0 when none)
   */
  record ExecutionStatus(String program, int line, ExecState state) {
    public ExecutionStatus {
      Objects.requireNonNull(program, "program");
      Objects.requireNonNull(state, "state");
    }
  }

  /** The active alarm, if any. */
  Optional<AlarmEntry> activeAlarm();

  /** Alarm history, newest first. */
  List<AlarmEntry> alarmHistory();

  /** Clears the alarm history (the active alarm stays until RESET). */
  void clearAlarmHistory();

  /** MESSAGE[] texts the programs wrote (the user screen), oldest first. */
  List<String> userMessages();

  /**
   * Why the last jog stopped by itself, with axis and value ("J1 at its upper limit (170.0 deg)",
   * the edge of reach, a wrist singularity); "" when it did not. The pendant shows it on the prompt
   * line so a stop never looks like a broken robot.
   */
  String jogStopReason();

  /**
   * One alarm as the pendant shows it: {@code SRVO-062 ...}, {@code INTP-311 (PICK, 4) ...}.
   *
   * @param code FANUC-style code, e.g. {@code MOTN-017}
   * @param program program name, "" when not from a program
   * @param line program line, 0 when none
   */
  record AlarmEntry(String code, String message, String program, int line) {
    public AlarmEntry {
      Objects.requireNonNull(code, "code");
      Objects.requireNonNull(message, "message");
      Objects.requireNonNull(program, "program");
    }

    /** One line: {@code INTP-311 (PICK, 4) Undefined label}. */
    public String display() {
      String where = program.isEmpty() ? "" : " (" + program + ", " + line + ")";
      return code + where + " " + message;
    }
  }

  // ---- tasks and BG Logic -------------------------------------------------------------------

  /**
   * What runs now, by program: "RUNNING" or "PAUSED" for the main program and every RUN task,
   * "BG" for a running background logic program (the SELECT screen marks them).
   */
  java.util.Map<String, String> programStates();

  /** One line of STATUS Program: a running program, its state ("RUNNING", "PAUSED") and line. */
  record TaskInfo(String program, String state, int line, boolean main) {}

  /** The main program and the RUN tasks, main first (STATUS Program). */
  List<TaskInfo> tasks();

  /** PAUSE (true) or resume (false) one RUN task. */
  Result pauseTask(String program, boolean pause);

  /** ABORT one RUN task. */
  Result abortTask(String program);

  /** One BG Logic slot (SETUP BG Logic). */
  record BgSlot(String program, boolean running) {}

  /** The BG Logic slots, in order. */
  List<BgSlot> bgSlots();

  /** Puts a program in the next BG Logic slot (refused with the controller's reason). */
  Result addBg(String program);

  /** START (true) or STOP (false) a BG Logic slot. */
  Result runBg(String program, boolean run);

  /** Removes a program from its BG Logic slot. */
  Result removeBg(String program);

  /** Outcome of a command the controller may refuse. */
  sealed interface Result {
    /** Done (or started), with an optional message for the prompt line. */
    record Ok(String message) implements Result {
      public Ok {
        Objects.requireNonNull(message, "message");
      }
    }

    /** Refused, with the reason for the prompt line. */
    record Refused(String reason) implements Result {
      public Refused {
        Objects.requireNonNull(reason, "reason");
      }
    }

    /** Done, nothing to say. */
    static Result ok() {
      return new Ok("");
    }

    /** Refused with a reason. */
    static Result refused(String reason) {
      return new Refused(reason);
    }
  }
}
