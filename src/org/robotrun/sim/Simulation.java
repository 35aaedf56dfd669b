package org.robotrun.sim;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.math.Transform;
import org.robotrun.program.Instruction.FrameKind;

/**
 * The fixed-step simulation: every {@link #step} advances each controller by one tick (default
 * {@link #DEFAULT_TICK_SEC}, a controller's interpolation period). Deterministic: time is
 * {@code ticks × tick}, there is no wall clock and no randomness, so the same inputs give the
 * same states bit for bit. The GUI calls {@link #step} in real time; headless callers as fast as
 * they can. {@link #snapshot} builds an immutable picture for the renderer and status panels.
 *
 * <p>Not thread-safe: one thread steps it and reads snapshots (or hands them to another).
 */
public final class Simulation {
  /** Default tick: 4 ms. */
  public static final double DEFAULT_TICK_SEC = 0.004;

  private final List<Controller> controllers;
  private final List<DrawItem> cellItems;
  private final double floorZ;
  private final double tickSec;
  private long ticks;

  /**
   * @param controllers the robots (each standing at the cell's WORLD origin)
   * @param cellItems fixed things to draw besides the robots (tables, fixtures), in WORLD
   * @param floorZ height of the floor in WORLD (mm)
   */
  public Simulation(List<Controller> controllers, List<DrawItem> cellItems, double floorZ, double tickSec) {
    if (!(tickSec > 0 && tickSec <= 0.1)) {
      throw new IllegalArgumentException("tick must be in (0, 0.1] s, got " + tickSec);
    }
    this.controllers = List.copyOf(controllers);
    this.cellItems = List.copyOf(cellItems);
    this.floorZ = floorZ;
    this.tickSec = tickSec;
  }

  /** One robot, nothing else, the floor under the robot's base, 4 ms ticks. */
  public static Simulation of(Controller controller) {
    return new Simulation(List.of(controller), List.of(), controller.model().X_WB().z(), DEFAULT_TICK_SEC);
  }

  /** Advances every controller by one tick. */
  public void step() {
    for (Controller c : controllers) {
      c.tick(tickSec);
    }
    ticks++;
  }

  /** Simulated time (s): ticks × tick length. */
  public double timeSec() {
    return ticks * tickSec;
  }

  public long ticks() {
    return ticks;
  }

  public double tickSec() {
    return tickSec;
  }

  public List<Controller> controllers() {
    return controllers;
  }

  /** The current picture: draw list (cell and robots) and robot states. */
  public SimSnapshot snapshot() {
    List<DrawItem> items = new ArrayList<>(cellItems);
    List<RobotState> states = new ArrayList<>();
    for (Controller c : controllers) {
      RobotDrawList.addRobot(items, c.name(), c.model(), Transform.IDENTITY, c.jointsRad());
      var j = c.currentJoints();
      states.add(new RobotState(c.name(), new double[] {j.j1Deg(), j.j2Deg(), j.j3Deg(), j.j4Deg(), j.j5Deg(), j.j6Deg()},
          c.tcpInWorld(), c.frames().active(FrameKind.TOOL), c.frames().active(FrameKind.USER), c.overridePct(),
          c.status(), c.activeAlarms()));
    }
    double t = timeSec();
    return new SimSnapshot(t, new SceneSnapshot(t, items, floorZ), states);
  }
}
