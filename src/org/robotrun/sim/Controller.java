package org.robotrun.sim;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
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
import org.robotrun.motion.JogFrame;
import org.robotrun.motion.JogResult;
import org.robotrun.motion.JogState;
import org.robotrun.motion.Jogger;
import org.robotrun.motion.MotionFault;
import org.robotrun.motion.MotionLimits;
import org.robotrun.motion.MotionListener;
import org.robotrun.motion.MotionRunner;
import org.robotrun.motion.MoveRequest;
import org.robotrun.motion.Speed;
import org.robotrun.motion.Termination;
import org.robotrun.program.TaskPort;
import org.robotrun.program.Alarm;
import org.robotrun.program.AlarmCode;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Interpreter;
import org.robotrun.program.InterpreterSettings;
import org.robotrun.program.MotionPort;
import org.robotrun.program.MotionRequest;
import org.robotrun.program.Outcome;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.Registers;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.RobotModel;

/**
 * One robot's controller: programs, registers and I/O, frames, the interpreter, the motion queue,
 * jogging, override and alarms. The {@link Simulation} advances it with {@link #tick}; a teach
 * pendant drives it through the public methods below (units at this boundary are the pendant's:
 * mm, degrees, FANUC's coupled J3; joint values inside are radians in the kinematic convention).
 *
 * <h2>For a pendant</h2>
 * <ul>
 *   <li>Programs: {@link #programNames}, {@link #program}, {@link #saveProgram}, {@link #deleteProgram}.
 *   <li>Data: {@link #registers} (live R, PR, I/O, flags, timers), {@link #registerComment}.
 *   <li>Frames: {@link #frames} ({@link FrameTable}: UTOOL/UFRAME 1..10 with comments, active numbers).
 *   <li>Position: {@link #currentJoints}, {@link #currentPose}, {@link #tcpInWorld},
 *       {@link #toJoints}, {@link #toCartesian}, {@link #moveTo} (MOVE_TO).
 *   <li>Jog: {@link #setCoordSystem}, {@link #jogKeyDown}, {@link #jogKeyUp}, {@link #jogStop},
 *       {@link #setDeadman}, {@link #jogMessage}.
 *   <li>Execution: {@link #run} (SHIFT+FWD / SHIFT+BWD from a line), {@link #setStepMode},
 *       {@link #hold}, {@link #abort}, {@link #reset}, {@link #status}, {@link #setOverridePct}.
 *   <li>Alarms: {@link #activeAlarms}, {@link #alarmHistory}, {@link #raiseAlarm}.
 *   <li>Timing: {@link #lastCycleTimeSec}, {@link #motionTimings}.
 * </ul>
 *
 * <p>Motion semantics: a FINE move is done for the program when the arm stops at its point; a
 * CNT move once the arm reaches its blend point, so the next move can blend in. HOLD decelerates
 * along the path and resumes on SHIFT+FWD; an alarm stops the arm where it is and drops queued
 * motion. Jogging works while no motion runs, with the deadman held and no alarm active.
 *
 * <p>Not thread-safe: the simulation thread owns it; a GUI posts commands to that thread.
 * Deterministic: no wall clock.
 */
public final class Controller implements MotionPort {
  /** Joint speed of MOVE_TO (fraction of max, before override). */
  public static final double MOVE_TO_SPEED_FRACTION = 0.3;
  private static final int HISTORY = 100;
  private static final int TIMINGS = 10_000;

  private final String name;
  private final RobotModel model;
  private final MotionLimits limits;
  private final MotionRunner runner;
  private final Jogger jogger;
  private final JogState jogKeys = new JogState();
  private final TargetResolver resolver;
  private final FrameTable frames = new FrameTable();
  private final Registers registers;
  private final Map<String, Program> programs = new TreeMap<>();
  private final Map<String, String> comments = new HashMap<>();
  private final Interpreter interpreter;
  private final SimpleGripper gripper = new SimpleGripper();
  private boolean defaultGripperIo = true;

  private final Map<Long, MoveState> moves = new HashMap<>();
  private final List<Vec3> arcHistory = new ArrayList<>();
  private Transform lastTargetW;
  /** ABORT while moving: the arm decelerates (held), then its motion is dropped. */
  private boolean dropWhenStopped;
  private long nextHandle = 1;
  private int overridePct = 100;
  private RobotControl.CoordSystem coord = RobotControl.CoordSystem.JOINT;
  private JogFrame jogFrame = JogFrame.JOINT;
  private boolean deadman = true;
  /** Headless default: a controller without a pendant runs as in AUTO ({@code robotrun run}). */
  private RobotControl.Mode mode = RobotControl.Mode.AUTO;
  /** Which E-stop buttons are pressed (pendant, operator panel). */
  private boolean estopPendant;
  private boolean estopPanel;
  private String jogMessage = "";
  private final List<ControllerAlarm> activeAlarms = new ArrayList<>();
  private final Deque<ControllerAlarm> history = new ArrayDeque<>();
  /** WARN alarms since the controller started (the last 1000): nothing stopped for them. */
  private final Deque<ControllerAlarm> warnings = new ArrayDeque<>();
  /** The newest WARN alarm since the last RESET: the pendant shows it while no alarm is active. */
  private ControllerAlarm shownWarning;
  private final Deque<MotionTiming> timings = new ArrayDeque<>();
  private Alarm lastInterpreterAlarm;
  private double timeSec;
  private double runStartSec = Double.NaN;
  private double lastCycleTimeSec = Double.NaN;
  private Interpreter.State lastState = Interpreter.State.IDLE;
  /** RUN tasks, background logic and the UOP signals (issue 15), each in its own class. */
  private final Tasks tasks;
  private final BgLogic bgLogic;
  private final Uop uop;

