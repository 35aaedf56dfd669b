package org.robotrun.io;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import org.robotrun.io.LocatedJson.JArray;
import org.robotrun.io.LocatedJson.JObject;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.JointSpec;
import org.robotrun.robot.LinkMesh;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.LinkSpec;
import org.robotrun.robot.RobotModel;

/**
 * Reads one robot file (RobotRun's JSON: millimetres and degrees, docs/robots.md) into a
 * {@link RobotModel}, checking every field: each problem is reported with its line, JSON path, the
 * range or kind expected and what was found, all of them at once (not only the first), and a field
 * the format does not have is an error rather than silently ignored.
 */
final class RobotFileReader extends JsonFieldReader {
  /** Largest distance a robot file may give, in mm: 100 m (the largest arms reach under 5 m). */
  static final double MAX_MM = 100_000;
  /** Joint limits within ±3 turns (FANUC wrist axes go to ±450° or ±720°). */
  static final double MAX_JOINT_DEG = 1080;
  /** Joint speeds up to 3600 °/s (the fastest wrist axes are under 1500 °/s). */
  static final double MAX_JOINT_SPEED_DEG_PER_SEC = 3600;

  private static final Set<String> TOP = Set.of("format", "id", "name", "source", "units", "payloadKg", "reachMm",
      "maxLinearSpeed", "coupledJ3", "worldInBase", "joints", "flange", "links");
  private static final Set<String> UNITS = Set.of("length", "angle");
  private static final Set<String> XYZ = Set.of("x", "y", "z");
  private static final Set<String> POSE = Set.of("xyz", "rpy");
  private static final Set<String> JOINT = Set.of("name", "xyz", "rpy", "axis", "lower", "upper", "maxSpeed");
  private static final Set<String> LINK = Set.of("name", "shapes", "meshes");
  private static final Set<String> BOX = Set.of("type", "xyz", "rpy", "size", "color");
  private static final Set<String> CYLINDER = Set.of("type", "xyz", "rpy", "radius", "length", "color");
  private static final Set<String> MESH = Set.of("file", "color");
  /** The colour a shape or mesh may name: a role of the arm's paint, or #rrggbb. */
  static final Pattern COLOR = Pattern.compile("body|joint|base|flange|white|#[0-9a-fA-F]{6}");
  private static final String COLORS = "body, joint, base, flange, white or #rrggbb";

  private final RobotDefinitions.MeshFiles meshFiles;

  private RobotFileReader(String file, RobotDefinitions.MeshFiles meshFiles) {
    super(file);
    this.meshFiles = meshFiles;
  }

  /**
   * The robot {@code text} describes.
   *
   * @throws FileFormatException naming the file, and for each problem its line, field and what was expected
   */
  static RobotModel read(String file, String text, RobotDefinitions.MeshFiles meshFiles) {
    RobotFileReader r = new RobotFileReader(file, meshFiles);
    RobotModel model = r.robot(text);
    if (!r.errors.isEmpty() || model == null) {
      throw failure(file, r.errors);
    }
    return model;
  }

  /** One exception for all the problems: the first as its line, every one on a line of its own in the message. */
  private static FileFormatException failure(String file, List<ScenarioError> errors) {
    if (errors.isEmpty()) {
      return new FileFormatException(file, 0, "not a robot file");
    }
    ScenarioError first = errors.get(0);
    if (errors.size() == 1) {
      return new FileFormatException(file, first.line(), reason(first));
    }
    StringBuilder more = new StringBuilder(reason(first));
    for (ScenarioError e : errors.subList(1, errors.size())) {
      more.append('\n').append(e.line() > 0 ? file + ":" + e.line() + ": " : file + ": ").append(reason(e));
    }
    return new FileFormatException(file, first.line(), more.toString());
  }

  private static String reason(ScenarioError e) {
    return e.path().isEmpty() ? e.message() : e.path() + ": " + e.message();
  }

