package org.robotrun.app;

import java.io.PrintWriter;
import java.util.Arrays;
import java.util.concurrent.Callable;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.render.AntiAliasing;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.render.HeadlessRenderer;
import org.robotrun.render.OrbitCamera;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.SceneSnapshot;
import org.robotrun.sim.SceneSnapshots;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Option;

/** {@code robotrun bench render}: frames per second of the default scene, headless. */
@Command(
    name = "render",
    mixinStandardHelpOptions = true,
    description = {
      "Render the default scene headless (OSMesa) for a while and print frames per second; with --scenario and "
          + "--vision-camera, a vision camera's view instead.",
      "Each frame is drawn, edge-smoothed as robotrun render does it and finished (glFinish); the arm moves every frame, so the scene is rebuilt from a fresh snapshot as in the simulator.",
      "Output: fps=X frames=N seconds=S width=W height=H antialias=MODE median_frame_ms=T cpu_ms_per_frame=C",
      "cpu_ms_per_frame counts every thread of the process (Mesa renders on several), so it stays meaningful on a loaded machine."
    })
public final class BenchRenderCommand implements Callable<Integer> {
  @Spec CommandSpec spec;
  private final HeadlessRenderer[] rendererRef = {null};

  @Option(names = "--width", defaultValue = "1280", description = "Width in pixels (default: ${DEFAULT-VALUE}).")
  int width;

  @Option(names = "--height", defaultValue = "800", description = "Height in pixels (default: ${DEFAULT-VALUE}).")
  int height;

  @Option(names = "--seconds", defaultValue = "5", description = "How long to measure (default: ${DEFAULT-VALUE}).")
  double seconds;

  @Option(names = "--antialias", paramLabel = "MODE",
      description = "Edge smoothing: ${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE}, as robotrun render and the window use).")
  AntiAliasing antialias = AntiAliasing.DEFAULT;

  @Option(names = "--scenario", paramLabel = "FILE.json",
      description = "With --vision-camera: the scenario whose vision camera is drawn.")
  java.nio.file.Path scenario;

  @Option(names = "--vision-camera", paramLabel = "NAME",
      description = "Time the camera view instead: what this vision camera of --scenario sees, at its image size, with "
          + "the parts its processes found outlined (one RUN_FIND first), from a fresh snapshot every frame.")
  String visionCamera;

  @Override
  public Integer call() {
    if (visionCamera != null && scenario == null || scenario != null && visionCamera == null) {
      throw new UserError("--scenario and --vision-camera go together");
    }
    RenderCommand.checkSize("--width", width);
    RenderCommand.checkSize("--height", height);
    if (!(seconds > 0 && seconds <= 600)) {
      throw new UserError("--seconds: expected more than 0 and at most 600, got " + seconds);
    }
    RobotModel robot = RobotDefinitions.defaultRobot();
    OrbitCamera camera = new OrbitCamera();
    java.util.function.IntConsumer[] frame = {null};
    if (visionCamera != null) {
      org.robotrun.world.Scenario sc = ScenarioFiles.load(scenario);
      org.robotrun.world.VisionSetup.Camera cam = VisionRender.camera(sc, visionCamera);
      org.robotrun.sim.Simulation sim = VisionRender.cell(sc);
      org.robotrun.sim.VisionSystem vs = sim.vision().orElseThrow();
      for (org.robotrun.world.VisionSetup.Process p : sc.vision().processes()) {
        if (p.camera().equals(cam.name())) {
          vs.runFind(sim.controllers().get(0), p.name());
        }
      }
      width = cam.widthPx();
      height = cam.heightPx();
      frame[0] = i -> {
        var X_CK = vs.cameraPose(cam);
        rendererRef[0].renderFrame(vs.withOutlines(sim.snapshot().scene(), cam.name()),
            org.robotrun.render.VisionCameraView.viewProjection(cam, X_CK), org.robotrun.render.VisionCameraView.eye(X_CK));
      };
    }
    try (HeadlessRenderer r = new HeadlessRenderer(width, height, antialias)) {
      rendererRef[0] = r;
      if (frame[0] == null) {
        frame[0] = i -> r.renderFrame(scene(robot, i), camera);
      }
      // Warm up: shader compilation, mesh upload, JIT.
      for (int i = 0; i < 10; i++) {
        frame[0].accept(i);
      }
      long cpuStart = processCpuNs();
      long start = System.nanoTime();
      long end = start + (long) (seconds * 1e9);
      int frames = 0;
      long[] frameNs = new long[1 << 16];
      long t = start;
      while (t < end && frames < frameNs.length) {
        frame[0].accept(frames);
        long now = System.nanoTime();
        frameNs[frames++] = now - t;
        t = now;
      }
      double elapsed = (t - start) / 1e9;
      double cpuMsPerFrame = (processCpuNs() - cpuStart) / 1e6 / frames;
      long[] sorted = Arrays.copyOf(frameNs, frames);
      Arrays.sort(sorted);
      PrintWriter o = spec.commandLine().getOut();
      o.printf(java.util.Locale.ROOT, "fps=%.1f frames=%d seconds=%.2f width=%d height=%d antialias=%s median_frame_ms=%.2f cpu_ms_per_frame=%.2f%s%n",
          frames / elapsed, frames, elapsed, width, height, antialias.name().toLowerCase(java.util.Locale.ROOT), sorted[frames / 2] / 1e6, cpuMsPerFrame,
          visionCamera == null ? "" : " camera=" + visionCamera);
      o.flush();
    } catch (GlUnavailableException e) {
      throw new UserError("cannot render: " + e.getMessage(), Main.EXIT_FAILED);
    }
    return Main.EXIT_OK;
  }

  /** CPU time of the whole process (all threads, the renderer's included), in ns. */
  private static long processCpuNs() {
    return ProcessHandle.current().info().totalCpuDuration().map(java.time.Duration::toNanos).orElse(0L);
  }

  private static SceneSnapshot scene(RobotModel robot, int frame) {
    double s = Math.sin(frame * 0.02);
    double[] q = {0.6 * s, 0.3 * s, 0.2 * s, 0.5 * s, 0.4 * s + 0.5, s};
    return SceneSnapshots.singleRobot(robot, q, frame / 60.0);
  }
}