  /** Bookkeeping of one started motion. */
  private static final class MoveState {
    final String program;
    final int line;
    final boolean fine;
    double startSec = Double.NaN;
    boolean finished;
    Start.Rejected failure;
    /** The planner's request, to plan it again from where the arm stopped. */
    MoveRequest request;
    /** The TCP's end point in the world (DISTANCE BEFORE). */
    Transform targetW;
    /** Stopped at once (servo alarm, E-stop) before it finished: SHIFT+FWD plans it again. */
    boolean interrupted;

    MoveState(String program, int line, boolean fine) {
      this.program = program;
      this.line = line;
      this.fine = fine;
    }
  }

  /**
   * A controller for {@code model} with the arm at {@code start}.
   *
   * @param name the robot's name in reports ("robot1")
   * @param start joints (pendant degrees, coupled J3)
   */
  public Controller(String name, RobotModel model, Position.Joint start) {
    this(name, model, start, InterpreterSettings.defaults());
  }

  public Controller(String name, RobotModel model, Position.Joint start, InterpreterSettings settings) {
    this.name = Objects.requireNonNull(name, "name");
    this.model = model;
    this.registers = new Registers(settings.ioRanges());
    this.limits = MotionLimits.forModel(model);
    this.resolver = new TargetResolver(model);
    double[] q0 = resolver.kinematicOf(start);
    int bad = model.firstJointOutsideLimits(q0);
    if (bad >= 0) {
      throw new IllegalArgumentException(String.format(java.util.Locale.ROOT, "start position: J%d = %.1f deg is outside its limits", bad + 1,
          start.element(bad + 1)));
    }
    this.runner = new MotionRunner(model, limits, q0, new Events());
    this.jogger = new Jogger(model, limits);
    this.interpreter = new Interpreter(n -> Optional.ofNullable(programs.get(n)), registers, this, settings);
    interpreter.leavePulsesToCaller();
    this.tasks = new Tasks(this, n -> Optional.ofNullable(programs.get(n)), settings);
    this.bgLogic = new BgLogic(this, n -> Optional.ofNullable(programs.get(n)), settings);
    this.uop = new Uop(this);
    interpreter.setTaskPort(new TaskPort() {
      @Override
      public Optional<String> run(String program) {
        return tasks.run(program);
      }

      @Override
      public void warning(Alarm alarm) {
        taskAlarm(alarm);
      }

      @Override
      public int backgroundStatus(int slot) {
        var slots = bgLogic.slots();
        if (slot < 1 || slot > slots.size()) {
          return 0;
        }
        return slots.get(slot - 1).running() ? 2 : 1;
      }
    });
  }

  public String name() {
    return name;
  }

  public RobotModel model() {
    return model;
  }

  // ================================================================ simulation

  /** Advances by {@code dtSec}: the program runs, then the arm moves (program motion or jog). */
  public void tick(double dtSec) {
    timeSec += dtSec;
    // the T1 cap watches the active tool's TCP (the pendant may select another at any time)
    applySpeedCap();
    if (defaultGripperIo) {
      gripper.tick(registers, dtSec);
    }
    uop.tick(dtSec);
    // Pulses count down once per tick in the shared I/O, whoever started them (a RUN task or an
    // action program that ended leaves its pulse to end on time), just before the programs run.
    registers.advancePulses(dtSec);
    Outcome o = interpreter.tick(dtSec);
    tasks.tick(dtSec);
    bgLogic.tick(dtSec);
    if (o instanceof Outcome.Alarmed a && a.alarm() != lastInterpreterAlarm) {
      lastInterpreterAlarm = a.alarm();
      Alarm al = a.alarm();
      // A motion fault was raised when it happened; the interpreter reports it again on its poll.
      boolean known = activeAlarms.stream().anyMatch(x -> x.code().equals(al.code()) && x.message().equals(al.message()));
      if (!known) {
        addAlarm(new ControllerAlarm(al.code(), al.message(), al.program(), al.line(), timeSec));
      }
      stopMotion();
    }
    if (!activeAlarms.isEmpty() && interpreter.state() == Interpreter.State.RUNNING) {
      // An alarm the program did not see itself (a CNT move failing after the program moved on).
      interpreter.hold();
    }
    Interpreter.State state = interpreter.state();
    if (state == Interpreter.State.RUNNING && lastState == Interpreter.State.IDLE) {
      runStartSec = timeSec - dtSec;
    }
    lastState = state;
    boolean jogging = runner.idle() && jogKeys.anyOn();
    runner.tick(dtSec);
    if (dropWhenStopped && runner.atRest()) {
      runner.stopNow();
      dropWhenStopped = false;
    }
    if (runner.idle()) {
      if (jogging && (!deadman || !activeAlarms.isEmpty())) {
        jogger.stop(jogKeys);
      }
      double[] q = runner.joints();
      double[] q0 = q.clone();
      JogResult r = jogger.tick(q, jogKeys, jogFrame, overridePct / 100.0, frames.activeTool(), jogAxes(), dtSec);
      capJogStep(q0, q, dtSec);
      switch (r) {
        case JogResult.Moving m -> runner.setJoints(q);
        case JogResult.Stopped s -> {
          runner.setJoints(q);
          jogMessage = s.message();
        }
        case JogResult.Idle i -> {
        }
      }
    }
    if (state == Interpreter.State.IDLE && !Double.isNaN(runStartSec) && runner.idle()) {
      lastCycleTimeSec = timeSec - runStartSec;
      runStartSec = Double.NaN;
    }
  }

