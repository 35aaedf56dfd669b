package org.robotrun.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.render.AntiAliasing;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.render.HeadlessRenderer;
import org.robotrun.render.OrbitCamera;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.SceneSnapshot;
import org.robotrun.sim.SceneSnapshots;
import org.robotrun.world.Scenario;
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

  @Option(names = "--antialias", paramLabel = "MODE",
      description = "Edge smoothing: ${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE}, as the window uses; MSAA4 is smoother at silhouettes and costs about 2.5 times the CPU in Mesa's software renderer).")
  AntiAliasing antialias = AntiAliasing.DEFAULT;

  @Option(names = "--joints", paramLabel = "J1,...,J6",
      description = "Joint angles in degrees as the pendant shows them (J3 coupled to J2), for the first robot. Default: the scenario's initial joints, or all 0.")
  String joints;

  @Option(names = "--scenario", paramLabel = "FILE.json",
      description = "Draw this scenario's cell (robots and their end effectors, fixtures, parts; bodies in contact red) from its camera view. Default: the default robot alone.")
  Path scenario;

  @Option(names = "--show-boxes",
      description = "With --scenario: draw the collision boxes (robot links, tool, objects) as green wire frames, red where they touch.")
  boolean showBoxes;

  @Option(names = "--seed", paramLabel = "N",
      description = "With --scenario: the seed of its random part placement and vision noise (docs/vision.md). Default: the scenario's.")
  Long seed;

  @Option(names = "--vision-camera", paramLabel = "NAME",
      description = "With --scenario: draw what this vision camera sees, at its image size (--width/--height are ignored).")
  String visionCamera;

  @Option(names = "--vision-find", paramLabel = "PROCESS",
      description = "With --vision-camera: run VISION RUN_FIND of this process first, outline the found parts and print their found poses.")
  String visionFind;

  @picocli.CommandLine.Spec picocli.CommandLine.Model.CommandSpec spec;

  @Override
  public Integer call() {
    checkSize("--width", width);
    checkSize("--height", height);
    NativeLibraries.prepare();
    Path dir = out.toAbsolutePath().getParent();
    if (dir == null || !Files.isDirectory(dir)) {
      throw new UserError("--out: the directory " + dir + " does not exist");
    }
    if (Files.isDirectory(out)) {
      throw new UserError("--out: " + out + " is a directory; give a file name ending in .png");
    }
    if (showBoxes && scenario == null) {
      throw new UserError("--show-boxes: needs --scenario (for the robot alone use scenarios/empty-cell.json)");
    }
    if (seed != null && !org.robotrun.io.VisionJson.isValidSeed(seed)) {
      throw new UserError("--seed: expected " + org.robotrun.io.VisionJson.SEED_RANGE + " (as vision.seed), got " + seed);
    }
    if ((seed != null || visionCamera != null) && scenario == null) {
      throw new UserError((seed != null ? "--seed" : "--vision-camera") + ": needs --scenario");
    }
    if (visionFind != null && visionCamera == null) {
      throw new UserError("--vision-find: needs --vision-camera");
    }
    if (visionCamera != null) {
      Scenario sc = VisionRender.seeded(ScenarioFiles.load(scenario), seed, spec.commandLine().getErr());
      try {
        VisionRender.render(sc, visionCamera, visionFind, out, antialias, spec.commandLine().getOut());
      } catch (GlUnavailableException e) {
        throw new UserError("cannot render: " + e.getMessage(), Main.EXIT_FAILED);
      } catch (java.io.UncheckedIOException e) {
        throw new UserError("--out: cannot write " + out + " (" + e.getCause().getMessage() + ")");
      }
      return Main.EXIT_OK;
    }
    OrbitCamera camera = new OrbitCamera();
    SceneSnapshot scene;
    if (scenario == null) {
      RobotModel robot = RobotDefinitions.defaultRobot();
      double[] q = joints == null ? new double[RobotModel.DOF] : JointsOption.parseToKinematic(joints, robot);
      scene = SceneSnapshots.singleRobot(robot, q, 0);
    } else {
      Scenario sc = VisionRender.seeded(ScenarioFiles.load(scenario), seed, spec.commandLine().getErr());
      scene = ScenarioFiles.simulatedScene(sc, joints, showBoxes);
      sc.camera().ifPresent(v -> ScenarioFiles.applyCamera(v, camera));
    }
    try (HeadlessRenderer r = new HeadlessRenderer(width, height, antialias)) {
      r.renderPng(scene, camera, out);
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
