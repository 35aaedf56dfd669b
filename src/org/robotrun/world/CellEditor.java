package org.robotrun.world;

import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;

/**
 * The cell editor's model (the RobotRun paper's section 3.6): the named scenarios of a workspace,
 * one of them active, and edits of the active one's fixtures and parts: add a box, cylinder or
 * STL mesh, rename, recolour, change kind, parent, pose (X Y Z W P R) and size, duplicate,
 * delete, undo and redo. Every edit either applies whole or is refused with one message that
 * names the field and the range it accepts; a refused edit changes nothing.
 *
 * <p>What is edited is the cell as the scenario starts it (start poses): the simulation rebuilds
 * its parts from {@link #active()} after each edit. Not thread-safe; no window needed.
 */
public final class CellEditor {
  /** Largest coordinate or size accepted (mm): 100 m, far beyond any teaching cell. */
  public static final double MAX_MM = 100_000;
  /** Largest angle accepted for W, P, R (degrees). */
  public static final double MAX_DEG = 360;
  /** Largest STL scale factor accepted. */
  public static final double MAX_SCALE = 10_000;
  /** Undo steps kept. */
  static final int UNDO_DEPTH = 200;

  /** What an edit did. */
  public sealed interface Result {
    /** Applied; {@code message} says what, for a status line. */
    record Done(String message) implements Result {}

    /** Refused, nothing changed; {@code message} names the field and what it accepts. */
    record Refused(String message) implements Result {}
  }

  /** A number field of an object. */
  public enum NumberField {
    X("X", "mm"), Y("Y", "mm"), Z("Z", "mm"), W("W", "deg"), P("P", "deg"), R("R", "deg"),
    LENGTH("length", "mm"), WIDTH("width", "mm"), HEIGHT("height", "mm"), RADIUS("radius", "mm"),
    SCALE("scale", "");

    private final String label;
    private final String unit;

    NumberField(String label, String unit) {
      this.label = label;
      this.unit = unit;
    }

    public String label() {
      return label;
    }

    public String unit() {
      return unit;
    }

    boolean isPose() {
      return ordinal() <= R.ordinal();
    }

    boolean isAngle() {
      return this == W || this == P || this == R;
    }

    /** The values the field takes, as a refusal says them after "enter" ("-100000 to 100000 mm"). */
    String range() {
      if (isAngle()) {
        return "-" + fmt(MAX_DEG) + " to " + fmt(MAX_DEG) + " deg";
      }
      if (isPose()) {
        return "-" + fmt(MAX_MM) + " to " + fmt(MAX_MM) + " mm";
      }
      if (this == SCALE) {
        return "more than 0, at most " + fmt(MAX_SCALE);
      }
      return "more than 0, at most " + fmt(MAX_MM) + " mm";
    }

    boolean accepts(double v) {
      if (!Double.isFinite(v)) {
        return false;
      }
      if (isAngle()) {
        return Math.abs(v) <= MAX_DEG;
      }
      if (isPose()) {
        return Math.abs(v) <= MAX_MM;
      }
      return v > 0 && v <= (this == SCALE ? MAX_SCALE : MAX_MM);
    }
  }

  /** Reads an STL file into a mesh in mm; throws IllegalArgumentException with a message saying why not. */
  @FunctionalInterface
  public interface MeshLoader {
    TriangleMesh load(Path file, double scale);
  }

  /** The whole edited state: immutable, so undo keeps whole copies. */
  private record State(List<Scenario> scenarios, int active) {}

  private State state;
  private final Deque<State> undo = new ArrayDeque<>();
  private final Deque<State> redo = new ArrayDeque<>();
  /** What each undo and redo step did (the edit's own confirmation), so undoing can say what it took back. */
  private final Deque<String> undoWhat = new ArrayDeque<>();
  private final Deque<String> redoWhat = new ArrayDeque<>();
  private final MeshLoader meshes;
  private long revision;

  /**
   * @param scenario the cell to start with (it becomes the only scenario, active)
   * @param meshes how STL files are read (the io package's reader; tests pass their own)
   */
  public CellEditor(Scenario scenario, MeshLoader meshes) {
    this(List.of(scenario), 0, meshes);
  }

