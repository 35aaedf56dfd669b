package org.robotrun.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Stream;
import org.robotrun.collision.BoxFit;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.JointSpec;
import org.robotrun.robot.LinkMesh;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.LinkSpec;
import org.robotrun.robot.RobotModel;

/**
 * Turns a URDF of a serial 6-axis arm into a {@link RobotModel}: the moving joints become the
 * six joints, links joined by fixed joints are merged into the frame of the moving link they
 * hang from, {@code tool0} (else {@code flange}) becomes the flange, visual geometry becomes
 * display meshes and collision geometry the link bodies (a box, cylinder or sphere as it is; a
 * mesh, or a link with no collision element, gets an oriented box fitted to its mesh).
 *
 * <p>Units are converted once, by {@link UrdfReader} (metres to mm) and {@link AssimpMeshes}
 * (COLLADA units and up axis). Anything that is not a serial 6-axis arm, and any missing file
 * or bad value, is a {@link FileFormatException} naming the file (and line) and the reason.
 * See docs/robot-import.md.
 */
public final class UrdfImporter {
  /** Joint speed given to a continuous joint whose URDF gives none (rad/s, 180°/s). */
  static final double DEFAULT_CONTINUOUS_SPEED = Math.PI;

  private UrdfImporter() {}

  /**
   * An imported robot and what the import found.
   *
   * @param model the robot, its display meshes in its links
   * @param bodies one line per collision body: where it came from and, for fitted boxes, the
   *     box's volume against the mesh's convex hull
   * @param notes what was assumed or merged, one line each
   * @param meshFiles the mesh files read (for {@link UrdfCache}'s content hash)
   */
  public record Result(RobotModel model, List<BodyReport> bodies, List<String> notes, List<Path> meshFiles) {

    public Result(RobotModel model, List<BodyReport> bodies, List<String> notes) {
      this(model, bodies, notes, List.of());
    }
  }

  /**
   * One collision body of the imported model.
   *
   * @param link the robot link it belongs to
   * @param source "box", "cylinder", "sphere (as its bounding cube)", "fitted to collision mesh FILE"
   *     or "fitted to visual meshes"
   * @param boxVolumeMm3 the body's volume (mm³)
   * @param hullVolumeMm3 the fitted mesh's convex hull volume (mm³), NaN for primitives
   */
  public record BodyReport(String link, String source, double boxVolumeMm3, double hullVolumeMm3) {
    /** Fitted box volume over hull volume, NaN for primitives. */
    public double ratio() {
      return boxVolumeMm3 / hullVolumeMm3;
    }
  }

  /**
   * Imports {@code urdf}.
   *
   * @param packages package name → folder, for {@code package://NAME/...} mesh paths; a package
   *     not given is looked for by walking up from the URDF's folder
   * @throws FileFormatException naming file, line and reason for anything refused
   */
  public static Result importRobot(Path urdf, Map<String, Path> packages) {
    String source = urdf.toString();
    UrdfReader.Robot robot = UrdfReader.read(urdf);
    Chain chain = Chain.of(source, robot);
    return new Build(source, urdf.toAbsolutePath().normalize(), robot, chain, packages).model();
  }

