package org.robotrun.app;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.TerminalText;
import org.robotrun.io.UserDirs;
import org.robotrun.io.StlReader;
import org.robotrun.math.Angles;
import org.robotrun.math.Xyzwpr;
import org.robotrun.pendant.Pendant;
import org.robotrun.program.Interpreter;
import org.robotrun.program.Program;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.CellStepper;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ControllerPort;
import org.robotrun.grade.Course;
import org.robotrun.grade.Grader;
import org.robotrun.grade.TaskLoad;
import org.robotrun.grade.TaskReader;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.ui.CellEditorPanel;
import org.robotrun.ui.CellPanel;
import org.robotrun.ui.CheckWorkPanel;
import org.robotrun.ui.FileDialogs;
import org.robotrun.ui.FileMenu;
import org.robotrun.ui.LayoutState;
import org.robotrun.ui.OperatorPanel;
import org.robotrun.ui.PendantKeyboard;
import org.robotrun.ui.PendantPanel;
import org.robotrun.ui.SimulatorWindow;
import org.robotrun.ui.WindowSettings;
import org.robotrun.ui.Workbench;
import org.robotrun.world.CameraView;
import org.robotrun.world.CellEditor;
import org.robotrun.world.Scenario;
import org.robotrun.world.TriangleMesh;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun gui} (also what {@code robotrun} alone does): the simulator window. */
@Command(
    name = "gui",
    mixinStandardHelpOptions = true,
    description = {
      "Open the simulator window (what 'robotrun' with no subcommand does): the cell in 3D and the teach pendant side by side.",
      "The window works in a workspace, a folder with cell.json and programs/NAME.LS (docs/workspace.md): with no option "
          + "it opens the last workspace, or creates the default one (Linux ~/.local/share/robotrun/workspace, Windows "
          + "%%APPDATA%%\\RobotRun\\workspace, macOS ~/Library/Application Support/RobotRun/workspace). Every change is saved "
          + "within 2 s and on close; File menu: New/Open workspace (Ctrl+O), Open scenario, Save now (Ctrl+S), Save a copy, "
          + "Import/Export .LS, Recent, Hand in, Quit (Ctrl+Q).",
      "Mouse: left drag orbits, right or middle drag pans, wheel zooms, a click selects an object; Home resets the view.",
      "Pendant keys are buttons on the pendant panel and keys on the keyboard (docs/user-guide.md): hold Space for the DEADMAN and Shift for SHIFT (with TP ENABLE on) to jog and run, Q..Y jog +J1..+J6 (+X..+ZR), A..H jog -J1..-J6, arrows move the cursor, F1-F5 the function keys. Ctrl+H or ? shows the key map."
    })
public final class GuiCommand implements Callable<Integer> {
  @Option(names = "--width", defaultValue = "0",
      description = "Window width in screen coordinates (default: fit the screen, at most 1280 times the monitor's scale).")
  int width;

  @Option(names = "--height", defaultValue = "0",
      description = "Window height (default: fit the screen, at most 800 times the monitor's scale).")
  int height;

  @Option(names = "--workspace", paramLabel = "DIR|FILE.zip",
      description = "Open the workspace in DIR, creating it when the folder is new or empty; a hand-in FILE.zip opens read-only. "
          + "Default: the last workspace.")
  Path workspace;

  @Option(names = "--scenario", paramLabel = "FILE.rrcell|FILE.json",
      description = "Start a new workspace copied from this scenario (the scenario file is not changed; the copy goes to "
          + "the RobotRun data folder, workspaces/NAME); its cell can then be edited.")
  Path scenario;

  @Option(names = "--course", paramLabel = "DIR|course.json",
      description = "The course whose labs the Labs menu lists (docs/labs/README.md); default: the shipped one, "
          + "scenarios/labs. Each lab's workspace is in ~/robotrun-labs/ID (ROBOTRUN_LABS_HOME sets another folder).")
  Path courseFile;

  @Option(names = "--task", paramLabel = "TASK.json",
      description = "A grading task (docs/grading.md): adds a Check menu whose 'Check my work' runs the task's visible "
          + "checks on your programs and frames. Without --workspace or --scenario, starts from the task's scenario; "
          + "with a --workspace folder that is new or empty, makes it from the task's scenario (a lab's own workspace, "
          + "reopened the next time).")
  Path task;

  @Option(names = "--program", paramLabel = "FILE.LS",
      description = "Also load this TP program into the pendant's program list (repeatable); 'robotrun FILE.LS' does the same, so a file manager can open .LS files in RobotRun.")
  List<Path> programFiles = new ArrayList<>();