  private RobotModel robot(String text) {
    JObject top = topObject(text, TOP);
    if (top == null) {
      return null;
    }
    if (top.members().containsKey("format")) {
      format(top, 1);
    }
    String id = label(top, "id", "");
    String name = label(top, "name", "");
    string(top, "source", "", false);
    JObject units = member(top, "units", "", UNITS, false);
    if (units != null) {
      unit(units, "length", "mm", "millimetres");
      unit(units, "angle", "deg", "degrees");
    }
    positive(top, "payloadKg", "", false, 100_000);
    positive(top, "reachMm", "", false, MAX_MM);
    double maxLinear = number(top, "maxLinearSpeed", "", false, 1, RobotModel.MAX_LINEAR_SPEED_LIMIT_MM_PER_SEC,
        RobotModel.DEFAULT_MAX_LINEAR_SPEED_MM_PER_SEC);
    boolean coupledJ3 = bool(top, "coupledJ3", "").orElse(false);

    JObject wib = member(top, "worldInBase", "", XYZ, true);
    Transform X_WB = null;
    if (wib != null) {
      Double x = number(wib, "x", "worldInBase", true, -MAX_MM, MAX_MM).orElse(null);
      Double y = number(wib, "y", "worldInBase", true, -MAX_MM, MAX_MM).orElse(null);
      Double z = number(wib, "z", "worldInBase", true, -MAX_MM, MAX_MM).orElse(null);
      if (x != null && y != null && z != null) {
        // WORLD sits above the base plate; the base frame seen from WORLD is the inverse offset.
        X_WB = Transform.translation(-x, -y, -z);
      }
    }

    List<JointSpec> joints = new ArrayList<>();
    JArray js = array(top, "joints", "", true);
    if (js != null) {
      if (js.items().size() != RobotModel.DOF) {
        error(js.line(), "joints", "expected 6 joints (J1 to J6), got " + js.items().size());
      }
      for (int i = 0; i < js.items().size(); i++) {
        JointSpec j = joint(js.items().get(i), "joints[" + i + "]");
        if (j != null) {
          joints.add(j);
        }
      }
    }

    JObject flange = member(top, "flange", "", POSE, true);
    Transform X_6F = flange == null ? null : pose(flange, "flange");

    List<LinkSpec> links = new ArrayList<>();
    JArray ls = array(top, "links", "", true);
    if (ls != null) {
      if (ls.items().size() != RobotModel.DOF + 1) {
        error(ls.line(), "links", "expected 7 links (the base and one for each joint), got " + ls.items().size());
      }
      for (int i = 0; i < ls.items().size(); i++) {
        LinkSpec l = link(ls.items().get(i), "links[" + i + "]");
        if (l != null) {
          links.add(l);
        }
      }
    }

    if (!errors.isEmpty() || X_WB == null || X_6F == null || id == null || name == null) {
      return null;
    }
    try {
      // The closed form's parameters come from the chain (OpwDerivation), never from the file.
      // The controller's $SPEEDLIM for this arm (mm/s): the default when the file does not say.
      return RobotModel.fromChain(id, name, joints, X_6F, X_WB, links, coupledJ3).withMaxLinearSpeed(maxLinear);
    } catch (IllegalArgumentException e) {
      error(top.line(), "", e.getMessage());
      return null;
    }
  }

  /** A name or id: a string of 1..100 characters without control characters. */
  private String label(JObject o, String key, String at) {
    String s = string(o, key, at, true).orElse(null);
    if (s != null && (s.isBlank() || s.length() > 100 || s.chars().anyMatch(Character::isISOControl))) {
      error(o.members().get(key).line(), join(at, key), "expected a name of 1..100 characters (no control characters), got \""
          + TerminalText.safe(s.length() > 100 ? s.substring(0, 100) + "..." : s) + "\"");
      return null;
    }
    return s;
  }

  private void unit(JObject units, String key, String expected, String what) {
    string(units, key, "units", true).ifPresent(u -> {
      if (!u.equals(expected)) {
        error(units.members().get(key).line(), "units." + key, "expected \"" + expected + "\" (a robot file is in "
            + what + "; robotrun robot import converts a URDF's), got \"" + TerminalText.safe(u) + "\"");
      }
    });
  }

