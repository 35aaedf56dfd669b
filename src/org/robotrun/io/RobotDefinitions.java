package org.robotrun.io;

import com.fasterxml.jackson.core.JsonParseException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Locale;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.JointSpec;
import org.robotrun.robot.LinkMesh;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.LinkSpec;
import org.robotrun.robot.RobotModel;

/**
 * Reads robot definitions (JSON in {@code resources/robots/}, millimetres and degrees) into
 * immutable {@link RobotModel}s. Degrees become radians here, once.
 */
public final class RobotDefinitions {
  /** The robot a new cell gets when nothing else is said. */
  public static final String DEFAULT_ROBOT = "lrmate200id";

  private static final ObjectMapper JSON = new ObjectMapper();

  private RobotDefinitions() {}

  /**
   * The library shipped in the jar, in listing order (each has {@code resources/robots/ID.json}).
   */
  public static final List<String> LIBRARY = List.of(
      "lrmate200id", "lrmate200id4s", "er4ia", "m10ia", "m10id12", "m20ia", "r2000ic165f", "crx10ia", "crx10ial");

  /**
   * A library entry's facts for listings: what the file says besides the chain.
   *
   * @param id library id
   * @param name model name
   * @param payloadKg rated payload (kg), NaN when the file does not say
   * @param reachMm reach (mm) as the file states it, NaN when it does not
   * @param source where the numbers come from
   */
  public record Entry(String id, String name, double payloadKg, double reachMm, String source) {}

  /**
   * Loads a robot by what a scenario's {@code model} field holds: a library id (e.g.
   * "lrmate200id"), or a path to a robot file ({@code .json}, RobotRun's own format). A relative
   * path is taken against {@code baseDir} (the scenario's folder; null: the working directory).
   * This is the one place a model name becomes a model; a {@code .urdf} is imported in memory
   * (as {@code robotrun robot import} would, package folders found from the file's place).
   *
   * @throws FileFormatException naming the file (or the library) and what is wrong
   */
  public static RobotModel resolve(String model, Path baseDir) {
    if (!isPath(model)) {
      return load(model);
    }
    Path file;
    try {
      file = baseDir == null ? Path.of(model) : baseDir.resolve(model);
    } catch (InvalidPathException e) {
      throw new FileFormatException(model, 0, "not a valid path");
    }
    return loadFile(file.toAbsolutePath().normalize());
  }

  /** Whether a model name is a file path (has an extension or a separator) rather than a library id. */
  public static boolean isPath(String model) {
    String lower = model.toLowerCase(Locale.ROOT);
    return lower.endsWith(".json") || lower.endsWith(".urdf") || model.contains("/") || model.contains("\\");
  }

  /** Whether a scenario's {@code model} names a robot file (RobotRun's JSON or a URDF): {@link #isPath}. */
  public static boolean isFileReference(String model) {
    return isPath(model);
  }

  /**
   * Loads a robot by id or by absolute path (what a loaded scenario's robot holds after
   * {@link #resolve}): the function the simulation builders take.
   */
  public static RobotModel load(String id) {
    if (isPath(id)) {
      return resolve(id, null);
    }
    String path = "/robots/" + id + ".json";
    try (InputStream in = RobotDefinitions.class.getResourceAsStream(path)) {
      if (in == null || !id.matches("[a-z0-9_]+")) {
        throw new FileFormatException(path, 0, "no robot definition named '" + id + "' (library: "
            + String.join(", ", LIBRARY) + ")");
      }
      return parse(path, JSON.readTree(in), file -> {
        try (InputStream m = RobotDefinitions.class.getResourceAsStream("/robots/" + file)) {
          if (m == null) {
            throw new FileFormatException(path, 0, "mesh '" + file + "' is not in the jar");
          }
          return StlReader.parse("/robots/" + file, m.readAllBytes(), 1);
        }
      });
    } catch (JsonParseException e) {
      throw new FileFormatException(path, e.getLocation().getLineNr(), e.getOriginalMessage());
    } catch (IOException e) {
      throw new FileFormatException(path, 0, e.getMessage());
    }
  }

