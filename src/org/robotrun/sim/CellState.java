package org.robotrun.sim;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.robotrun.collision.Obb;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.program.IoKind;
import org.robotrun.program.Registers;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/**
 * What moves in a cell besides the arms: the world's parts and each robot's end effector.
 *
 * <p>I/O, per robot with an end effector, on the ports its {@link org.robotrun.world.ToolIo}
 * names (by default {@link #OUTPUT}, {@link #INPUT_ACTUATED}, {@link #INPUT_HOLDING}): RO[1]
 * switches it on (close the gripper, vacuum on, dispense); RI[1] turns ON
 * {@link EndEffectorState#ACTUATION_SEC} after RO[1] goes ON and OFF as long after it goes OFF;
 * RI[2] is ON while a part is held.
 *
 * <p>Gripping: when RO[1] goes ON, a gripper or suction cup takes the part whose box overlaps
 * its pickup zone (the one nearest the TCP if several do) and keeps its pose in the flange
 * frame from then on. When RO[1] goes OFF the part stays where it is; if its bottom is within
 * {@link #SNAP_MM} of a fixture's upper face (level, or tilted up to
 * {@link #MAX_SUPPORT_TILT_DEG}), it is set down on that face and becomes that fixture's child
 * (it rests there); otherwise it stays in the air, a child of the cell (there is no gravity). A grip is rare, so the parts are scanned directly rather than
 * through the collision world, which may not exist (collision checking can be off).
 *
 * <p>{@link #version} changes whenever a part jumps (set down, reset) or the held set changes,
 * so the collision check knows to resynchronise; {@link #drainEvents} hands it grips and
 * releases. Not thread-safe: the simulation thread owns it.
 */
public final class CellState {
  /** The output that switches the end effector. */
  public static final int OUTPUT = 1;
  /** The input that reports the end effector closed (vacuum on, dispensing). */
  public static final int INPUT_ACTUATED = 1;
  /** The input that reports a part held. */
  public static final int INPUT_HOLDING = 2;
  /** How far a released part may be above (or sunk into) a fixture top and still be set on it (mm). */
  public static final double SNAP_MM = 2;
  /** Steepest fixture face that still holds a released part (degrees from level). */
  static final double MAX_SUPPORT_TILT_DEG = 45;

  private static final double MIN_SUPPORT_NZ = Math.cos(Math.toRadians(MAX_SUPPORT_TILT_DEG));

  /** A grip, a release or a reset, for the collision check's allowances. */
  sealed interface Event {
    /** Robot {@code robot} (controller index) took {@code part}. */
    record Gripped(String part, int robot) implements Event {}

    /** Robot {@code robot} let go of {@code part}. */
    record Released(String part, int robot) implements Event {}

    /** Every part went back to its start. */
    record Reset() implements Event {}
  }

  private World world;
  private final List<Optional<EndEffectorState>> tools;
  private final List<Event> events = new ArrayList<>();
  private long version;

  /**
   * @param world the fixtures and parts at the start
   * @param robotNames one per robot, in controller order
   * @param endEffectors one per robot: its tool, or empty for a robot without one (the default
   *     cell, where the controller's simple gripper I/O runs instead)
   */
  CellState(World world, List<String> robotNames, List<Optional<MountedTool>> endEffectors) {
    if (robotNames.size() != endEffectors.size()) {
      throw new IllegalArgumentException("one end effector entry per robot");
    }
    this.world = world;
    List<Optional<EndEffectorState>> t = new ArrayList<>();
    for (int r = 0; r < robotNames.size(); r++) {
      String name = robotNames.get(r);
      t.add(endEffectors.get(r).map(g -> new EndEffectorState(name, g)));
    }
    this.tools = List.copyOf(t);
  }

  /** The fixtures and parts as they are now. */
  public World world() {
    return world;
  }

  /** Every part back at its start pose and parent, nothing held, traces cleared ("reset scene"). */
  public void reset() {
    world = world.reset();
    for (Optional<EndEffectorState> t : tools) {
      t.ifPresent(EndEffectorState::reset);
    }
    events.clear();
    events.add(new Event.Reset());
    version++;
  }

  /**
   * The cell was edited (the cell editor): these fixtures and parts from now on, at their start
   * poses, nothing held, traces cleared.
   */
  void replaceWorld(World edited) {
    world = edited.reset();
    for (Optional<EndEffectorState> t : tools) {
      t.ifPresent(EndEffectorState::reset);
    }
    events.clear();
    events.add(new Event.Reset());
    version++;
  }