  /** Several named scenarios, {@code active} the one shown. */
  public CellEditor(List<Scenario> scenarios, int active, MeshLoader meshes) {
    if (scenarios.isEmpty() || active < 0 || active >= scenarios.size()) {
      throw new IllegalArgumentException("need at least one scenario and a valid active index");
    }
    this.state = new State(List.copyOf(scenarios), active);
    this.meshes = meshes;
  }

  // ---- reading ---------------------------------------------------------------------------

  /** The active scenario as edited. */
  public Scenario active() {
    return state.scenarios.get(state.active);
  }

  public int activeIndex() {
    return state.active;
  }

  public List<Scenario> scenarios() {
    return state.scenarios;
  }

  public World world() {
    return active().world();
  }

  /** Grows by one with every change (applied, undone or redone): the simulation rebuilds then. */
  public long revision() {
    return revision;
  }

  public boolean canUndo() {
    return !undo.isEmpty();
  }

  public boolean canRedo() {
    return !redo.isEmpty();
  }

  /** The value shown in a number field (mm, degrees, or the mesh scale); NaN when the shape has none. */
  public double number(String object, NumberField f) {
    WorldObject o = world().find(object).orElseThrow(() -> new IllegalArgumentException("no object named '" + object + "'"));
    Xyzwpr p = Xyzwpr.fromTransform(o.startPose());
    return switch (f) {
      case X -> p.x();
      case Y -> p.y();
      case Z -> p.z();
      case W -> p.wDeg();
      case P -> p.pDeg();
      case R -> p.rDeg();
      case LENGTH -> o.shape() instanceof Shape.Box b ? b.lengthMm() : Double.NaN;
      case WIDTH -> o.shape() instanceof Shape.Box b ? b.widthMm() : Double.NaN;
      case HEIGHT -> switch (o.shape()) {
        case Shape.Box b -> b.heightMm();
        case Shape.Cylinder c -> c.heightMm();
        case Shape.Mesh m -> Double.NaN;
      };
      case RADIUS -> o.shape() instanceof Shape.Cylinder c ? c.radiusMm() : Double.NaN;
      case SCALE -> o.shape() instanceof Shape.Mesh m ? m.scale() : Double.NaN;
    };
  }

  // ---- object edits ------------------------------------------------------------------------

  /** Adds a 100 mm box (a part) at the cell origin with a free name ("box1", "box2", ...). */
  public Result addBox() {
    return addObject(freeName("box"), new Shape.Box(100, 100, 100));
  }

  /** Adds a cylinder of radius 50 mm, 100 mm high (a part). */
  public Result addCylinder() {
    return addObject(freeName("cylinder"), new Shape.Cylinder(50, 100));
  }

  /** Adds the STL mesh in {@code file}, its coordinates times {@code scale} giving mm (a fixture). */
  public Result addMesh(Path file, double scale) {
    if (!NumberField.SCALE.accepts(scale)) {
      return refused("scale " + fmt(scale) + ": Value out of range, enter " + NumberField.SCALE.range());
    }
    String f = file.getFileName() == null ? "" : file.getFileName().toString();
    if (!f.toLowerCase(Locale.ROOT).endsWith(".stl")) {
      return refused("STL file: expected a file ending in .stl, got '" + f + "'");
    }
    TriangleMesh mesh;
    try {
      mesh = meshes.load(file, scale);
    } catch (IllegalArgumentException e) {
      return refused("STL file " + f + ": " + e.getMessage());
    }
    String stem = f.substring(0, f.length() - 4).replaceAll("[^A-Za-z0-9_]", "_");
    WorldObject o = WorldObject.of(freeName(stem.isEmpty() ? "mesh" : stem), ObjectKind.FIXTURE,
        new Shape.Mesh(file, scale, mesh), Rgb.GREY, Transform.IDENTITY, Optional.empty());
    return apply(withWorld(append(o)), "imported " + f + " as fixture " + o.name() + " (" + mesh.triangleCount()
        + " triangles, scale " + fmt(scale) + ")");
  }

  private Result addObject(String name, Shape shape) {
    Transform at = freeSpot(shape);
    WorldObject o = WorldObject.of(name, ObjectKind.PART, shape, new Rgb(0xd9, 0x6b, 0x2b), at, Optional.empty());
    Xyzwpr p = Xyzwpr.fromTransform(at);
    return apply(withWorld(append(o)), "added " + name + " at X " + fmt(p.x()) + " Y " + fmt(p.y()) + " Z " + fmt(p.z()));
  }

