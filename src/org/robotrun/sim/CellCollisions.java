package org.robotrun.sim;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.robotrun.collision.Body;
import org.robotrun.collision.BodyKind;
import org.robotrun.collision.BodyPair;
import org.robotrun.collision.CollisionWorld;
import org.robotrun.collision.Obb;
import org.robotrun.collision.StandardPairFilter;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.RobotModel;
import org.robotrun.world.LocalBox;
import org.robotrun.world.RobotBodies;
import org.robotrun.world.World;
import org.robotrun.world.WorldBodies;

/**
 * Collision checking of a cell, once per tick: every robot's link bodies (a box around each link
 * shape) and its end effector's boxes (or, for a robot without one, a 20 mm square bar from the
 * flange to the active TCP), the world's fixtures and parts, and the floor, under
 * {@link CellPairFilter}.
 * Reports the contacts that began at this tick, so a lasting contact raises one alarm, not one
 * per tick.
 *
 * <p>Held parts: a held part's box follows it, shrunk by {@link #HELD_CLEARANCE_MM} on every
 * face so that a part set down exactly on a surface (or slid along one) does not count as a
 * collision, while one pushed into a fixture does. Two kinds of contact are allowed for a while:
 * at a grip, the part against whatever it rests on or leans against (until they separate: the
 * lift), and at a release, the part against the robot that let it go (until the tool has
 * moved clear). Allowed pairs are checked every tick and dropped once apart.
 *
 * <p>The tool bar is rebuilt when a robot's active tool changes (rare). Not thread-safe.
 */
final class CellCollisions {
  /** Cross-section of the tool bar (mm) of a robot without an end effector. */
  static final double TOOL_BAR_MM = 20;
  /** Gap left between the flange and the tool bar so the bar does not touch the wrist (mm). */
  static final double TOOL_GAP_MM = 2;
  /** A held part's box is this much smaller on every face (mm). */
  static final double HELD_CLEARANCE_MM = 0.5;

  private final List<Controller> controllers;
  private final CellState cell;
  private final double floorZ;
  private CollisionWorld collision;
  private WorldBodies objects;
  private List<RobotBodies> robots;
  private Transform[] tools;
  /** Per robot: handles of its end effector's boxes (empty without one). */
  private int[][] toolHandles;
  /** Per robot: the flange in the cell at the last check. */
  private final Transform[] X_CF;
  private final LinkPoses[] poses;
  /** Joints at the last check, per robot: nothing moved, nothing new to find. */
  private final double[][] lastQ;
  private long cellVersion = -1;
  private final Set<BodyPair> allowed = new LinkedHashSet<>();
  private Set<String> touching = new HashSet<>();
  /** Per robot name: its end effector's type as a student reads it ("gripper"); absent without one. */
  private final Map<String, String> toolTypes = new java.util.HashMap<>();

  /** Bodies touching at the last check, by draw-item name (a link's boxes "#k" merged). */
  Set<String> touchingBodies() {
    Set<String> out = new HashSet<>();
    for (String pair : touching) {
      for (String body : pair.split("\\|")) {
        int hash = body.indexOf('#');
        out.add(hash < 0 ? body : body.substring(0, hash));
      }
    }
    return out;
  }

  /** The tool bar of {@code X_FT} in the flange frame: its pose and full edge lengths; empty for a short tool. */
  static java.util.Optional<LocalBox> toolBar(Transform X_FT) {
    Vec3 p = X_FT.translationVector();
    double length = p.norm() - TOOL_GAP_MM;
    if (length <= 1) {
      return java.util.Optional.empty();
    }
    // A bar along the flange-to-TCP line, centred half-way past the gap.
    Vec3 dir = p.normalized();
    Vec3 centre = dir.times(TOOL_GAP_MM + length / 2);
    Transform X_FB = alongZ(dir).withTranslation(centre.x(), centre.y(), centre.z());
    return java.util.Optional.of(new LocalBox(X_FB, TOOL_BAR_MM / 2, TOOL_BAR_MM / 2, length / 2));
  }

  /**
   * A contact that began: the two bodies' ids ("robot1/link5#1", "table") and their names as a
   * student knows them ("robot1 J5 wrist", {@link BodyNames}).
   */
  record NewContact(String a, String aOwner, String b, String bOwner, String aText, String bText) {}

  /** Name of the floor's body: a fixture whose top is the cell's floor. */
  static final String FLOOR = "floor";
  /** Half size of the floor slab (mm): 20 m square, 10 mm thick. */
  static final double FLOOR_HALF_MM = 10_000;

  /** @param poses per robot, its links in the cell (shared with the simulation's flange, computed once a tick) */
  CellCollisions(List<Controller> controllers, LinkPoses[] poses, CellState cell, double floorZ) {
    this.controllers = controllers;
    this.cell = cell;
    this.floorZ = floorZ;
    this.poses = poses.clone();
    this.lastQ = new double[controllers.size()][];
    this.X_CF = new Transform[controllers.size()];
    build();
  }

