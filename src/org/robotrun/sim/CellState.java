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
 * {@link #SNAP_MM} of the top of a fixture under it, it is set down on that top and becomes
 * that fixture's child (it rests there); otherwise it stays in the air, a child of the cell
 * (there is no gravity). A grip is rare, so the parts are scanned directly rather than
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
   * The part released at {@code X_CP}: set on the highest fixture top within {@link #SNAP_MM}
   * of its bottom, under its footprint, as that fixture's child; else where it is, in the cell.
   */
  static WorldObject setDown(World world, String part, Transform X_CP) {
    WorldObject o = world.find(part).orElseThrow();
    Obb box = o.shape().collisionBox(X_CP);
    double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
    double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
    bounds(box, lo, hi);
    double bottom = lo[2];
    // A slab under the part's footprint, SNAP_MM either side of its bottom.
    Obb slab = Obb.axisAligned((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, bottom,
        (hi[0] - lo[0]) / 2, (hi[1] - lo[1]) / 2, SNAP_MM);
    String support = null;
    double top = Double.NEGATIVE_INFINITY;
    for (WorldObject f : world.objects()) {
      if (f.kind() != ObjectKind.FIXTURE) {
        continue;
      }
      Obb fb = world.collisionBox(f.name());
      if (!fb.overlaps(slab)) {
        continue;
      }
      double[] flo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
      double[] fhi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
      bounds(fb, flo, fhi);
      if (fhi[2] <= bottom + SNAP_MM && fhi[2] > top) {
        top = fhi[2];
        support = f.name();
      }
    }
    if (support == null) {
      return o.movedTo(X_CP, Optional.empty());
    }
    Transform X_CPset = X_CP.withTranslation(X_CP.x(), X_CP.y(), X_CP.z() + (top - bottom));
    Transform X_CS = world.poseInCell(support);
    return o.movedTo(X_CS.inverse().compose(X_CPset), Optional.of(support));
  }

  private static void bounds(Obb box, double[] lo, double[] hi) {
    for (int i = 0; i < 8; i++) {
      double[] c = box.corner(i);
      for (int k = 0; k < 3; k++) {
        lo[k] = Math.min(lo[k], c[k]);
        hi[k] = Math.max(hi[k], c[k]);
      }
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