  /**
   * Where a new object goes: standing on the floor (the first robot's base height) in front of
   * or beside the first robot, at least {@link #CLEAR_OF_ROBOT_MM} from every robot's base axis
   * and touching no object; the first such spot of a few rings around the robot. At the cell
   * origin it would stand inside the robot's base and stop it with a collision alarm at once.
   */
  private Transform freeSpot(Shape shape) {
    Vec3 base = active().robots().get(0).X_CB().translationVector();
    double up = shape instanceof Shape.Box b ? b.heightMm() / 2 : shape instanceof Shape.Cylinder c ? c.heightMm() / 2 : 0;
    World w = world();
    for (double radius : new double[] {550, 750, 950, 1200}) {
      for (double deg : new double[] {0, -35, 35, -70, 70, -110, 110, 180}) {
        double x = base.x() + radius * Math.cos(Math.toRadians(deg));
        double y = base.y() + radius * Math.sin(Math.toRadians(deg));
        Transform t = Transform.translation(Math.rint(x), Math.rint(y), Math.rint(base.z() + up));
        var box = shape.collisionBox(t);
        boolean clear = w.objects().stream().noneMatch(o -> w.collisionBox(o.name()).overlaps(box))
            && active().robots().stream().allMatch(r -> {
              Vec3 rb = r.X_CB().translationVector();
              return Math.hypot(rb.x() - t.translationVector().x(), rb.y() - t.translationVector().y()) >= CLEAR_OF_ROBOT_MM;
            });
        if (clear) {
          return t;
        }
      }
    }
    return Transform.translation(base.x() + 550, base.y(), base.z() + up);
  }

  /** How far from a robot's base axis a new object stands at least (mm). */
  static final double CLEAR_OF_ROBOT_MM = 450;

  /** A copy of {@code object} named "NAME_copy" (numbered if taken), 100 mm along +Y. */
  public Result duplicate(String object) {
    Optional<WorldObject> found = world().find(object);
    if (found.isEmpty()) {
      return refused("no object named '" + object + "'");
    }
    WorldObject o = found.get();
    Transform moved = Transform.translation(0, 100, 0).compose(o.startPose());
    WorldObject copy = WorldObject.of(freeName(o.name() + "_copy"), o.kind(), o.shape(), o.colour(), moved, o.startParent()).withTouchable(o.touchable());
    return apply(withWorld(append(copy)), "duplicated " + o.name() + " as " + copy.name());
  }

  /** Deletes {@code object}; refused while other objects stand on it (delete or re-parent them first). */
  public Result delete(String object) {
    if (world().find(object).isEmpty()) {
      return refused("no object named '" + object + "'");
    }
    List<String> children = world().objects().stream()
        .filter(o -> o.startParent().filter(object::equals).isPresent()).map(WorldObject::name).toList();
    if (!children.isEmpty()) {
      return refused("cannot delete " + object + ": " + String.join(", ", children) + " stand"
          + (children.size() == 1 ? "s" : "") + " on it; delete them or change their parent first");
    }
    List<WorldObject> out = new ArrayList<>(world().objects());
    out.removeIf(o -> o.name().equals(object));
    return apply(withWorld(new World(out)), "deleted " + object);
  }

  /** Renames {@code object}; objects standing on it follow. */
  public Result rename(String object, String newName) {
    String n = newName == null ? "" : newName.trim();
    if (!n.matches("[A-Za-z_][A-Za-z0-9_\\-]{0,31}")) {
      return refused("name: expected 1 to 32 letters, digits, _ or - starting with a letter or _, got '" + newName + "'");
    }
    if (n.equals(object)) {
      return new Result.Done("");
    }
    if (world().find(n).isPresent()) {
      return refused("name: '" + n + "' is already taken");
    }
    List<WorldObject> out = new ArrayList<>();
    for (WorldObject o : world().objects()) {
      WorldObject r = o;
      if (o.name().equals(object)) {
        r = WorldObject.of(n, o.kind(), o.shape(), o.colour(), o.startPose(), o.startParent()).withTouchable(o.touchable());
      }
      if (r.startParent().filter(object::equals).isPresent()) {
        r = WorldObject.of(r.name(), r.kind(), r.shape(), r.colour(), r.startPose(), Optional.of(n)).withTouchable(r.touchable());
      }
      out.add(r);
    }
    return apply(withWorld(new World(out)), "renamed " + object + " to " + n);
  }