  /**
   * T1: a jog tick that would move the flange or the TCP faster than 250 mm/s is shortened to
   * that speed (a joint jog of J1 far from the axis would otherwise outrun it; a Cartesian jog
   * keeps to it already, {@link Jogger#setCartesianSpeedCap}).
   */
  private void capJogStep(double[] q0, double[] q, double dtSec) {
    if (mode != RobotControl.Mode.T1) {
      return;
    }
    double limit = RobotControl.Mode.T1_SPEED_MM_PER_SEC * dtSec;
    double moved = MotionRunner.cartesianStepMm(model, q0, q, frames.activeTool());
    if (moved > limit) {
      double s = 0.999 * limit / moved;
      for (int i = 0; i < q.length; i++) {
        q[i] = q0[i] + (q[i] - q0[i]) * s;
      }
    }
  }

  /**
   * Whether the stand-in gripper answers RO[1] on RI[1] (true until a simulation gives the robot
   * an end effector, which then owns that I/O).
   */
  void setDefaultGripperIo(boolean on) {
    defaultGripperIo = on;
  }

  /** Simulated time of this controller (s). */
  public double timeSec() {
    return timeSec;
  }

  /** Whether a program is active (running or paused) or the arm is moving. */
  public boolean busy() {
    return interpreter.state() == Interpreter.State.RUNNING || interpreter.state() == Interpreter.State.PAUSED
        || !runner.idle() || !tasks.isEmpty();
  }

  // ================================================================ programs and data

  /** Names of the stored programs, alphabetical. */
  public List<String> programNames() {
    return List.copyOf(programs.keySet());
  }

  public Optional<Program> program(String programName) {
    return Optional.ofNullable(programs.get(programName));
  }

  /**
   * Stores (creates or replaces) a program. A program that is paused or waiting for a CALL to
   * return goes on in the new version ({@link Interpreter#reload()}): what runs is what the
   * pendant shows.
   */
  public void saveProgram(Program p) {
    programs.put(p.name(), p);
    interpreter.reload();
  }

  /** Deletes a program; refused while it is active (running, paused, or a caller of either). */
  public RobotControl.Result deleteProgram(String programName) {
    if (interpreter.isActive(programName) || (busy() && interpreter.currentProgram().equals(programName))) {
      return RobotControl.Result.refused(programName + " is running or paused: ABORT it first");
    }
    return programs.remove(programName) == null
        ? RobotControl.Result.refused("no program " + programName)
        : RobotControl.Result.ok();
  }

  /** The live registers and I/O. */
  public Registers registers() {
    return registers;
  }

  /** Item comment of a register ({@code table} "R" or "PR"), "" when none. */
  public String registerComment(String table, int index) {
    return comments.getOrDefault(table + "[" + index + "]", "");
  }

  public void setRegisterComment(String table, int index, String comment) {
    comments.put(table + "[" + index + "]", Objects.requireNonNull(comment));
  }

  /** Tool and user frames and the active numbers. */
  public FrameTable frames() {
    return frames;
  }

  // ================================================================ position

  /** Joints in kinematic radians (renderer, trace). */
  public double[] jointsRad() {
    return runner.joints();
  }

  /** The current joints (pendant degrees). */
  public Position.Joint currentJoints() {
    return resolver.currentJoints(runner.joints());
  }

  /** The TCP of the active tool in WORLD. */
  public Vec3 flangeInWorld() {
    return resolver.tcp(runner.joints(), Transform.IDENTITY).translationVector();
  }

  /** The active tool's TCP in WORLD. */
  public Xyzwpr tcpInWorld() {
    return Xyzwpr.fromTransform(resolver.tcp(runner.joints(), frames.activeTool()));
  }

  /** The TCP of tool frame {@code toolFrame} (0 = flange) in user frame {@code userFrame} (0 = WORLD), with CONFIG. */
  public Position.Cartesian currentPose(int userFrame, int toolFrame) {
    return resolver.lpos(runner.joints(), frames.transform(FrameKind.USER, userFrame),
        frames.transform(FrameKind.TOOL, toolFrame));
  }

  /** A Cartesian position in the given frames as joints (its CONFIG), or why it has none. */
  public IkResult toJoints(Position.Cartesian pose, int userFrame, int toolFrame) {
    return resolver.jointsOf(pose, frames.transform(FrameKind.USER, userFrame), frames.transform(FrameKind.TOOL, toolFrame),
        runner.joints());
  }

