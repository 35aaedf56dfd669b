package org.robotrun.app;

import static org.lwjgl.glfw.GLFW.GLFW_MOD_CONTROL;
import static org.lwjgl.glfw.GLFW.GLFW_MOD_SUPER;

import imgui.ImGui;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.robotrun.io.UserDirs;
import org.robotrun.math.Angles;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.render.OrbitCamera;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.Controller;
import org.robotrun.ui.FileDialogs;
import org.robotrun.ui.FileMenu;
import org.robotrun.ui.RobotStatusPanel;
import org.robotrun.ui.SimulatorWindow;
import org.robotrun.world.CameraView;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun gui} (also what {@code robotrun} alone does): the simulator window on a workspace. */
@Command(
    name = "gui",
    mixinStandardHelpOptions = true,
    description = {
      "Open the simulator window (what 'robotrun' with no subcommand does): the cell in 3D and the teach pendant.",
      "The window works in a workspace, a folder with cell.json and programs/NAME.LS (docs/workspace.md): with no option "
          + "it opens the last workspace, or creates the default one (Linux ~/.local/share/robotrun/workspace, Windows "
          + "%APPDATA%\\RobotRun\\workspace, macOS ~/Library/Application Support/RobotRun/workspace). Every change is saved "
          + "within 2 s and on close; File menu: New/Open workspace (Ctrl+O), Open scenario, Save now (Ctrl+S), Save a copy, "
          + "Import/Export .LS, Recent, Hand in, Quit (Ctrl+Q).",
      "Mouse: left drag orbits, right or middle drag pans, wheel zooms; Home resets the view.",
      "Pendant keys are buttons on the pendant panel and keys on the keyboard (docs/user-guide.md): Shift is the deadman, Q..Y jog +J1..+J6 (+X..+ZR), A..H jog -J1..-J6, arrows move the cursor, F1-F5 the function keys."
    })
public final class GuiCommand implements Callable<Integer> {
  @Option(names = "--width", defaultValue = "1280", description = "Window width (default: ${DEFAULT-VALUE}).")
  int width = 1280;

  @Option(names = "--height", defaultValue = "800", description = "Window height (default: ${DEFAULT-VALUE}).")
  int height = 800;

  @Option(names = "--workspace", paramLabel = "DIR|FILE.zip",
      description = "Open the workspace in DIR, creating it when the folder is new or empty; a hand-in FILE.zip opens read-only. "
          + "Default: the last workspace.")
  Path workspace;

  @Option(names = "--scenario", paramLabel = "FILE.json",
      description = "Start a new workspace copied from this scenario (the scenario file is not changed; the copy goes to "
          + "the RobotRun data folder, workspaces/NAME).")
  Path scenario;