  /** Sets the colour from "#rrggbb". */
  public Result setColour(String object, String hex) {
    Optional<Rgb> c = Rgb.parse(hex == null ? "" : hex.trim());
    if (c.isEmpty()) {
      return refused("colour: expected #rrggbb (six hex digits), got '" + hex + "'");
    }
    return replace(object, o -> WorldObject.of(o.name(), o.kind(), o.shape(), c.get(), o.startPose(), o.startParent()).withTouchable(o.touchable()),
        "colour of " + object + " is " + c.get().hex());
  }

  /** Part (can be picked up) or fixture (stays); a fixture others stand on stays a fixture. */
  public Result setKind(String object, ObjectKind kind) {
    if (kind == ObjectKind.PART && world().objects().stream().anyMatch(o -> o.startParent().filter(object::equals).isPresent())) {
      return refused("kind: " + object + " stays a fixture while objects stand on it");
    }
    return replace(object, o -> WorldObject.of(o.name(), kind, o.shape(), o.colour(), o.startPose(), o.startParent()).withTouchable(o.touchable()),
        object + " is a " + kind.name().toLowerCase(Locale.ROOT));
  }

  /**
   * Puts {@code object} on the fixture {@code parent} (empty: on the cell). Its pose is kept in
   * the cell, so the object does not jump; its numbers change to be relative to the new parent.
   */
  public Result setParent(String object, Optional<String> parent) {
    Optional<WorldObject> found = world().find(object);
    if (found.isEmpty()) {
      return refused("no object named '" + object + "'");
    }
    Transform X_CO = world().reset().poseInCell(object);
    Transform pose = X_CO;
    if (parent.isPresent()) {
      Optional<WorldObject> p = world().find(parent.get());
      if (p.isEmpty()) {
        return refused("parent: no fixture named '" + parent.get() + "'");
      }
      if (p.get().kind() != ObjectKind.FIXTURE) {
        return refused("parent: expected a fixture, '" + parent.get() + "' is a part");
      }
      for (Optional<String> up = Optional.of(parent.get()); up.isPresent(); up = world().find(up.get()).flatMap(WorldObject::startParent)) {
        if (up.get().equals(object)) {
          return refused("parent: " + parent.get() + " stands on " + object + " (directly or through others): that would make a loop");
        }
      }
      pose = world().reset().poseInCell(parent.get()).inverse().compose(X_CO);
    }
    Transform finalPose = pose;
    return replace(object, o -> WorldObject.of(o.name(), o.kind(), o.shape(), o.colour(), finalPose, parent).withTouchable(o.touchable()),
        object + (parent.isPresent() ? " stands on " + parent.get() : " stands in the cell"));
  }

  /** Sets one number field from the text typed into it. */
  public Result setNumber(String object, NumberField f, String text) {
    String t = text == null ? "" : text.trim();
    double v;
    try {
      v = Double.parseDouble(t);
    } catch (NumberFormatException e) {
      return refusedNumber(object, f, "'" + text + "'", "not a number");
    }
    if (t.matches("(?i).*(nan|infinity|[fd])$")) {
      return refusedNumber(object, f, "'" + text + "'", "not a number");
    }
    return setNumber(object, f, v);
  }

  /**
   * A refused number, worded as the controller's "Value out of range": the field, what was
   * typed, why, the range to enter, and the value the field keeps (issue 29).
   */
  private Result refusedNumber(String object, NumberField f, String typed, String why) {
    double old = world().find(object).isPresent() ? number(object, f) : Double.NaN;
    String kept = Double.isNaN(old) ? "" : "; " + f.label() + " stays " + fmt(old) + (f.unit().isEmpty() ? "" : " " + f.unit());
    return refused(f.label() + " " + typed + ": " + why + ", enter " + f.range() + kept);
  }