  /**
   * Loads a robot from a file: RobotRun's JSON (display meshes named in it are read relative to
   * its folder) or a URDF (imported in memory, as {@code robotrun robot import} would, with the
   * package folders a scenario gave for it; kept by {@link UrdfCache} while unchanged).
   *
   * @throws FileFormatException naming the file, line or field, and what was expected
   */
  public static RobotModel loadFile(Path file) {
    String name = file.toString();
    if (!Files.isRegularFile(file)) {
      throw new FileFormatException(name, 0, "robot file not found (paths are relative to the scenario file)");
    }
    if (name.toLowerCase(Locale.ROOT).endsWith(".urdf")) {
      return UrdfCache.load(file);
    }
    Path dir = file.toAbsolutePath().normalize().getParent();
    try {
      String text = BoundedFiles.readUtf8(file, MAX_FILE_BYTES, "robot files");
      return parse(name, JSON.readTree(text), mesh -> {
        Path p = Path.of(mesh);
        if (p.isAbsolute() || mesh.contains("..")) {
          throw new FileFormatException(name, 0, "mesh '" + mesh + "': expected a path relative to the robot file's folder");
        }
        return StlReader.read(dir.resolve(p), 1);
      });
    } catch (JsonParseException e) {
      throw new FileFormatException(name, e.getLocation().getLineNr(), e.getOriginalMessage());
    } catch (UnreadableFileException e) {
      throw new FileFormatException(name, 0, e.getMessage());
    } catch (IOException e) {
      throw new FileFormatException(name, 0, "cannot read: " + e.getMessage());
    }
  }

  /** Largest robot file read (the library's are under 8 KiB; meshes are separate files). */
  public static final long MAX_FILE_BYTES = 4L << 20;

  /** Reads the mesh a robot file names (relative path, mm, binary or ASCII STL). */
  interface MeshFiles {
    org.robotrun.world.TriangleMesh read(String relativePath) throws IOException;
  }

  /** The library's entries, in {@link #LIBRARY} order. */
  public static List<Entry> library() {
    List<Entry> out = new ArrayList<>();
    for (String id : LIBRARY) {
      String path = "/robots/" + id + ".json";
      try (InputStream in = RobotDefinitions.class.getResourceAsStream(path)) {
        JsonNode root = JSON.readTree(in);
        out.add(new Entry(id, root.path("name").asText(id), root.path("payloadKg").asDouble(Double.NaN),
            root.path("reachMm").asDouble(Double.NaN), root.path("source").asText("")));
      } catch (IOException | RuntimeException e) {
        throw new FileFormatException(path, 0, "cannot read the library entry: " + e.getMessage());
      }
    }
    return out;
  }

  /** The default robot. */
  public static RobotModel defaultRobot() {
    return load(DEFAULT_ROBOT);
  }

  static RobotModel parse(String source, JsonNode root, MeshFiles meshFiles) throws IOException {
    try {
      return parseChecked(source, root, meshFiles);
    } catch (IllegalArgumentException e) {
      throw new FileFormatException(source, 0, e.getMessage());
    }
  }

  private static RobotModel parseChecked(String source, JsonNode root, MeshFiles meshFiles) throws IOException {
    Reader r = new Reader(source);
    List<JointSpec> joints = new ArrayList<>();
    JsonNode js = r.array(root, "joints");
    for (int i = 0; i < js.size(); i++) {
      JsonNode j = js.get(i);
      String at = "joints[" + i + "]";
      double[] axis = r.vec(j, "axis", at);
      joints.add(new JointSpec(
          r.text(j, "name", at),
          r.pose(j, at),
          new Vec3(axis[0], axis[1], axis[2]),
          Math.toRadians(r.number(j, "lower", at)),
          Math.toRadians(r.number(j, "upper", at)),
          Math.toRadians(r.number(j, "maxSpeed", at))));
    }
    Transform X_6F = r.pose(r.object(root, "flange", ""), "flange");
    JsonNode wib = r.object(root, "worldInBase", "");
    // WORLD sits above the base plate; the base frame seen from WORLD is the inverse offset.
    Transform X_WB = Transform.translation(
        -r.number(wib, "x", "worldInBase"), -r.number(wib, "y", "worldInBase"), -r.number(wib, "z", "worldInBase"));

    List<LinkSpec> links = new ArrayList<>();
    JsonNode ls = r.array(root, "links");
    for (int i = 0; i < ls.size(); i++) {
      JsonNode l = ls.get(i);
      String at = "links[" + i + "]";
      List<LinkShape> shapes = new ArrayList<>();
      JsonNode ss = r.array(l, "shapes");
      for (int k = 0; k < ss.size(); k++) {
        JsonNode s = ss.get(k);
        String sat = at + ".shapes[" + k + "]";
        Transform pose = r.pose(s, sat);
        String color = r.text(s, "color", sat);
        String type = r.text(s, "type", sat);
        shapes.add(switch (type) {
          case "box" -> {
            double[] size = r.vec(s, "size", sat);
            yield new LinkShape.Box(pose, new Vec3(size[0], size[1], size[2]), color);
          }
          case "cylinder" -> new LinkShape.Cylinder(
              pose, r.number(s, "radius", sat), r.number(s, "length", sat), color);
          default -> throw new FileFormatException(source, 0, sat + ".type: expected box or cylinder, got '" + type + "'");
        });
      }
      List<LinkMesh> meshes = new ArrayList<>();
      if (l.has("meshes")) {
        JsonNode ms = r.array(l, "meshes");
        for (int k = 0; k < ms.size(); k++) {
          JsonNode m = ms.get(k);
          String mat = at + ".meshes[" + k + "]";
          String file = r.text(m, "file", mat);
          String color = m.has("color") ? r.text(m, "color", mat) : "body";
          if (!color.matches("body|joint|base|flange|white|#[0-9a-fA-F]{6}")) {
            throw new FileFormatException(source, 0, mat + ".color: expected body, joint, base, flange, white or #rrggbb, got '" + color + "'");
          }
          meshes.add(new LinkMesh(source + ":" + file, meshFiles.read(file).corners(), color));
        }
      }
      links.add(new LinkSpec(r.text(l, "name", at), shapes, meshes));
    }

    try {
      // The closed form's parameters come from the chain (OpwDerivation), never from the file.
      RobotModel model = RobotModel.fromChain(
          r.text(root, "id", ""), r.text(root, "name", ""), joints, X_6F, X_WB, links,
          root.path("coupledJ3").asBoolean(false));
      // the controller's $SPEEDLIM for this arm (mm/s); the default when the file does not say
      return root.has("maxLinearSpeed") ? model.withMaxLinearSpeed(r.number(root, "maxLinearSpeed", "")) : model;
    } catch (IllegalArgumentException e) {
      throw new FileFormatException(source, 0, e.getMessage());
    }
  }

