package org.robotrun.sim;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.robotrun.control.RobotControl;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.motion.JogState;
import org.robotrun.program.AlarmCode;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.Registers;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;

/**
 * The {@link RobotControl} port of one {@link Controller}: what a teach pendant and an operator
 * panel drive. The switch signals (TP ENABLE, DEADMAN, SHIFT, mode, E-stop) arrive here and every
 * safety decision is made here, once: whether a jog or a start may go (mode, TP ENABLE, E-stop,
 * DEADMAN, SHIFT, then the controller's own alarm and motion checks), hold-to-run in T1/T2,
 * SRVO-003 when the DEADMAN lets go. The switches are stored once: DEADMAN in the controller, TP
 * ENABLE in its UOP, the jog coordinate system in the controller; only SHIFT lives here. Time is
 * not part of the port: the cell's {@link CellStepper} advances the controller.
 */
public final class ControllerPort implements RobotControl {
  private final Controller controller;
  private final RobotFrameTeacher teacher = new RobotFrameTeacher();
  private boolean shiftHeld;
  /** Whether a jog key went down since jogging last stopped (for the SHIFT-released message). */
  private boolean jogging;

  /**
   * The port of {@code controller} with a pendant in hand: the mode switch at T1, TP ENABLE on
   * (a cold-started controller's pendant is picked up switched on), DEADMAN and SHIFT let go.
   */
  public ControllerPort(Controller controller) {
    this.controller = Objects.requireNonNull(controller, "controller");
    controller.setMode(Mode.T1);
    controller.setDeadman(false);
    controller.uop().setTpEnabled(true);
  }

  /** The controller behind this port. */
  public Controller controller() {
    return controller;
  }

  // ---- programs, data, frames ----------------------------------------------------------------

  @Override
  public List<String> programNames() {
    return controller.programNames();
  }

  @Override
  public Optional<Program> program(String name) {
    return controller.program(name);
  }

  @Override
  public void saveProgram(Program program) {
    controller.saveProgram(program);
  }

  @Override
  public Result deleteProgram(String name) {
    return controller.deleteProgram(name);
  }

  @Override
  public Registers registers() {
    return controller.registers();
  }

  @Override
  public java.util.Map<String, String> programStates() {
    java.util.Map<String, String> out = new java.util.TreeMap<>();
    for (org.robotrun.sim.BgLogic.Slot s : controller.bgLogic().slots()) {
      if (s.running()) {
        out.put(s.program(), "BG");
      }
    }
    org.robotrun.sim.ExecutionStatus main = controller.status();
    if (main.state() == org.robotrun.sim.ExecutionStatus.State.RUNNING
        || main.state() == org.robotrun.sim.ExecutionStatus.State.PAUSED) {
      out.put(main.program(), main.state().name());
    }
    for (org.robotrun.sim.Tasks.Task t : controller.tasks().list()) {
      out.put(t.program(), t.status().state().name());
    }
    return out;
  }

  @Override
  public List<TaskInfo> tasks() {
    List<TaskInfo> out = new java.util.ArrayList<>();
    org.robotrun.sim.ExecutionStatus main = controller.status();
    if (main.state() == org.robotrun.sim.ExecutionStatus.State.RUNNING
        || main.state() == org.robotrun.sim.ExecutionStatus.State.PAUSED) {
      out.add(new TaskInfo(main.program(), main.state().name(), main.line(), true));
    }
    for (org.robotrun.sim.Tasks.Task t : controller.tasks().list()) {
      out.add(new TaskInfo(t.program(), t.status().state().name(), t.status().line(), false));
    }
    return out;
  }

  @Override
  public Result pauseTask(String program, boolean pause) {
    boolean found = pause ? controller.tasks().pause(program) : controller.tasks().resume(program);
    return found ? Result.ok() : Result.refused(program + " is not a running task");
  }

  @Override
  public Result abortTask(String program) {
    return controller.tasks().abort(program) ? Result.ok() : Result.refused(program + " is not a running task");
  }

  @Override
  public List<BgSlot> bgSlots() {
    return controller.bgLogic().slots().stream().map(s -> new BgSlot(s.program(), s.running())).toList();
  }

