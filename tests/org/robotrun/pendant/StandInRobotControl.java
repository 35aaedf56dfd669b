package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.TreeMap;
import org.robotrun.control.RobotControl;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Alarm;
import org.robotrun.program.Config;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Interpreter;
import org.robotrun.program.InterpreterSettings;
import org.robotrun.program.Motion;
import org.robotrun.program.MotionPort;
import org.robotrun.program.MotionRequest;
import org.robotrun.program.Outcome;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.Registers;

/**
 * An in-memory controller for the pendant without the simulation: programs run on the real
 * {@link Interpreter}, but the arm is {@link ToyKinematics} (a gantry with a wrist) moving in
 * joint interpolation at the commanded speed, with no collision; frames are taught by the
 * {@link FrameTeacher} it is given. Its numbers are easy to check by hand, which is what the
 * pendant's own tests need; it is not a model of the real arm ({@code app.ControllerPort} is).
 *
 * <p>Time advances only through {@link #advance(double)}, in fixed 4 ms ticks. Its switch rules
 * (TP ENABLE, DEADMAN, SHIFT, mode) copy {@code sim.ControllerPort}'s; {@code ControlPortContractTest}
 * runs the same cases on both and checks that they agree.
 */
public final class StandInRobotControl implements RobotControl {
  static final double TICK_SEC = 0.004;
  /** Joint speed at 100 % (deg/s) for J motion and joint jog at 100 % override. */
  static final double JOINT_SPEED_DEG_PER_SEC = 100;
  static final double JOG_LINEAR_MM_PER_SEC = 250;
  static final double JOG_ROTATION_DEG_PER_SEC = 30;
  static final double JOG_JOINT_DEG_PER_SEC = 30;
  /** MOVE_TO speed (% of joint speed), slow as on a pendant. */
  static final double MOVE_TO_PERCENT = 20;

  private final TreeMap<String, Program> programs = new TreeMap<>();
  private final Registers registers = new Registers();
  private final Map<CommentTable, Map<Integer, String>> comments = new EnumMap<>(CommentTable.class);
  private final Map<FrameKind, Position.Cartesian[]> frames = new EnumMap<>(FrameKind.class);
  private final Map<FrameKind, String[]> frameComments = new EnumMap<>(FrameKind.class);
  private final Map<FrameKind, Integer> active = new EnumMap<>(FrameKind.class);
  private final Interpreter interpreter;
  private final Port port = new Port();

  private Position.Joint joints = Position.Joint.ZERO;
  private int overridePct = 100;
  private double pendingSec;
  private boolean aborted;
  private AlarmEntry ownAlarm;
  private Alarm reportedAlarm;
  private final List<AlarmEntry> history = new ArrayList<>();

  private CoordSystem jogCoord = CoordSystem.JOINT;
  /** Jog direction per axis 1..6 (index 0 unused): -1, 0, +1. */
  private final int[] jogDirection = new int[7];
  private final boolean[] jogLatched = new boolean[7];

  /** The one motion in progress (program motion or MOVE_TO), or null. */
  private Move move;
  private long nextHandle = 1;
  private final Map<Long, MotionPort.Start.Rejected> failures = new HashMap<>();

  private final FrameTeacher teacher;

  /** As {@link #StandInRobotControl(FrameTeacher)} with no frame teaching ({@link FrameTeacher#NONE}). */
  public StandInRobotControl() {
    this(FrameTeacher.NONE);
  }

  /**
   * An empty controller: no programs, registers zero, frames zero, robot at all joints 0;
   * frame teaching by {@code teacher}.
   */
  public StandInRobotControl(FrameTeacher teacher) {
    this.teacher = Objects.requireNonNull(teacher, "teacher");
    for (CommentTable t : CommentTable.values()) {
      comments.put(t, new HashMap<>());
    }
    for (FrameKind k : FrameKind.values()) {
      Position.Cartesian[] f = new Position.Cartesian[11];
      java.util.Arrays.fill(f, Position.Cartesian.ZERO);
      frames.put(k, f);
      String[] c = new String[11];
      java.util.Arrays.fill(c, "");
      frameComments.put(k, c);
      active.put(k, 0);
    }
    interpreter = new Interpreter(name -> Optional.ofNullable(programs.get(name)), registers, port,
        InterpreterSettings.defaults());
  }