  /** Small typed accessors that name the JSON path of whatever is missing or wrong. */
  private record Reader(String source) {
    JsonNode array(JsonNode n, String field) {
      JsonNode a = n.get(field);
      if (a == null || !a.isArray()) {
        throw new FileFormatException(source, 0, field + ": expected an array");
      }
      return a;
    }

    JsonNode object(JsonNode n, String field, String at) {
      JsonNode o = n.get(field);
      if (o == null || !o.isObject()) {
        throw new FileFormatException(source, 0, join(at, field) + ": expected an object");
      }
      return o;
    }

    String text(JsonNode n, String field, String at) {
      JsonNode t = n.get(field);
      if (t == null || !t.isTextual()) {
        throw new FileFormatException(source, 0, join(at, field) + ": expected a string");
      }
      return t.asText();
    }

    double number(JsonNode n, String field, String at) {
      JsonNode t = n.get(field);
      if (t == null || !t.isNumber() || !Double.isFinite(t.asDouble())) {
        throw new FileFormatException(source, 0, join(at, field) + ": expected a finite number");
      }
      return t.asDouble();
    }

    double[] numbers(JsonNode n, String field, String at, int count) {
      JsonNode a = n.get(field);
      if (a == null || !a.isArray() || a.size() != count) {
        throw new FileFormatException(source, 0, join(at, field) + ": expected " + count + " numbers");
      }
      double[] out = new double[count];
      for (int i = 0; i < count; i++) {
        if (!a.get(i).isNumber() || !Double.isFinite(a.get(i).asDouble())) {
          throw new FileFormatException(source, 0, join(at, field) + "[" + i + "]: expected a finite number, got "
              + describe(a.get(i)));
        }
        out[i] = a.get(i).asDouble();
      }
      return out;
    }

    double[] vec(JsonNode n, String field, String at) {
      return numbers(n, field, at, 3);
    }

    /** "xyz" (mm) and optional "rpy" (deg, R = Rz·Ry·Rx) as a transform. */
    Transform pose(JsonNode n, String at) {
      double[] xyz = n.has("xyz") ? vec(n, "xyz", at) : new double[3];
      double[] rpy = n.has("rpy") ? vec(n, "rpy", at) : new double[3];
      return Transform.fromRpy(xyz[0], xyz[1], xyz[2],
          Math.toRadians(rpy[0]), Math.toRadians(rpy[1]), Math.toRadians(rpy[2]));
    }

    /** What a value is, as the scenario reader's messages say it ("the number 1e3", "a string"). */
    private static String describe(JsonNode v) {
      return v.isNumber() ? "the number " + v.asText() : v.isTextual() ? "a string" : v.isArray() ? "an array"
          : v.isObject() ? "an object" : v.isBoolean() ? "a boolean" : "null";
    }

    private static String join(String at, String field) {
      return at.isEmpty() ? field : at + "." + field;
    }
  }
}
