package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.robotrun.control.RobotControl;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.LsWriter;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.TerminalText;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.program.Program;
import org.robotrun.sim.CellStepper;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.world.Scenario;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code robotrun pendant}: drives the teach pendant from a .keys script and prints its LCD. */
@Command(
    name = "pendant",
    mixinStandardHelpOptions = true,
    description = {
      "Run a .keys script on the teach pendant and print the LCD as text at every SHOW.",
      "Script lines: a key (ENTER, F1, SHIFT+FWD, +X/J1, DOWN *3), TYPE text, HOLD key, RELEASE key (HOLD DEADMAN, HOLD SHIFT), TP ON|OFF, MODE T1|T2|AUTO, ESTOP [PANEL], RELEASE ESTOP, CYCLE START, ROBOT n|name, WAIT seconds (simulated), SHOW, and # comments. See docs/pendant.md.",
      "The script starts like a student picking up the pendant of a cold-started controller: TP ON, DEADMAN released, mode T1, override 10%% (--mode and --override change the start). Jogging and SHIFT+FWD need TP ON, DEADMAN and SHIFT held; in T1/T2 a program runs only while SHIFT and DEADMAN are held.",
      "The pendant drives the simulation's controller: the scenario's first robot, or without --scenario the default cell (default robot at HOME, UTOOL 1 a 100 mm pointer, UFRAME 1 = WORLD). In a cell of several robots each has its own controller and pendant (the status line starts with its name); ROBOT 2 or ROBOT name switches to another; --program and --save concern the first robot's programs; --mode and --override set every robot's start.",
      "With --workspace DIR the workspace is opened (or created) first and everything the script changes is saved back to it when the script ends (and at each SHOW); a second RobotRun on the same workspace opens it read-only. Opening it is a cold start too (T1, 10%%).",
      "Exit codes: 0 script ran (pendant errors show on its prompt line), 1 --save or the workspace could not be written "
          + "(a --workspace that cannot be saved to: held by another RobotRun for more than 10 s, read-only, a hand-in "
          + "zip or unpacked folder: the script is not run), 2 bad option, unreadable program or malformed script (file:line)."
    })
public final class PendantCommand implements Callable<Integer> {
  /** The override a cold start sets ($SCR.$COLDOVRD on a controller): 10%. */
  static final int COLD_START_OVERRIDE_PCT = 10;

  @Option(names = "--keys", required = true, paramLabel = "FILE.keys", description = "The key script to run.")
  Path keys;

  @Option(names = "--program", paramLabel = "FILE.LS",
      description = "A TP program (.LS) to load before the script runs; repeat for more. A file with errors is exit 2.")
  List<Path> programs = new java.util.ArrayList<>();

  @Option(names = "--mode", paramLabel = "T1|T2|AUTO",
      description = "The operator panel's mode switch at the start (default: the scenario's \"mode\", else T1).")
  String mode;

  @Option(names = "--override", paramLabel = "PCT", defaultValue = "10",
      description = "Speed override at the start, 1..100 (default: ${DEFAULT-VALUE}, the controller's cold start, $SCR.$COLDOVRD).")
  int overridePct;

  @Option(names = "--trace", paramLabel = "FILE.csv",
      description = "Write one CSV row per simulation tick (the same columns as run --trace; docs/run-report.md).")
  Path trace;

  @Option(names = "--save", paramLabel = "DIR",
      description = "After the script, write every program to DIR/NAME.LS (the directory must exist).")
  Path saveDir;

  @Option(names = "--scenario", paramLabel = "FILE",
      description = "Scenario JSON to load first (its cell, frames, registers and programs; docs/scenario-format.md); "
          + "the script starts on its first robot's pendant (ROBOT 2 switches; docs/pendant.md). Default: the default cell.")
  Path scenario;

  @Option(names = "--workspace", paramLabel = "DIR",
      description = "A workspace folder to open (or create) first: its cell, saved state and programs; "
          + "what the script changes is saved back to it as the window saves it (docs/workspace.md).")
  Path workspace;

  @Option(names = "--max-wall-seconds", paramLabel = "N", defaultValue = "3600",
      description = "Stop with exit code 1 when the script has run this long in real (wall-clock) time, 1.."
          + "86400 (default: ${DEFAULT-VALUE}). A safety net for graders; results are otherwise deterministic.")
  double maxWallSeconds;

  @Spec
  CommandSpec spec;