  // ---- programs, registers, frames ------------------------------------------------------

  @Override
  public List<String> programNames() {
    return List.copyOf(programs.keySet());
  }

  @Override
  public Optional<Program> program(String name) {
    return Optional.ofNullable(programs.get(name));
  }

  @Override
  public void saveProgram(Program program) {
    programs.put(program.name(), program);
  }

  @Override
  public Result deleteProgram(String name) {
    if (!programs.containsKey(name)) {
      return Result.refused("No program " + name);
    }
    Interpreter.State s = interpreter.state();
    if ((s == Interpreter.State.RUNNING || s == Interpreter.State.PAUSED) && interpreter.currentProgram().equals(name)) {
      return Result.refused("Cannot delete " + name + ": it is " + (s == Interpreter.State.RUNNING ? "running" : "paused")
          + " (abort it first)");
    }
    programs.remove(name);
    return Result.ok();
  }

  @Override
  public Registers registers() {
    return registers;
  }

  @Override
  public String comment(CommentTable table, int index) {
    return comments.get(table).getOrDefault(index, "");
  }

  @Override
  public void setComment(CommentTable table, int index, String comment) {
    comments.get(table).put(index, Objects.requireNonNull(comment, "comment"));
  }

  @Override
  public Position.Cartesian frame(FrameKind kind, int number) {
    return frames.get(kind)[checkFrame(number, 1)];
  }

  @Override
  public void setFrame(FrameKind kind, int number, Position.Cartesian value) {
    frames.get(kind)[checkFrame(number, 1)] = Objects.requireNonNull(value, "value");
  }

  @Override
  public String frameComment(FrameKind kind, int number) {
    return frameComments.get(kind)[checkFrame(number, 1)];
  }

  @Override
  public void setFrameComment(FrameKind kind, int number, String comment) {
    frameComments.get(kind)[checkFrame(number, 1)] = Objects.requireNonNull(comment, "comment");
  }

  @Override
  public int activeFrame(FrameKind kind) {
    return active.get(kind);
  }

  @Override
  public void selectFrame(FrameKind kind, int number) {
    active.put(kind, checkFrame(number, 0));
  }

  private static int checkFrame(int n, int lowest) {
    if (n < lowest || n > 10) {
      throw new IllegalArgumentException("frame number " + n + " (expected " + lowest + "..10)");
    }
    return n;
  }

  /** X_WU of user frame n (0 = world). */
  private Transform userFrame(int n) {
    return n == 0 ? Transform.IDENTITY : frames.get(FrameKind.USER)[n].toXyzwpr().toTransform();
  }

  /** X_FT of tool frame n (0 = flange). */
  private Transform toolFrame(int n) {
    return n == 0 ? Transform.IDENTITY : frames.get(FrameKind.TOOL)[n].toXyzwpr().toTransform();
  }

  @Override
  public TeachResult teachFrame(FrameKind kind, int number, TeachMethod method, List<Position.Joint> points) {
    if (method.kind() != kind) {
      return new TeachResult.Failed(method.title() + " teaches " + method.kind() + " frames, not " + kind);
    }
    if (points.size() != method.pointNames().size()) {
      return new TeachResult.Failed(method.title() + " needs " + method.pointNames().size() + " points, got " + points.size());
    }
    List<Transform> flanges = points.stream().map(ToyKinematics::flangeInWorld).toList();
    Transform tool = toolFrame(activeFrame(FrameKind.TOOL));
    List<Vec3> tcps = flanges.stream().map(f -> f.compose(tool).translationVector()).toList();
    TeachResult r = teacher.teach(method, flanges, tcps);
    if (r instanceof TeachResult.Taught t) {
      setFrame(kind, number, t.frame());
    }
    return r;
  }

  // ---- position ----------------------------------------------------------------------------

  @Override
  public Position.Joint currentJoints() {
    return joints;
  }