  /** Sets one number field (mm, degrees or scale). */
  public Result setNumber(String object, NumberField f, double v) {
    Optional<WorldObject> found = world().find(object);
    if (found.isEmpty()) {
      return refused("no object named '" + object + "'");
    }
    if (!f.accepts(v)) {
      return refusedNumber(object, f, fmt(v), "Value out of range");
    }
    WorldObject o = found.get();
    if (f.isPose()) {
      Xyzwpr p = Xyzwpr.fromTransform(o.startPose());
      Xyzwpr q = Xyzwpr.ofDegrees(
          f == NumberField.X ? v : p.x(), f == NumberField.Y ? v : p.y(), f == NumberField.Z ? v : p.z(),
          f == NumberField.W ? v : p.wDeg(), f == NumberField.P ? v : p.pDeg(), f == NumberField.R ? v : p.rDeg());
      return replace(object, x -> WorldObject.of(x.name(), x.kind(), x.shape(), x.colour(), q.toTransform(), x.startParent()).withTouchable(x.touchable()),
          object + " " + f.label() + " = " + fmt(v) + " " + f.unit());
    }
    Shape s = o.shape();
    Shape changed;
    switch (s) {
      case Shape.Box b -> {
        if (f != NumberField.LENGTH && f != NumberField.WIDTH && f != NumberField.HEIGHT) {
          return refused(f.label() + ": a box has length, width and height");
        }
        changed = new Shape.Box(f == NumberField.LENGTH ? v : b.lengthMm(), f == NumberField.WIDTH ? v : b.widthMm(),
            f == NumberField.HEIGHT ? v : b.heightMm());
      }
      case Shape.Cylinder c -> {
        if (f != NumberField.RADIUS && f != NumberField.HEIGHT) {
          return refused(f.label() + ": a cylinder has radius and height");
        }
        changed = new Shape.Cylinder(f == NumberField.RADIUS ? v : c.radiusMm(), f == NumberField.HEIGHT ? v : c.heightMm());
      }
      case Shape.Mesh m -> {
        if (f != NumberField.SCALE) {
          return refused(f.label() + ": a mesh has a scale");
        }
        TriangleMesh mesh;
        try {
          mesh = meshes.load(m.file(), v);
        } catch (IllegalArgumentException e) {
          return refused("scale: " + e.getMessage());
        }
        changed = new Shape.Mesh(m.file(), v, mesh);
      }
    }
    return replace(object, x -> WorldObject.of(x.name(), x.kind(), changed, x.colour(), x.startPose(), x.startParent()).withTouchable(x.touchable()),
        object + " " + f.label() + " = " + fmt(v) + (f.unit().isEmpty() ? "" : " " + f.unit()));
  }

  /** Moves {@code object} by {@code d} mm along a cell axis (0 x, 1 y, 2 z): an axis handle's drag. */
  public Result nudge(String object, int axis, double dMm) {
    NumberField f = axis == 0 ? NumberField.X : axis == 1 ? NumberField.Y : NumberField.Z;
    return setNumber(object, f, number(object, f) + dMm);
  }

  // ---- scenarios ---------------------------------------------------------------------------

  /** Adds a scenario: a copy of the active one under {@code name}, and makes it active. */
  public Result addScenario(String name) {
    String n = name == null ? "" : name.trim();
    if (n.isEmpty() || n.length() > 60) {
      return refused("scenario name: expected 1 to 60 characters, got '" + (name == null ? "" : name) + "'");
    }
    if (state.scenarios.stream().anyMatch(s -> s.name().equals(n))) {
      return refused("scenario name: '" + n + "' is already taken");
    }
    Scenario a = active();
    Scenario copy = a.withName(n, a.description());
    List<Scenario> out = new ArrayList<>(state.scenarios);
    out.add(copy);
    return apply(new State(List.copyOf(out), out.size() - 1), "scenario " + n + " added");
  }