  /** Held part → name of the robot holding it. */
  public Map<String, String> heldBy() {
    Map<String, String> out = new LinkedHashMap<>();
    for (Optional<EndEffectorState> t : tools) {
      t.ifPresent(s -> s.held().ifPresent(h -> out.put(h.part(), s.robot)));
    }
    return out;
  }

  Optional<EndEffectorState> tool(int robot) {
    return tools.get(robot);
  }

  long version() {
    return version;
  }

  /** Grips, releases and resets since the last call, oldest first. */
  List<Event> drainEvents() {
    List<Event> out = List.copyOf(events);
    events.clear();
    return out;
  }

  /**
   * One tick, after the controllers moved: reads each robot's output, grips or releases,
   * carries held parts with their flanges, advances the fingers and sets the inputs.
   *
   * @param X_CF each robot's flange in the cell now
   * @return whether anything a collision check sees moved without an arm moving (fingers)
   */
  boolean tick(List<Controller> controllers, Transform[] X_CF, double dtSec) {
    boolean toolsMoved = false;
    for (int r = 0; r < tools.size(); r++) {
      if (tools.get(r).isEmpty()) {
        continue;
      }
      // X_CF[r] is computed only for tools that pick or trace (see needsFlangePose).
      EndEffectorState s = tools.get(r).get();
      Registers io = controllers.get(r).registers();
      // The held part follows the flange first, so a release leaves it where the flange is now.
      if (s.held().isPresent()) {
        EndEffectorState.Held h = s.held().get();
        world = world.with(world.find(h.part()).orElseThrow().movedTo(X_CF[r].compose(h.X_FP()), Optional.empty()));
      }
      boolean cmd = io.bit(IoKind.RO, s.io.output());
      if (cmd != s.on()) {
        s.setOn(cmd);
        if (cmd && s.geometry.picksParts()) {
          grip(r, s, X_CF[r]);
        } else if (!cmd && s.held().isPresent()) {
          release(r, s);
        }
      }
      toolsMoved |= s.actuate(dtSec) && s.geometry.hasFingers();
      if (s.on() && s.geometry.leavesTrace()) {
        s.extendTrace(X_CF[r].compose(s.geometry.X_FT()).translationVector());
      }
      if (s.settled() && io.bit(IoKind.RI, s.io.actuatedInput()) != s.on()) {
        io.setBit(IoKind.RI, s.io.actuatedInput(), s.on());
      }
      boolean holding = s.held().isPresent();
      if (io.bit(IoKind.RI, s.io.holdingInput()) != holding) {
        io.setBit(IoKind.RI, s.io.holdingInput(), holding);
      }
    }
    return toolsMoved;
  }

  private void grip(int r, EndEffectorState s, Transform X_CF) {
    Obb zone = s.geometry.pickupZone().orElseThrow().inWorld(X_CF);
    Vec3 p_CT = X_CF.compose(s.geometry.X_FT()).translationVector();
    Map<String, String> held = heldBy();
    String best = null;
    double bestDistance = Double.POSITIVE_INFINITY;
    for (WorldObject o : world.objects()) {
      if (o.kind() != ObjectKind.PART || held.containsKey(o.name())) {
        continue;
      }
      Obb box = world.collisionBox(o.name());
      double d = new Vec3(box.cx(), box.cy(), box.cz()).distanceTo(p_CT);
      if (d < bestDistance && box.overlaps(zone)) {
        best = o.name();
        bestDistance = d;
      }
    }
    if (best == null) {
      return;
    }
    Transform X_CP = world.poseInCell(best);
    // The part's width across the fingers (the flange's y axis): its box's extent along it.
    Obb box = world.collisionBox(best);
    Vec3 y = X_CF.axis(1);
    double width = 2 * (Math.abs(box.r00() * y.x() + box.r10() * y.y() + box.r20() * y.z()) * box.hx()
        + Math.abs(box.r01() * y.x() + box.r11() * y.y() + box.r21() * y.z()) * box.hy()
        + Math.abs(box.r02() * y.x() + box.r12() * y.y() + box.r22() * y.z()) * box.hz());
    s.hold(new EndEffectorState.Held(best, X_CF.inverse().compose(X_CP), width));
    world = world.with(world.find(best).orElseThrow().movedTo(X_CP, Optional.empty()));
    events.add(new Event.Gripped(best, r));
    version++;
  }

  private void release(int r, EndEffectorState s) {
    String part = s.held().orElseThrow().part();
    s.release();
    world = world.with(setDown(world, part, world.poseInCell(part)));
    events.add(new Event.Released(part, r));
    version++;
  }