  private JointSpec joint(LocatedJson v, String at) {
    JObject j = object(v, at, JOINT);
    if (j == null) {
      return null;
    }
    int before = errors.size();
    String name = label(j, "name", at);
    Transform X_PJ = pose(j, at);
    double[] axis = numbers(j, "axis", at, true, "[x, y, z] (the joint's axis)", -1, 1, 3);
    if (axis != null && axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2] < 1e-12) {
      error(j.members().get("axis").line(), join(at, "axis"), "expected a direction, got [0, 0, 0]");
    }
    double lower = number(j, "lower", at, true, -MAX_JOINT_DEG, MAX_JOINT_DEG, 0);
    double upper = number(j, "upper", at, true, -MAX_JOINT_DEG, MAX_JOINT_DEG, 0);
    if (errors.size() == before && !(lower < upper)) {
      error(j.members().get("upper").line(), join(at, "upper"), "expected more than lower (" + plain(lower)
          + "), got " + plain(upper));
    }
    double speed = positive(j, "maxSpeed", at, true, MAX_JOINT_SPEED_DEG_PER_SEC).orElse(1.0);
    if (errors.size() != before) {
      return null;
    }
    return new JointSpec(name, X_PJ, new Vec3(axis[0], axis[1], axis[2]), Math.toRadians(lower),
        Math.toRadians(upper), Math.toRadians(speed));
  }

  private LinkSpec link(LocatedJson v, String at) {
    JObject l = object(v, at, LINK);
    if (l == null) {
      return null;
    }
    int before = errors.size();
    String name = label(l, "name", at);
    List<LinkShape> shapes = new ArrayList<>();
    JArray ss = array(l, "shapes", at, true);
    if (ss != null) {
      for (int k = 0; k < ss.items().size(); k++) {
        LinkShape s = shape(ss.items().get(k), at + ".shapes[" + k + "]");
        if (s != null) {
          shapes.add(s);
        }
      }
    }
    List<LinkMesh> meshes = new ArrayList<>();
    JArray ms = array(l, "meshes", at, false);
    if (ms != null) {
      for (int k = 0; k < ms.items().size(); k++) {
        String mat = at + ".meshes[" + k + "]";
        JObject m = object(ms.items().get(k), mat, MESH);
        if (m == null) {
          continue;
        }
        String meshFile = string(m, "file", mat, true).orElse(null);
        String color = color(m, mat, "body");
        if (meshFile != null && color != null) {
          try {
            meshes.add(new LinkMesh(file + ":" + meshFile, meshFiles.read(meshFile).corners(), color));
          } catch (FileFormatException e) {
            // this file's own complaint (a path that leaves its folder) without its name again; a mesh's with the mesh's
            error(m.members().get("file").line(), join(mat, "file"), e.file().equals(file) ? e.reason() : e.getMessage());
          } catch (IOException e) {
            error(m.members().get("file").line(), join(mat, "file"), "cannot read mesh '" + TerminalText.safe(meshFile)
                + "': " + e.getMessage());
          }
        }
      }
    }
    return errors.size() == before ? new LinkSpec(name, shapes, meshes) : null;
  }

  private LinkShape shape(LocatedJson v, String at) {
    JObject probe = object(v, at, null);
    if (probe == null) {
      return null;
    }
    String type = string(probe, "type", at, true).orElse(null);
    if (type == null) {
      return null;
    }
    if (!type.equals("box") && !type.equals("cylinder")) {
      error(probe.members().get("type").line(), join(at, "type"), "expected \"box\" or \"cylinder\", got \""
          + TerminalText.safe(type) + "\"");
      return null;
    }
    boolean box = type.equals("box");
    JObject s = object(v, at, box ? BOX : CYLINDER);
    int before = errors.size();
    Transform pose = pose(s, at);
    String color = color(s, at, null);
    if (box) {
      double[] size = numbers(s, "size", at, true, "[x, y, z] (mm, each more than 0)", 0, MAX_MM, 3);
      if (size != null) {
        for (int k = 0; k < 3; k++) {
          if (!(size[k] > 0)) {
            error(s.members().get("size").line(), join(at, "size") + "[" + k + "]", "expected a number 0.."
                + plain(MAX_MM) + " (more than 0), got the number " + plain(size[k]));
          }
        }
      }
      return errors.size() == before ? new LinkShape.Box(pose, new Vec3(size[0], size[1], size[2]), color) : null;
    }
    double radius = positive(s, "radius", at, true, MAX_MM).orElse(0.0);
    double length = positive(s, "length", at, true, MAX_MM).orElse(0.0);
    return errors.size() == before ? new LinkShape.Cylinder(pose, radius, length, color) : null;
  }

  /** A colour field: required when {@code fallback} is null. */
  private String color(JObject o, String at, String fallback) {
    String c = string(o, "color", at, fallback == null).orElse(null);
    if (c == null) {
      return o.members().containsKey("color") ? null : fallback;
    }
    if (!COLOR.matcher(c).matches()) {
      error(o.members().get("color").line(), join(at, "color"), "expected " + COLORS + ", got \""
          + TerminalText.safe(c) + "\"");
      return null;
    }
    return c;
  }

  /** "xyz" (mm) and optional "rpy" (deg, R = Rz·Ry·Rx) as a transform; identity parts when absent. */
  private Transform pose(JObject o, String at) {
    double[] xyz = numbers(o, "xyz", at, false, "[x, y, z] (mm)", -MAX_MM, MAX_MM, 3);
    double[] rpy = numbers(o, "rpy", at, false, "[roll, pitch, yaw] (degrees)", -360, 360, 3);
    double[] p = xyz == null ? new double[3] : xyz;
    double[] r = rpy == null ? new double[3] : rpy;
    return Transform.fromRpy(p[0], p[1], p[2], Math.toRadians(r[0]), Math.toRadians(r[1]), Math.toRadians(r[2]));
  }
}
