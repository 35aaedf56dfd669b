package org.robotrun.app;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.motion.JogFrame;
import org.robotrun.motion.JogState;
import org.robotrun.pendant.RobotControl;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.Registers;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.CommandResult;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ControllerAlarm;
import org.robotrun.sim.OperatingMode;
import org.robotrun.sim.Simulation;

/**
 * The pendant's {@link RobotControl} port on a real {@link Controller} of a {@link Simulation}:
 * the robot model's kinematics, the motion planner, collision-free jog limits and the
 * project's frame teaching ({@link RobotFrameTeacher}). It lives in {@code app} (not
 * {@code pendant}) because the controller's API speaks {@code motion} and {@code robot} types,
 * which DESIGN.md keeps out of the pendant package.
 */
public final class SimRobotControl implements RobotControl {
  private final Simulation simulation;
  private final Controller controller;
  private double pendingSec;
  private final RobotFrameTeacher teacher = new RobotFrameTeacher();
  private java.util.function.Consumer<Simulation> afterTick = s -> { };

  /** Drives {@code controller}; {@link #advance} steps {@code simulation} (which owns it). */
  public SimRobotControl(Simulation simulation, Controller controller) {
    this.simulation = Objects.requireNonNull(simulation, "simulation");
    this.controller = Objects.requireNonNull(controller, "controller");
    if (!simulation.controllers().contains(controller)) {
      throw new IllegalArgumentException("controller " + controller.name() + " is not in the simulation");
    }
    // a pendant in hand: the mode switch starts at T1, as a window or script starts
    controller.setMode(OperatingMode.T1);
  }

  private static Result result(CommandResult r) {
    return switch (r) {
      case CommandResult.Ok ok -> new Result.Ok(ok.message());
      case CommandResult.Refused no -> new Result.Refused(no.reason());
    };
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
    return result(controller.deleteProgram(name));
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
  public void tpEnableChanged(boolean on) {
    controller.uop().setTpEnabled(on);
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
    return result(controller.moveTo(target, userFrame, toolFrame));
  }

  @Override
  public Result jogKeyDown(CoordSystem coord, int axis, int sign, boolean latched) {
    controller.setCoordSystem(JogFrame.valueOf(coord.name()));
    return result(controller.jogKeyDown(axis, sign, latched ? JogState.Press.LATCHED : JogState.Press.HELD));
  }

  @Override
  public Result jogIncrement(CoordSystem coord, int axis, int sign, boolean veryFine) {
    controller.setCoordSystem(JogFrame.valueOf(coord.name()));
    return result(controller.jogIncrement(axis, sign, veryFine));
  }

  @Override
  public void jogKeyUp(int axis, int sign) {
    controller.jogKeyUp(axis, sign);
  }

  @Override
  public void jogStop() {
    controller.jogStop();
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
  public Result run(String program, int line, boolean forward) {
    return result(controller.run(program, line, forward));
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
    return Mode.valueOf(controller.mode().name());
  }

  @Override
  public void setMode(Mode mode) {
    controller.setMode(OperatingMode.valueOf(mode.name()));
  }

  @Override
  public void emergencyStop(boolean fromPendant) {
    controller.emergencyStop(fromPendant);
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
  public void deadmanReleased() {
    controller.deadmanReleased();
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
    return controller.alarmHistory().stream().map(SimRobotControl::entry).toList();
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

  /** Called after every simulation tick {@link #advance} runs (a CSV trace). */
  public void setAfterTick(java.util.function.Consumer<Simulation> listener) {
    afterTick = Objects.requireNonNull(listener, "listener");
  }

  /** The simulation this port steps. */
  public Simulation simulation() {
    return simulation;
  }

  /** Steps the simulation in whole ticks; a remainder under one tick carries over to the next call. */
  @Override
  public void advance(double dtSec) {
    if (!(dtSec >= 0) || Double.isInfinite(dtSec)) {
      throw new IllegalArgumentException("dtSec must be finite and >= 0, got " + dtSec);
    }
    pendingSec += dtSec;
    double tick = simulation.tickSec();
    while (pendingSec >= tick - 1e-12) {
      simulation.step();
      afterTick.accept(simulation);
      pendingSec -= tick;
    }
  }
}