  @Override
  public Integer call() {
    RenderCommand.checkSize("--width", width);
    RenderCommand.checkSize("--height", height);
    if (workspace != null && scenario != null) {
      throw new UserError("--workspace and --scenario: give one of them");
    }
    UserDirs dirs = UserDirs.fromSystem();
    Path dir;
    if (scenario != null) {
      dir = WorkspaceFiles.createFromScenario(scenario, dirs.newWorkspaceFor(stem(scenario)));
    } else {
      dir = workspace != null ? workspace : WorkspaceSession.lastOrDefault(dirs);
    }
    WindowCell[] cell = {null};
    FileDialogs dialogs = new FileDialogs();
    SimulatorWindow[] window = {null};
    java.util.function.BooleanSupplier[] closeGuard = {() -> true};
    GuiFileActions actions = new GuiFileActions(dirs, () -> cell[0], next -> {
      cell[0].close();
      cell[0] = next;
      window[0].setTitle(next.title());
      next.applyCamera(window[0].camera());
    }, () -> {
      if (closeGuard[0].getAsBoolean()) {
        window[0].requestClose();
      }
    }, () -> window[0].camera());
    FileMenu menu = new FileMenu(actions, dialogs);
    boolean[] warned = {false};
    closeGuard[0] = () -> {
      // Work that cannot be saved keeps the window open once, with the reason; closing again quits.
      WindowCell c = cell[0];
      if (warned[0] || c.session.workspace.readOnly()) {
        return true;
      }
      String problem = c.session.autosave.saveNow(3000);
      if (problem.isEmpty()) {
        return true;
      }
      warned[0] = true;
      menu.tell("Your last changes are NOT saved: " + problem
          + "\n\nFix the problem (the window keeps trying), or close again to quit without them.");
      return false;
    };
    actions.setMenu(menu);
    cell[0] = WindowCell.open(dir, dirs, menu, () -> cameraView(window[0] == null ? null : window[0].camera()));
    try (SimulatorWindow w = new SimulatorWindow(cell[0].title(), width, height)) {
      window[0] = w;
      cell[0].applyCamera(w.camera());
      // The pendant panel covers the right of the window: centre the cell in what is left.
      w.camera().setCentreShift(-0.3f);
      w.setShortcutHandler((key, action, mods) ->
          menu.onKey(key, action, (mods & (GLFW_MOD_CONTROL | GLFW_MOD_SUPER)) != 0));
      w.setKeyHandler((key, action) -> cell[0].keyboard.onKey(key, action));
      w.setCharHandler(cp -> cell[0].keyboard.onChar(cp));
      w.setFocusLostHandler(() -> cell[0].releaseKeys());
      w.setFocusGainedHandler(() -> cell[0].checkExternalEdits(menu));
      w.setCloseHandler(closeGuard[0]);
      double[] last = {0};
      boolean[] firstFrame = {System.getenv("ROBOTRUN_TIMING") != null};
      w.run(t -> {
            WindowCell c = cell[0];
            // Real time drives the simulation; a stalled frame never makes it jump more than 0.1 s.
            c.pendant.advance(Math.min(0.1, t - last[0]));
            last[0] = t;
            c.session.autosave.poll(System.nanoTime());
            return c.session.sim.snapshot().scene();
          },
          (fw, fh) -> {
            WindowCell c = cell[0];
            if (ImGui.beginMainMenuBar()) {
              menu.drawMenu();
              c.drawSaveState(menu);
              ImGui.endMainMenuBar();
            }
            Controller controller = c.session.sim.controllers().get(0);
            RobotModel robot = controller.model();
            double[] q = controller.jointsRad();
            double[] pendantDeg = Angles.toDegrees(JointConvention.kinematicToPendant(robot, q));
            RobotStatusPanel.draw("Robot", pendantDeg, Xyzwpr.fromTransform(ForwardKinematics.flangePoseInWorld(robot, q)));
            c.pendantPanel.draw(fw, fh);
            c.cellPanel.draw();
            menu.drawPopups();
            if (firstFrame[0]) {
              firstFrame[0] = false;
              long ms = System.currentTimeMillis() - java.lang.management.ManagementFactory.getRuntimeMXBean().getStartTime();
              System.err.println("robotrun: first frame " + ms + " ms after the JVM started");
            }
          });
    } catch (GlUnavailableException e) {
      cell[0].close();
      throw new UserError("cannot open the simulator window: " + e.getMessage(), Main.EXIT_FAILED);
    } finally {
      dialogs.close();
    }
    if (System.getenv("ROBOTRUN_PRINT_LCD_ON_EXIT") != null) {
      // for the window test: what the pendant showed when the window closed
      System.out.println(cell[0].pendant.render());
    }
    String problem = cell[0].closeAndReport();
    if (!problem.isEmpty()) {
      throw new UserError(problem, Main.EXIT_FAILED);
    }
    return Main.EXIT_OK;
  }

  static String stem(Path file) {
    String n = file.getFileName().toString();
    int dot = n.lastIndexOf('.');
    return dot > 0 ? n.substring(0, dot) : n;
  }

  static Optional<CameraView> cameraView(OrbitCamera camera) {
    if (camera == null) {
      return Optional.empty();
    }
    var t = camera.target();
    return Optional.of(new CameraView(new Vec3(t.x, t.y, t.z), camera.distance(), camera.yaw(), camera.pitch()));
  }
}