  /** Joints as a Cartesian position of {@code toolFrame} in {@code userFrame}. */
  public Position.Cartesian toCartesian(Position.Joint joints, int userFrame, int toolFrame) {
    return resolver.cartesianOf(joints, frames.transform(FrameKind.USER, userFrame),
        frames.transform(FrameKind.TOOL, toolFrame));
  }

  /**
   * MOVE_TO: a FINE joint move to {@code target} at {@link #MOVE_TO_SPEED_FRACTION} of joint
   * speed (times override). A Cartesian target is taken in {@code userFrame}/{@code toolFrame}.
   */
  public RobotControl.Result moveTo(Position target, int userFrame, int toolFrame) {
    if (!activeAlarms.isEmpty()) {
      return RobotControl.Result.refused("alarm active: RESET first");
    }
    if (interpreter.state() == Interpreter.State.RUNNING) {
      return RobotControl.Result.refused("a program is running: HOLD it first");
    }
    if (!runner.idle()) {
      if (!runner.atRest() || interpreter.state() == Interpreter.State.PAUSED) {
        return RobotControl.Result.refused("the robot is moving: HOLD and wait");
      }
      // A held MOVE_TO: the new one replaces it.
      runner.stopNow();
    }
    double[] q;
    switch (target) {
      case Position.Joint j -> q = resolver.kinematicOf(j);
      case Position.Cartesian c -> {
        IkResult r = toJoints(c, userFrame, toolFrame);
        if (r instanceof IkResult.Unreachable u) {
          return RobotControl.Result.refused("unreachable: " + u.message());
        }
        q = ((IkResult.Solved) r).q();
      }
    }
    int bad = model.firstJointOutsideLimits(q);
    if (bad >= 0) {
      return RobotControl.Result.refused(String.format(java.util.Locale.ROOT, "J%d would be outside its limits", bad + 1));
    }
    long h = nextHandle++;
    moves.put(h, new MoveState("", 0, true));
    jogger.stop(jogKeys);
    runner.resume();
    runner.enqueue(new MoveRequest.Joint(q, new Speed.JointPercent(MOVE_TO_SPEED_FRACTION), Termination.fine(), 1, h));
    return RobotControl.Result.ok();
  }

  // ================================================================ jog

  /** The jog coordinate system (COORD key). */
  public RobotControl.CoordSystem coordSystem() {
    return coord;
  }

  /** Selects the jog coordinate system (a change stops every jog axis). */
  public void setCoordSystem(RobotControl.CoordSystem system) {
    if (system != coord) {
      jogger.stop(jogKeys);
      coord = Objects.requireNonNull(system);
      jogFrame = switch (system) {
        case JOINT -> JogFrame.JOINT;
        case JGFRM -> JogFrame.JGFRM;
        case WORLD -> JogFrame.WORLD;
        case TOOL -> JogFrame.TOOL;
        case USER -> JogFrame.USER;
      };
    }
  }

  /**
   * A jog key goes down: axis 1..6 (J1..J6, or X, Y, Z, rotation about X, Y, Z), sign ±1, held
   * (keyboard) or latched (on-screen click).
   */
  public RobotControl.Result jogKeyDown(int axis, int sign, JogState.Press press) {
    RobotControl.Result refused = jogRefusal();
    if (refused != null) {
      return refused;
    }
    jogMessage = "";
    jogKeys.keyDown(axis - 1, sign, press);
    return RobotControl.Result.ok();
  }

  /** Why a jog may not start now (alarm, DEADMAN, a program moving, AUTO, E-stop), or null when it may. */
  private RobotControl.Result jogRefusal() {
    if (!activeAlarms.isEmpty()) {
      return RobotControl.Result.refused("alarm active: RESET first");
    }
    if (!deadman) {
      return RobotControl.Result.refused("hold the DEADMAN to jog");
    }
    if (interpreter.state() == Interpreter.State.RUNNING || !runner.idle()) {
      return RobotControl.Result.refused("cannot jog while the robot moves under a program");
    }
    if (mode == RobotControl.Mode.AUTO) {
      return RobotControl.Result.refused("AUTO mode: the pendant cannot jog (turn the mode switch to T1)");
    }
    if (estopped()) {
      return RobotControl.Result.refused("E-stop pressed: release it and RESET");
    }
    return null;
  }

  /** The frame USER and JGFRM jog along: the active user frame or the active jog frame. */
  private Transform jogAxes() {
    return coord == RobotControl.CoordSystem.JGFRM ? frames.activeJogFrame() : frames.activeUser();
  }

  /** Incremental jog, FINE: mm per key press (X, Y, Z). */
  public static final double FINE_STEP_MM = 0.023;
  /** Incremental jog, FINE: degrees per key press (joints, rotations). */
  public static final double FINE_STEP_DEG = 0.001;
  /** Incremental jog, VFINE: mm per key press. */
  public static final double VFINE_STEP_MM = 0.002;
  /** Incremental jog, VFINE: degrees per key press. */
  public static final double VFINE_STEP_DEG = 0.0001;

