package org.robotrun.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Angles;
import org.robotrun.math.Xyzwpr;
import org.robotrun.pendant.Pendant;
import org.robotrun.program.Program;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.Controller;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.ui.CellPanel;
import org.robotrun.ui.PendantKeyboard;
import org.robotrun.ui.PendantPanel;
import org.robotrun.ui.RobotStatusPanel;
import org.robotrun.ui.SimulatorWindow;
import org.robotrun.world.Scenario;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun gui} (also what {@code robotrun} alone does): the simulator window. */
@Command(
    name = "gui",
    mixinStandardHelpOptions = true,
    description = {
      "Open the simulator window (what 'robotrun' with no subcommand does): the cell in 3D and the teach pendant.",
      "Mouse: left drag orbits, right or middle drag pans, wheel zooms; Home resets the view.",
      "Pendant keys are buttons on the pendant panel and keys on the keyboard (docs/user-guide.md): Shift is the deadman, Q..Y jog +J1..+J6 (+X..+ZR), A..H jog -J1..-J6, arrows move the cursor, F1-F5 the function keys."
    })
public final class GuiCommand implements Callable<Integer> {
  @Option(names = "--width", defaultValue = "1280", description = "Window width (default: ${DEFAULT-VALUE}).")
  int width = 1280;

  @Option(names = "--height", defaultValue = "800", description = "Window height (default: ${DEFAULT-VALUE}).")
  int height = 800;

  @Option(names = "--scenario", paramLabel = "FILE.json",
      description = "Open this scenario's cell (robots, fixtures, parts, frames, registers and programs). Default: the default robot in an empty cell.")
  Path scenario;

  @Option(names = "--program", paramLabel = "FILE.LS",
      description = "Load this TP program into the pendant's program list (repeatable); 'robotrun FILE.LS' does the same, so a file manager can open .LS files in RobotRun.")
  List<Path> programFiles = new ArrayList<>();

  /** Start-up timing and the packaging's class-data training run: close after this many frames. */
  @Option(names = "--quit-after-frames", hidden = true, defaultValue = "0")
  int quitAfterFrames;

  @Override
  public Integer call() {
    Natives.windowProblem(Natives.currentPlatform()).ifPresent(why -> {
      throw new UserError("cannot open the simulator window: " + why, Main.EXIT_FAILED);
    });
    try {
      return openWindow();
    } catch (GlUnavailableException e) {
      if (e.noGl33Context() && SoftwareGl.mayRetry(System.getProperty("os.name", ""), System.getenv())) {
        System.err.println("robotrun: " + e.getMessage());
        System.err.println("robotrun: starting again with Mesa's software renderer (llvmpipe): slower, but it works without OpenGL 3.3 from the graphics driver");
        Optional<Integer> code = SoftwareGl.relaunch();
        if (code.isPresent()) {
          return code.get();
        }
      }
      String software = SoftwareGl.active(System.getenv()) ? " (also with Mesa's software renderer)" : "";
      throw new UserError("cannot open the simulator window: " + e.getMessage() + software, Main.EXIT_FAILED);
    } catch (LinkageError e) {
      // A native library that does not load on this machine: one line, no stack trace.
      throw new UserError("cannot open the simulator window: a native library did not load on "
          + Natives.currentPlatform() + " (" + e.getMessage() + ")", Main.EXIT_FAILED);
    }
  }

  private int openWindow() {
    RenderCommand.checkSize("--width", width);
    RenderCommand.checkSize("--height", height);
    Simulation sim;
    List<Program> programs = new ArrayList<>();
    Scenario sc = null;
    if (scenario == null) {
      sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
    } else {
      sc = ScenarioFiles.load(scenario);
      try {
        sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
        programs.addAll(RunCommand.loadPrograms(sc.programs()));
      } catch (IllegalArgumentException e) {
        throw new UserError(scenario + ": " + e.getMessage());
      } catch (IOException e) {
        throw new UserError(scenario + ": cannot read a program (" + e.getMessage() + ")");
      }
    }
    Controller controller = sim.controllers().get(0);
    SimRobotControl control = new SimRobotControl(sim, controller);
    if (!programFiles.isEmpty()) {
      try {
        programs.addAll(RunCommand.loadPrograms(programFiles));
      } catch (IOException e) {
        throw new UserError("--program: cannot read a program (" + e.getMessage() + ")");
      }
    }
    programs.forEach(control::saveProgram);
    Pendant pendant = new Pendant(control, new LsLineParser());
    PendantPanel pendantPanel = new PendantPanel(pendant);
    CellPanel cellPanel = new CellPanel(sim);
    RobotModel robot = controller.model();
    String title = "RobotRun — " + (sc != null && !sc.name().isBlank() ? sc.name() : robot.displayName())
        + (SoftwareGl.active(System.getenv()) ? " (software rendering)" : "");
    try (SimulatorWindow w = new SimulatorWindow(title, width, height)) {
      w.setFrameLimit(quitAfterFrames);
      if (sc != null) {
        sc.camera().ifPresent(v -> ScenarioFiles.applyCamera(v, w.camera()));
      }
      PendantKeyboard keyboard = new PendantKeyboard(pendant);
      // The pendant panel covers the right of the window: centre the cell in what is left.
      w.camera().setCentreShift(-0.3f);
      w.setKeyHandler(keyboard::onKey);
      w.setCharHandler(keyboard::onChar);
      w.setFocusLostHandler(() -> {
        keyboard.releaseAll();
        pendantPanel.releaseLatched();
      });
      double[] last = {0};
      w.run(t -> {
            // Real time drives the simulation; a stalled frame never makes it jump more than 0.1 s.
            pendant.advance(Math.min(0.1, t - last[0]));
            last[0] = t;
            return sim.snapshot().scene();
          },
          (fw, fh) -> {
            double[] q = controller.jointsRad();
            double[] pendantDeg = Angles.toDegrees(JointConvention.kinematicToPendant(robot, q));
            RobotStatusPanel.draw("Robot", pendantDeg, Xyzwpr.fromTransform(ForwardKinematics.flangePoseInWorld(robot, q)));
            pendantPanel.draw(fw, fh);
            cellPanel.draw();
          });
    }
    return Main.EXIT_OK;
  }
}
