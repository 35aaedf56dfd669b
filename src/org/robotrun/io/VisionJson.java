package org.robotrun.io;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.robotrun.io.LocatedJson.JArray;
import org.robotrun.io.LocatedJson.JNumber;
import org.robotrun.io.LocatedJson.JObject;
import org.robotrun.math.PoseLimits;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Rgb;
import org.robotrun.world.Shape;
import org.robotrun.world.VisionSetup;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/**
 * The scenario's optional {@code "vision"} section (docs/scenario-format.md, "vision"): cameras,
 * models, vision processes, random placement. Read with located errors (JSON path and line) and
 * checked against the cell: robot and part names exist, every model matches a part, a fixed
 * camera sees something of the cell in its search window.
 */
public final class VisionJson extends JsonFieldReader {
  /** The section's key in the scenario file. */
  public static final String KEY = "vision";

  /** Seeds are whole numbers below this in size: exact in a double, so written and read back unchanged. */
  public static final double SEED_LIMIT = 9.0e15;

  /** What a seed may be, for messages: the range {@link #isValidSeed} takes (16 digits at most). */
  public static final String SEED_RANGE = "a whole number from -8999999999999999 to 8999999999999999";

  /** Whether {@code seed} is a seed {@code vision.seed} (and so {@code --seed}) takes: |seed| below {@link #SEED_LIMIT}. */
  public static boolean isValidSeed(double seed) {
    return seed == Math.rint(seed) && Math.abs(seed) < SEED_LIMIT;
  }

  private static final Set<String> TOP = Set.of("seed", "cameras", "models", "processes", "placements");
  private static final Set<String> CAMERA = Set.of("name", "robot", "pose", "fovDeg", "imageSize", "searchWindow",
      "noise");
  private static final Set<String> WINDOW = Set.of("left", "top", "right", "bottom");
  private static final Set<String> NOISE = Set.of("positionMm", "rotationDeg", "missProbability");
  private static final Set<String> MODEL = Set.of("name", "id", "namePrefix", "color", "shape");
  private static final Set<String> PROCESS = Set.of("name", "camera", "models", "userFrame", "reference", "type",
      "numberToFind");
  private static final Set<String> PLACEMENT = Set.of("parts", "xMm", "yMm", "rDeg", "minGapMm", "kinds");
  private static final Set<String> KIND = Set.of("shape", "size", "radius", "height", "color");
  private static final Set<String> POSE = Set.of("x", "y", "z", "w", "p", "r");
  private static final Set<String> XYZ = Set.of("x", "y", "z");
  /** Largest image side accepted (pixels). */
  static final int MAX_PIXELS = 8192;

  private VisionJson(String file) {
    super(file);
  }

  /**
   * Reads {@code top.vision}; problems go to {@code errors}. Absent: {@link VisionSetup#NONE}.
   *
   * @param robots the scenario's robot names (a robot-mounted camera names one)
   * @param objects the scenario's objects (placements and models are checked against them)
   */
  public static VisionSetup read(JObject top, String file, List<String> robots, List<WorldObject> objects,
      List<ScenarioError> errors) {
    LocatedJson v = top.members().get(KEY);
    if (v == null) {
      return VisionSetup.NONE;
    }
    VisionJson r = new VisionJson(file);
    VisionSetup out = r.section(v, robots, objects);
    errors.addAll(r.errors);
    return r.errors.isEmpty() && out != null ? out : VisionSetup.NONE;
  }

  private VisionSetup section(LocatedJson v, List<String> robots, List<WorldObject> objects) {
    JObject o = object(v, KEY, TOP);
    if (o == null) {
      return null;
    }
    long seed = 1;
    if (o.members().containsKey("seed")) {
      LocatedJson s = o.members().get("seed");
      if (s instanceof JNumber n && n.integral() && isValidSeed(n.value())) {
        seed = (long) n.value();
      } else {
        error(s.line(), KEY + ".seed", "expected " + SEED_RANGE + ", got " + s.describe());
      }
    }
    World world = worldOf(objects);
    List<VisionSetup.Camera> cameras = new ArrayList<>();
    forEach(o, "cameras", (c, at) -> camera(c, at, robots, world, cameras));
    List<VisionSetup.Model> models = new ArrayList<>();
    List<VisionSetup.Placement> placements = new ArrayList<>();
    forEach(o, "placements", (p, at) -> placement(p, at, objects, placements));
    forEach(o, "models", (m, at) -> model(m, at, objects, placements, models));
    List<VisionSetup.Process> processes = new ArrayList<>();
    forEach(o, "processes", (p, at) -> process(p, at, cameras, models, processes));
    return new VisionSetup(seed, cameras, models, processes, placements);
  }