  /** The structure: root, the six moving joints in order, and which robot link each URDF link merges into. */
  private record Chain(String root, List<UrdfReader.Joint> moving, Map<String, Integer> linkIndex,
      Map<String, Transform> X_RL, Map<String, List<UrdfReader.Joint>> children, List<UrdfReader.Joint> tool) {

    /**
     * Sorts the moving joints below {@code link} (after the arm's sixth joint) into a gripper's
     * or tool's ({@code tool}: prismatic, mimic, after a 'tool0' or 'flange' link, on a link that
     * branches into several moving joints, or below such a joint) and the rest ({@code extra}).
     */
    static void collectAfter(String link, boolean toolSide, Map<String, List<UrdfReader.Joint>> children,
        Map<String, Integer> movingBelow, List<UrdfReader.Joint> tool, List<UrdfReader.Joint> extra) {
      boolean flangeHere = toolSide || FLANGE_NAMES.contains(link);
      List<UrdfReader.Joint> kids = children.getOrDefault(link, List.of());
      long branches = kids.stream().filter(j -> (j.actuated() ? 1 : 0) + movingBelow.get(j.child()) > 0).count();
      for (UrdfReader.Joint j : kids) {
        boolean side = flangeHere;
        if (j.actuated()) {
          boolean isTool = flangeHere || branches > 1 || j.type().equals("prismatic") || j.mimic();
          (isTool ? tool : extra).add(j);
          side = side || isTool;
        }
        collectAfter(j.child(), side, children, movingBelow, tool, extra);
      }
    }

    static Chain of(String source, UrdfReader.Robot robot) {
      if (robot.links().isEmpty()) {
        throw new FileFormatException(source, 0, "not a serial 6-axis arm: the file has no links");
      }
      Map<String, UrdfReader.Joint> parentJoint = new HashMap<>();
      Map<String, List<UrdfReader.Joint>> children = new LinkedHashMap<>();
      for (UrdfReader.Joint j : robot.joints()) {
        UrdfReader.Joint other = parentJoint.putIfAbsent(j.child(), j);
        if (other != null) {
          throw new FileFormatException(source, j.childLine(), "not a serial arm: link '" + j.child() + "' is the child of joint '"
              + other.name() + "' (line " + other.line() + ") and of joint '" + j.name() + "', which closes a loop");
        }
        children.computeIfAbsent(j.parent(), k -> new ArrayList<>()).add(j);
      }
      List<String> roots = robot.links().keySet().stream().filter(l -> !parentJoint.containsKey(l)).toList();
      if (roots.isEmpty()) {
        throw new FileFormatException(source, 0, "not a serial arm: every link is the child of a joint, so the joints form a loop");
      }
      if (roots.size() > 1) {
        throw new FileFormatException(source, robot.links().get(roots.get(1)).line(), "not one connected arm: links "
            + roots + " are each the child of no joint (one base link expected)");
      }
      String root = roots.get(0);
      // Moving joints below each link, counted from the leaves up; a link may start at most one branch that moves.
      Map<String, Integer> movingBelow = new HashMap<>();
      List<String> order = new ArrayList<>();
      List<String> stack = new ArrayList<>(List.of(root));
      while (!stack.isEmpty()) {
        String l = stack.remove(stack.size() - 1);
        order.add(l);
        for (UrdfReader.Joint j : children.getOrDefault(l, List.of())) {
          stack.add(j.child());
        }
      }
      if (order.size() != robot.links().size()) {
        List<String> lost = robot.links().keySet().stream().filter(l -> !order.contains(l)).toList();
        throw new FileFormatException(source, robot.links().get(lost.get(0)).line(), "not a serial arm: links " + lost
            + " cannot be reached from the base link '" + root + "': their joints form a loop");
      }
      for (int i = order.size() - 1; i >= 0; i--) {
        String l = order.get(i);
        int n = 0;
        for (UrdfReader.Joint j : children.getOrDefault(l, List.of())) {
          n += (j.actuated() ? 1 : 0) + movingBelow.get(j.child());
        }
        movingBelow.put(l, n);
      }
      // Walk the one moving branch from the root up to the sixth moving joint; a link before it
      // may start at most one branch that moves.
      List<UrdfReader.Joint> moving = new ArrayList<>();
      String end = root;
      boolean more = true;
      while (more && moving.size() < RobotModel.DOF) {
        more = false;
        UrdfReader.Joint first = null;
        for (UrdfReader.Joint j : children.getOrDefault(end, List.of())) {
          if ((j.actuated() ? 1 : 0) + movingBelow.get(j.child()) > 0) {
            if (first != null) {
              throw new FileFormatException(source, robot.links().get(end).line(), "not a serial arm: link '" + end
                  + "' branches into joints '" + first.name() + "' and '" + j.name()
                  + "', and both lead to moving joints (a tree); RobotRun imports one chain of 6 joints");
            }
            first = j;
          }
        }
        if (first != null) {
          if (first.actuated()) {
            moving.add(first);
          }
          end = first.child();
          more = true;
        }
      }
      for (UrdfReader.Joint j : moving) {
        if (j.type().equals("prismatic")) {
          throw new FileFormatException(source, j.line(), "joint '" + j.name() + "' is prismatic: RobotRun's arms turn on six "
              + "revolute joints; a linear axis (track, gantry) is not supported");
        }
        if (j.mimic()) {
          throw new FileFormatException(source, j.line(), "joint '" + j.name() + "' mimics another joint: RobotRun needs six independent joints");
        }
      }
      // Moving joints after the sixth: a gripper's or tool's (fixed, with a note) or a seventh axis (refused).
      List<UrdfReader.Joint> tool = new ArrayList<>();
      List<UrdfReader.Joint> extra = new ArrayList<>();
      if (moving.size() == RobotModel.DOF) {
        collectAfter(end, false, children, movingBelow, tool, extra);
      }
      if (moving.size() != RobotModel.DOF || !extra.isEmpty()) {
        List<UrdfReader.Joint> all = new ArrayList<>(moving);
        all.addAll(extra);
        all.addAll(tool);
        String names = all.stream().map(UrdfReader.Joint::name).toList().toString();
        throw new FileFormatException(source, extra.isEmpty() ? 0 : extra.get(0).line(), "not a serial 6-axis arm: "
            + all.size() + " moving joint" + (all.size() == 1 ? "" : "s") + " from '" + root + "' to '" + end + "' " + names
            + "; RobotRun needs exactly 6" + (extra.isEmpty() ? "" : " (joint '" + extra.get(0).name()
            + "' continues the arm after the sixth; a gripper's joints are imported as fixed when they are prismatic, "
            + "mimic, after a 'tool0' or 'flange' link, or on a hand that branches into fingers)"));
      }
      // Every URDF link's robot link and its frame there.
      Map<String, Integer> index = new HashMap<>();
      Map<String, Transform> X_RL = new HashMap<>();
      index.put(root, 0);
      X_RL.put(root, Transform.IDENTITY);
      for (String l : order) {
        for (UrdfReader.Joint j : children.getOrDefault(l, List.of())) {
          int k = moving.indexOf(j);
          if (k >= 0) {
            index.put(j.child(), k + 1);
            X_RL.put(j.child(), Transform.IDENTITY);
          } else {
            index.put(j.child(), index.get(l));
            X_RL.put(j.child(), X_RL.get(l).compose(j.X_PJ()).compose(restMotion(j)));
          }
        }
      }
      return new Chain(root, moving, index, X_RL, children, tool);
    }
  }