  @Override
  public Integer call() {
    if (saveDir != null && !Files.isDirectory(saveDir)) {
      throw new UserError("--save: the directory " + saveDir + " does not exist");
    }
    WallClock.checkOption(maxWallSeconds);
    List<String> lines = InputFiles.lines("--keys", keys, KeyScript.MAX_FILE_BYTES, "key scripts");
    KeyScript script = switch (KeyScript.parse(keys.toString(), lines)) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new UserError(bad.error().display());
    };
    RobotControl.Mode startMode = RobotControl.Mode.T1;
    if (mode != null) {
      try {
        startMode = RobotControl.Mode.valueOf(mode.toUpperCase(java.util.Locale.ROOT));
      } catch (IllegalArgumentException e) {
        throw new UserError("--mode: expected T1, T2 or AUTO, got '" + mode + "'");
      }
    }
    if (overridePct < 1 || overridePct > 100) {
      throw new UserError("--override: expected 1..100, got " + overridePct);
    }
    if (trace != null) {
      try {
        org.robotrun.io.AtomicFiles.checkWritable(trace);
      } catch (IOException e) {
        throw new UserError("--trace: " + e.getMessage());
      }
    }
    List<Path> programFiles = new java.util.ArrayList<>();
    WorkspaceSession session = null;
    if (workspace != null && scenario != null) {
      throw new UserError("--workspace: give it alone (a workspace has its own cell)");
    }
    Simulation sim;
    Scenario cell = null;
    if (workspace != null) {
      session = openForWriting(workspace);
      if (!session.problems().isEmpty()) {
        System.err.println("robotrun: " + session.problems());
      }
      sim = session.sim;
    } else if (scenario != null) {
      Scenario sc = ScenarioFiles.load(scenario);
      try {
        sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
      } catch (FileFormatException | IllegalArgumentException e) {
        throw new UserError(scenario + ": " + e.getMessage());
      }
      programFiles.addAll(sc.preload(0).programs());
      cell = sc;
    } else {
      sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
    }
    // One pendant per robot, each like a cold-started controller's; the script starts on the first (ROBOT switches).
    List<String> robotNames = sim.controllers().stream().map(org.robotrun.sim.Controller::name).toList();
    List<ControllerPort> controls = new java.util.ArrayList<>();
    List<Pendant> pendants = new java.util.ArrayList<>();
    for (org.robotrun.sim.Controller c : sim.controllers()) {
      ControllerPort rc = new ControllerPort(c);
      int k = controls.size();
      // --mode for every robot; else each robot's own mode switch (the scenario's, or T1)
      java.util.Optional<String> own = mode != null || cell == null || k >= cell.robots().size()
          ? java.util.Optional.empty() : cell.preload(k).mode();
      rc.setMode(own.map(RobotControl.Mode::valueOf).orElse(startMode));
      rc.setOverridePct(overridePct);
      controls.add(rc);
      Pendant p = new Pendant(rc, new LsLineParser());
      if (robotNames.size() > 1) {
        p.setRobotLabel(c.name());
      }
      pendants.add(p);
    }
    ControllerPort control = controls.get(0);
    programFiles.addAll(programs);
    for (Path file : programFiles) {
      control.saveProgram(readProgram(file));
    }
    for (int i = 1; cell != null && i < cell.robots().size(); i++) {
      for (Path file : cell.robots().get(i).programs()) {
        controls.get(i).saveProgram(readProgram(file));
      }
    }
    script.unknownRobot(keys.toString(), robotNames).ifPresent(m -> {
      throw new UserError(m.display());
    });
    script.inputOutOfRange(keys.toString(), robotNames, pendants).ifPresent(m -> {
      throw new UserError(m.display());
    });
    PrintWriter out = spec.commandLine().getOut();
    WallClock clock = WallClock.start(maxWallSeconds);
    WorkspaceSession ws = session;
    java.util.function.Consumer<String> show = text -> {
      out.print(TerminalText.safe(text));
      if (ws != null) {
        ws.autosave.poll(System.nanoTime());
      }
    };
    int[] stopped = {0};
    CellStepper stepper = new CellStepper(sim);
    if (trace == null) {
      stopped[0] = script.run(pendants, robotNames, stepper::advance, show, clock::expired);
    } else {
      try {
        org.robotrun.io.AtomicFiles.write(trace, stream -> {
          java.io.Writer w = new java.io.BufferedWriter(new java.io.OutputStreamWriter(stream, StandardCharsets.UTF_8));
          org.robotrun.sim.TraceWriter tw = new org.robotrun.sim.TraceWriter(w, sim.controllers());
          tw.write(sim);
          stepper.setAfterTick(tw::write);
          stopped[0] = script.run(pendants, robotNames, stepper::advance, show, clock::expired);
          w.flush();
        });
      } catch (IOException | java.io.UncheckedIOException e) {
        // as run says it: a full disk while tracing is one line, never an internal error
        Throwable t = e instanceof java.io.UncheckedIOException u ? u.getCause() : e;
        String why = t.getMessage() == null ? t.getClass().getSimpleName() : t.getMessage();
        throw new UserError("--trace: could not write " + trace + " (" + why + "); the old file, if any, is unchanged",
            Main.EXIT_FAILED);
      }
    }
    int stoppedAt = stopped[0];
    out.flush();
    if (session != null) {
      String problem = session.autosave.saveNow(10_000);
      session.close();
      if (!problem.isEmpty() && !session.workspace.readOnly()) {
        throw new UserError("--workspace: " + problem, Main.EXIT_FAILED);
      }
    }
    if (stoppedAt > 0) {
      throw new UserError(keys + ":" + stoppedAt + ": stopped: the script ran longer than --max-wall-seconds "
          + WallClock.format(maxWallSeconds) + " s of real time", Main.EXIT_FAILED);
    }
    if (saveDir != null) {
      for (String name : control.programNames()) {
        Path file = saveDir.resolve(name + ".LS");
        try {
          LsWriter.write(control.program(name).orElseThrow(), file);
        } catch (IOException e) {
          throw new UserError("--save: cannot write " + file + " (" + e.getMessage() + ")", Main.EXIT_FAILED);
        }
      }
    }
    return Main.EXIT_OK;
  }

  /** How long a script waits for another RobotRun to let go of the workspace. */
  static volatile double lockWaitSeconds = 10;

  /**
   * Opens the workspace for the script, which must be able to save what it does: while another
   * RobotRun holds it, waits up to {@link #lockWaitSeconds} for it; when it still cannot be
   * written (held, a read-only folder or disk, a lock file that is not a file, a hand-in zip),
   * fails before the script runs, exit 1, saying why. A script whose result cannot be saved is
   * never run.
   */
  private static WorkspaceSession openForWriting(Path workspace) {
    long deadline = System.nanoTime() + (long) (lockWaitSeconds * 1e9);
    boolean said = false;
    while (true) {
      WorkspaceSession s = WorkspaceSession.open(workspace, false, java.util.Optional::empty,
          m -> System.err.println("robotrun: " + m));
      Path progs = s.workspace.folder().resolve(org.robotrun.io.Workspace.PROGRAMS);
      if (!s.workspace.readOnly() && Files.exists(progs, java.nio.file.LinkOption.NOFOLLOW_LINKS)
          && !Files.isDirectory(progs, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
        // programs/ that is a file, a link or a FIFO: no program could be saved (issue 26)
        s.close();
        throw new UserError("--workspace: " + progs + " is not a folder (a workspace keeps its programs in "
            + "programs/); the script was not run, since nothing it did could be saved", Main.EXIT_FAILED);
      }
      if (!s.workspace.readOnly() && s.workspace.cellBlocked()) {
        // cell.json unreadable: the script would run on the default cell, not the workspace's
        // (issue 26); the window may show the default cell, a script must not act on it.
        Path cellFile = s.workspace.folder().resolve(org.robotrun.io.Workspace.CELL);
        String problem = s.workspace.problems().isEmpty() ? "" : s.workspace.problems().get(0).lines().findFirst().orElse("") + "\n";
        s.close();
        throw new UserError(problem + "--workspace: " + cellFile + " cannot be read; the script was not run, "
            + "since it would act on the default cell instead of the workspace's. Fix the file (or move it away) "
            + "and run again", Main.EXIT_FAILED);
      }
      if (!s.workspace.readOnly()) {
        return s;
      }
      String why = s.workspace.readOnlyReason();
      boolean busy = s.workspace.lockBusy();
      s.close();
      if (busy && System.nanoTime() < deadline) {
        if (!said) {
          System.err.println("robotrun: " + workspace + ": another RobotRun has this workspace open; waiting up to "
              + WallClock.format(lockWaitSeconds) + " s for it");
          said = true;
        }
        try {
          Thread.sleep(200);
        } catch (InterruptedException e) {
          Thread.currentThread().interrupt();
          throw new UserError("--workspace: interrupted while waiting for " + workspace, Main.EXIT_FAILED);
        }
        continue;
      }
      throw new UserError("--workspace: " + workspace + ": " + why.replace(": opened read-only, nothing is saved", "")
          + "; the script was not run, since nothing it did could be saved", Main.EXIT_FAILED);
    }
  }

  private static Program readProgram(Path file) {
    LsReadResult r;
    try {
      r = LsReader.read(file);
    } catch (java.nio.file.NoSuchFileException e) {
      throw new UserError("--program: no such file " + file);
    } catch (IOException e) {
      throw new UserError("--program: cannot read " + file + " (" + e.getMessage() + ")");
    }
    if (r.hasErrors() || r.program() == null) {
      String first = r.diagnostics().stream().filter(Diagnostic::blocksLoading).findFirst().map(Diagnostic::toString)
          .orElse(file + ": not a program");
      throw new UserError("--program: " + first);
    }
    return r.program();
  }
}