  /**
   * Incremental jog (override FINE or VFINE): one step of axis 1..6 in the current jog
   * coordinates, at once: FINE {@value #FINE_STEP_MM} mm / {@value #FINE_STEP_DEG} deg, VFINE
   * {@value #VFINE_STEP_MM} mm / {@value #VFINE_STEP_DEG} deg (the R-30iB's approximate sizes).
   */
  public RobotControl.Result jogIncrement(int axis, int sign, boolean veryFine) {
    RobotControl.Result refused = jogRefusal();
    if (refused != null) {
      return refused;
    }
    jogger.stop(jogKeys);
    double mm = veryFine ? VFINE_STEP_MM : FINE_STEP_MM;
    double deg = veryFine ? VFINE_STEP_DEG : FINE_STEP_DEG;
    double[] q = runner.joints();
    JogResult r = jogger.step(q, jogFrame, axis - 1, sign, mm, Math.toRadians(deg), frames.activeTool(), jogAxes());
    return switch (r) {
      case JogResult.Stopped s -> RobotControl.Result.refused(s.message());
      default -> {
        runner.setJoints(q);
        boolean linear = coord != RobotControl.CoordSystem.JOINT && axis <= 3;
        // plain decimals: VFINE's 0.0001 deg is not "1.0E-4"
        yield new RobotControl.Result.Ok(String.format(java.util.Locale.ROOT, "%s step: %s%s", veryFine ? "VFINE" : "FINE",
            java.math.BigDecimal.valueOf(linear ? mm : deg).stripTrailingZeros().toPlainString(), linear ? " mm" : " deg"));
      }
    };
  }

  /** A jog key comes up (a held axis stops; latched axes go on). */
  public void jogKeyUp(int axis, int sign) {
    jogKeys.keyUp(axis - 1, sign);
  }

  /** Every jog axis off. */
  public void jogStop() {
    jogger.stop(jogKeys);
  }

  /** Which jog axes are on: −1, 0, +1 for axes 1..6 (latched keys show on the pendant). */
  public int jogDirection(int axis) {
    return jogKeys.direction(axis - 1);
  }

  /** The enabling (DEADMAN) signal as the controller sees it (the pendant gates TP ENABLE, DEADMAN and SHIFT): off stops jogging. */
  public void setDeadman(boolean held) {
    deadman = held;
    if (!held) {
      jogger.stop(jogKeys);
    }
  }

  /** Whether the enabling (DEADMAN) signal is on (headless: always). */
  public boolean deadman() {
    return deadman;
  }

  /** Why the last jog stopped by itself ("" when it did not). */
  public String jogMessage() {
    return jogMessage;
  }

  // ================================================================ execution

  public int overridePct() {
    return overridePct;
  }

  // ================================================================ safety

  /** The mode switch. */
  public RobotControl.Mode mode() {
    return mode;
  }

  /**
   * Turns the mode switch. A running program pauses and jogging stops (a controller stops the
   * arm when the switch turns); in T1 every motion is capped at 250 mm/s at the TCP and flange.
   */
  public void setMode(RobotControl.Mode newMode) {
    Objects.requireNonNull(newMode, "mode");
    if (newMode != mode && interpreter.state() == Interpreter.State.RUNNING) {
      hold();
    }
    jogger.stop(jogKeys);
    mode = newMode;
    applySpeedCap();
  }

  private void applySpeedCap() {
    runner.setCartesianSpeedCap(mode == RobotControl.Mode.T1 ? RobotControl.Mode.T1_SPEED_MM_PER_SEC : Double.POSITIVE_INFINITY,
        frames.activeTool());
    // a Cartesian jog keeps to the cap itself, so it stays on its line (capJogStep's margin below
    // it only holds the arm a hair behind the jog's pose, which the ramp down makes up)
    jogger.setCartesianSpeedCap(mode == RobotControl.Mode.T1 ? RobotControl.Mode.T1_SPEED_MM_PER_SEC : Double.POSITIVE_INFINITY);
  }

  /**
   * An E-stop button goes down: {@code fromPendant} the teach pendant's (SRVO-002), else the
   * operator panel's (SRVO-001). The arm stops at once (no deceleration along the path), a running
   * program pauses, jogging stops. RESET clears the alarm only after every E-stop is released.
   */
  public void emergencyStop(boolean fromPendant) {
    boolean was = fromPendant ? estopPendant : estopPanel;
    if (fromPendant) {
      estopPendant = true;
    } else {
      estopPanel = true;
    }
    if (!was) {
      AlarmCode code = fromPendant ? AlarmCode.SRVO_002 : AlarmCode.SRVO_001;
      raiseAlarm(code.code(), code.text());
    }
  }

  /** Releases (twists out) both E-stop buttons; the alarm stays until RESET. */
  public void releaseEmergencyStop() {
    estopPendant = false;
    estopPanel = false;
  }

  /** Whether an E-stop button is pressed. */
  public boolean estopped() {
    return estopPendant || estopPanel;
  }

  /**
   * The DEADMAN switch was let go while the pendant is enabled: SRVO-003. The arm stops at once,
   * a running program pauses (SHIFT+FWD resumes it after RESET with the DEADMAN held).
   */
  public void deadmanReleased() {
    raiseAlarm(AlarmCode.SRVO_003.code(), AlarmCode.SRVO_003.text());
  }

  /** Speed override 1..100 %: scales every motion, program and jog, at once (ramped). */
  @Override
  public void setOverridePct(int percent) {
    if (percent < 1 || percent > 100) {
      throw new IllegalArgumentException("override must be 1..100 %, got " + percent);
    }
    overridePct = percent;
    runner.setOverride(percent / 100.0);
  }