  /** Start-up timing and the packaging's class-data training run: close after this many frames. */
  @Option(names = "--quit-after-frames", hidden = true, defaultValue = "0")
  int quitAfterFrames;

  /** {@code robotrun bench window} runs the window with these: seconds per phase ({@link WindowBench}). */
  @Option(names = "--bench-seconds", hidden = true, defaultValue = "0")
  double benchSeconds;

  /** The program the bench's run phase runs. */
  @Option(names = "--bench-program", hidden = true, defaultValue = "")
  String benchProgram;

  /**
   * Everything one window session holds; tests drive it through {@link #open}. {@code workspace}
   * is null when the window shows a scenario without a workspace (tests).
   */
  public record Session(SimulatorWindow window, Workbench bench, Simulation sim, Controller controller, Pendant pendant,
      CellEditor editor, WindowSettings settings, WindowCell workspace, org.robotrun.ui.RobotSelector robots,
      CellStepper stepper, java.util.concurrent.atomic.AtomicReference<org.robotrun.sim.SceneSnapshot> frameScene) {}

  @Override
  public Integer call() {
    Natives.windowProblem(Natives.currentPlatform()).ifPresent(why -> {
      throw new UserError("cannot open the simulator window: " + why, Main.EXIT_FAILED);
    });
    NativeLibraries.prepare();
    try {
      return openWindow();
    } catch (GlUnavailableException e) {
      if (e.noGl33Context() && SoftwareGl.mayRetry(System.getProperty("os.name", ""), System.getenv())) {
        System.err.println("robotrun: " + TerminalText.safe(e.getMessage()));
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
    if (width != 0) {
      RenderCommand.checkSize("--width", width);
    }
    if (height != 0) {
      RenderCommand.checkSize("--height", height);
    }
    if (workspace != null && scenario != null) {
      throw new UserError("--workspace and --scenario: give one of them");
    }
    boolean log = System.getenv("ROBOTRUN_FRAME_LOG") != null;
    if (log) {
      stage("command line parsed");
    }
    TaskLoad.Loaded taskLoaded = task == null ? null : switch (TaskReader.read(task)) {
      case TaskLoad.Loaded l -> l;
      case TaskLoad.Failed f -> throw new UserError(f.message());
    };
    if (taskLoaded != null && scenario == null && workspace == null) {
      scenario = taskLoaded.task().scenario();
    }
    List<Program> extraPrograms;
    try {
      extraPrograms = programFiles.isEmpty() ? List.of() : RunCommand.loadPrograms(programFiles);
    } catch (IOException e) {
      throw new UserError("--program: cannot read a program (" + e.getMessage() + ")");
    }
    UserDirs dirs = UserDirs.fromSystem();
    Course course = course(courseFile);
    Path labsHome = labsHome();
    Path next;
    if (scenario != null) {
      next = WorkspaceFiles.createFromScenario(scenario, dirs.newWorkspaceFor(stem(scenario)));
    } else if (taskLoaded != null && workspace != null
        && (!java.nio.file.Files.exists(workspace) || WorkspaceFiles.isEmptyFolder(workspace))) {
      // A lab: the student's own workspace for the task, made from the task's cell the first time and reopened after.
      next = WorkspaceFiles.createFromScenario(taskLoaded.task().scenario(), workspace);
    } else {
      next = workspace != null ? workspace : WorkspaceSession.lastOrDefault(dirs);
    }
    String problem = "";
    // File ▸ Open workspace and a scenario switch end one session and start the next on the
    // folder in the same window.
    SimulatorWindow window = null;
    try {
      while (next != null) {
        Path[] switchTo = {null};
        Session s = openWorkspace(next, dirs, switchTo, width, height, WindowSettings.forWorkspace(next), window);
        window = s.window();
        // Programs opened from the file manager join the workspace's list (the first window only).
        extraPrograms.forEach(s.controller()::saveProgram);
        extraPrograms = List.of();
        if (log) {
          stage("cell and window ready");
        }
        // The Labs menu: the course's labs; a workspace in the labs folder is its lab's, with its task.
        java.util.Optional<Course.Lab> lab = course == null ? java.util.Optional.empty()
            : labOf(course, labsHome, next);
        TaskLoad.Loaded sessionTask = taskLoaded;
        if (sessionTask == null && lab.isPresent() && TaskReader.read(lab.get().task()) instanceof TaskLoad.Loaded l) {
          sessionTask = l;
        }
        org.robotrun.ui.LabsPanel labs = null;
        if (course != null) {
          SimulatorWindow sw = s.window();
          labs = new org.robotrun.ui.LabsPanel(course, labsHome, lab, chosen -> {
            Path dir = labsHome.resolve(chosen.id());
            if (!java.nio.file.Files.exists(dir) || WorkspaceFiles.isEmptyFolder(dir)) {
              WorkspaceFiles.createFromScenario(chosen.cell(), dir);
            }
            switchTo[0] = dir;
            sw.requestClose();
          });
          s.bench().addMenus(labs);
        }
        if (sessionTask != null) {
          CheckWorkPanel check = new CheckWorkPanel(new Grader(sessionTask.task(), sessionTask.scenario()),
              s.sim().controllers());
          if (labs != null) {
            check.onResult(labs::checked);
          }
          s.bench().addMenus(check);
        }
        SimulatorWindow w = s.window();
        if (System.getenv("ROBOTRUN_FRAME_LOG") != null) {
          logFrames(w);
        }
        if (quitAfterFrames > 0) {
          w.setAfterFrameHandler(() -> {
            if (w.frames() >= quitAfterFrames) {
              w.close(true);
            }
          });
        }
        WindowBench benchmark = null;
        if (benchSeconds > 0) {
          benchmark = new WindowBench(s, benchSeconds, benchProgram, System.out);
          benchmark.install();
          benchSeconds = 0;  // the first session only
        }
        run(s, benchmark == null ? null : benchmark.simCpuNanos());
        if (log) {
          stage("window loop ended");
        }
        if (System.getenv("ROBOTRUN_PRINT_LCD_ON_EXIT") != null) {
          // for the window test: what the pendant showed when the window closed
          System.out.println(s.pendant().render());
        }
        String saved = s.workspace().closeAndReport();
        if (log) {
          stage("workspace saved and closed");
        }
        problem = !saved.isEmpty() || benchmark == null ? saved : benchmark.problem();
        next = switchTo[0];
      }
    } finally {
      if (window != null) {
        window.close();
        if (log) {
          stage("window closed");
        }
      }
    }
    if (!problem.isEmpty()) {
      throw new UserError(problem, Main.EXIT_FAILED);
    }
    return Main.EXIT_OK;
  }

  /** The cell as loaded: built off the main thread while the window opens. */
  private record Cell(Simulation sim, Scenario scenario, List<Program> programs, List<List<Program>> robotPrograms) {
    Cell(Simulation sim, Scenario scenario, List<Program> programs) {
      this(sim, scenario, programs, List.of());
    }
  }

  private static Cell loadCell(Path scenario) {
    if (scenario == null) {
      return new Cell(DefaultCell.simulation(RobotDefinitions.defaultRobot()), null, List.of());
    }
    Scenario sc = ScenarioFiles.load(scenario);
    try {
      Simulation sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
      List<Program> first = new java.util.ArrayList<>(RunCommand.loadPrograms(sc.programs()));
      first.addAll(RunCommand.loadPrograms(sc.robots().get(0).programs()));
      List<List<Program>> perRobot = new java.util.ArrayList<>();
      for (var r : sc.robots()) {
        perRobot.add(RunCommand.loadPrograms(r.programs()));
      }
      return new Cell(sim, sc, first, perRobot);
    } catch (IllegalArgumentException e) {
      throw new UserError(scenario + ": " + e.getMessage());
    } catch (IOException e) {
      throw new UserError(scenario + ": cannot read a program (" + e.getMessage() + ")");
    }
  }

  private static <T> T join(java.util.concurrent.CompletableFuture<T> f) {
    try {
      return f.join();
    } catch (java.util.concurrent.CompletionException e) {
      if (e.getCause() instanceof RuntimeException r) {
        throw r;
      }
      throw e;
    }
  }

  /** Builds the cell of a scenario (no workspace: nothing is saved), the pendant and the window (not yet running). */
  public static Session open(Path scenario, int width, int height, WindowSettings settings) {
    return open(scenario, null, null, null, width, height, settings, null);
  }

  /**
   * Opens the workspace in {@code dir} (created when new) in a window that saves it: autosave,
   * the File menu, outside edits, the close guard. A File-menu switch to another workspace puts
   * its folder in {@code switchTo[0]} and closes the window.
   */
  static Session openWorkspace(Path dir, UserDirs dirs, Path[] switchTo, int width, int height, WindowSettings settings,
      SimulatorWindow reuse) {
    return open(null, dir, dirs, switchTo, width, height, settings, reuse);
  }

  /** @param reuse the window of the session before (another workspace, a scenario switch), or null for a new one */
  private static Session open(Path scenario, Path workspaceDir, UserDirs dirs, Path[] switchTo, int width, int height,
      WindowSettings settings, SimulatorWindow reuse) {
    // The cell loads (JSON, robot model, programs) on another thread while GLFW, OpenGL and
    // ImGui start on this one: the two together are most of the time to the first frame.
    java.util.List<String> early = new java.util.concurrent.CopyOnWriteArrayList<>();
    SimulatorWindow[] windowRef = {null};
    var wsLoading = workspaceDir == null ? null : java.util.concurrent.CompletableFuture.supplyAsync(
        () -> WindowCell.open(workspaceDir, dirs, early::add,
            () -> cameraView(windowRef[0] == null ? null : windowRef[0].camera())));
    var loading = wsLoading != null
        ? wsLoading.thenApply(c -> new Cell(c.session.sim, c.session.workspace.scenario(), List.of()))
        : java.util.concurrent.CompletableFuture.supplyAsync(() -> loadCell(scenario));
    SimulatorWindow w;
    try {
      w = reuse != null ? reuse.reopen() : new SimulatorWindow("RobotRun", width, height);
    } catch (GlUnavailableException e) {
      join(loading);  // a bad scenario is reported as such, even without a display
      throw e;
    }
    windowRef[0] = w;
    Cell cell;
    WindowCell ws;
    try {
      cell = join(loading);
      ws = wsLoading == null ? null : join(wsLoading);
    } catch (RuntimeException e) {
      if (reuse == null) {
        w.close();  // a reused window is the caller's to close
      }
      throw e;
    }
    Simulation sim = cell.sim();
    Scenario sc = cell.scenario();
    List<Program> programs = cell.programs();
    if (System.getenv("ROBOTRUN_FRAME_LOG") != null) {
      stage("cell built");
    }
    Controller controller = sim.controllers().get(0);
    // the scene the window drew this frame (set by run), for the views that draw it again
    java.util.concurrent.atomic.AtomicReference<org.robotrun.sim.SceneSnapshot> frameScene = new java.util.concurrent.atomic.AtomicReference<>();
    // Every robot has its own controller port and pendant; the robot selector picks the one the
    // window drives. A fresh window is a cold start for each: mode T1 (the port's default, or the
    // scenario's), override $SCR.$COLDOVRD = 10%.
    List<Pendant> pendants = new java.util.ArrayList<>();
    for (int i = 0; i < sim.controllers().size(); i++) {
      Controller c = sim.controllers().get(i);
      ControllerPort rc = new ControllerPort(c);
      rc.setOverridePct(PendantCommand.COLD_START_OVERRIDE_PCT);
      java.util.Optional<String> mode = sc != null && i < sc.robots().size() ? sc.preload(i).mode() : java.util.Optional.empty();
      if (mode.isPresent()) {
        rc.setMode(org.robotrun.control.RobotControl.Mode.valueOf(mode.get()));
      }
      Pendant p = new Pendant(rc, new LsLineParser());
      if (sim.controllers().size() > 1) {
        p.setRobotLabel(c.name());
      }
      if (ws != null && ws.session.workspace.readOnly()) {
        // A hand-in (or a workspace another RobotRun holds) is looked at, never changed in
        // silence: program edits are refused where the student types (docs/workspace.md).
        p.setReadOnly(readOnlyEditMessage(ws.session.workspace.readOnlyReason()));
      }
      pendants.add(p);
    }
    programs.forEach(pendants.get(0).control()::saveProgram);
    for (int i = 1; i < cell.robotPrograms().size() && i < pendants.size(); i++) {
      cell.robotPrograms().get(i).forEach(pendants.get(i).control()::saveProgram);
    }
    Pendant pendant = pendants.get(0);
    org.robotrun.ui.RobotSelector selector = new org.robotrun.ui.RobotSelector(
        sim.controllers().stream().map(Controller::name).toList(), pendants);
    PendantPanel pendantPanel = new PendantPanel(selector);
    CellPanel cellPanel = new CellPanel(sim);
    RobotModel robot = controller.model();
    CellEditor editor = null;
    if (sc != null) {
      // A workspace's other named scenarios (scenarios/NAME.json) follow the active one in the list.
      List<Scenario> all = new java.util.ArrayList<>(List.of(sc));
      if (ws != null) {
        all.addAll(ws.session.workspace.otherScenarios());
      }
      editor = new CellEditor(all, 0, GuiCommand::loadStl);
    }
    if (ws != null && editor != null) {
      CellEditor ed = editor;
      String running = sc.name();
      ws.session.otherScenarios = () -> ed.scenarios().stream().filter(x -> !x.name().equals(running)).toList();
    }
    // In a workspace the edited cell is saved with the workspace (autosave); "Export" writes a scenario copy.
    Path editedCopy = ws != null ? null
        : scenario == null ? null : scenario.toAbsolutePath().resolveSibling(stem(scenario) + "-edited.json");
    CellEditorPanel editorPanel = editor == null ? null : new CellEditorPanel(editor, editedCopy);
    if (editorPanel != null && ws != null) {
      editorPanel.inWorkspace();
    }
    w.setTitle((ws != null ? ws.title()
        : "RobotRun — " + (sc != null && !sc.name().isBlank() ? sc.name() : robot.displayName()))
        + (SoftwareGl.active(System.getenv()) ? " (software rendering)" : ""));
    if (sc != null) {
      sc.camera().ifPresent(v -> ScenarioFiles.applyCamera(v, w.camera()));
    }
    LayoutState layout = settings.load();
    Workbench bench = new Workbench(w.camera(), w.contentScale(), pendant, pendantPanel, cellPanel, editorPanel,
        new Workbench.RobotStatus() {
          // The robot the selector has chosen.
          private Controller selected() {
            return sim.controllers().get(selector.selected());
          }

          @Override
          public double[] pendantDeg() {
            Controller c = selected();
            return Angles.toDegrees(JointConvention.kinematicToPendant(c.model(), c.jointsRad()));
          }

          @Override
          public Xyzwpr flangeInWorld() {
            Controller c = selected();
            return Xyzwpr.fromTransform(ForwardKinematics.flangePoseInWorld(c.model(), c.jointsRad()));
          }

          @Override
          public String modelName() {
            return selected().model().displayName();
          }

          @Override
          public List<String> jointNames() {
            return selected().model().joints().stream().map(j -> j.name()).toList();
          }
        },
        sc == null ? "" : sc.description(), () -> sim.snapshot().scene(), layout);
    // Menus of other parts of the window go into the menu bar here, left of View and Help.
    bench.setPendantSource(selector);
    bench.setMinimumSizeHandler(w::setMinimumSize);
    if (selector.size() > 1) {
      bench.addLeadSection(org.robotrun.ui.RobotSelector.TITLE, selector::drawContents);
    }
    // the controller's panels, each shown when the cell uses it (PanelRules) or the View menu asks
    bench.addPanel(org.robotrun.ui.PanelRules.Panel.OPERATOR, new OperatorPanel(selector)::drawContents);
    // the PLC panel follows the robot the selector chose (each robot has its own UOP)
    org.robotrun.ui.PlcPanel plc = new org.robotrun.ui.PlcPanel(() -> sim.controllers().get(selector.selected()));
    bench.addPanel(org.robotrun.ui.PanelRules.Panel.PLC, plc::drawContents);
    bench.addPanel(org.robotrun.ui.PanelRules.Panel.TASKS, plc::drawTasks);
    bench.addPanel(org.robotrun.ui.PanelRules.Panel.BG_LOGIC, plc::drawBgLogic);
    bench.setCellUse(cellUse(sim, sc != null && !sc.description().isBlank()));
    PendantKeyboard keyboard = new PendantKeyboard(selector);
    // Keys held on the robot left behind are let go before the pendant changes hands.
    selector.onBeforeSwitch(() -> {
      keyboard.releaseAll();
      pendantPanel.releaseLatched();
    });
    w.setKeyHandler(keyboard::onKey);
    w.setCharHandler(cp -> bench.onChar(cp) || keyboard.onChar(cp));
    w.setShortcutHandler(bench::onShortcut);
    if (ws != null) {
      FileMenu menu = fileMenu(ws, dirs, w, switchTo);
      early.forEach(menu::tell);
      bench.addMenus(menu);
      w.setShortcutHandler((key, mods) -> menu.onShortcut(key, mods) || bench.onShortcut(key, mods));
      w.setFocusGainedHandler(() -> ws.checkExternalEdits(menu));
      ws.onSwitch(menu::tell, () -> {
        switchTo[0] = ws.session.workspace.folder();
        w.requestClose();
      });
    }
    if (selector.size() > 1) {
      bench.addMenus(selector);  // after File
    }
    if (sim.vision().isPresent()) {
      // Vision (issue 16): camera views in the Vision menu, Reset with a seed in the side panel.
      org.robotrun.ui.VisionPanel vision = new org.robotrun.ui.VisionPanel(sim, () -> {
        org.robotrun.sim.SceneSnapshot shown = frameScene.get();
        return shown != null ? shown : sim.snapshot().scene();
      });
      bench.addSection(org.robotrun.ui.VisionPanel.TITLE, vision::drawContents);
      bench.addMenus(vision);
    }
    w.setViewClickHandler(bench::onViewClick);
    w.setViewPressHandler(bench.viewPress());
    w.setFocusLostHandler(() -> {
      keyboard.releaseAll();
      pendantPanel.releaseLatched();
    });
    return new Session(w, bench, sim, controller, pendant, editor, settings, ws, selector, new CellStepper(sim), frameScene);
  }

  /** What the cell uses now, over every robot, for the left column's panel rules; a RUN seen once keeps the task list. */
  static java.util.function.Supplier<org.robotrun.ui.PanelRules.CellUse> cellUse(Simulation sim, boolean task) {
    boolean[] tasksRun = {false};
    return () -> {
      boolean production = false, bg = false, notT1 = false;
      for (Controller c : sim.controllers()) {
        production |= c.uop().setup().isPresent();
        bg |= !c.bgLogic().slots().isEmpty();
        tasksRun[0] |= !c.tasks().list().isEmpty() || runsATask(c);
        notT1 |= c.mode() != org.robotrun.control.RobotControl.Mode.T1;
      }
      return new org.robotrun.ui.PanelRules.CellUse(task, production, bg, tasksRun[0], notT1);
    };
  }

  /** Whether a program of {@code c} has a RUN statement (the cell uses a second task). */
  private static boolean runsATask(Controller c) {
    for (String name : c.programNames()) {
      Program p = c.program(name).orElse(null);
      if (p != null && p.lines().stream().anyMatch(l -> l instanceof org.robotrun.program.Instruction.Run)) {
        return true;
      }
    }
    return false;
  }

  /** The course the Labs menu lists: {@code --course}, else the shipped one when it is there (null: no Labs menu). */
  static Course course(Path given) {
    if (given != null) {
      try {
        return Course.read(given);
      } catch (Course.CourseException e) {
        throw new UserError("--course: " + e.getMessage());
      }
    }
    for (Path p : shipped("scenarios/labs/course.json")) {
      if (java.nio.file.Files.isRegularFile(p)) {
        try {
          return Course.read(p);
        } catch (Course.CourseException e) {
          System.err.println("robotrun: the Labs menu is off: " + e.getMessage());
          return null;
        }
      }
    }
    return null;
  }

  /**
   * Where a shipped file ({@code relative} to the project folder, e.g. scenarios/labs/course.json) may
   * be: beside the application, or in the current folder.
   */
  static List<Path> shipped(String relative) {
    List<Path> out = new java.util.ArrayList<>();
    try {
      Path jar = Path.of(GuiCommand.class.getProtectionDomain().getCodeSource().getLocation().toURI());
      Path dir = jar.getParent();
      for (int up = 0; dir != null && up < 3; up++, dir = dir.getParent()) {
        out.add(dir.resolve(relative));
      }
    } catch (java.net.URISyntaxException | RuntimeException e) {
      // no code source: the current folder only
    }
    out.add(Path.of(relative));
    return out;
  }

  /** The student's labs folder: ROBOTRUN_LABS_HOME, else ~/robotrun-labs. */
  static Path labsHome() {
    String env = System.getenv("ROBOTRUN_LABS_HOME");
    return (env != null && !env.isBlank() ? Path.of(env) : Path.of(System.getProperty("user.home"), "robotrun-labs"))
        .toAbsolutePath().normalize();
  }

  /** The lab whose workspace {@code dir} is: a folder of the labs folder named after a lab's id. */
  static java.util.Optional<Course.Lab> labOf(Course course, Path home, Path dir) {
    Path d = dir.toAbsolutePath().normalize();
    if (d.getParent() == null || !d.getParent().equals(home)) {
      return java.util.Optional.empty();
    }
    return course.lab(d.getFileName().toString());
  }

  /** The File menu of a workspace window, with the guard that keeps unsaved work from closing silently. */
  /** The pendant's prompt line at a refused edit in a read-only workspace (at most two LCD lines' worth). */
  static String readOnlyEditMessage(String reason) {
    String why = reason.replace(": opened read-only, nothing is saved", "");
    return "READ-ONLY (" + why + "): edits are refused. File > Save a copy as... gives a workspace you can edit";
  }

  private static FileMenu fileMenu(WindowCell ws, UserDirs dirs, SimulatorWindow w, Path[] switchTo) {
    FileDialogs dialogs = new FileDialogs();
    java.util.function.BooleanSupplier[] closeGuard = {() -> true};
    GuiFileActions actions = new GuiFileActions(dirs, () -> ws, dir -> {
      switchTo[0] = dir;
      w.requestClose();
    }, () -> {
      if (closeGuard[0].getAsBoolean()) {
        w.requestClose();
      }
    });
    FileMenu menu = new FileMenu(actions, dialogs);
    actions.setMenu(menu);
    menu.setStatusLine(() -> ws.drawSaveState(menu));
    boolean[] warned = {false};
    closeGuard[0] = () -> {
      // Work that cannot be saved keeps the window open once, with the reason; closing again quits.
      if (warned[0] || ws.session.workspace.readOnly()) {
        return true;
      }
      String problem = ws.session.autosave.saveNow(3000);
      if (problem.isEmpty()) {
        return true;
      }
      warned[0] = true;
      menu.tell("Your last changes are NOT saved: " + problem
          + "\n\nFix the problem (the window keeps trying), or close again to quit without them.");
      return false;
    };
    w.setCloseHandler(closeGuard[0]);
    return menu;
  }

  static java.util.Optional<CameraView> cameraView(org.robotrun.render.OrbitCamera camera) {
    if (camera == null) {
      return java.util.Optional.empty();
    }
    var t = camera.target();
    return java.util.Optional.of(new CameraView(new org.robotrun.math.Vec3(t.x, t.y, t.z), camera.distance(),
        camera.yaw(), camera.pitch()));
  }

  /** Runs the window until it is closed, then saves its layout. */
  public static void run(Session s) {
    run(s, null);
  }

  /**
   * Runs the window until it is closed, then saves its layout; with {@code simCpuNanos}, adds to it
   * the CPU time the window's thread spends stepping the simulation ({@code bench window}).
   */
  static void run(Session s, java.util.concurrent.atomic.AtomicLong simCpuNanos) {
    var cpuClock = simCpuNanos == null ? null : ManagementFactory.getThreadMXBean();
    double[] last = {0};
    long[] appliedRevision = {s.editor() == null ? 0 : s.editor().revision()};
    double[][] prevQ = {allJoints(s.sim())};
    int[] prevLcd = {0};
    boolean[] dirty = {false};
    long[] lastSave = {System.nanoTime()};
    s.bench().setLayoutChangeHandler(() -> dirty[0] = true);
    // Idle, the window sleeps until something needs a frame: a message expiring, the autosave's
    // next look after a change, the layout's save; a finished background save wakes it too.
    if (s.workspace() != null) {
      s.workspace().session.autosave.setAfterWrite(org.robotrun.ui.SimulatorWindow::wakeFromAnyThread);
    }
    s.window().setWakeSource(() -> {
      long next = s.bench().nextRedrawNanos();
      if (s.workspace() != null) {
        next = Math.min(next, s.workspace().session.autosave.nextPollNanos(s.window().lastActiveFrameNanos()));
      }
      if (dirty[0]) {
        next = Math.min(next, lastSave[0] + 1_000_000_001L);
      }
      return next;
    });
    s.window().run(t -> {
          // Real time drives the simulation (a stalled frame never makes it jump more than 0.1 s);
          // then the pendant in hand catches up with its controller.
          long cpu0 = cpuClock == null ? 0 : cpuClock.getCurrentThreadCpuTime();
          s.stepper().advanceRealTime(t - last[0]);
          s.robots().get().follow();
          if (cpuClock != null) {
            simCpuNanos.addAndGet(cpuClock.getCurrentThreadCpuTime() - cpu0);
          }
          last[0] = t;
          if (s.workspace() != null) {
            s.workspace().session.autosave.poll(System.nanoTime());
          }
          if (s.editor() != null && s.editor().revision() != appliedRevision[0]) {
            appliedRevision[0] = s.editor().revision();
            if (s.workspace() != null && ScenarioSwitch.wanted(s.workspace().session, s.editor())) {
              s.workspace().switchScenario(s.editor(), cameraView(s.window().camera()));
            } else {
              s.sim().replaceWorld(s.editor().world());
            }
          }
          if (dirty[0] && System.nanoTime() - lastSave[0] > 1_000_000_000L) {
            dirty[0] = false;
            lastSave[0] = System.nanoTime();
            warn(s.settings().save(s.bench().layoutState()));
          }
          // the one snapshot of this frame: the 3D view and the camera views draw it
          org.robotrun.sim.SceneSnapshot scene = s.sim().snapshot().scene();
          s.frameScene().set(scene);
          return s.bench().marked(scene);
        },
        s.bench(),
        () -> {
          // busy while the arm moves, a program runs, a jog key is on or the pendant's text changes
          // (any robot of the cell: the one not selected may be running)
          double[] q = allJoints(s.sim());
          boolean moved = !java.util.Arrays.equals(q, prevQ[0]);
          prevQ[0] = q;
          // the selected robot's LCD as drawn last frame: building the screen once more per frame
          // cost as much as drawing it
          int lcd = s.bench().pendantPanel().drawnLcdHash();
          boolean lcdChanged = lcd != prevLcd[0];
          prevLcd[0] = lcd;
          boolean jog = false;
          boolean running = false;
          for (Controller c : s.sim().controllers()) {
            for (int a = 1; a <= 6; a++) {
              jog |= c.jogDirection(a) != 0;
            }
            running |= c.interpreter().state() == Interpreter.State.RUNNING;
          }
          return moved || lcdChanged || jog || running;
        });
    warn(s.settings().save(s.bench().layoutState()));
  }

  /** Every robot's joints, one after the other. */
  private static double[] allJoints(Simulation sim) {
    double[] out = new double[0];
    for (Controller c : sim.controllers()) {
      double[] q = c.jointsRad();
      double[] both = java.util.Arrays.copyOf(out, out.length + q.length);
      System.arraycopy(q, 0, both, out.length, q.length);
      out = both;
    }
    return out;
  }

  private static void stage(String what) {
    long jvmStart = ManagementFactory.getRuntimeMXBean().getStartTime();
    System.err.println("robotrun: " + what + " " + (System.currentTimeMillis() - jvmStart) + " ms after the JVM started");
  }

  /**
   * Benchmark hook (ROBOTRUN_FRAME_LOG set): the time from JVM start to the first frame on screen,
   * then the frames drawn in every 5 s, on stderr.
   */
  private static void logFrames(SimulatorWindow w) {
    long jvmStart = ManagementFactory.getRuntimeMXBean().getStartTime();
    w.setFirstFrameHandler(() -> System.err.println("robotrun: first frame "
        + (System.currentTimeMillis() - jvmStart) + " ms after the JVM started"));
    long[] since = {System.nanoTime(), 0};
    long[][] phases = {w.phaseNanos()};
    var threads = ManagementFactory.getThreadMXBean();
    var os = ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean o ? o : null;
    long[] cpu = {threads.getCurrentThreadCpuTime(), os == null ? 0 : os.getProcessCpuTime()};
    w.setAfterFrameHandler(() -> {
      long now = System.nanoTime();
      if (now - since[0] >= 5_000_000_000L) {
        long n = w.frames() - since[1];
        StringBuilder per = new StringBuilder();
        long[] p = w.phaseNanos();
        for (int i = 0; i < p.length; i++) {
          per.append(String.format(java.util.Locale.ROOT, " %s %.2f", SimulatorWindow.PHASES.get(i),
              n == 0 ? 0 : (p[i] - phases[0][i]) / 1e6 / n));
        }
        long c = threads.getCurrentThreadCpuTime();
        long pc = os == null ? 0 : os.getProcessCpuTime();
        System.err.printf(java.util.Locale.ROOT, "robotrun: %d frames in %.1f s (%.1f frames/s); ms per frame:%s;"
            + " CPU per frame: window thread %.2f ms, process %.2f ms%n", n, (now - since[0]) / 1e9,
            n / ((now - since[0]) / 1e9), per, n == 0 ? 0 : (c - cpu[0]) / 1e6 / n, n == 0 ? 0 : (pc - cpu[1]) / 1e6 / n);
        since[0] = now;
        since[1] = w.frames();
        phases[0] = p;
        cpu[0] = c;
        cpu[1] = pc;
      }
    });
  }

  private static void warn(String problem) {
    if (!problem.isEmpty()) {
      System.err.println("robotrun: " + TerminalText.safe(problem));
    }
  }

  private static TriangleMesh loadStl(Path file, double scale) {
    try {
      return StlReader.read(file, scale);
    } catch (IOException | org.robotrun.io.FileFormatException e) {
      throw new IllegalArgumentException(e.getMessage(), e);
    }
  }

  static String stem(Path p) {
    String f = p.getFileName().toString();
    String lower = f.toLowerCase(java.util.Locale.ROOT);
    return lower.endsWith(".json") ? f.substring(0, f.length() - 5)
        : lower.endsWith(Main.CELL_EXTENSION) ? f.substring(0, f.length() - Main.CELL_EXTENSION.length()) : f;
  }
}