  @Override
  public Result addBg(String program) {
    return controller.bgLogic().add(program).<Result>map(Result::refused).orElse(Result.ok());
  }

  @Override
  public Result runBg(String program, boolean run) {
    return controller.bgLogic().setRunning(program, run).<Result>map(Result::refused).orElse(Result.ok());
  }

  @Override
  public Result removeBg(String program) {
    return controller.bgLogic().remove(program) ? Result.ok() : Result.refused(program + " is not in a BG Logic slot");
  }

  @Override
  public String comment(CommentTable table, int index) {
    return controller.registerComment(table.name(), index);
  }

  @Override
  public void setComment(CommentTable table, int index, String comment) {
    controller.setRegisterComment(table.name(), index, comment);
  }

  @Override
  public Position.Cartesian frame(FrameKind kind, int number) {
    return controller.frames().position(kind, number);
  }

  @Override
  public void setFrame(FrameKind kind, int number, Position.Cartesian value) {
    controller.frames().setPosition(kind, number, value);
  }

  @Override
  public String frameComment(FrameKind kind, int number) {
    return controller.frames().comment(kind, number);
  }

  @Override
  public void setFrameComment(FrameKind kind, int number, String comment) {
    controller.frames().setComment(kind, number, comment);
  }

  @Override
  public int activeFrame(FrameKind kind) {
    return controller.frames().active(kind);
  }

  @Override
  public void selectFrame(FrameKind kind, int number) {
    controller.frames().select(kind, number);
  }

  @Override
  public Position.Cartesian jogFrame(int number) {
    return controller.frames().jogFrame(number);
  }

  @Override
  public void setJogFrame(int number, Position.Cartesian value) {
    controller.frames().setJogFrame(number, value);
  }

  @Override
  public int activeJogFrame() {
    return controller.frames().activeJogNumber();
  }

  @Override
  public void selectJogFrame(int number) {
    controller.frames().selectJogFrame(number);
  }

  @Override
  public TeachResult teachFrame(FrameKind kind, int number, TeachMethod method, List<Position.Joint> points) {
    if (method.kind() != kind) {
      return new TeachResult.Failed(method.title() + " teaches " + method.kind() + " frames, not " + kind);
    }
    if (points.size() != method.pointNames().size()) {
      return new TeachResult.Failed(method.title() + " needs " + method.pointNames().size() + " points, got " + points.size());
    }
    // flange poses X_WF for tool methods; TCP positions of the active tool in WORLD for user methods
    List<Transform> X_WF = points.stream().map(q -> controller.toCartesian(q, 0, 0).toXyzwpr().toTransform()).toList();
    int tool = activeFrame(FrameKind.TOOL);
    List<Vec3> p_W = points.stream().map(q -> controller.toCartesian(q, 0, tool).toXyzwpr().position()).toList();
    TeachResult r = teacher.teach(method, X_WF, p_W);
    if (r instanceof TeachResult.Taught t) {
      setFrame(kind, number, t.frame());
    }
    return r;
  }

  // ---- position and jog ----------------------------------------------------------------------

  @Override
  public List<String> jointNames() {
    return controller.model().joints().stream().map(org.robotrun.robot.JointSpec::name).toList();
  }

  @Override
  public boolean coupledJ3() {
    return controller.model().coupledJ3();
  }

  @Override
  public Position.Joint currentJoints() {
    return controller.currentJoints();
  }

  @Override
  public Position.Cartesian currentPose(int userFrame, int toolFrame) {
    return controller.currentPose(userFrame, toolFrame);
  }

  @Override
  public Conversion<Position.Joint> toJoints(Position.Cartesian pose, int userFrame, int toolFrame) {
    return switch (controller.toJoints(pose, userFrame, toolFrame)) {
      case IkResult.Solved s -> {
        RobotModel model = controller.model();
        double[] p = JointConvention.kinematicToPendant(model, s.q());
        yield new Conversion.Ok<>(new Position.Joint(Math.toDegrees(p[0]), Math.toDegrees(p[1]), Math.toDegrees(p[2]),
            Math.toDegrees(p[3]), Math.toDegrees(p[4]), Math.toDegrees(p[5])));
      }
      case IkResult.Unreachable u -> new Conversion.Failed<>(u.message());
    };
  }

