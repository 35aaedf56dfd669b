package org.robotrun.io;

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
      return RobotFileReader.read(path, new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8), file -> {
        try (InputStream m = RobotDefinitions.class.getResourceAsStream("/robots/" + file)) {
          if (m == null) {
            throw new FileFormatException(path, 0, "mesh '" + file + "' is not in the jar");
          }
          return StlReader.parse("/robots/" + file, m.readAllBytes(), 1);
        }
      });
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
      return RobotFileReader.read(name, text, mesh -> {
        Path p = Path.of(mesh);
        if (p.isAbsolute() || mesh.contains("..")) {
          throw new FileFormatException(name, 0, "mesh '" + mesh + "': expected a path relative to the robot file's folder");
        }
        return StlReader.read(dir.resolve(p), 1);
      });
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
}