  private static World worldOf(List<WorldObject> objects) {
    try {
      return new World(objects);
    } catch (IllegalArgumentException e) {
      return null; // the scenario reader reports bad objects itself
    }
  }

  private interface Item {
    void read(JObject o, String at);
  }

  private void forEach(JObject o, String key, Item item) {
    JArray a = array(o, key, KEY, false);
    if (a == null) {
      return;
    }
    for (int i = 0; i < a.items().size(); i++) {
      String at = KEY + "." + key + "[" + i + "]";
      Set<String> allowed = switch (key) {
        case "cameras" -> CAMERA;
        case "models" -> MODEL;
        case "processes" -> PROCESS;
        default -> PLACEMENT;
      };
      JObject x = object(a.items().get(i), at, allowed);
      if (x != null) {
        item.read(x, at);
      }
    }
  }

  // ---- cameras ----------------------------------------------------------------------------

  private void camera(JObject c, String at, List<String> robots, World world, List<VisionSetup.Camera> out) {
    int before = errors.size();
    String name = uniqueName(c, at, out.stream().map(VisionSetup.Camera::name).toList(), "camera");
    Optional<String> robot = string(c, "robot", at, false);
    if (robot.isPresent() && !robots.contains(robot.get())) {
      error(c.members().get("robot").line(), join(at, "robot"), "no robot named '" + robot.get()
          + "' (robots: " + String.join(", ", robots) + ")");
    }
    Transform pose = pose(c, "pose", at);
    double fov = number(c, "fovDeg", at, true, 1, 170, 40);
    int[] size = imageSize(c, at);
    double nMm = 0;
    double nDeg = 0;
    double miss = 0;
    JObject noise = member(c, "noise", at, NOISE, false);
    if (noise != null) {
      String np = join(at, "noise");
      nMm = number(noise, "positionMm", np, false, 0, 100, 0);
      nDeg = number(noise, "rotationDeg", np, false, 0, 45, 0);
      miss = number(noise, "missProbability", np, false, 0, 1, 0);
    }
    VisionSetup.Window window = new VisionSetup.Window(0, 0, size[0], size[1]);
    JObject w = member(c, "searchWindow", at, WINDOW, false);
    if (w != null) {
      String wp = join(at, "searchWindow");
      double left = number(w, "left", wp, true, 0, size[0], 0);
      double topPx = number(w, "top", wp, true, 0, size[1], 0);
      double right = number(w, "right", wp, true, 0, size[0], size[0]);
      double bottom = number(w, "bottom", wp, true, 0, size[1], size[1]);
      if (!(left < right && topPx < bottom)) {
        error(w.line(), wp, "expected left < right and top < bottom (pixels inside the " + size[0] + "x" + size[1]
            + " image)");
      } else {
        window = new VisionSetup.Window(left, topPx, right, bottom);
      }
    }
    if (errors.size() > before || name == null || pose == null) {
      return;
    }
    VisionSetup.Camera cam = new VisionSetup.Camera(name, robot, pose, Math.toRadians(fov), size[0], size[1], window,
        nMm, Math.toRadians(nDeg), miss);
    if (robot.isEmpty() && world != null && !seesSomething(cam, world)) {
      error(c.line(), at, "camera '" + name + "' sees no object of the cell inside its search window: it looks "
          + "along its own +z axis (w=180 looks straight down); check its pose and field of view");
    }
    out.add(cam);
  }

  /** True when a corner or the centre of some object's box projects into the search window. */
  static boolean seesSomething(VisionSetup.Camera cam, World world) {
    Transform X_KC = cam.pose().inverse();
    for (WorldObject o : world.objects()) {
      var box = o.shape().boundingBox();
      Transform X_KB = X_KC.compose(world.poseInCell(o.name())).compose(box.X_LB());
      for (int k = 0; k < 9; k++) {
        double sx = k == 8 ? 0 : (k & 1) == 0 ? -1 : 1;
        double sy = k == 8 ? 0 : (k & 2) == 0 ? -1 : 1;
        double sz = k == 8 ? 0 : (k & 4) == 0 ? -1 : 1;
        Vec3 p = X_KB.apply(new Vec3(sx * box.hxMm(), sy * box.hyMm(), sz * box.hzMm()));
        double[] uv = cam.project(p.x(), p.y(), p.z());
        if (uv != null && cam.window().contains(uv[0], uv[1])) {
          return true;
        }
      }
    }
    return false;
  }