  public boolean stepMode() {
    return interpreter.stepMode();
  }

  public void setStepMode(boolean on) {
    interpreter.setStepMode(on);
  }

  /**
   * SHIFT+FWD (forward) or SHIFT+BWD: runs {@code programName} from {@code line}; a paused run of
   * the same program resumes from where it stopped (a held motion continues).
   */
  public RobotControl.Result run(String programName, int line, boolean forward) {
    if (estopped()) {
      return RobotControl.Result.refused("E-stop pressed: release it and RESET");
    }
    if (!activeAlarms.isEmpty()) {
      return RobotControl.Result.refused("alarm active: RESET first (" + activeAlarms.get(0).display() + ")");
    }
    if (interpreter.state() == Interpreter.State.ALARMED && interpreter.callDepth() > 0) {
      // an alarm paused the program (not yet seen by a tick): it keeps its stack until RESET
      return RobotControl.Result.refused("alarm active: RESET first (" + interpreter.alarm().map(Alarm::display).orElse("") + ")");
    }
    Program p = programs.get(programName);
    if (p == null) {
      return RobotControl.Result.refused("no program " + programName);
    }
    if (line < 1 || line > Math.max(1, p.lineCount())) {
      return RobotControl.Result.refused("line " + line + " is not in " + programName + " (1.." + p.lineCount() + ")");
    }
    jogger.stop(jogKeys);
    switch (interpreter.state()) {
      case RUNNING -> {
        return RobotControl.Result.refused(interpreter.currentProgram() + " is running");
      }
      case PAUSED -> {
        if (!interpreter.currentProgram().equals(programName) && interpreter.callDepth() <= 1) {
          return RobotControl.Result.refused(interpreter.currentProgram() + " is paused: ABORT it first");
        }
        if (interpreter.cursorLine() != line && interpreter.callDepth() <= 1) {
          interpreter.setCursor(line);
        }
      }
      case IDLE, ALARMED -> {
        if (tasks.isRunning(programName)) {
          return RobotControl.Result.refused("INTP-105 Run request failed: " + programName + " is already running");
        }
        Optional<String> holder = tasks.groupHolder();
        if (p.usesMotionGroup() && holder.isPresent()) {
          return RobotControl.Result.refused("INTP-105 Run request failed: PROG-040 Already locked by other task ("
              + holder.get() + " holds group 1)");
        }
        interpreter.select(programName);
        interpreter.setCursor(line);
      }
    }
    if (interpreter.state() == Interpreter.State.PAUSED && forward) {
      replanInterrupted();
    }
    if (forward) {
      tasks.resumeAll();
    }
    runner.resume();
    if (forward) {
      interpreter.forward();
    } else {
      interpreter.backward();
    }
    String notice = interpreter.notice();
    return new RobotControl.Result.Ok(notice);
  }

  /**
   * After a stop at once (servo alarm, E-stop), the move the program waits on is planned again
   * from where the arm stands to its target, as a controller resumes an interrupted motion;
   * earlier moves it was blending out of count as done.
   */
  private void replanInterrupted() {
    long last = -1;
    for (Map.Entry<Long, MoveState> e : moves.entrySet()) {
      if (e.getValue().interrupted) {
        last = Math.max(last, e.getKey());
      }
    }
    for (Map.Entry<Long, MoveState> e : moves.entrySet()) {
      MoveState m = e.getValue();
      if (!m.interrupted) {
        continue;
      }
      m.interrupted = false;
      if (e.getKey() == last && runner.idle() && m.request != null) {
        runner.enqueue(m.request);
      } else {
        m.finished = true;
      }
    }
  }

  /** HOLD: the program pauses, the arm decelerates along its path, jogging stops. */
  public void hold() {
    interpreter.hold();
    tasks.holdAll();
    runner.hold();
    jogger.stop(jogKeys);
  }

  /** FCTN ABORT: ends the program; a moving arm decelerates along its path to a stop. */
  public void abort() {
    interpreter.abort();
    tasks.abortAll();
    if (!runner.idle()) {
      cancel(-1);
    }
  }

  /** RESET: clears the active alarms (the history keeps them). */
  public void reset() {
    if (estopped()) {
      // RESET does nothing while an E-stop button is still pressed
      return;
    }
    activeAlarms.clear();
    shownWarning = null;
    interpreter.reset();
    lastInterpreterAlarm = null;
  }

  /** Where execution stands. */
  public ExecutionStatus status() {
    ExecutionStatus.State s = switch (interpreter.state()) {
      case IDLE -> ExecutionStatus.State.IDLE;
      case RUNNING -> ExecutionStatus.State.RUNNING;
      case PAUSED -> ExecutionStatus.State.PAUSED;
      case ALARMED -> ExecutionStatus.State.ALARMED;
    };
    return new ExecutionStatus(interpreter.currentProgram(), interpreter.cursorLine(), s);
  }

  /** The interpreter (user screen, notices); the controller owns its state. */
  public Interpreter interpreter() {
    return interpreter;
  }

  /** Simulated seconds of the last program run from SHIFT+FWD to its end (arm at rest); NaN before the first. */
  public double lastCycleTimeSec() {
    return lastCycleTimeSec;
  }

