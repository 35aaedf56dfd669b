package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.RobotFileWriter;
import org.robotrun.io.UrdfImporter;
import org.robotrun.robot.JointSpec;
import org.robotrun.robot.LinkSpec;
import org.robotrun.robot.RobotModel;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code robotrun robot import FILE.urdf --out DIR}: a URDF arm as a RobotRun robot folder. */
@Command(
    name = "import",
    mixinStandardHelpOptions = true,
    description = {
      "Import a serial 6-axis arm from a URDF as a RobotRun robot.",
      "It writes the new folder DIR: DIR/ID.json (a RobotRun robot) and DIR/meshes/*.stl (its display meshes). A scenario names it as \"model\": \"DIR/ID.json\" (or names the .urdf itself).",
      "Meshes: STL, OBJ, COLLADA (its unit and up axis honoured); package://NAME/... is found with --package NAME=DIR or by walking up to the package.xml naming it.",
      "Collision bodies: the URDF's boxes and cylinders (spheres as cubes); meshes get tight fitted boxes. xacro files are refused: expand them first (xacro robot.urdf.xacro > robot.urdf). Anything but a serial 6-axis arm is refused in one line, and nothing is written. Prints the joints, the flange, what was merged or assumed, and each fitted box's volume against its mesh's convex hull. See docs/robot-import.md.",
      ""
    })
final class RobotImportCommand implements Callable<Integer> {
  @Spec picocli.CommandLine.Model.CommandSpec spec;

  @Parameters(index = "0", paramLabel = "FILE.urdf", description = "The URDF file (not .xacro).")
  Path urdf;

  @Option(names = "--package", paramLabel = "NAME=DIR", description = "Where package NAME is (repeatable).")
  List<String> packages = List.of();

  @Option(names = "--out", required = true, paramLabel = "DIR", description = "New folder to write (must not exist, or be empty).")
  Path out;

  @Override
  public Integer call() {
    Map<String, Path> dirs = packageDirs(packages);
    if (!Files.isRegularFile(urdf) && !urdf.toString().toLowerCase(Locale.ROOT).endsWith(".xacro")) {
      throw new UserError(urdf + ": no such file", Main.EXIT_BAD_INPUT);
    }
    long t0 = System.nanoTime();
    UrdfImporter.Result r;
    Path json;
    try {
      r = UrdfImporter.importRobot(urdf, dirs);
      json = RobotFileWriter.write(r.model(), "Imported from " + urdf.getFileName() + " by robotrun robot import.", out);
    } catch (FileFormatException e) {
      throw new UserError(e.getMessage(), Main.EXIT_BAD_INPUT);
    } catch (IOException e) {
      throw new UserError(out + ": cannot write: " + e.getMessage(), Main.EXIT_FAILED);
    }
    double ms = (System.nanoTime() - t0) / 1e6;
    print(spec.commandLine().getOut(), r, json, ms);
    return Main.EXIT_OK;
  }

  /** The {@code --package NAME=DIR} options as a map (name → absolute folder). */
  static Map<String, Path> packageDirs(List<String> packages) {
    Map<String, Path> dirs = new LinkedHashMap<>();
    for (String p : packages) {
      int eq = p.indexOf('=');
      if (eq <= 0 || eq == p.length() - 1) {
        throw new UserError("--package: expected NAME=DIR, got '" + p + "'", Main.EXIT_BAD_INPUT);
      }
      Path dir = Path.of(p.substring(eq + 1));
      if (!Files.isDirectory(dir)) {
        throw new UserError("--package " + p + ": no such folder " + dir, Main.EXIT_BAD_INPUT);
      }
      dirs.put(p.substring(0, eq), dir.toAbsolutePath().normalize());
    }
    return dirs;
  }

  static void print(PrintWriter o, UrdfImporter.Result r, Path json, double ms) {
    RobotModel m = r.model();
    o.printf(Locale.ROOT, "robot '%s' (id %s): 6 joints%n", m.displayName(), m.id());
    for (JointSpec j : m.joints()) {
      o.printf(Locale.ROOT, "  %-20s %9.2f .. %8.2f deg  %8.2f deg/s%n", j.name(), Math.toDegrees(j.lowerRad()),
          Math.toDegrees(j.upperRad()), Math.toDegrees(j.maxSpeedRadPerSec()));
    }
    int tris = 0;
    for (LinkSpec l : m.links()) {
      tris += l.meshes().stream().mapToInt(x -> x.triangleCount()).sum();
    }
    o.printf(Locale.ROOT, "display meshes: %d triangles%n", tris);
    for (String n : r.notes()) {
      o.println("note: " + n);
    }
    o.println("collision bodies (fitted box volume against the mesh's convex hull):");
    o.printf(Locale.ROOT, "  %-16s %-44s %12s %12s %7s%n", "link", "body", "box cm3", "hull cm3", "box/hull");
    for (UrdfImporter.BodyReport b : r.bodies()) {
      boolean fitted = !Double.isNaN(b.hullVolumeMm3());
      o.printf(Locale.ROOT, "  %-16s %-44s %12.1f %12s %7s%n", b.link(), b.source(), b.boxVolumeMm3() / 1000,
          fitted ? String.format(Locale.ROOT, "%.1f", b.hullVolumeMm3() / 1000) : "-",
          fitted && b.hullVolumeMm3() > 0 ? String.format(Locale.ROOT, "%.2f", b.ratio()) : "-");
    }
    o.printf(Locale.ROOT, "wrote %s (%.0f ms); in a scenario: \"model\": \"%s\"%n", json, ms, json.toString().replace('\\', '/'));
    o.flush();
  }
}