  @Override
  public Position.Cartesian currentPose(int userFrame, int toolFrame) {
    return toCartesian(joints, userFrame, toolFrame);
  }

  @Override
  public Position.Cartesian toCartesian(Position.Joint q, int userFrame, int toolFrame) {
    Transform X_UT = userFrame(userFrame).inverse().compose(ToyKinematics.flangeInWorld(q)).compose(toolFrame(toolFrame));
    return Position.Cartesian.of(Xyzwpr.fromTransform(X_UT), Config.DEFAULT);
  }

  @Override
  public Conversion<Position.Joint> toJoints(Position.Cartesian pose, int userFrame, int toolFrame) {
    Transform X_WF = userFrame(userFrame).compose(pose.toXyzwpr().toTransform()).compose(toolFrame(toolFrame).inverse());
    return ToyKinematics.joints(X_WF).<Conversion<Position.Joint>>map(Conversion.Ok::new)
        .orElseGet(() -> new Conversion.Failed<>("position is out of reach (joint limit ±" + ToyKinematics.LIMIT_DEG + " deg)"));
  }

  @Override
  public Result moveTo(Position target, int userFrame, int toolFrame) {
    if (interpreter.state() == Interpreter.State.RUNNING) {
      return Result.refused("A program is running: HOLD or abort it first");
    }
    if (ownAlarm != null || interpreter.state() == Interpreter.State.ALARMED) {
      return Result.refused("Alarm active: RESET first");
    }
    Optional<Position.Joint> q = jointsOf(target, userFrame, toolFrame);
    if (q.isEmpty()) {
      return Result.refused("MOVE_TO: position is out of reach");
    }
    move = new Move(0, joints, q.get(), durationJoint(joints, q.get(), MOVE_TO_PERCENT));
    return new Result.Ok("Moving (" + (int) MOVE_TO_PERCENT + "% joint speed)");
  }

  private Optional<Position.Joint> jointsOf(Position p, int uf, int ut) {
    return switch (p) {
      case Position.Joint j -> ToyKinematics.withinLimits(j) ? Optional.of(j) : Optional.empty();
      case Position.Cartesian c -> toJoints(c, uf, ut) instanceof Conversion.Ok<Position.Joint> ok
          ? Optional.of(ok.value()) : Optional.empty();
    };
  }

  // ---- jog ---------------------------------------------------------------------------------

  @Override
  public CoordSystem coordSystem() {
    return jogCoord;
  }

  @Override
  public void setCoordSystem(CoordSystem coord) {
    jogStop();
    jogSinceStop = false;
    jogCoord = coord;
  }

  @Override
  public Result jogKeyDown(int axis, int sign, boolean latched) {
    Optional<String> refused = switchRefusal("jog");
    if (refused.isPresent()) {
      return Result.refused(refused.get());
    }
    if (interpreter.state() == Interpreter.State.RUNNING) {
      return Result.refused("Cannot jog while a program runs: HOLD first");
    }
    if (ownAlarm != null || interpreter.state() == Interpreter.State.ALARMED) {
      return Result.refused("Alarm active: RESET before jogging");
    }
    if (axis < 1 || axis > 6 || Math.abs(sign) != 1) {
      throw new IllegalArgumentException("jog axis " + axis + " sign " + sign);
    }
    if (latched && jogLatched[axis] && jogDirection[axis] == sign) {
      jogDirection[axis] = 0;
      jogLatched[axis] = false;
    } else {
      jogDirection[axis] = sign;
      jogLatched[axis] = latched;
    }
    move = null;
    jogSinceStop = true;
    return Result.ok();
  }

  @Override
  public Result jogIncrement(int axis, int sign, boolean veryFine) {
    Optional<String> refused = switchRefusal("jog");
    return refused.isPresent() ? Result.refused(refused.get())
        : Result.refused("incremental jog needs the simulation controller");
  }

  @Override
  public String jogStopReason() {
    return "";
  }

  // ---- switches: the controller's rules as sim.ControllerPort has them (ControlPortContractTest) ----

  private boolean tpEnabled = true;
  private boolean deadmanHeld;
  private boolean shiftHeld;
  private boolean jogSinceStop;