  @Override
  public Position.Cartesian toCartesian(Position.Joint joints, int userFrame, int toolFrame) {
    return controller.toCartesian(joints, userFrame, toolFrame);
  }

  @Override
  public Result moveTo(Position target, int userFrame, int toolFrame) {
    return controller.moveTo(target, userFrame, toolFrame);
  }

  @Override
  public CoordSystem coordSystem() {
    return controller.coordSystem();
  }

  @Override
  public void setCoordSystem(CoordSystem coord) {
    controller.setCoordSystem(coord);
    controller.jogStop();
    jogging = false;
  }

  @Override
  public Result jogKeyDown(int axis, int sign, boolean latched) {
    Optional<String> refused = switchRefusal("jog");
    if (refused.isPresent()) {
      return Result.refused(refused.get());
    }
    Result r = controller.jogKeyDown(axis, sign, latched ? JogState.Press.LATCHED : JogState.Press.HELD);
    if (r instanceof Result.Ok) {
      jogging = true;
    }
    return r;
  }

  @Override
  public Result jogIncrement(int axis, int sign, boolean veryFine) {
    Optional<String> refused = switchRefusal("jog");
    return refused.isPresent() ? Result.refused(refused.get()) : controller.jogIncrement(axis, sign, veryFine);
  }

  @Override
  public void jogKeyUp(int axis, int sign) {
    controller.jogKeyUp(axis, sign);
  }

  @Override
  public void jogStop() {
    controller.jogStop();
  }

  /** Whether a jog is on that has not stopped by itself since (a limit, the edge of reach). */
  private boolean jogging() {
    return jogging && controller.jogMessage().isEmpty();
  }

  /**
   * Why the pendant's switches do not allow {@code what} ("jog", "run") now, checked as a
   * controller does: mode, TP ENABLE, E-stop, DEADMAN, SHIFT.
   */
  private Optional<String> switchRefusal(String what) {
    if (controller.mode() == Mode.AUTO) {
      return Optional.of(what.equals("jog") ? "AUTO mode: the pendant cannot jog (mode switch to T1)"
          : "AUTO mode: start from the operator panel (TP OFF, CYCLE START)");
    }
    if (!tpEnabled()) {
      return Optional.of("TP disabled: turn TP ENABLE on to " + what);
    }
    if (controller.estopped()) {
      return Optional.of("E-stop pressed: release it and RESET");
    }
    if (!controller.deadman()) {
      return Optional.of("Hold the DEADMAN to " + what);
    }
    if (!shiftHeld) {
      return Optional.of("Hold SHIFT and the DEADMAN to " + what);
    }
    return Optional.empty();
  }

  // ---- switches -------------------------------------------------------------------------------

  @Override
  public double maxLinearSpeedMmPerSec() {
    return controller.model().maxLinearSpeedMmPerSec();
  }

  @Override
  public boolean tpEnabled() {
    return controller.uop().tpEnabled();
  }

  @Override
  public void setTpEnabled(boolean on) {
    if (!on && jogging) {
      controller.jogStop();
      jogging = false;
    }
    if (!on && tpEnabled()) {
      holdToRun("TP disabled");
    }
    controller.uop().setTpEnabled(on);
  }

  @Override
  public boolean deadmanHeld() {
    return controller.deadman();
  }

  @Override
  public Result setDeadman(boolean held) {
    if (held || !controller.deadman()) {
      controller.setDeadman(held);
      return Result.ok();
    }
    controller.setDeadman(false);
    jogging = false;
    if (!tpEnabled()) {
      return Result.ok();
    }
    boolean running = controller.status().state() == org.robotrun.sim.ExecutionStatus.State.RUNNING;
    controller.deadmanReleased();
    return new Result.Ok(AlarmCode.SRVO_003.code() + " " + AlarmCode.SRVO_003.text() + (running ? ": program paused" : "")
        + " (hold DEADMAN, RESET)");
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
    if (jogging()) {
      controller.jogStop();
      message = "Jog stopped: SHIFT released";
    }
    jogging = false;
    return new Result.Ok(holdToRun("SHIFT released").orElse(message));
  }