  private void build() {
    collision = new CollisionWorld(filter());
    objects = new WorldBodies(cell.world(), collision);
    // The floor is always there: a robot's base stands on it (not checked), its links and tool are.
    if (cell.world().find(FLOOR).isEmpty()) {
      collision.add(Body.fixture(FLOOR, FLOOR), Obb.axisAligned(0, 0, floorZ - 5, FLOOR_HALF_MM, FLOOR_HALF_MM, 5));
    }
    robots = new ArrayList<>();
    tools = new Transform[controllers.size()];
    toolHandles = new int[controllers.size()][];
    for (int r = 0; r < controllers.size(); r++) {
      Controller c = controllers.get(r);
      tools[r] = c.frames().activeTool();
      Optional<EndEffectorState> tool = cell.tool(r);
      List<List<LocalBox>> boxes = boxes(c.model(), tools[r]);
      if (tool.isPresent()) {
        boxes.set(Body.TOOL_LINK, List.of());
      }
      robots.add(new RobotBodies(c.name(), boxes, collision));
      List<LocalBox> toolBoxes = tool.map(t -> t.geometry.boxes(t.fingerGapMm())).orElse(List.of());
      List<String> toolNames = tool.map(t -> t.geometry.boxNames()).orElse(List.of());
      tool.ifPresentOrElse(t -> toolTypes.put(c.name(), t.geometry.type().name()), () -> toolTypes.remove(c.name()));
      toolHandles[r] = new int[toolBoxes.size()];
      for (int k = 0; k < toolBoxes.size(); k++) {
        String name = c.name() + "/tool/" + toolNames.get(k);
        toolHandles[r][k] = collision.add(Body.robotLink(c.name(), Body.TOOL_LINK, name),
            toolBoxes.get(k).inWorld(Transform.IDENTITY));
      }
    }
    java.util.Arrays.fill(lastQ, null);
    cellVersion = -1;
    touching = new HashSet<>();
  }

  private CellPairFilter filter() {
    Set<String> touchable = new HashSet<>();
    for (var o : cell.world().objects()) {
      if (o.touchable()) {
        touchable.add(o.name());
      }
    }
    return new CellPairFilter(new StandardPairFilter(cell.heldBy(), allowed), touchable);
  }

  /** Boxes per link 0..6 from the link shapes, and link 7 (tool) from the flange to the TCP. */
  static List<List<LocalBox>> boxes(RobotModel model, Transform X_FT) {
    List<List<LocalBox>> out = new ArrayList<>();
    for (var link : model.links()) {
      List<LocalBox> boxes = new ArrayList<>();
      for (LinkShape s : link.shapes()) {
        boxes.add(switch (s) {
          case LinkShape.Box b -> LocalBox.ofBox(b.X_LS(), b.size());
          case LinkShape.Cylinder cy -> LocalBox.ofCylinder(cy.X_LS(), cy.radius(), cy.length());
        });
      }
      out.add(boxes);
    }
    List<LocalBox> tool = new ArrayList<>();
    toolBar(X_FT).ifPresent(tool::add);
    out.add(tool);
    return out;
  }

  /** A rotation taking z onto the unit vector {@code d}. */
  private static Transform alongZ(Vec3 d) {
    Vec3 axis = Vec3.Z.cross(d);
    double s = axis.norm();
    double c = Vec3.Z.dot(d);
    if (s < 1e-12) {
      return c > 0 ? Transform.IDENTITY : Transform.rotation(1, 0, 0, Math.PI);
    }
    return Transform.rotation(axis.x() / s, axis.y() / s, axis.z() / s, Math.atan2(s, c));
  }