  /**
   * Robot {@code index} (cell order) of the active scenario becomes model {@code modelId} (a
   * library id), standing at {@code jointsRad} (pendant convention; the caller knows the new
   * model's limits). The window then opens the cell again with it.
   */
  public Result setRobotModel(int index, String modelId, List<Double> jointsRad) {
    Scenario a = active();
    if (index < 0 || index >= a.robots().size()) {
      return refused("robot: expected 1 to " + a.robots().size() + ", got " + (index + 1));
    }
    RobotSetup r = a.robots().get(index);
    if (r.modelId().equals(modelId)) {
      return new Result.Done("");
    }
    List<RobotSetup> robots = new ArrayList<>(a.robots());
    robots.set(index, r.withModel(modelId).withJoints(jointsRad));
    List<Scenario> out = new ArrayList<>(state.scenarios);
    out.set(state.active, a.withRobots(robots));
    return apply(new State(List.copyOf(out), state.active), r.name() + " is now " + modelId);
  }

  /** Makes scenario {@code index} the active one. */
  public Result activate(int index) {
    if (index < 0 || index >= state.scenarios.size()) {
      return refused("scenario: expected 1 to " + state.scenarios.size() + ", got " + (index + 1));
    }
    if (index == state.active) {
      return new Result.Done("");
    }
    return apply(new State(state.scenarios, index), "scenario " + state.scenarios.get(index).name() + " active");
  }

  /** Deletes the active scenario (never the last one). */
  public Result deleteActiveScenario() {
    if (state.scenarios.size() == 1) {
      return refused("cannot delete the only scenario");
    }
    List<Scenario> out = new ArrayList<>(state.scenarios);
    Scenario gone = out.remove(state.active);
    return apply(new State(List.copyOf(out), Math.max(0, state.active - 1)), "scenario " + gone.name() + " deleted");
  }

  // ---- undo ------------------------------------------------------------------------------

  public Result undo() {
    if (undo.isEmpty()) {
      return refused("nothing to undo");
    }
    redo.push(state);
    state = undo.pop();
    String what = undoWhat.pop();
    redoWhat.push(what);
    revision++;
    return new Result.Done("undone: " + what);
  }

  public Result redo() {
    if (redo.isEmpty()) {
      return refused("nothing to redo");
    }
    undo.push(state);
    state = redo.pop();
    String what = redoWhat.pop();
    undoWhat.push(what);
    revision++;
    return new Result.Done("redone: " + what);
  }

  // ---- internals ---------------------------------------------------------------------------

  private World append(WorldObject o) {
    List<WorldObject> out = new ArrayList<>(world().objects());
    out.add(o);
    return new World(out);
  }

  private Result replace(String object, java.util.function.UnaryOperator<WorldObject> change, String message) {
    Optional<WorldObject> found = world().find(object);
    if (found.isEmpty()) {
      return refused("no object named '" + object + "'");
    }
    List<WorldObject> out = new ArrayList<>(world().objects());
    out.replaceAll(o -> o.name().equals(object) ? change.apply(o) : o);
    World w;
    try {
      w = new World(out);
    } catch (IllegalArgumentException e) {
      return refused(e.getMessage());
    }
    return apply(withWorld(w), message);
  }

  private State withWorld(World w) {
    Scenario a = active();
    Scenario s = a.withWorld(w.reset());
    List<Scenario> out = new ArrayList<>(state.scenarios);
    out.set(state.active, s);
    return new State(List.copyOf(out), state.active);
  }

  private Result apply(State next, String message) {
    undo.push(state);
    undoWhat.push(message);
    while (undo.size() > UNDO_DEPTH) {
      undo.removeLast();
      undoWhat.removeLast();
    }
    redo.clear();
    redoWhat.clear();
    state = next;
    revision++;
    return new Result.Done(message);
  }

  private static Result refused(String message) {
    return new Result.Refused(message);
  }

  private String freeName(String stem) {
    String base = stem.matches("[A-Za-z_].*") ? stem : "o_" + stem;
    if (base.length() > 28) {
      base = base.substring(0, 28);
    }
    for (int i = 1; ; i++) {
      String n = base + i;
      if (world().find(n).isEmpty()) {
        return n;
      }
    }
  }

  static String fmt(double v) {
    if (v == Math.rint(v) && Math.abs(v) < 1e9) {
      return String.format(Locale.ROOT, "%.0f", v);
    }
    return Math.abs(v) >= 1e9 || (v != 0 && Math.abs(v) < 1e-3) ? String.format(Locale.ROOT, "%.3g", v)
        : String.format(Locale.ROOT, "%.3f", v);
  }
}
