package org.robotrun.app;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.program.Position;
import org.robotrun.render.AntiAliasing;
import org.robotrun.render.HeadlessRenderer;
import org.robotrun.render.VisionCameraView;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.sim.VisionSystem;
import org.robotrun.world.Scenario;
import org.robotrun.world.VisionSetup;

/** {@code robotrun render --vision-camera NAME [--vision-find PROCESS]}: the image a vision camera sees. */
final class VisionRender {
  private VisionRender() {}

  /** The scenario with its vision seed replaced when {@code seed} is given. */
  static Scenario seeded(Scenario sc, Long seed, PrintWriter err) {
    if (seed == null) {
      return sc;
    }
    if (sc.vision().isEmpty()) {
      err.println("robotrun: warning: --seed: the scenario has no vision section: the seed changes nothing");
      err.flush();
    }
    return sc.withVision(sc.vision().withSeed(seed));
  }

  /** The cell of {@code sc} with its vision system, one tick run (the arms stand still). */
  static Simulation cell(Scenario sc) {
    Simulation sim;
    try {
      sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
    } catch (FileFormatException | IllegalArgumentException e) {
      throw new UserError("--scenario: " + e.getMessage());
    }
    sim.step();
    return sim;
  }

  /** The camera of that name; a user error naming the cameras there are otherwise. */
  static VisionSetup.Camera camera(Scenario sc, String name) {
    return sc.vision().camera(name).orElseThrow(() -> new UserError("--vision-camera: no camera named '" + name
        + "' (" + (sc.vision().cameras().isEmpty() ? "the scenario has no vision cameras"
            : "cameras: " + String.join(", ", sc.vision().cameras().stream().map(VisionSetup.Camera::name).toList()))
        + ")"));
  }

  /**
   * Renders what {@code cameraName} sees to {@code out} at the camera's image size; with
   * {@code process}, runs RUN_FIND first, outlines the found parts and prints one line per part.
   */
  static void render(Scenario sc, String cameraName, String process, Path out, AntiAliasing aa, PrintWriter stdout) {
    VisionSetup.Camera cam = camera(sc, cameraName);
    Simulation sim = cell(sc);
    VisionSystem vs = sim.vision().orElseThrow();
    if (process != null) {
      VisionSetup.Process p = sc.vision().process(process).orElseThrow(() -> new UserError("--vision-find: no vision "
          + "process named '" + process + "'"));
      if (!p.camera().equals(cam.name())) {
        throw new UserError("--vision-find: process " + p.name() + " uses camera " + p.camera() + ", not " + cam.name());
      }
      List<VisionSystem.Detection> found = vs.runFind(sim.controllers().get(0), p.name());
      stdout.printf(Locale.ROOT, "%s found %d%n", p.name(), found.size());
      for (VisionSystem.Detection d : found) {
        Position.Cartesian f = d.result().found();
        Position.Cartesian o = d.result().offset();
        stdout.printf(Locale.ROOT, "  %s model %d score %.1f found UF[%d] X %.3f Y %.3f Z %.3f R %.3f offset X %.3f Y %.3f R %.3f%n",
            d.part(), d.result().modelId(), d.result().score(), d.result().userFrame(), f.xMm(), f.yMm(), f.zMm(),
            f.rDeg(), o.xMm(), o.yMm(), o.rDeg());
      }
      stdout.flush();
    }
    Transform X_CK = vs.cameraPose(cam);
    try (HeadlessRenderer r = new HeadlessRenderer(cam.widthPx(), cam.heightPx(), aa)) {
      r.renderPng(vs.withOutlines(sim.snapshot().scene(), cam.name()), VisionCameraView.viewProjection(cam, X_CK),
          VisionCameraView.eye(X_CK), out);
    }
  }
}