  private Optional<String> switchRefusal(String what) {
    if (mode == Mode.AUTO) {
      return Optional.of(what.equals("jog") ? "AUTO mode: the pendant cannot jog (mode switch to T1)"
          : "AUTO mode: start from the operator panel (TP OFF, CYCLE START)");
    }
    if (!tpEnabled) {
      return Optional.of("TP disabled: turn TP ENABLE on to " + what);
    }
    if (estop) {
      return Optional.of("E-stop pressed: release it and RESET");
    }
    if (!deadmanHeld) {
      return Optional.of("Hold the DEADMAN to " + what);
    }
    if (!shiftHeld) {
      return Optional.of("Hold SHIFT and the DEADMAN to " + what);
    }
    return Optional.empty();
  }

  private double maxLinearSpeedMmPerSec = 2000;

  @Override
  public double maxLinearSpeedMmPerSec() {
    return maxLinearSpeedMmPerSec;
  }

  /** The model's maximum TCP speed (mm/s) this stand-in reports (a CRX's 1000, say). */
  public void setMaxLinearSpeedMmPerSec(double mmPerSec) {
    maxLinearSpeedMmPerSec = mmPerSec;
  }

  @Override
  public boolean tpEnabled() {
    return tpEnabled;
  }

  @Override
  public void setTpEnabled(boolean on) {
    if (!on && jogSinceStop) {
      jogStop();
      jogSinceStop = false;
    }
    if (!on && tpEnabled) {
      holdToRun("TP disabled");
    }
    tpEnabled = on;
  }

  @Override
  public boolean deadmanHeld() {
    return deadmanHeld;
  }

  @Override
  public Result setDeadman(boolean held) {
    if (held || !deadmanHeld) {
      deadmanHeld = held;
      return Result.ok();
    }
    deadmanHeld = false;
    jogSinceStop = false;
    if (!tpEnabled) {
      return Result.ok();
    }
    boolean running = interpreter.state() == Interpreter.State.RUNNING;
    deadmanReleased();
    org.robotrun.program.AlarmCode c = org.robotrun.program.AlarmCode.SRVO_003;
    return new Result.Ok(c.code() + " " + c.text() + (running ? ": program paused" : "") + " (hold DEADMAN, RESET)");
  }

  @Override
  public boolean shiftHeld() {
    return shiftHeld;
  }

  @Override
  public Result setShift(boolean held) {
    if (held || !shiftHeld) {
      shiftHeld = held;
      return Result.ok();
    }
    shiftHeld = false;
    String message = "";
    if (jogSinceStop) {
      jogStop();
      message = "Jog stopped: SHIFT released";
    }
    jogSinceStop = false;
    return new Result.Ok(holdToRun("SHIFT released").orElse(message));
  }

  private Optional<String> holdToRun(String why) {
    if (mode.holdToRun() && interpreter.state() == Interpreter.State.RUNNING) {
      hold();
      return Optional.of("Program paused: " + why + " (hold-to-run in " + mode + "; SHIFT+FWD resumes)");
    }
    return Optional.empty();
  }

  @Override
  public Result mayStart(StartFrom from, boolean forward) {
    if (from == StartFrom.OPERATOR_PANEL) {
      if (mode != Mode.AUTO) {
        return Result.refused("CYCLE START works in AUTO: in " + mode + " run from the pendant (SHIFT+FWD)");
      }
      if (tpEnabled) {
        return Result.refused("CYCLE START refused: the TP is enabled (turn it OFF to run in AUTO)");
      }
      return Result.ok();
    }
    if (!shiftHeld) {
      return Result.refused("Hold SHIFT and press " + (forward ? "FWD" : "BWD") + " to run");
    }
    return switchRefusal("run").<Result>map(Result::refused).orElse(Result.ok());
  }

  // ---- tasks and BG Logic: this stand-in has neither ------------------------------------------

  @Override
  public Map<String, String> programStates() {
    return Map.of();
  }

  @Override
  public List<TaskInfo> tasks() {
    return List.of();
  }

  @Override
  public Result pauseTask(String program, boolean pause) {
    return Result.refused("this controller has no multitasking");
  }