  private int[] imageSize(JObject c, String at) {
    int[] size = integers(c, "imageSize", at, false, "[width, height] in pixels", 16, MAX_PIXELS, 2);
    return size == null ? new int[] {640, 480} : size;
  }

  // ---- models -----------------------------------------------------------------------------

  private void model(JObject m, String at, List<WorldObject> objects, List<VisionSetup.Placement> placements,
      List<VisionSetup.Model> out) {
    int before = errors.size();
    String name = uniqueName(m, at, out.stream().map(VisionSetup.Model::name).toList(), "model");
    int id = integer(m, "id", at, 1, 9999, true).map(Long::intValue).orElse(1);
    if (out.stream().anyMatch(x -> x.id() == id) && errors.size() == before) {
      error(m.members().get("id").line(), join(at, "id"), "model ID " + id + " is used by another model");
    }
    Optional<String> prefix = string(m, "namePrefix", at, false);
    Optional<Rgb> colour = string(m, "color", at, false).flatMap(s -> {
      Optional<Rgb> c = Rgb.parse(s);
      if (c.isEmpty()) {
        error(m.members().get("color").line(), join(at, "color"), "expected a colour as \"#rrggbb\", got \"" + s + "\"");
      }
      return c;
    });
    Optional<String> shape = string(m, "shape", at, false);
    if (shape.isPresent() && !Set.of("box", "cylinder", "mesh").contains(shape.get())) {
      error(m.members().get("shape").line(), join(at, "shape"), "expected \"box\", \"cylinder\" or \"mesh\", got \""
          + shape.get() + "\"");
    }
    if (errors.size() > before || name == null) {
      return;
    }
    VisionSetup.Model model = new VisionSetup.Model(name, id, prefix, colour, shape);
    // A part can also become one of a placement's kinds: the model may match it only then.
    boolean any = objects.stream().anyMatch(model::matches);
    for (VisionSetup.Placement p : placements) {
      for (String part : p.parts()) {
        WorldObject o = objects.stream().filter(x -> x.name().equals(part)).findFirst().orElse(null);
        for (VisionSetup.Kind k : p.kinds()) {
          any |= o != null && model.matches(new WorldObject(o.name(), o.kind(), k.shape(), k.colour(), o.pose(),
              o.parent(), o.startPose(), o.startParent()));
        }
      }
    }
    if (!any) {
      error(m.line(), at, "model '" + name + "' matches no part of the cell (check namePrefix, color and shape)");
      return;
    }
    out.add(model);
  }

  // ---- processes --------------------------------------------------------------------------