  /**
   * The part released at {@code X_CP}: set on the fixture face it is resting on, as that
   * fixture's child; else left where it is, in the cell. A face can hold a part when its
   * outward normal is at most {@link #MAX_SUPPORT_TILT_DEG} from straight up (a tilted jig
   * holds one, a wall does not). The part rests on it when its lowest point along that normal
   * is within {@link #SNAP_MM} of the face plane (above or sunk in) and its box overlaps the
   * face; it is then moved along the normal until it just touches, keeping its orientation.
   * If several faces qualify, the one the part is sunk deepest into wins (the highest top).
   */
  static WorldObject setDown(World world, String part, Transform X_CP) {
    WorldObject o = world.find(part).orElseThrow();
    Obb p = o.shape().collisionBox(X_CP);
    String support = null;
    double bestGap = Double.NEGATIVE_INFINITY;
    double nx = 0, ny = 0, nz = 0;
    for (WorldObject f : world.objects()) {
      if (f.kind() != ObjectKind.FIXTURE) {
        continue;
      }
      Obb fb = world.collisionBox(f.name());
      SupportFace face = SupportFace.upper(fb);
      if (face.nz() < MIN_SUPPORT_NZ) {
        continue;
      }
      double plane = face.nx() * fb.cx() + face.ny() * fb.cy() + face.nz() * fb.cz() + face.halfDepth();
      double gap = plane - lowest(p, face.nx(), face.ny(), face.nz());
      if (gap < -SNAP_MM || gap > SNAP_MM || gap <= bestGap || !face.slab(fb).overlaps(p)) {
        continue;
      }
      bestGap = gap;
      support = f.name();
      nx = face.nx();
      ny = face.ny();
      nz = face.nz();
    }
    if (support == null) {
      return o.movedTo(X_CP, Optional.empty());
    }
    Transform X_CPset = X_CP.withTranslation(X_CP.x() + nx * bestGap, X_CP.y() + ny * bestGap, X_CP.z() + nz * bestGap);
    Transform X_CS = world.poseInCell(support);
    return o.movedTo(X_CS.inverse().compose(X_CPset), Optional.of(support));
  }

  /** The lowest extent of box {@code b} along the unit direction n (mm). */
  private static double lowest(Obb b, double nx, double ny, double nz) {
    double c = nx * b.cx() + ny * b.cy() + nz * b.cz();
    return c - Math.abs(nx * b.r00() + ny * b.r10() + nz * b.r20()) * b.hx()
        - Math.abs(nx * b.r01() + ny * b.r11() + nz * b.r21()) * b.hy()
        - Math.abs(nx * b.r02() + ny * b.r12() + nz * b.r22()) * b.hz();
  }

  /**
   * A box face, by its outward unit normal n (in the cell), the box's half extent along n, and
   * which box axis (0..2) it is normal to.
   */
  private record SupportFace(double nx, double ny, double nz, double halfDepth, int axis) {
    /** The face of {@code b} whose outward normal points most nearly up. */
    static SupportFace upper(Obb b) {
      double[] zOfAxis = {b.r20(), b.r21(), b.r22()};
      int k = 0;
      for (int i = 1; i < 3; i++) {
        if (Math.abs(zOfAxis[i]) > Math.abs(zOfAxis[k])) {
          k = i;
        }
      }
      double s = zOfAxis[k] >= 0 ? 1 : -1;
      return switch (k) {
        case 0 -> new SupportFace(s * b.r00(), s * b.r10(), s * b.r20(), b.hx(), 0);
        case 1 -> new SupportFace(s * b.r01(), s * b.r11(), s * b.r21(), b.hy(), 1);
        default -> new SupportFace(s * b.r02(), s * b.r12(), s * b.r22(), b.hz(), 2);
      };
    }

    /** The face itself, thickened by {@link #SNAP_MM} either side: what a resting part overlaps. */
    Obb slab(Obb b) {
      double cx = b.cx() + nx * halfDepth;
      double cy = b.cy() + ny * halfDepth;
      double cz = b.cz() + nz * halfDepth;
      return new Obb(cx, cy, cz,
          axis == 0 ? SNAP_MM : b.hx(), axis == 1 ? SNAP_MM : b.hy(), axis == 2 ? SNAP_MM : b.hz(),
          b.r00(), b.r01(), b.r02(), b.r10(), b.r11(), b.r12(), b.r20(), b.r21(), b.r22());
    }
  }

  /** Whether robot {@code r}'s tool needs its flange pose each tick (it picks parts or leaves a trace). */
  boolean needsFlangePose(int r) {
    return tools.get(r).map(t -> t.geometry.picksParts() || t.geometry.leavesTrace()).orElse(false);
  }

  /** The trace of robot {@code r}'s process tool (empty for other tools). */
  List<EndEffectorState.TraceSegment> trace(int r) {
    return tools.get(r).map(EndEffectorState::trace).orElse(List.of());
  }
}