  @Override
  public Result abortTask(String program) {
    return Result.refused("this controller has no multitasking");
  }

  @Override
  public List<BgSlot> bgSlots() {
    return List.of();
  }

  @Override
  public Result addBg(String program) {
    return Result.refused("this controller has no BG Logic");
  }

  @Override
  public Result runBg(String program, boolean run) {
    return Result.refused("this controller has no BG Logic");
  }

  @Override
  public Result removeBg(String program) {
    return Result.refused("this controller has no BG Logic");
  }

  @Override
  public void jogKeyUp(int axis, int sign) {
    if (!jogLatched[axis] && jogDirection[axis] == sign) {
      jogDirection[axis] = 0;
    }
  }

  @Override
  public void jogStop() {
    java.util.Arrays.fill(jogDirection, 0);
    java.util.Arrays.fill(jogLatched, false);
  }

  private boolean jogging() {
    for (int d : jogDirection) {
      if (d != 0) {
        return true;
      }
    }
    return false;
  }

  private void jogTick(double dt) {
    for (int axis = 1; axis <= 6 && jogging(); axis++) {
      if (jogDirection[axis] != 0) {
        jogAxis(axis, jogDirection[axis], dt);
      }
    }
  }

  private void jogAxis(int jogAxis, int jogSign, double dt) {
    double scale = overridePct / 100.0;
    Position.Joint next;
    if (jogCoord == CoordSystem.JOINT) {
      next = joints.withElement(jogAxis, joints.element(jogAxis) + jogSign * JOG_JOINT_DEG_PER_SEC * scale * dt);
    } else {
      int ut = activeFrame(FrameKind.TOOL);
      Transform X_FT = toolFrame(ut);
      Transform X_WT = ToyKinematics.flangeInWorld(joints).compose(X_FT);
      // the jog frame's axes in world: world, the tool's own, or the active user frame's
      Transform X_WJ = switch (jogCoord) {
        case WORLD, JOINT -> Transform.IDENTITY;
        case TOOL -> X_WT;
        case USER -> userFrame(activeFrame(FrameKind.USER));
        case JGFRM -> jogFrames[activeJog].toXyzwpr().toTransform();
      };
      Vec3 axisW = X_WJ.axis((jogAxis - 1) % 3);
      Transform X_WT2;
      if (jogAxis <= 3) {
        Vec3 d = axisW.times(jogSign * JOG_LINEAR_MM_PER_SEC * scale * dt);
        X_WT2 = X_WT.withTranslation(X_WT.x() + d.x(), X_WT.y() + d.y(), X_WT.z() + d.z());
      } else {
        // rotate about the jog frame's axis through the TCP, keeping the TCP in place
        double angle = Math.toRadians(jogSign * JOG_ROTATION_DEG_PER_SEC * scale * dt);
        Transform rot = Transform.rotation(axisW.x(), axisW.y(), axisW.z(), angle);
        X_WT2 = rot.compose(X_WT.withTranslation(0, 0, 0)).withTranslation(X_WT.x(), X_WT.y(), X_WT.z());
      }
      Optional<Position.Joint> q = ToyKinematics.joints(X_WT2.compose(X_FT.inverse()));
      if (q.isEmpty()) {
        jogLimit();
        return;
      }
      next = q.get();
    }
    if (!ToyKinematics.withinLimits(next)) {
      jogLimit();
      return;
    }
    joints = next;
  }

  private void jogLimit() {
    int j = ToyKinematics.jointOverLimit(joints);
    raise(new AlarmEntry("MOTN-017", "Limit error (" + (j == 0 ? "jog would pass a joint limit" : "J" + j) + ")", "", 0));
    jogStop();
  }

  // ---- execution ---------------------------------------------------------------------------

  @Override
  public int overridePct() {
    return overridePct;
  }

  @Override
  public void setOverridePct(int percent) {
    overridePct = Math.max(1, Math.min(100, percent));
  }

  @Override
  public boolean stepMode() {
    return interpreter.stepMode();
  }

  @Override
  public void setStepMode(boolean on) {
    interpreter.setStepMode(on);
  }