  private void process(JObject p, String at, List<VisionSetup.Camera> cameras, List<VisionSetup.Model> models,
      List<VisionSetup.Process> out) {
    int before = errors.size();
    String name = uniqueName(p, at, List.of(), "vision process");
    if (name != null && out.stream().anyMatch(x -> x.name().equalsIgnoreCase(name))) {
      error(p.members().get("name").line(), join(at, "name"), "another vision process is named '" + name
          + "' (names are not case-sensitive)");
    }
    if (name != null && !name.matches("[A-Za-z][A-Za-z0-9_]{0,33}")) {
      error(p.members().get("name").line(), join(at, "name"), "expected a vision process name of letters, digits "
          + "and _ (at most 34, starting with a letter), got \"" + name + "\"");
    }
    Optional<String> camera = string(p, "camera", at, true);
    if (camera.isPresent() && cameras.stream().noneMatch(c -> c.name().equals(camera.get()))) {
      error(p.members().get("camera").line(), join(at, "camera"), "no camera named '" + camera.get() + "'");
    }
    List<String> modelNames = new ArrayList<>();
    JArray ms = array(p, "models", at, true);
    if (ms != null) {
      if (ms.items().isEmpty()) {
        error(ms.line(), join(at, "models"), "expected at least one model name");
      }
      for (int i = 0; i < ms.items().size(); i++) {
        LocatedJson v = ms.items().get(i);
        String mp = join(at, "models[" + i + "]");
        if (!(v instanceof LocatedJson.JString s)) {
          error(v.line(), mp, "expected a model name, got " + v.describe());
        } else if (models.stream().noneMatch(m -> m.name().equals(s.value()))) {
          error(v.line(), mp, "no model named '" + s.value() + "'");
        } else {
          modelNames.add(s.value());
        }
      }
    }
    int uf = integer(p, "userFrame", at, 0, 10, 0);
    Transform reference = pose(p, "reference", at);
    VisionSetup.ProcessType type = VisionSetup.ProcessType.TWO_D;
    Optional<String> t = string(p, "type", at, false);
    if (t.isPresent()) {
      switch (t.get()) {
        case "2D" -> type = VisionSetup.ProcessType.TWO_D;
        case "3D" -> type = VisionSetup.ProcessType.THREE_D;
        default -> error(p.members().get("type").line(), join(at, "type"), "expected \"2D\" or \"3D\", got \""
            + t.get() + "\"");
      }
    }
    int n = integer(p, "numberToFind", at, 1, 100, 1);
    if (errors.size() > before || name == null || reference == null || camera.isEmpty()) {
      return;
    }
    out.add(new VisionSetup.Process(name, camera.get(), modelNames, uf, reference, type, n));
  }

  // ---- placements -------------------------------------------------------------------------

  private void placement(JObject p, String at, List<WorldObject> objects, List<VisionSetup.Placement> out) {
    int before = errors.size();
    List<String> parts = new ArrayList<>();
    Set<String> taken = new HashSet<>();
    out.forEach(x -> taken.addAll(x.parts()));
    JArray a = array(p, "parts", at, true);
    if (a != null) {
      for (int i = 0; i < a.items().size(); i++) {
        LocatedJson v = a.items().get(i);
        String pp = join(at, "parts[" + i + "]");
        if (!(v instanceof LocatedJson.JString s)) {
          error(v.line(), pp, "expected a part name, got " + v.describe());
          continue;
        }
        Optional<WorldObject> o = objects.stream().filter(x -> x.name().equals(s.value())).findFirst();
        if (o.isEmpty()) {
          error(v.line(), pp, "no object named '" + s.value() + "'");
        } else if (o.get().kind() != ObjectKind.PART) {
          error(v.line(), pp, "'" + s.value() + "' is a fixture: only parts are placed at random");
        } else if (!taken.add(s.value())) {
          error(v.line(), pp, "'" + s.value() + "' is placed twice");
        } else {
          parts.add(s.value());
        }
      }
    }
    double[] x = range(p, "xMm", at, PoseLimits.MAX_COORDINATE_MM);
    double[] y = range(p, "yMm", at, PoseLimits.MAX_COORDINATE_MM);
    double[] r = p.members().containsKey("rDeg") ? range(p, "rDeg", at, 360) : new double[] {0, 0};
    double gap = number(p, "minGapMm", at, false, 0, PoseLimits.MAX_COORDINATE_MM, 0);
    List<VisionSetup.Kind> kinds = new ArrayList<>();
    JArray ks = array(p, "kinds", at, false);
    if (ks != null) {
      for (int i = 0; i < ks.items().size(); i++) {
        String kp = join(at, "kinds[" + i + "]");
        JObject k = object(ks.items().get(i), kp, KIND);
        if (k != null) {
          VisionSetup.Kind kind = kind(k, kp);
          if (kind != null) {
            kinds.add(kind);
          }
        }
      }
    }
    if (errors.size() > before || x == null || y == null || r == null) {
      return;
    }
    out.add(new VisionSetup.Placement(parts, x[0], x[1], y[0], y[1], Math.toRadians(r[0]), Math.toRadians(r[1]), gap,
        kinds));
  }

