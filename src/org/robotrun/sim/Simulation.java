package org.robotrun.sim;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.RobotModel;
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
  private final CellState cell;
  private final Transform[] X_CF;
  /** Per robot: its links and flange in the cell, computed once a tick for whoever needs them. */
  private final LinkPoses[] linkPoses;
  private final double floorZ;
  private final double tickSec;
  private long ticks;
  private CellCollisions collisions;
  private boolean checkCollisions = true;
  private boolean collisionAlarms = true;
  private boolean showBoxes;
  private final List<CollisionEvent> collisionEvents = new ArrayList<>();
  private VisionSystem vision;
  private WiredIo wiring = WiredIo.NONE;

  /** Colour of bodies in contact in snapshots. */
  public static final DrawItem.Color TOUCHING = DrawItem.Color.rgb(0.9, 0.1, 0.1);
  /** Colour of the tool bar in snapshots. */
  public static final DrawItem.Color TOOL_COLOR = DrawItem.Color.rgb(0.55, 0.56, 0.6);

  /** Alarm code of a collision. */
  public static final String COLLISION_ALARM = org.robotrun.program.AlarmCode.SRVO_050.code();
  /** Collision events kept (the oldest are dropped beyond this). */
  static final int MAX_EVENTS = 1000;

  /**
   * @param controllers the robots
   * @param X_CW each robot's WORLD frame in the cell frame C, in the same order
   * @param world fixtures and parts (drawn; parts are reported)
   * @param floorZ height of the floor in the cell (mm)
   */
  public Simulation(List<Controller> controllers, List<Transform> X_CW, World world, double floorZ, double tickSec) {
    this(controllers, X_CW, world, Collections.nCopies(controllers.size(), Optional.empty()), floorZ, tickSec);
  }

  /**
   * A cell whose robots carry end effectors (see {@link CellState} for their I/O): a robot with
   * one has its tool's boxes checked for collisions and picks parts; a robot without one (empty)
   * keeps the controller's simple gripper I/O and a bar from the flange to its TCP.
   *
   * @param endEffectors one per robot, in controller order
   */
  public Simulation(List<Controller> controllers, List<Transform> X_CW, World world,
      List<Optional<MountedTool>> endEffectors, double floorZ, double tickSec) {
    if (!(tickSec > 0 && tickSec <= 0.1)) {
      throw new IllegalArgumentException("tick must be in (0, 0.1] s, got " + tickSec);
    }
    if (X_CW.size() != controllers.size()) {
      throw new IllegalArgumentException("one placement per robot: " + controllers.size() + " robots, " + X_CW.size() + " placements");
    }
    this.controllers = List.copyOf(controllers);
    this.X_CW = List.copyOf(X_CW);
    this.cell = new CellState(world, this.controllers.stream().map(Controller::name).toList(), endEffectors);
    this.X_CF = new Transform[controllers.size()];
    this.linkPoses = new LinkPoses[controllers.size()];
    for (int r = 0; r < controllers.size(); r++) {
      linkPoses[r] = new LinkPoses(this.controllers.get(r).model(), this.X_CW.get(r));
      if (endEffectors.get(r).isPresent()) {
        // The end effector answers RI[1]; the controller's stand-in gripper must not.
        this.controllers.get(r).setDefaultGripperIo(false);
      }
    }
    this.floorZ = floorZ;
    this.tickSec = tickSec;
  }

  /** One robot, nothing else, the floor under the robot's base, 4 ms ticks. */
  public static Simulation of(Controller controller) {
    return new Simulation(List.of(controller), List.of(Transform.IDENTITY), World.empty(), controller.model().X_WB().z(),
        DEFAULT_TICK_SEC);
  }

  /**
   * Advances every controller by one tick, then the end effectors (grips, releases, held parts,
   * fingers, traces; {@link CellState}), then checks collisions: a contact that begins raises
   * {@link #COLLISION_ALARM} on each robot involved (the arm stops, the program pauses), or is
   * only recorded when {@link #setCollisionAlarms} is off.
   */
  public void step() {
    for (Controller c : controllers) {
      c.tick(tickSec);
    }
    ticks++;
    for (int r = 0; r < controllers.size(); r++) {
      if (cell.needsFlangePose(r)) {
        Controller c = controllers.get(r);
        // the same chain the collision check moves the links by (one per robot per tick)
        X_CF[r] = linkPoses[r].flange(c.jointsRad());
      }
    }
    boolean toolsMoved = cell.tick(controllers, X_CF, tickSec);
    // After every controller: a wired input sees this tick's outputs from the next tick on.
    wiring.propagate();
    if (checkCollisions) {
      if (collisions == null) {
        collisions = new CellCollisions(controllers, linkPoses, cell, floorZ);
      }
      List<CellCollisions.NewContact> began = collisions.check(toolsMoved);
      if (!began.isEmpty()) {
        reportContacts(began);
      }
    }
  }

  /**
   * Records contacts that began and, unless collisions only warn, raises one alarm per robot
   * involved (two fingers meeting the table in one tick are one collision); a held part's
   * contact stops the robot holding it.
   */
  private void reportContacts(List<CellCollisions.NewContact> began) {
    boolean[] alarmed = new boolean[controllers.size()];
    var held = cell.heldBy();
    for (CellCollisions.NewContact k : began) {
      if (collisionEvents.size() < MAX_EVENTS) {
        collisionEvents.add(new CollisionEvent(timeSec(), k.a(), k.b(), k.aText(), k.bText()));
      }
      if (!collisionAlarms) {
        continue;
      }
      String robotA = held.getOrDefault(k.aOwner(), k.aOwner());
      String robotB = held.getOrDefault(k.bOwner(), k.bOwner());
      // the arm (or what it holds) first: "robot1 gripper finger1 touches table"
      boolean robotFirst = controllers.stream().anyMatch(c -> c.name().equals(robotA))
          || controllers.stream().noneMatch(c -> c.name().equals(robotB));
      String text = robotFirst ? k.aText() + " touches " + k.bText() : k.bText() + " touches " + k.aText();
      for (int r = 0; r < controllers.size(); r++) {
        Controller c = controllers.get(r);
        if (!alarmed[r] && (c.name().equals(robotA) || c.name().equals(robotB))) {
          c.raiseAlarm(COLLISION_ALARM, "collision: " + text);
          alarmed[r] = true;
        }
      }
    }
  }

  /**
   * Connects outputs to inputs between (or within) the robots, as the scenario's wiring says
   * ({@link WiredIo}: an input follows its output from the next tick). The inputs take their
   * outputs' values at once.
   *
   * @throws IllegalArgumentException if a wire names a robot or port this cell does not have
   */
  public void setWiring(org.robotrun.world.Wiring w) {
    wiring = WiredIo.of(w, controllers);
    wiring.propagate();
  }

  /** Turns collision checking on (the default) or off. */
  public void setCollisionChecking(boolean on) {
    checkCollisions = on;
  }

  /**
   * Whether a collision stops the robot with {@link #COLLISION_ALARM} (true, the default) or is
   * only recorded in {@link #collisionEvents} and shown, for free play (false).
   */
  public void setCollisionAlarms(boolean alarm) {
    collisionAlarms = alarm;
  }

  public boolean collisionAlarms() {
    return collisionAlarms;
  }

  /**
   * Whether snapshots include the collision boxes (wire frame and translucent fill, green, or
   * red when touching) as of the last tick. Needs collision checking on.
   */
  public void setShowCollisionBoxes(boolean show) {
    showBoxes = show;
  }

  public boolean showCollisionBoxes() {
    return showBoxes;
  }

  /**
   * Reset scene: every part back at its start pose and on its start fixture, nothing held,
   * process traces cleared. The robots stay where they are (a part back at its start may now
   * touch a tool that stands there: that is reported as a collision at the next tick).
   */
  public void resetScene() {
    cell.reset();
  }

  /**
   * The cell editor changed the fixtures and parts: they stand at their start poses, nothing is
   * held, and the collision bodies are rebuilt at the next tick. The robots stay where they are.
   */
  public void replaceWorld(World edited) {
    cell.replaceWorld(edited);
    collisions = null;
  }

  /** Held part → name of the robot holding it. */
  public java.util.Map<String, String> heldParts() {
    return cell.heldBy();
  }

  /** The parts and end effectors (tests, draw lists). */
  CellState cellState() {
    return cell;
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

  /** The cell's vision system, when its scenario has one. */
  public Optional<VisionSystem> vision() {
    return Optional.ofNullable(vision);
  }

  void setVision(VisionSystem v) {
    vision = v;
  }

  /** The fixtures and parts, as they stand now. */
  public World world() {
    return cell.world();
  }

  /**
   * The current picture: draw list (fixtures, parts, robots, their end effectors and traces or
   * tool bars, in the cell frame; bodies in contact drawn in {@link #TOUCHING} red) and robot
   * states.
   */
  public SimSnapshot snapshot() {
    List<DrawItem> items = new ArrayList<>();
    WorldDrawList.addWorld(items, cell.world());
    List<RobotState> states = new ArrayList<>();
    for (int i = 0; i < controllers.size(); i++) {
      Controller c = controllers.get(i);
      // one forward kinematics per robot per frame: the links, the flange and the TCP from it
      RobotModel model = c.model();
      Transform[] X_RL = ForwardKinematics.linkPosesInBase(model, c.jointsRad());
      // X_WF composed as ForwardKinematics.flangePoseInWorld does, to the last bit
      Transform X_WF = model.X_WB().compose(X_RL[RobotModel.DOF].compose(model.X_6F()));
      for (int k = 0; k < X_RL.length; k++) {
        X_RL[k] = model.X_WB().compose(X_RL[k]);
      }
      RobotDrawList.addRobot(items, c.name(), model, X_CW.get(i), X_RL);
      Transform X_CF = X_CW.get(i).compose(X_WF);
      if (cell.tool(i).isPresent()) {
        EndEffectorDrawList.add(items, cell.tool(i).get(), X_CF);
      } else {
        CellCollisions.toolBar(c.frames().activeTool()).ifPresent(b -> items.add(new DrawItem(c.name() + "/tool",
            new DrawShape.Box(new org.robotrun.math.Vec3(2 * b.hxMm(), 2 * b.hyMm(), 2 * b.hzMm()), false),
            X_CF.compose(b.X_LB()), TOOL_COLOR)));
      }
      var j = c.currentJoints();
      states.add(new RobotState(c.name(), new double[] {j.j1Deg(), j.j2Deg(), j.j3Deg(), j.j4Deg(), j.j5Deg(), j.j6Deg()},
          org.robotrun.math.Xyzwpr.fromTransform(X_WF.compose(c.frames().activeTool())), c.frames().active(FrameKind.TOOL), c.frames().active(FrameKind.USER), c.overridePct(),
          c.status(), c.activeAlarms()));
    }
    if (showBoxes && checkCollisions && collisions != null) {
      CollisionBoxDrawList.add(items, collisions.world());
    }
    if (checkCollisions && collisions != null) {
      var touching = collisions.touchingBodies();
      if (!touching.isEmpty()) {
        items.replaceAll(d -> touching.contains(d.name()) ? new DrawItem(d.name(), d.shape(), d.X_WS(), TOUCHING) : d);
      }
    }
    double t = timeSec();
    return new SimSnapshot(t, new SceneSnapshot(t, items, floorZ), states);
  }
}