  /** Per-motion timings, oldest first (the last 10 000). */
  public List<MotionTiming> motionTimings() {
    return List.copyOf(timings);
  }

  // ================================================================ alarms

  /** Whether any alarm is active (cheaper than {@link #activeAlarms} in a loop). */
  public boolean hasActiveAlarm() {
    return !activeAlarms.isEmpty();
  }

  /** Active alarms, oldest first. */
  public List<ControllerAlarm> activeAlarms() {
    return List.copyOf(activeAlarms);
  }

  /** Alarm history, newest first (the last 100). */
  public List<ControllerAlarm> alarmHistory() {
    return List.copyOf(history);
  }

  public void clearAlarmHistory() {
    history.clear();
  }

  /**
   * Raises an alarm from outside the program (collision, pendant): the arm stops, a running
   * program pauses, jogging stops. The alarm names the active program's line, if one runs.
   */
  public void raiseAlarm(String code, String message) {
    boolean active = interpreter.state() == Interpreter.State.RUNNING || interpreter.state() == Interpreter.State.PAUSED;
    addAlarm(new ControllerAlarm(code, message, active ? interpreter.currentProgram() : "",
        active ? interpreter.cursorLine() : 0, timeSec));
    interpreter.hold();
    tasks.holdAll();
    stopMotion();
  }

  // ================================================================ tasks, BG logic, UOP (issue 15)

  /** The tasks RUN started beside the main program. */
  public Tasks tasks() {
    return tasks;
  }

  /** Background logic (MENU > SETUP > BG Logic). */
  public BgLogic bgLogic() {
    return bgLogic;
  }

  /** The UOP signals (UI/UO), the PLC sequence and the reference positions. */
  /** The UOP outputs as the controller's state is now (a run that ends has no next tick to write them). */
  public void settleOutputs() {
    uop.settleOutputs();
  }

  public Uop uop() {
    return uop;
  }

  /**
   * Applies a robot's production setup: UOP, program selection, reference positions, the PLC
   * sequence and the BG Logic slots (whose programs are checked at their first scan: load them
   * before the first tick).
   */
  public void configureProduction(org.robotrun.world.ProductionSetup.Robot setup) {
    uop.configure(setup);
    if (setup != null) {
      bgLogic.setScanSec(setup.bgScanSec());
      bgLogic.configure(setup.backgroundLogic());
    }
  }

  /**
   * An alarm a task, a BG program or a program's WARN raised: by its severity (docs/alarms.md). A
   * WARN is kept in the history and shown, and every program goes on; any other is active and holds
   * the main program and the tasks until RESET.
   */
  void taskAlarm(Alarm al) {
    ControllerAlarm a = new ControllerAlarm(al.code(), al.message(), al.program(), al.line(), timeSec);
    if (isWarning(a.code())) {
      addWarning(a);
    } else {
      addAlarm(a);
    }
  }

  /** WARN alarms raised so far, oldest first (the last 1000): nothing stopped for them. */
  public List<ControllerAlarm> warnings() {
    return List.copyOf(warnings);
  }

  /** The newest WARN alarm since the last RESET, if any (the pendant shows it while no alarm is active). */
  public Optional<ControllerAlarm> shownWarning() {
    return Optional.ofNullable(shownWarning);
  }

  private static boolean isWarning(String code) {
    return org.robotrun.program.AlarmCode.of(code).map(x -> x.severity() == org.robotrun.program.AlarmSeverity.WARN)
        .orElse(false);
  }

  private void addWarning(ControllerAlarm a) {
    shownWarning = a;
    history.addFirst(a);
    while (history.size() > HISTORY) {
      history.removeLast();
    }
    warnings.addLast(a);
    while (warnings.size() > 1000) {
      warnings.removeFirst();
    }
  }

  /** A servo alarm from the UOP (*IMSTP): the arm stops at once, the programs pause. */
  void raiseServoAlarm(org.robotrun.program.AlarmCode code) {
    raiseAlarm(code.code(), code.text());
  }

  /**
   * INTP-105 for a start from the PLC or BG Logic the controller refused: a WARN (docs/alarms.md),
   * so the programs already running go on.
   */
  void raiseRunFailed(String why) {
    ControllerAlarm a = new ControllerAlarm(org.robotrun.program.AlarmCode.INTP_105.code(), "Run request failed: " + why,
        "", 0, timeSec);
    if (isWarning(a.code())) {
      addWarning(a);
    } else {
      addAlarm(a);
    }
  }

  /** Whether a SERVO-severity alarm is active (servo power off until RESET). */
  public boolean servoOff() {
    for (ControllerAlarm a : activeAlarms) {
      if (org.robotrun.program.AlarmCode.of(a.code()).map(x -> x.severity() == org.robotrun.program.AlarmSeverity.SERVO)
          .orElse(false)) {
        return true;
      }
    }
    return false;
  }

  private void addAlarm(ControllerAlarm a) {
    // A run that ends on an alarm has no cycle time.
    runStartSec = Double.NaN;
    activeAlarms.add(a);
    history.addFirst(a);
    while (history.size() > HISTORY) {
      history.removeLast();
    }
    jogger.stop(jogKeys);
  }

