package org.robotrun.sim;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.math.Transform;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.world.World;

/**
 * The fixed-step simulation: every {@link #step} advances each controller by one tick (default
 * {@link #DEFAULT_TICK_SEC}, a controller's interpolation period). Deterministic: time is
 * {@code ticks × tick}, there is no wall clock and no randomness, so the same inputs give the
 * same states bit for bit. The GUI calls {@link #step} in real time; headless callers as fast as
 * they can. {@link #snapshot} builds an immutable picture for the renderer and status panels.
 *
 * <p>Frames: each robot has its own WORLD (on its J1 axis at J2 height); the cell frame C is the
 * scenario's. Snapshots draw in C.
 *
 * <p>Not thread-safe: one thread steps it and reads snapshots (or hands them to another).
 */
public final class Simulation {
  /** Default tick: 4 ms. */
  public static final double DEFAULT_TICK_SEC = 0.004;

  private final List<Controller> controllers;
  private final List<Transform> X_CW;
  private final World world;
  private final double floorZ;
  private final double tickSec;
  private long ticks;
  private CellCollisions collisions;
  private boolean checkCollisions = true;
  private final List<CollisionEvent> collisionEvents = new ArrayList<>();

  /** Alarm code of a collision. */
  public static final String COLLISION_ALARM = "SRVO-050";
  /** Collision events kept (the oldest are dropped beyond this). */
  static final int MAX_EVENTS = 1000;

  /**
   * @param controllers the robots
   * @param X_CW each robot's WORLD frame in the cell frame C, in the same order
   * @param world fixtures and parts (drawn; parts are reported)
   * @param floorZ height of the floor in the cell (mm)
   */
  public Simulation(List<Controller> controllers, List<Transform> X_CW, World world, double floorZ, double tickSec) {
    if (!(tickSec > 0 && tickSec <= 0.1)) {
      throw new IllegalArgumentException("tick must be in (0, 0.1] s, got " + tickSec);
    }
    if (X_CW.size() != controllers.size()) {
      throw new IllegalArgumentException("one placement per robot: " + controllers.size() + " robots, " + X_CW.size() + " placements");
    }
    this.controllers = List.copyOf(controllers);
    this.X_CW = List.copyOf(X_CW);
    this.world = world;
    this.floorZ = floorZ;
    this.tickSec = tickSec;
  }

  /** One robot, nothing else, the floor under the robot's base, 4 ms ticks. */
  public static Simulation of(Controller controller) {
    return new Simulation(List.of(controller), List.of(Transform.IDENTITY), World.empty(), controller.model().X_WB().z(),
        DEFAULT_TICK_SEC);
  }

  /**
   * Advances every controller by one tick, then checks collisions: a contact that begins raises
   * {@link #COLLISION_ALARM} on each robot involved (the arm stops, the program pauses).
   */
  public void step() {
    for (Controller c : controllers) {
      c.tick(tickSec);
    }
    ticks++;
    if (checkCollisions) {
      if (collisions == null) {
        collisions = new CellCollisions(controllers, X_CW, world);
      }
      for (CellCollisions.NewContact k : collisions.check()) {
        if (collisionEvents.size() < MAX_EVENTS) {
          collisionEvents.add(new CollisionEvent(timeSec(), k.a(), k.b()));
        }
        for (Controller c : controllers) {
          if (c.name().equals(k.aOwner()) || c.name().equals(k.bOwner())) {
            c.raiseAlarm(COLLISION_ALARM, "collision: " + k.a() + " touches " + k.b());
          }
        }
      }
    }
  }

  /** Turns collision checking on (the default) or off. */
  public void setCollisionChecking(boolean on) {
    checkCollisions = on;
  }

  /** Contacts that began during the run, oldest first (at most 1000). */
  public List<CollisionEvent> collisionEvents() {
    return List.copyOf(collisionEvents);
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

  /** Each robot's WORLD frame in the cell, in controller order. */
  public List<Transform> robotPlacements() {
    return X_CW;
  }

  /** The fixtures and parts, as they stand now. */
  public World world() {
    return world;
  }

  /** The current picture: draw list (cell and robots) and robot states. */
  public SimSnapshot snapshot() {
    List<DrawItem> items = new ArrayList<>();
    WorldDrawList.addWorld(items, world);
    List<RobotState> states = new ArrayList<>();
    for (int i = 0; i < controllers.size(); i++) {
      Controller c = controllers.get(i);
      RobotDrawList.addRobot(items, c.name(), c.model(), X_CW.get(i), c.jointsRad());
      var j = c.currentJoints();
      states.add(new RobotState(c.name(), new double[] {j.j1Deg(), j.j2Deg(), j.j3Deg(), j.j4Deg(), j.j5Deg(), j.j6Deg()},
          c.tcpInWorld(), c.frames().active(FrameKind.TOOL), c.frames().active(FrameKind.USER), c.overridePct(),
          c.status(), c.activeAlarms()));
    }
    double t = timeSec();
    return new SimSnapshot(t, new SceneSnapshot(t, items, floorZ), states);
  }
}