  @Override
  public Result run(StartFrom from, String program, int line, boolean forward) {
    Result may = mayStart(from, forward);
    if (may instanceof Result.Refused) {
      return may;
    }
    if (ownAlarm != null || interpreter.state() == Interpreter.State.ALARMED) {
      return Result.refused("Alarm active: RESET first");
    }
    if (!programs.containsKey(program)) {
      return Result.refused("No program " + program);
    }
    int count = programs.get(program).lineCount();
    if (line < 1 || line > count + (forward ? 0 : 1)) {
      return Result.refused("Line " + line + " is outside " + program + " (1.." + count + ")");
    }
    jogStop();
    Interpreter.State s = interpreter.state();
    if (s == Interpreter.State.RUNNING) {
      return Result.refused("Already running: HOLD first");
    }
    if (s == Interpreter.State.PAUSED && !interpreter.currentProgram().equals(program)) {
      return Result.refused(interpreter.currentProgram() + " is paused: abort it (FCTN) before running " + program);
    }
    if (s == Interpreter.State.IDLE) {
      interpreter.select(program);
      interpreter.setCursor(line);
    } else if (interpreter.cursorLine() != line) {
      // a paused program moves on from the cursor line, as on the controller
      interpreter.setCursor(line);
    }
    aborted = false;
    if (forward) {
      interpreter.forward();
      return Result.ok();
    }
    Outcome o = interpreter.backward();
    noteAlarm();
    return o instanceof Outcome.Paused && !interpreter.notice().isEmpty() ? Result.refused(interpreter.notice())
        : new Result.Ok(interpreter.notice());
  }

  @Override
  public void hold() {
    interpreter.hold();
    jogStop();
    if (move != null && move.handle == 0) {
      move = null;
    }
  }

  @Override
  public void abort() {
    if (interpreter.state() == Interpreter.State.RUNNING || interpreter.state() == Interpreter.State.PAUSED) {
      interpreter.abort();
      aborted = true;
    }
    move = null;
  }

  // ---- safety: mode switch, E-stop, deadman (the controller's rules, without an arm model) ----

  private Mode mode = Mode.T1;
  private boolean estop;

  @Override
  public Mode mode() {
    return mode;
  }

  @Override
  public void setMode(Mode newMode) {
    if (newMode != mode && interpreter.state() == Interpreter.State.RUNNING) {
      hold();
    }
    jogStop();
    jogSinceStop = false;
    mode = newMode;
  }

  @Override
  public void emergencyStop(boolean fromPendant) {
    if (!estop) {
      org.robotrun.program.AlarmCode c = fromPendant ? org.robotrun.program.AlarmCode.SRVO_002
          : org.robotrun.program.AlarmCode.SRVO_001;
      raise(new AlarmEntry(c.code(), c.text(), "", 0));
    }
    estop = true;
    jogSinceStop = false;
    jogStop();
    move = null;
  }

  @Override
  public void releaseEmergencyStop() {
    estop = false;
  }

  @Override
  public boolean emergencyStopped() {
    return estop;
  }

  private final Position.Cartesian[] jogFrames = java.util.Collections.nCopies(6, Position.Cartesian.ZERO)
      .toArray(Position.Cartesian[]::new);
  private int activeJog = 1;

  @Override
  public Position.Cartesian jogFrame(int number) {
    return jogFrames[number];
  }

  @Override
  public void setJogFrame(int number, Position.Cartesian value) {
    jogFrames[number] = value;
  }

  @Override
  public int activeJogFrame() {
    return activeJog;
  }

  @Override
  public void selectJogFrame(int number) {
    activeJog = number;
  }

  private void deadmanReleased() {
    org.robotrun.program.AlarmCode c = org.robotrun.program.AlarmCode.SRVO_003;
    raise(new AlarmEntry(c.code(), c.text(), "", 0));
    jogStop();
  }

  @Override
  public void reset() {
    if (estop) {
      return;
    }
    interpreter.reset();
    ownAlarm = null;
    reportedAlarm = null;
  }