  /** Link names taken as the flange, in order of preference. */
  static final List<String> FLANGE_NAMES = List.of("tool0", "flange");

  /**
   * A gripper or tool joint after the arm held still: at 0 when 0 is inside its limits (or it
   * has none), else at the limit nearest 0; the identity for a fixed joint.
   */
  static double restValue(UrdfReader.Joint j) {
    if (!j.actuated() || j.type().equals("continuous") || j.limit().isEmpty()) {
      return 0;
    }
    UrdfReader.Limit l = j.limit().get();
    return l.lower() > 0 ? l.lower() : (l.upper() < 0 && l.upper() > l.lower() ? l.upper() : 0);
  }

  private static Transform restMotion(UrdfReader.Joint j) {
    double v = restValue(j);
    if (v == 0) {
      return Transform.IDENTITY;
    }
    Vec3 a = j.axis();
    return j.type().equals("prismatic") ? Transform.translation(a.x() * v, a.y() * v, a.z() * v)
        : Transform.rotation(a.x(), a.y(), a.z(), v);
  }

  /** Builds the model: joints with limits, flange, meshes and bodies. */
  private static final class Build {
    private final String source;
    private final Path urdf;
    private final UrdfReader.Robot robot;
    private final Chain chain;
    private final Map<String, Path> packages;
    private final List<String> notes = new ArrayList<>();
    private final List<BodyReport> bodies = new ArrayList<>();
    private final Map<String, Path> found = new HashMap<>();
    private final java.util.Set<Path> meshFiles = new java.util.LinkedHashSet<>();

    Build(String source, Path urdf, UrdfReader.Robot robot, Chain chain, Map<String, Path> packages) {
      this.source = source;
      this.urdf = urdf;
      this.robot = robot;
      this.chain = chain;
      this.packages = packages;
    }

