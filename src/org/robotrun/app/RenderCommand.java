package org.robotrun.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.render.HeadlessRenderer;
import org.robotrun.render.OrbitCamera;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.SceneSnapshots;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun render}: draws the cell to a PNG with no display. */
@Command(
    name = "render",
    mixinStandardHelpOptions = true,
    description = {
      "Render the robot cell to a PNG file without a display.",
      "Uses GLFW's null platform with an OSMesa context: on Linux it needs Mesa's libOSMesa (Debian: libosmesa6).",
      "Exit codes: 0 written, 1 no OpenGL available, 2 bad option value."
    })
public final class RenderCommand implements Callable<Integer> {
  @Option(names = "--out", required = true, paramLabel = "FILE.png", description = "PNG file to write.")
  Path out;

  @Option(names = "--width", defaultValue = "1280", description = "Image width in pixels (default: ${DEFAULT-VALUE}).")
  int width;

  @Option(names = "--height", defaultValue = "800", description = "Image height in pixels (default: ${DEFAULT-VALUE}).")
  int height;

  @Option(names = "--joints", paramLabel = "J1,...,J6",
      description = "Joint angles in degrees as the pendant shows them (J3 coupled to J2). Default: all 0.")
  String joints;

  @Override
  public Integer call() {
    checkSize("--width", width);
    checkSize("--height", height);
    Path dir = out.toAbsolutePath().getParent();
    if (dir == null || !Files.isDirectory(dir)) {
      throw new UserError("--out: the directory " + dir + " does not exist");
    }
    if (Files.isDirectory(out)) {
      throw new UserError("--out: " + out + " is a directory; give a file name ending in .png");
    }
    RobotModel robot = RobotDefinitions.defaultRobot();
    double[] q = joints == null ? new double[RobotModel.DOF] : JointsOption.parseToKinematic(joints, robot);
    try (HeadlessRenderer r = new HeadlessRenderer(width, height)) {
      r.renderPng(SceneSnapshots.singleRobot(robot, q, 0), new OrbitCamera(), out);
    } catch (GlUnavailableException e) {
      throw new UserError("cannot render: " + e.getMessage(), Main.EXIT_FAILED);
    } catch (java.io.UncheckedIOException e) {
      throw new UserError("--out: cannot write " + out + " (" + e.getCause().getMessage() + ")");
    }
    return Main.EXIT_OK;
  }

  static void checkSize(String option, int v) {
    if (v < 16 || v > 8192) {
      throw new UserError(option + ": expected 16 to 8192 pixels, got " + v);
    }
  }
}