  /**
   * Moves every robot's bodies to its current joints and the parts to where the cell has them,
   * runs the check, returns contacts that began now.
   *
   * @param toolsMoved whether fingers moved this tick (the arms may not have)
   */
  List<NewContact> check(boolean toolsMoved) {
    for (int r = 0; r < controllers.size(); r++) {
      if (cell.tool(r).isEmpty() && !controllers.get(r).frames().activeTool().equals(tools[r])) {
        build();
        break;
      }
    }
    boolean moved = toolsMoved;
    if (cell.version() != cellVersion) {
      cellVersion = cell.version();
      applyEvents();
      syncObjects();
      moved = true;
    }
    for (int r = 0; r < controllers.size(); r++) {
      double[] q = controllers.get(r).jointsRad();
      boolean armMoved = lastQ[r] == null || !java.util.Arrays.equals(q, lastQ[r]);
      if (!armMoved && !toolsMoved) {
        continue;
      }
      moved = true;
      if (armMoved) {
        lastQ[r] = q;
        Transform[] X_CL = poses[r].at(q);
        robots.get(r).moveTo(X_CL, collision);
        X_CF[r] = X_CL[Body.TOOL_LINK];
      }
      moveTool(r);
      moveHeldPart(r);
    }
    if (!moved) {
      return List.of();
    }
    int n = collision.update();
    pruneAllowed();
    if (n == 0 && touching.isEmpty()) {
      return List.of();
    }
    Set<String> now = new HashSet<>();
    List<NewContact> began = new ArrayList<>();
    for (var contact : collision.contacts()) {
      String key = contact.a().name() + "|" + contact.b().name();
      now.add(key);
      if (!touching.contains(key)) {
        began.add(new NewContact(contact.a().name(), contact.a().owner(), contact.b().name(), contact.b().owner(),
            BodyNames.of(contact.a(), toolTypes.getOrDefault(contact.a().owner(), "")),
            BodyNames.of(contact.b(), toolTypes.getOrDefault(contact.b().owner(), ""))));
      }
    }
    touching = now;
    return began;
  }

  private void moveTool(int r) {
    Optional<EndEffectorState> tool = cell.tool(r);
    if (tool.isEmpty() || X_CF[r] == null) {
      return;
    }
    List<LocalBox> boxes = tool.get().geometry.boxes(tool.get().fingerGapMm());
    for (int k = 0; k < toolHandles[r].length; k++) {
      collision.setBox(toolHandles[r][k], boxes.get(k).inWorld(X_CF[r]));
    }
  }

  private void moveHeldPart(int r) {
    cell.tool(r).flatMap(EndEffectorState::held).ifPresent(h -> collision.setBox(objects.handle(h.part()),
        partBox(cell.world(), h.part(), true)));
  }

  /** Every object's box where the cell has it (after a set-down or reset). */
  private void syncObjects() {
    World world = cell.world();
    Map<String, String> held = cell.heldBy();
    for (var o : world.objects()) {
      collision.setBox(objects.handle(o.name()), partBox(world, o.name(), held.containsKey(o.name())));
    }
  }

  private static Obb partBox(World world, String name, boolean held) {
    Obb b = world.collisionBox(name);
    if (!held) {
      return b;
    }
    double c = HELD_CLEARANCE_MM;
    return new Obb(b.cx(), b.cy(), b.cz(), Math.max(0, b.hx() - c), Math.max(0, b.hy() - c), Math.max(0, b.hz() - c),
        b.r00(), b.r01(), b.r02(), b.r10(), b.r11(), b.r12(), b.r20(), b.r21(), b.r22());
  }

  /** Grips and releases: allow the contacts they start with, and new held-part rules. */
  private void applyEvents() {
    World world = cell.world();
    for (CellState.Event e : cell.drainEvents()) {
      switch (e) {
        // What the part rests on or leans against when it is taken.
        case CellState.Event.Gripped g -> allowTouching(world, g.part(), true, other -> other.kind() != BodyKind.ROBOT);
        // The tool (or wrist) that just let it go.
        case CellState.Event.Released rel -> {
          String robot = controllers.get(rel.robot()).name();
          allowTouching(world, rel.part(), false, other -> other.kind() == BodyKind.ROBOT && other.owner().equals(robot));
        }
        // Everything back at its start: nothing held, nothing to allow.
        case CellState.Event.Reset reset -> allowed.clear();
      }
    }
    collision.setFilter(filter());
  }

  /** Allows the contacts {@code part} has now with the bodies {@code which} accepts. */
  private void allowTouching(World world, String part, boolean held, java.util.function.Predicate<Body> which) {
    Body p = collision.body(objects.handle(part));
    for (int h : collision.overlapping(partBox(world, part, held), b -> !b.owner().equals(part) && which.test(b))) {
      allowed.add(BodyPair.of(p, collision.body(h)));
    }
  }

  /** Drops allowed pairs whose boxes no longer touch; the new rules apply from the next check. */
  private void pruneAllowed() {
    if (allowed.isEmpty()) {
      return;
    }
    boolean changed = false;
    for (var it = allowed.iterator(); it.hasNext(); ) {
      BodyPair p = it.next();
      int a = handleOf(p.first());
      int b = handleOf(p.second());
      if (a < 0 || b < 0 || !collision.box(a).overlaps(collision.box(b))) {
        it.remove();
        changed = true;
      }
    }
    if (changed) {
      collision.setFilter(filter());
    }
  }

  private int handleOf(String bodyName) {
    for (int h = 0; h < collision.size(); h++) {
      if (collision.body(h).name().equals(bodyName)) {
        return h;
      }
    }
    return -1;
  }

  /** The collision world as of the last check (for drawing boxes green or red). */
  CollisionWorld world() {
    return collision;
  }
}