  private VisionSetup.Kind kind(JObject k, String at) {
    Optional<String> shape = string(k, "shape", at, true);
    Rgb colour = string(k, "color", at, true).flatMap(s -> {
      Optional<Rgb> c = Rgb.parse(s);
      if (c.isEmpty()) {
        error(k.members().get("color").line(), join(at, "color"), "expected a colour as \"#rrggbb\", got \"" + s + "\"");
      }
      return c;
    }).orElse(null);
    if (shape.isEmpty()) {
      return null;
    }
    Shape s;
    switch (shape.get()) {
      case "box" -> {
        JObject size = member(k, "size", at, XYZ, true);
        if (size == null) {
          return null;
        }
        String sp = join(at, "size");
        double lx = number(size, "x", sp, true, 0.1, PoseLimits.MAX_COORDINATE_MM, 1);
        double ly = number(size, "y", sp, true, 0.1, PoseLimits.MAX_COORDINATE_MM, 1);
        double lz = number(size, "z", sp, true, 0.1, PoseLimits.MAX_COORDINATE_MM, 1);
        s = new Shape.Box(lx, ly, lz);
      }
      case "cylinder" -> s = new Shape.Cylinder(number(k, "radius", at, true, 0.1, PoseLimits.MAX_COORDINATE_MM, 1),
          number(k, "height", at, true, 0.1, PoseLimits.MAX_COORDINATE_MM, 1));
      default -> {
        error(k.members().get("shape").line(), join(at, "shape"), "expected \"box\" or \"cylinder\", got \""
            + shape.get() + "\"");
        return null;
      }
    }
    return colour == null ? null : new VisionSetup.Kind(s, colour);
  }

  // ---- shared fields ----------------------------------------------------------------------

  private String uniqueName(JObject o, String at, List<String> taken, String what) {
    Optional<String> name = string(o, "name", at, true);
    if (name.isEmpty()) {
      return null;
    }
    if (name.get().isBlank()) {
      error(o.members().get("name").line(), join(at, "name"), "expected a " + what + " name, got an empty string");
      return null;
    }
    if (taken.contains(name.get())) {
      error(o.members().get("name").line(), join(at, "name"), "another " + what + " is named '" + name.get() + "'");
      return null;
    }
    return name.get();
  }

  /** {@code [min, max]} with |values| ≤ limit; null with an error when bad. */
  private double[] range(JObject o, String key, String at, double limit) {
    double[] out = numbers(o, key, at, true, "[min, max]", -limit, limit, 2);
    if (out != null && out[0] > out[1]) {
      error(o.members().get(key).line(), join(at, key), "expected [min, max] with min <= max, got [" + plain(out[0])
          + ", " + plain(out[1]) + "]");
      return null;
    }
    return out;
  }

  /** A pose {x, y, z (mm), w, p, r (deg, default 0)}; null with errors when bad. */
  private Transform pose(JObject o, String key, String at) {
    JObject p = member(o, key, at, POSE, true);
    if (p == null) {
      return null;
    }
    String path = join(at, key);
    int before = errors.size();
    double[] v = new double[6];
    String[] names = {"x", "y", "z", "w", "p", "r"};
    for (int k = 0; k < 6; k++) {
      v[k] = k < 3
          ? number(p, names[k], path, true, -PoseLimits.MAX_COORDINATE_MM, PoseLimits.MAX_COORDINATE_MM, 0)
          : number(p, names[k], path, false, -PoseLimits.MAX_ANGLE_DEG, PoseLimits.MAX_ANGLE_DEG, 0);
    }
    return errors.size() > before ? null : Xyzwpr.ofDegrees(v[0], v[1], v[2], v[3], v[4], v[5]).toTransform();
  }

  // ---- writing ----------------------------------------------------------------------------