    Result model() {
      for (UrdfReader.Joint j : chain.tool()) {
        double v = restValue(j);
        boolean linear = j.type().equals("prismatic");
        notes.add(String.format(Locale.ROOT, "joint '%s' (%s%s, line %d) after the arm's sixth joint: imported as fixed at %.1f %s"
            + " (a gripper's or tool's joint; RobotRun moves six)", j.name(), j.type(), j.mimic() ? ", mimic" : "", j.line(),
            linear ? v : Math.toDegrees(v), linear ? "mm" : "deg"));
      }
      List<JointSpec> joints = new ArrayList<>();
      for (UrdfReader.Joint j : chain.moving()) {
        joints.add(joint(j));
      }
      Transform X_6F = flange();
      List<LinkSpec> links = new ArrayList<>();
      for (int i = 0; i <= RobotModel.DOF; i++) {
        links.add(link(i));
      }
      String id = robot.name().toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9_-]+", "_").replaceAll("^_+|_+$", "");
      if (id.isEmpty()) {
        id = "imported";
      }
      RobotModel model;
      try {
        // The solver comes from the chain, as for the library (closed form where the arm is OPW).
        model = RobotModel.fromChain(id, robot.name(), joints, X_6F, worldInBase(joints).inverse(), links, false);
      } catch (IllegalArgumentException e) {
        throw new FileFormatException(source, 0, e.getMessage());
      }
      return new Result(model, bodies, notes, List.copyOf(meshFiles));
    }

    private JointSpec joint(UrdfReader.Joint j) {
      int parent = chain.linkIndex().get(j.parent());
      Transform X_PJ = chain.X_RL().get(j.parent()).compose(j.X_PJ());
      double lower, upper, speed;
      String at = "joint '" + j.name() + "'";
      if (j.type().equals("continuous")) {
        lower = -2 * Math.PI;
        upper = 2 * Math.PI;
        notes.add(at + " is continuous: limited to ±360° as a FANUC J6 is");
        speed = j.limit().map(UrdfReader.Limit::velocity).filter(v -> !Double.isNaN(v)).orElse(Double.NaN);
        if (Double.isNaN(speed)) {
          speed = DEFAULT_CONTINUOUS_SPEED;
          notes.add(at + " gives no velocity: assumed 180°/s");
        }
        if (!(speed > 0)) {
          throw new FileFormatException(source, j.limit().get().line(), at + " <limit> velocity: expected a positive speed (rad/s), got " + speed);
        }
      } else {
        UrdfReader.Limit l = j.limit().orElseThrow(() -> new FileFormatException(source, j.line(), at
            + ": a revolute joint needs <limit lower=\"..\" upper=\"..\" velocity=\"..\"/> (radians, rad/s)"));
        if (!l.hasLower() || !l.hasUpper()) {
          throw new FileFormatException(source, l.line(), at + " <limit>: expected lower and upper (radians)");
        }
        if (!(l.lower() < l.upper())) {
          throw new FileFormatException(source, l.line(), at + " <limit>: expected lower below upper, got lower " + l.lower()
              + " and upper " + l.upper() + " (radians)");
        }
        if (l.velocity() < 0) {
          throw new FileFormatException(source, l.line(), at + " <limit>: expected velocity > 0 (rad/s), got " + l.velocity());
        }
        lower = l.lower();
        upper = l.upper();
        speed = l.velocity();
        if (Double.isNaN(speed) || speed == 0) {
          // CAD exporters write velocity="0" (or nothing) for "not set".
          speed = DEFAULT_CONTINUOUS_SPEED;
          notes.add(at + (Double.isNaN(l.velocity()) ? " gives no velocity" : " gives velocity 0 (not set)") + ": assumed 180°/s");
        }
      }
      assert parent == chain.moving().indexOf(j);
      // A robot file takes limits within ±3 turns and speeds up to 3600°/s (RobotFileReader): what
      // is imported must load again from the file `robot import` writes.
      double maxLimit = Math.toRadians(RobotFileReader.MAX_JOINT_DEG);
      if (lower < -maxLimit || upper > maxLimit) {
        notes.add(at + " turns beyond ±" + (int) RobotFileReader.MAX_JOINT_DEG + "°: limited to ±"
            + (int) RobotFileReader.MAX_JOINT_DEG + "°");
        lower = Math.max(lower, -maxLimit);
        upper = Math.min(upper, maxLimit);
      }
      double maxSpeed = Math.toRadians(RobotFileReader.MAX_JOINT_SPEED_DEG_PER_SEC);
      if (speed > maxSpeed) {
        notes.add(at + " gives velocity " + String.format(java.util.Locale.ROOT, "%.0f", Math.toDegrees(speed))
            + "°/s: limited to " + (int) RobotFileReader.MAX_JOINT_SPEED_DEG_PER_SEC + "°/s");
        speed = maxSpeed;
      }
      return new JointSpec(j.name(), X_PJ, j.axis(), lower, upper, speed);
    }