  private void stopMotion() {
    for (MoveState m : moves.values()) {
      m.interrupted = !m.finished && m.failure == null;
    }
    runner.stopNow();
    dropWhenStopped = false;
    arcHistory.clear();
    lastTargetW = null;
  }

  // ================================================================ MotionPort (the interpreter's side)

  @Override
  public Start startMotion(MotionRequest request) {
    if (dropWhenStopped) {
      // A new motion right after ABORT/BWD: finish the stop at once.
      runner.stopNow();
      dropWhenStopped = false;
    }
    if (!runner.acceptsMove()) {
      return new Start.Rejected(MotionAlarms.QUEUE_BUSY, "a motion is already waiting");
    }
    long h = nextHandle++;
    if (!TargetResolver.isArc(request)) {
      arcHistory.clear();
    } else if (arcHistory.isEmpty()) {
      arcHistory.add((lastTargetW != null && !runner.idle() ? lastTargetW
          : runner.tcpInWorld(frames.activeTool())).translationVector());
    }
    TargetResolver.Resolved r = resolver.resolve(request, frames, runner.joints(), arcHistory, h);
    return switch (r) {
      case TargetResolver.Refused no -> no.why();
      case TargetResolver.Move m -> {
        if (TargetResolver.isArc(request)) {
          arcHistory.add(m.X_WTarget().translationVector());
        }
        lastTargetW = m.X_WTarget();
        MoveState state = new MoveState(request.program(), request.line(), request.fine());
        state.request = m.move();
        state.targetW = m.X_WTarget();
        moves.put(h, state);
        runner.enqueue(m.move());
        yield new Start.Started(h);
      }
    };
  }

  @Override
  public Status poll(long handle) {
    MoveState m = moves.get(handle);
    if (m == null) {
      return Status.DONE;
    }
    if (m.failure != null) {
      return Status.FAILED;
    }
    if (m.finished || (!m.fine && runner.passedBlendPoint(handle))) {
      return Status.DONE;
    }
    return Status.RUNNING;
  }

  @Override
  public double timeLeftSec(long handle) {
    return moves.containsKey(handle) ? runner.timeLeftSec(handle) : 0;
  }

  @Override
  public double distanceLeftMm(long handle) {
    MoveState m = moves.get(handle);
    if (m == null || m.targetW == null) {
      return 0;
    }
    return runner.tcpInWorld(frames.activeTool()).translationVector().distanceTo(m.targetW.translationVector());
  }

  @Override
  public Start.Rejected failure(long handle) {
    MoveState m = moves.get(handle);
    return m == null || m.failure == null ? new Start.Rejected(MotionAlarms.UNREACHABLE, "unknown motion") : m.failure;
  }

  @Override
  public void hold(long handle) {
    runner.hold();
  }

  @Override
  public void resume(long handle) {
    runner.resume();
  }

  /** The program gives up its motion (ABORT, BWD): the arm decelerates along its path, then the motion is dropped. */
  @Override
  public void cancel(long handle) {
    moves.remove(handle);
    arcHistory.clear();
    lastTargetW = null;
    if (runner.atRest()) {
      runner.stopNow();
    } else {
      runner.hold();
      dropWhenStopped = true;
    }
  }

  @Override
  public Position.Cartesian currentLpos() {
    return resolver.lpos(runner.joints(), frames.activeUser(), frames.activeTool());
  }

  @Override
  public Position.Joint currentJpos() {
    return currentJoints();
  }

  @Override
  public int activeFrame(FrameKind kind) {
    return frames.active(kind);
  }

  @Override
  public void selectFrame(FrameKind kind, int number) {
    frames.select(kind, number);
  }

  @Override
  public Position.Cartesian frame(FrameKind kind, int number) {
    return frames.position(kind, number);
  }

  @Override
  public void setFrame(FrameKind kind, int number, Position.Cartesian value) {
    frames.setPosition(kind, number, value);
  }

  /** Receives the motion runner's events. */
  private final class Events implements MotionListener {
    @Override
    public void moveStarted(long tag, double simTimeSec) {
      MoveState m = moves.get(tag);
      if (m != null) {
        m.startSec = timeSec;
      }
    }

    @Override
    public void moveFinished(long tag, double simTimeSec) {
      MoveState m = moves.remove(tag);
      if (m == null) {
        return;
      }
      m.finished = true;
      // Removed: poll answers DONE for a handle it no longer knows.
      if (!Double.isNaN(m.startSec)) {
        timings.addLast(new MotionTiming(m.program, m.line, m.startSec, timeSec));
        while (timings.size() > TIMINGS) {
          timings.removeFirst();
        }
      }
    }

    @Override
    public void moveFailed(long tag, MotionFault fault) {
      MoveState m = moves.get(tag);
      Start.Rejected why = new Start.Rejected(MotionAlarms.codeOf(fault), fault.message());
      arcHistory.clear();
      lastTargetW = null;
      if (m == null || m.program.isEmpty()) {
        moves.remove(tag);
        addAlarm(new ControllerAlarm(why.code(), why.message(), "", 0, timeSec));
        return;
      }
      m.failure = why;
      addAlarm(new ControllerAlarm(why.code(), why.message(), m.program, m.line, timeSec));
    }
  }
}