  /** Writes the section (nothing for {@link VisionSetup#NONE}); {@code number} writes tidy numbers. */
  public static void write(JsonGenerator g, VisionSetup v, NumberWriter number) throws IOException {
    if (v.isEmpty()) {
      return;
    }
    g.writeObjectFieldStart(KEY);
    g.writeNumberField("seed", v.seed());
    g.writeArrayFieldStart("cameras");
    for (VisionSetup.Camera c : v.cameras()) {
      g.writeStartObject();
      g.writeStringField("name", c.name());
      if (c.robot().isPresent()) {
        g.writeStringField("robot", c.robot().get());
      }
      pose(g, "pose", c.pose(), number);
      number.write(g, "fovDeg", Math.toDegrees(c.fovRad()));
      g.writeArrayFieldStart("imageSize");
      g.writeNumber(c.widthPx());
      g.writeNumber(c.heightPx());
      g.writeEndArray();
      g.writeObjectFieldStart("searchWindow");
      number.write(g, "left", c.window().left());
      number.write(g, "top", c.window().top());
      number.write(g, "right", c.window().right());
      number.write(g, "bottom", c.window().bottom());
      g.writeEndObject();
      g.writeObjectFieldStart("noise");
      number.write(g, "positionMm", c.noiseMm());
      number.write(g, "rotationDeg", Math.toDegrees(c.noiseRad()));
      number.write(g, "missProbability", c.missProbability());
      g.writeEndObject();
      g.writeEndObject();
    }
    g.writeEndArray();
    g.writeArrayFieldStart("models");
    for (VisionSetup.Model m : v.models()) {
      g.writeStartObject();
      g.writeStringField("name", m.name());
      g.writeNumberField("id", m.id());
      if (m.namePrefix().isPresent()) {
        g.writeStringField("namePrefix", m.namePrefix().get());
      }
      if (m.colour().isPresent()) {
        g.writeStringField("color", m.colour().get().hex());
      }
      if (m.shape().isPresent()) {
        g.writeStringField("shape", m.shape().get());
      }
      g.writeEndObject();
    }
    g.writeEndArray();
    g.writeArrayFieldStart("processes");
    for (VisionSetup.Process p : v.processes()) {
      g.writeStartObject();
      g.writeStringField("name", p.name());
      g.writeStringField("camera", p.camera());
      g.writeArrayFieldStart("models");
      for (String m : p.models()) {
        g.writeString(m);
      }
      g.writeEndArray();
      g.writeNumberField("userFrame", p.userFrame());
      pose(g, "reference", p.reference(), number);
      g.writeStringField("type", p.type().text());
      g.writeNumberField("numberToFind", p.maxFound());
      g.writeEndObject();
    }
    g.writeEndArray();
    g.writeArrayFieldStart("placements");
    for (VisionSetup.Placement p : v.placements()) {
      g.writeStartObject();
      g.writeArrayFieldStart("parts");
      for (String s : p.parts()) {
        g.writeString(s);
      }
      g.writeEndArray();
      pair(g, "xMm", p.xMinMm(), p.xMaxMm(), number);
      pair(g, "yMm", p.yMinMm(), p.yMaxMm(), number);
      pair(g, "rDeg", Math.toDegrees(p.rMinRad()), Math.toDegrees(p.rMaxRad()), number);
      number.write(g, "minGapMm", p.minGapMm());
      if (!p.kinds().isEmpty()) {
        g.writeArrayFieldStart("kinds");
        for (VisionSetup.Kind k : p.kinds()) {
          g.writeStartObject();
          switch (k.shape()) {
            case Shape.Box b -> {
              g.writeStringField("shape", "box");
              g.writeObjectFieldStart("size");
              number.write(g, "x", b.lengthMm());
              number.write(g, "y", b.widthMm());
              number.write(g, "z", b.heightMm());
              g.writeEndObject();
            }
            case Shape.Cylinder c -> {
              g.writeStringField("shape", "cylinder");
              number.write(g, "radius", c.radiusMm());
              number.write(g, "height", c.heightMm());
            }
            case Shape.Mesh m -> throw new IllegalStateException("a placement kind is a box or a cylinder");
          }
          g.writeStringField("color", k.colour().hex());
          g.writeEndObject();
        }
        g.writeEndArray();
      }
      g.writeEndObject();
    }
    g.writeEndArray();
    g.writeEndObject();
  }

  /** How the scenario writer writes a number field (tidy digits). */
  public interface NumberWriter {
    void write(JsonGenerator g, String field, double v) throws IOException;
  }

  private static void pair(JsonGenerator g, String field, double a, double b, NumberWriter number) throws IOException {
    g.writeArrayFieldStart(field);
    g.writeRawValue(tidy(a));
    g.writeRawValue(tidy(b));
    g.writeEndArray();
  }

  private static String tidy(double v) {
    return org.robotrun.math.DecimalText.plain(Math.rint(v * 1e9) / 1e9);
  }

  private static void pose(JsonGenerator g, String field, Transform t, NumberWriter number) throws IOException {
    Xyzwpr p = Xyzwpr.fromTransform(t);
    g.writeObjectFieldStart(field);
    number.write(g, "x", p.x());
    number.write(g, "y", p.y());
    number.write(g, "z", p.z());
    number.write(g, "w", p.wDeg());
    number.write(g, "p", p.pDeg());
    number.write(g, "r", p.rDeg());
    g.writeEndObject();
  }
}