  @Override
  public ExecutionStatus status() {
    ExecState st = switch (interpreter.state()) {
      case IDLE -> aborted ? ExecState.ABORTED : ExecState.IDLE;
      case RUNNING -> ExecState.RUNNING;
      case PAUSED -> ExecState.PAUSED;
      case ALARMED -> ExecState.ABORTED;
    };
    return new ExecutionStatus(interpreter.currentProgram(), interpreter.cursorLine(), st);
  }

  @Override
  public Optional<AlarmEntry> activeAlarm() {
    if (ownAlarm != null) {
      return Optional.of(ownAlarm);
    }
    return interpreter.alarm().map(StandInRobotControl::entry);
  }

  private static AlarmEntry entry(Alarm a) {
    return new AlarmEntry(a.code(), a.message(), a.program(), a.line());
  }

  @Override
  public List<AlarmEntry> alarmHistory() {
    return List.copyOf(history);
  }

  @Override
  public void clearAlarmHistory() {
    history.clear();
  }

  private void raise(AlarmEntry a) {
    ownAlarm = a;
    history.add(0, a);
    if (interpreter.state() == Interpreter.State.RUNNING) {
      interpreter.hold();
    }
  }

  /** Puts a new interpreter alarm into the history once. */
  private void noteAlarm() {
    Optional<Alarm> a = interpreter.alarm();
    if (a.isPresent() && a.get() != reportedAlarm) {
      reportedAlarm = a.get();
      history.add(0, entry(a.get()));
    }
  }

  @Override
  public List<String> userMessages() {
    return interpreter.userScreen();
  }

  // ---- time --------------------------------------------------------------------------------

  /** Advances simulated time in whole 4 ms ticks (the test's clock: a key script's WAIT). */
  public void advance(double dtSec) {
    if (!(dtSec >= 0) || Double.isInfinite(dtSec)) {
      throw new IllegalArgumentException("dtSec must be finite and >= 0, got " + dtSec);
    }
    // whole ticks; a remainder under one tick carries over to the next call
    pendingSec += dtSec;
    while (pendingSec >= TICK_SEC - 1e-12) {
      pendingSec -= TICK_SEC;
      if (jogging()) {
        jogTick(TICK_SEC);
      }
      if (move != null && !move.held) {
        move.elapsedSec += TICK_SEC * overridePct / 100.0;
        joints = move.at();
        if (move.done()) {
          joints = move.to;
          if (move.handle == 0) {
            move = null;
          }
        }
      }
      interpreter.tick(TICK_SEC);
      noteAlarm();
    }
  }

  // ---- motion for the interpreter ----------------------------------------------------------

  private static double durationJoint(Position.Joint from, Position.Joint to, double percent) {
    double max = 0;
    for (int j = 1; j <= 6; j++) {
      max = Math.max(max, Math.abs(to.element(j) - from.element(j)));
    }
    return max / (JOINT_SPEED_DEG_PER_SEC * percent / 100.0);
  }

  /** A joint-interpolated move; {@code elapsedSec} counts override-scaled time. */
  private static final class Move {
    final long handle;
    final Position.Joint from;
    final Position.Joint to;
    final double durationSec;
    double elapsedSec;
    boolean held;

    Move(long handle, Position.Joint from, Position.Joint to, double durationSec) {
      this.handle = handle;
      this.from = from;
      this.to = to;
      this.durationSec = durationSec;
    }

    boolean done() {
      return elapsedSec >= durationSec;
    }

    Position.Joint at() {
      double s = durationSec <= 0 ? 1 : Math.min(1, elapsedSec / durationSec);
      Position.Joint d = to.minus(from);
      return from.plus(new Position.Joint(d.j1Deg() * s, d.j2Deg() * s, d.j3Deg() * s, d.j4Deg() * s, d.j5Deg() * s,
          d.j6Deg() * s));
    }
  }