    /**
     * Where WORLD sits in the base frame: as on a FANUC controller, on the J1 axis at the height
     * of J2 (when J1 turns about the base's z axis); otherwise at the base frame itself.
     */
    private Transform worldInBase(List<JointSpec> joints) {
      JointSpec j1 = joints.get(0);
      Vec3 axis = j1.X_PJ().rotate(j1.axis());
      if (Math.abs(Math.abs(axis.z()) - 1) > 1e-9) {
        notes.add("J1 does not turn about the base's z axis: WORLD is the base frame");
        return Transform.IDENTITY;
      }
      double z2 = j1.X_PJ().compose(joints.get(1).X_PJ()).z();
      notes.add(String.format(Locale.ROOT, "WORLD: on the J1 axis at J2's height, %.3f mm above the base frame (as on a FANUC arm)", z2));
      return Transform.translation(j1.X_PJ().x(), j1.X_PJ().y(), z2);
    }

    private Transform flange() {
      for (String name : FLANGE_NAMES) {
        Integer k = chain.linkIndex().get(name);
        if (k != null && k == RobotModel.DOF) {
          notes.add("flange: link '" + name + "'");
          return chain.X_RL().get(name);
        }
      }
      notes.add("no 'tool0' or 'flange' link after the last joint: the flange is link 6's own frame");
      return Transform.IDENTITY;
    }

    /** Robot link i: its merged URDF links' visuals (display meshes) and collisions (bodies). */
    private LinkSpec link(int i) {
      List<String> members = robot.links().keySet().stream().filter(l -> chain.linkIndex().get(l) == i).toList();
      String name = i == 0 ? chain.root() : chain.moving().get(i - 1).child();
      String role = i == 0 ? "base" : "body";
      // Display: triangles grouped by colour.
      Map<String, List<double[]>> byColor = new LinkedHashMap<>();
      List<double[]> allVisual = new ArrayList<>();
      for (String m : members) {
        Transform X_RL = chain.X_RL().get(m);
        for (UrdfReader.Geometry g : robot.links().get(m).visuals()) {
          double[] t = triangles(g, X_RL.compose(g.X_LG()));
          byColor.computeIfAbsent(g.colorHex().orElse(role), k -> new ArrayList<>()).add(t);
          allVisual.add(t);
        }
      }
      List<LinkMesh> meshes = new ArrayList<>();
      int k = 0;
      for (Map.Entry<String, List<double[]>> e : byColor.entrySet()) {
        meshes.add(new LinkMesh(urdf + "#" + name + "/" + k++, floats(e.getValue()), e.getKey()));
      }
      // Bodies: collision primitives as they are, meshes fitted.
      List<LinkShape> shapes = new ArrayList<>();
      for (String m : members) {
        Transform X_RL = chain.X_RL().get(m);
        for (UrdfReader.Geometry g : robot.links().get(m).collisions()) {
          Transform X_RG = X_RL.compose(g.X_LG());
          switch (g.shape()) {
            case UrdfReader.Shape.Box b -> {
              shapes.add(new LinkShape.Box(X_RG, b.sizeMm(), role));
              bodies.add(new BodyReport(name, "box", b.sizeMm().x() * b.sizeMm().y() * b.sizeMm().z(), Double.NaN));
            }
            case UrdfReader.Shape.Cylinder c -> {
              shapes.add(new LinkShape.Cylinder(X_RG, c.radiusMm(), c.lengthMm(), role));
              bodies.add(new BodyReport(name, "cylinder", Math.PI * c.radiusMm() * c.radiusMm() * c.lengthMm(), Double.NaN));
            }
            case UrdfReader.Shape.Sphere s -> {
              double d = 2 * s.radiusMm();
              shapes.add(new LinkShape.Box(X_RG, new Vec3(d, d, d), role));
              bodies.add(new BodyReport(name, "sphere (as its bounding cube)", d * d * d, Double.NaN));
            }
            case UrdfReader.Shape.Mesh mesh -> fitted(shapes, name, role, triangles(g, X_RG), "fitted to collision mesh " + mesh.filename());
          }
        }
      }
      boolean hasCollision = members.stream().anyMatch(m -> !robot.links().get(m).collisions().isEmpty());
      if (!hasCollision && !allVisual.isEmpty()) {
        fitted(shapes, name, role, concat(allVisual), "fitted to visual meshes");
      }
      if (shapes.isEmpty()) {
        notes.add("link '" + name + "' has no visual or collision geometry: it has no body");
      }
      if (members.size() > 1) {
        notes.add("link '" + name + "' includes " + members.stream().filter(m -> !m.equals(name)).toList() + " (fixed joints)");
      }
      return new LinkSpec(name, shapes, meshes);
    }