  /** T1/T2: a running program pauses when SHIFT, DEADMAN or TP ENABLE lets go (the arm decelerates). */
  private Optional<String> holdToRun(String why) {
    if (controller.mode().holdToRun() && controller.status().state() == org.robotrun.sim.ExecutionStatus.State.RUNNING) {
      controller.hold();
      return Optional.of("Program paused: " + why + " (hold-to-run in " + controller.mode() + "; SHIFT+FWD resumes)");
    }
    return Optional.empty();
  }

  // ---- execution and alarms ------------------------------------------------------------------

  @Override
  public int overridePct() {
    return controller.overridePct();
  }

  @Override
  public void setOverridePct(int percent) {
    controller.setOverridePct(Math.max(1, Math.min(100, percent)));
  }

  @Override
  public boolean stepMode() {
    return controller.stepMode();
  }

  @Override
  public void setStepMode(boolean on) {
    controller.setStepMode(on);
  }

  @Override
  public Result mayStart(StartFrom from, boolean forward) {
    if (from == StartFrom.OPERATOR_PANEL) {
      if (controller.mode() != Mode.AUTO) {
        return Result.refused("CYCLE START works in AUTO: in " + controller.mode() + " run from the pendant (SHIFT+FWD)");
      }
      if (tpEnabled()) {
        return Result.refused("CYCLE START refused: the TP is enabled (turn it OFF to run in AUTO)");
      }
      return Result.ok();
    }
    if (!shiftHeld) {
      return Result.refused("Hold SHIFT and press " + (forward ? "FWD" : "BWD") + " to run");
    }
    return switchRefusal("run").<Result>map(Result::refused).orElse(Result.ok());
  }

  @Override
  public Result run(StartFrom from, String program, int line, boolean forward) {
    Result may = mayStart(from, forward);
    return may instanceof Result.Refused ? may : controller.run(program, line, forward);
  }

  @Override
  public void hold() {
    controller.hold();
  }

  @Override
  public void abort() {
    controller.abort();
  }

  @Override
  public void reset() {
    controller.reset();
  }

  @Override
  public Mode mode() {
    return controller.mode();
  }

  @Override
  public void setMode(Mode mode) {
    controller.setMode(mode);
    jogging = false;
  }

  @Override
  public void emergencyStop(boolean fromPendant) {
    controller.emergencyStop(fromPendant);
    jogging = false;
  }

  @Override
  public void releaseEmergencyStop() {
    controller.releaseEmergencyStop();
  }

  @Override
  public boolean emergencyStopped() {
    return controller.estopped();
  }

  @Override
  public ExecutionStatus status() {
    org.robotrun.sim.ExecutionStatus s = controller.status();
    ExecState state = switch (s.state()) {
      case IDLE -> ExecState.IDLE;
      case RUNNING -> ExecState.RUNNING;
      case PAUSED -> ExecState.PAUSED;
      // a PAUSE/STOP/SERVO alarm keeps the program (and its call stack): it reads PAUSED; ABORT ended it
      case ALARMED -> controller.interpreter().callDepth() > 0 ? ExecState.PAUSED : ExecState.ABORTED;
    };
    return new ExecutionStatus(s.program(), s.line(), state);
  }

  private static AlarmEntry entry(ControllerAlarm a) {
    return new AlarmEntry(a.code(), a.message(), a.program(), a.line());
  }

  @Override
  public Optional<AlarmEntry> activeAlarm() {
    List<ControllerAlarm> active = controller.activeAlarms();
    // the newest active alarm is the one a pendant shows on its top line
    return active.isEmpty() ? Optional.empty() : Optional.of(entry(active.get(active.size() - 1)));
  }

  @Override
  public List<AlarmEntry> alarmHistory() {
    return controller.alarmHistory().stream().map(ControllerPort::entry).toList();
  }

  @Override
  public void clearAlarmHistory() {
    controller.clearAlarmHistory();
  }

  @Override
  public List<String> userMessages() {
    return controller.interpreter().userScreen();
  }

  @Override
  public String jogStopReason() {
    return controller.jogMessage();
  }
}