  /** The interpreter's motion port onto the toy arm. */
  private final class Port implements MotionPort {
    @Override
    public Start startMotion(MotionRequest r) {
      MotionRequest.Waypoint wp = r.target();
      Position target = wp.position();
      if (target instanceof Position.Cartesian c && r.offset().isPresent() && r.offset().get() instanceof Position.Cartesian o) {
        target = c.plus(o);
      }
      if (target instanceof Position.Cartesian c && (wp.userFrame() != activeFrame(FrameKind.USER)
          || wp.toolFrame() != activeFrame(FrameKind.TOOL))) {
        return new Start.Rejected(org.robotrun.program.AlarmCode.SIMU_007.code(), wp.name() + " was taught in UF " + wp.userFrame() + " UT " + wp.toolFrame()
            + " but UF " + activeFrame(FrameKind.USER) + " UT " + activeFrame(FrameKind.TOOL) + " are active");
      }
      if (r.incremental()) {
        target = switch (target) {
          case Position.Joint j -> joints.plus(j);
          case Position.Cartesian c -> currentPose(activeFrame(FrameKind.USER), activeFrame(FrameKind.TOOL)).plus(c);
        };
      }
      Optional<Position.Joint> q = jointsOf(target, wp.userFrame(), wp.toolFrame());
      if (q.isEmpty()) {
        return new Start.Rejected("MOTN-017", wp.name() + " is out of reach (joint limit)");
      }
      double duration = switch (r.speedUnit()) {
        case PERCENT -> durationJoint(joints, q.get(), Math.max(1e-6, r.speed()));
        case SEC -> r.speed();
        case MSEC -> r.speed() / 1000.0;
        case MM_PER_SEC, CM_PER_MIN, INCH_PER_MIN -> distanceMm(joints, q.get()) / mmPerSec(r.speed(), r.speedUnit());
        case DEG_PER_SEC -> durationJoint(joints, q.get(), 100) * JOINT_SPEED_DEG_PER_SEC / Math.max(1e-6, r.speed());
      };
      long h = nextHandle++;
      move = new Move(h, joints, q.get(), duration);
      return new Start.Started(h);
    }

    private double mmPerSec(double v, Motion.SpeedUnit u) {
      return Math.max(1e-6, switch (u) {
        case CM_PER_MIN -> v * 10 / 60;
        case INCH_PER_MIN -> v * 25.4 / 60;
        default -> v;
      });
    }

    private double distanceMm(Position.Joint a, Position.Joint b) {
      return ToyKinematics.flangeInWorld(a).translationVector().distanceTo(ToyKinematics.flangeInWorld(b).translationVector());
    }

    @Override
    public Status poll(long handle) {
      if (failures.containsKey(handle)) {
        return Status.FAILED;
      }
      if (move != null && move.handle == handle) {
        return move.done() ? Status.DONE : Status.RUNNING;
      }
      return Status.DONE;
    }

    @Override
    public Start.Rejected failure(long handle) {
      return failures.getOrDefault(handle, new Start.Rejected(org.robotrun.program.AlarmCode.SIMU_011.code(), "motion failed"));
    }

    @Override
    public void hold(long handle) {
      if (move != null && move.handle == handle) {
        move.held = true;
      }
    }

    @Override
    public void resume(long handle) {
      if (move != null && move.handle == handle) {
        move.held = false;
      }
    }

    @Override
    public void cancel(long handle) {
      if (move != null && move.handle == handle) {
        move = null;
      }
    }

    @Override
    public Position.Cartesian currentLpos() {
      return currentPose(activeFrame(FrameKind.USER), activeFrame(FrameKind.TOOL));
    }

    @Override
    public Position.Joint currentJpos() {
      return joints;
    }

    @Override
    public int activeFrame(FrameKind kind) {
      return StandInRobotControl.this.activeFrame(kind);
    }

    @Override
    public void selectFrame(FrameKind kind, int number) {
      StandInRobotControl.this.selectFrame(kind, number);
    }

    @Override
    public Position.Cartesian frame(FrameKind kind, int number) {
      return StandInRobotControl.this.frame(kind, number);
    }

    @Override
    public void setFrame(FrameKind kind, int number, Position.Cartesian value) {
      StandInRobotControl.this.setFrame(kind, number, value);
    }

    @Override
    public int overridePct() {
      return overridePct;
    }

    @Override
    public void setOverridePct(int percent) {
      StandInRobotControl.this.setOverridePct(percent);
    }
  }
}