    private void fitted(List<LinkShape> shapes, String link, String role, double[] t, String what) {
      BoxFit fit = BoxFit.fit(t);
      shapes.add(new LinkShape.Box(fit.X_LB(), fit.size(), role));
      bodies.add(new BodyReport(link, what, fit.volume(), fit.hullVolume()));
    }

    /** The geometry's triangles in the robot link frame (mm), 9 doubles each. */
    private double[] triangles(UrdfReader.Geometry g, Transform X_RG) {
      double[] local = switch (g.shape()) {
        case UrdfReader.Shape.Box b -> Primitives.box(b.sizeMm());
        case UrdfReader.Shape.Cylinder c -> Primitives.cylinder(c.radiusMm(), c.lengthMm());
        case UrdfReader.Shape.Sphere s -> Primitives.sphere(s.radiusMm());
        case UrdfReader.Shape.Mesh m -> meshTriangles(m, g.line());
      };
      double[] out = new double[local.length];
      for (int i = 0; i < local.length; i += 3) {
        Vec3 p = X_RG.apply(new Vec3(local[i], local[i + 1], local[i + 2]));
        out[i] = p.x();
        out[i + 1] = p.y();
        out[i + 2] = p.z();
      }
      return out;
    }

    private double[] meshTriangles(UrdfReader.Shape.Mesh m, int line) {
      Path file = resolve(m.filename(), line);
      double[] t;
      try {
        t = AssimpMeshes.read(file);
      } catch (FileFormatException e) {
        throw new FileFormatException(source, line, "mesh '" + m.filename() + "': " + e.getMessage());
      }
      double sx = m.scale().x() * 1000, sy = m.scale().y() * 1000, sz = m.scale().z() * 1000;
      boolean mirrored = m.scale().x() * m.scale().y() * m.scale().z() < 0;
      for (int i = 0; i < t.length; i += 3) {
        t[i] *= sx;
        t[i + 1] *= sy;
        t[i + 2] *= sz;
      }
      if (mirrored) {
        // A mirroring scale turns triangles inside out; swap two corners so they face out again.
        for (int i = 0; i < t.length; i += 9) {
          for (int c = 0; c < 3; c++) {
            double tmp = t[i + 3 + c];
            t[i + 3 + c] = t[i + 6 + c];
            t[i + 6 + c] = tmp;
          }
        }
      }
      return t;
    }

    /** The file a URDF mesh path names: {@code package://NAME/rest}, {@code file://ABS} or relative to the URDF. */
    private Path resolve(String filename, int line) {
      Path file;
      if (filename.startsWith("package://")) {
        String rest = filename.substring("package://".length());
        int slash = rest.indexOf('/');
        if (slash <= 0) {
          throw new FileFormatException(source, line, "mesh '" + filename + "': expected package://NAME/path");
        }
        String pkg = rest.substring(0, slash);
        Path dir = packageDir(pkg, filename, line);
        file = dir.resolve(rest.substring(slash + 1));
      } else if (filename.startsWith("file://")) {
        file = Path.of(filename.substring("file://".length()));
      } else {
        file = urdf.getParent().resolve(filename);
      }
      file = file.normalize();
      if (!Files.isRegularFile(file)) {
        throw new FileFormatException(source, line, "mesh '" + filename + "' not found (looked for " + file + ")");
      }
      if (!AssimpMeshes.supports(file.toString())) {
        throw new FileFormatException(source, line, "mesh '" + filename + "': expected an .stl, .obj or .dae file");
      }
      meshFiles.add(file);
      return file;
    }

    private Path packageDir(String pkg, String filename, int line) {
      if (packages.containsKey(pkg)) {
        return packages.get(pkg);
      }
      if (found.containsKey(pkg)) {
        return found.get(pkg);
      }
      // Walk up from the URDF: a folder, or one of its subfolders (a workspace's src/), whose package.xml names pkg.
      for (Path dir = urdf.getParent(); dir != null; dir = dir.getParent()) {
        if (isPackage(dir, pkg)) {
          found.put(pkg, dir);
          return dir;
        }
        try (Stream<Path> subs = Files.list(dir)) {
          Optional<Path> sub = subs.filter(Files::isDirectory).sorted().filter(d -> isPackage(d, pkg)).findFirst();
          if (sub.isPresent()) {
            found.put(pkg, sub.get());
            return sub.get();
          }
        } catch (IOException | SecurityException e) {
          // An unreadable folder on the way up is not where the package is.
        }
      }
      throw new FileFormatException(source, line, "mesh '" + filename + "': package '" + pkg
          + "' not found (give --package " + pkg + "=DIR, or keep the URDF inside the package whose package.xml names it)");
    }

    private static boolean isPackage(Path dir, String pkg) {
      Path xml = dir.resolve("package.xml");
      if (!Files.isRegularFile(xml)) {
        return false;
      }
      try {
        XmlTree.Element root = XmlTree.parse(xml.toString(), BoundedFiles.read(xml, 1 << 20, "package.xml files"));
        return root.child("name").map(XmlTree.Element::text).filter(pkg::equals).isPresent();
      } catch (IOException | RuntimeException e) {
        return false;
      }
    }
  }

  private static double[] concat(List<double[]> parts) {
    int n = parts.stream().mapToInt(p -> p.length).sum();
    double[] out = new double[n];
    int k = 0;
    for (double[] p : parts) {
      System.arraycopy(p, 0, out, k, p.length);
      k += p.length;
    }
    return out;
  }

  private static float[] floats(List<double[]> parts) {
    double[] d = concat(parts);
    float[] f = new float[d.length];
    for (int i = 0; i < d.length; i++) {
      f[i] = (float) d[i];
    }
    return f;
  }

  /** Triangles of URDF's primitive shapes, centred on their frame (mm), cylinders along z. */
  static final class Primitives {
    private static final int SEGMENTS = 32;

    private Primitives() {}

    static double[] box(Vec3 size) {
      double hx = size.x() / 2, hy = size.y() / 2, hz = size.z() / 2;
      double[][] c = new double[8][];
      for (int i = 0; i < 8; i++) {
        c[i] = new double[] {(i & 1) == 0 ? -hx : hx, (i & 2) == 0 ? -hy : hy, (i & 4) == 0 ? -hz : hz};
      }
      int[][] quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
      double[] out = new double[12 * 9];
      int k = 0;
      for (int[] q : quads) {
        for (int[] t : new int[][] {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}) {
          for (int v : t) {
            System.arraycopy(c[v], 0, out, k, 3);
            k += 3;
          }
        }
      }
      return out;
    }

    static double[] cylinder(double r, double length) {
      double h = length / 2;
      double[] out = new double[SEGMENTS * 4 * 9];
      int k = 0;
      for (int i = 0; i < SEGMENTS; i++) {
        double a0 = 2 * Math.PI * i / SEGMENTS, a1 = 2 * Math.PI * (i + 1) / SEGMENTS;
        double x0 = r * Math.cos(a0), y0 = r * Math.sin(a0), x1 = r * Math.cos(a1), y1 = r * Math.sin(a1);
        double[][] tris = {{x0, y0, -h, x1, y1, -h, x1, y1, h}, {x0, y0, -h, x1, y1, h, x0, y0, h},
            {0, 0, -h, x1, y1, -h, x0, y0, -h}, {0, 0, h, x0, y0, h, x1, y1, h}};
        for (double[] t : tris) {
          System.arraycopy(t, 0, out, k, 9);
          k += 9;
        }
      }
      return out;
    }

    static double[] sphere(double r) {
      int rings = SEGMENTS / 2;
      double[] out = new double[SEGMENTS * rings * 2 * 9];
      int k = 0;
      for (int i = 0; i < rings; i++) {
        double t0 = Math.PI * i / rings, t1 = Math.PI * (i + 1) / rings;
        for (int j = 0; j < SEGMENTS; j++) {
          double p0 = 2 * Math.PI * j / SEGMENTS, p1 = 2 * Math.PI * (j + 1) / SEGMENTS;
          double[] a = point(r, t0, p0), b = point(r, t1, p0), c = point(r, t1, p1), d = point(r, t0, p1);
          for (double[] v : new double[][] {a, b, c, a, c, d}) {
            System.arraycopy(v, 0, out, k, 3);
            k += 3;
          }
        }
      }
      return out;
    }

    private static double[] point(double r, double theta, double phi) {
      return new double[] {r * Math.sin(theta) * Math.cos(phi), r * Math.sin(theta) * Math.sin(phi), r * Math.cos(theta)};
    }
  }
}
