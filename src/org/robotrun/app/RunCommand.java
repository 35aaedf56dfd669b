package org.robotrun.app;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.function.Consumer;
import java.util.stream.Stream;
import org.robotrun.io.AtomicFiles;
import org.robotrun.io.BoundedFiles;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.UnreadableFileException;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.ScenarioReader;
import org.robotrun.world.Scenario;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.TerminalText;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.HeadlessRun;
import org.robotrun.sim.ProductionRun;
import org.robotrun.world.ProductionSetup;
import org.robotrun.sim.Simulation;
import org.robotrun.sim.TraceWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun run}: executes a program headless and reports how it ended. */
@Command(
    name = "run",
    mixinStandardHelpOptions = true,
    description = {
      "Run a TP program with no window, as fast as the machine allows, in 4 ms simulation ticks.",
      "The controller runs as in AUTO mode (operator panel start, no T1 speed cap, no hold-to-run) at --override.",
      "With --scenario the cell, frames, registers and programs come from the scenario (its programs are loaded "
          + "before --programs; --program defaults to its main program); the program runs on the first robot.",
      "A cell of several robots runs every robot's main program at once (the first robot's is --program), all robots "
          + "in one 4 ms tick; wired outputs reach their inputs the next tick; the run ends when all have ended or at "
          + "the first alarm on any robot. The report has one entry per robot and the cell's cycle time.",
      "A scenario whose production setup has \"runStartsFromPlc\" is started by its PLC sequence through the UOP "
          + "signals instead (docs/production.md): robot 1 runs what its PLC starts; the run ends when the sequence is "
          + "done and no program runs.",
      "With --workspace DIR|FILE.zip they come from a workspace or a hand-in (docs/workspace.md), as the window would run them.",
      "Without --scenario the default cell is used: the default robot at HOME (J5 = -90 deg), UTOOL[1] a 100 mm "
          + "pointer along the flange z axis, UFRAME[1] = WORLD, both active; RO[1] closes the gripper and RI[1] "
          + "reports it closed 0.1 s later.",
      "Collisions (robot links and tool against the floor, fixtures, parts, other robots and the arm itself) are "
          + "checked every tick; a new contact is alarm SRVO-050 (a scenario may ask for warnings instead).",
      "Exit codes: 0 the program (every robot's) reached its end, 1 an alarm stopped one (or the time limit passed), 2 bad input.",
      "The JSON report is described in docs/run-report.md; the trace has one CSV row per tick (time, joints, TCP)."
    })
public final class RunCommand implements Callable<Integer> {
  @Option(names = "--scenario", paramLabel = "FILE",
      description = "Scenario JSON (robots, world, frames, registers, programs; docs/scenario-format.md). Default: the default cell.")
  Path scenario;

  @Option(names = "--workspace", paramLabel = "DIR|FILE.zip",
      description = "A workspace folder or a hand-in zip: its cell, saved state (registers, frames, outputs) and programs, "
          + "run as the window would; --program defaults to its main program. The workspace is not changed.")
  Path workspace;

  @Option(names = "--program", paramLabel = "NAME",
      description = "The program to run (its /PROG name). Default: the scenario's or workspace's main program.")
  String program;

  @Option(names = "--programs", arity = "1..*", paramLabel = "DIR|FILE.ls",
      description = "Program files to load: .LS files, or directories whose .LS files are all loaded.")
  List<Path> programs = new ArrayList<>();

  @Option(names = "--override", defaultValue = "100", paramLabel = "PCT",
      description = "Speed override in percent, 1..100 (default: ${DEFAULT-VALUE}).")
  int overridePct;

  @Option(names = "--max-sim-seconds", defaultValue = "600", paramLabel = "N",
      description = "Stop with exit code 1 after this much simulated time, more than 0 and at most 86400 "
          + "(default: ${DEFAULT-VALUE}).")
  double maxSimSeconds;

  @Option(names = "--max-wall-seconds", defaultValue = "3600", paramLabel = "N",
      description = "Stop with exit code 1 (alarm RUN-002) when the run has taken this long in real (wall-clock) time, "
          + "1..86400 (default: ${DEFAULT-VALUE}). A safety net for graders; it never changes what a finished run reports.")
  double maxWallSeconds;

  /** Largest --max-sim-seconds: a day of simulated time (21.6 million ticks). */
  static final double MAX_SIM_SECONDS = 86_400;

  @Option(names = "--seed", paramLabel = "N",
      description = "Seed of the scenario's random part placement and vision noise (docs/vision.md). Default: the "
          + "scenario's vision.seed. Same seed, same placement and vision results.")
  Long seed;

  @Option(names = "--report", paramLabel = "out.json", description = "Write the JSON report here.")
  Path report;

  @Option(names = "--trace", paramLabel = "out.csv", description = "Write one CSV row per tick here.")
  Path trace;

  /**
   * --seed, the one place it is handled: the cell's parts placed and its vision noise drawn from
   * the seed instead of the cell's {@code vision.seed}; a warning names {@code cellName} when the
   * cell has no vision section.
   */
  private void reseed(Simulation sim, String cellName) {
    if (sim.vision().isEmpty()) {
      System.err.println("robotrun: warning: --seed: " + cellName + " has no vision section: the seed changes nothing");
      return;
    }
    org.robotrun.sim.VisionSystem.reseed(sim, sim.vision().get().setup(), seed);
  }

  @Override
  public Integer call() throws IOException {
    try {
      return runCommand();
    } finally {
      if (openSession != null) {
        openSession.close();  // the hand-in's temporary copy goes, whatever happened
      }
    }
  }

  /** The workspace this run opened, closed by {@link #call} whatever happens. */
  private WorkspaceSession openSession;

  private Integer runCommand() throws IOException {
    if (seed != null && !org.robotrun.io.VisionJson.isValidSeed(seed)) {
      throw new UserError("--seed: expected " + org.robotrun.io.VisionJson.SEED_RANGE + " (as vision.seed), got " + seed);
    }
    if (overridePct < 1 || overridePct > 100) {
      throw new UserError("--override: expected 1..100, got " + overridePct);
    }
    if (!(maxSimSeconds > 0 && maxSimSeconds <= MAX_SIM_SECONDS)) {
      throw new UserError("--max-sim-seconds: expected more than 0 and at most " + (long) MAX_SIM_SECONDS
          + " seconds, got " + WallClock.format(maxSimSeconds));
    }
    WallClock.checkOption(maxWallSeconds);
    // Every output is checked before the simulation, so a bad path never costs a long run.
    checkOutput("--report", report);
    checkOutput("--trace", trace);
    if (report != null && trace != null && report.toAbsolutePath().normalize().equals(trace.toAbsolutePath().normalize())) {
      throw new UserError("--report and --trace name the same file " + report);
    }
    Simulation sim;
    String cellName;
    Scenario cell = null;
    // a production setup may say the run starts from its PLC sequence (docs/production.md)
    java.util.Optional<ProductionSetup.Robot> plcStart = java.util.Optional.empty();
    List<Path> programFiles = new ArrayList<>();
    List<Program> fromWorkspace = new ArrayList<>();
    WorkspaceSession session = null;
    if (workspace != null) {
      if (scenario != null) {
        throw new UserError("--workspace and --scenario: give one of them (a workspace has its own cell)");
      }
      session = WorkspaceSession.open(workspace, true, java.util.Optional::empty, m -> {});
      openSession = session;
      if (session.workspace.cellBlocked()) {
        String why = session.problems();
        session.close();
        throw new UserError(why);
      }
      if (!session.workspace.problems().isEmpty()) {
        System.err.println("robotrun: warning: " + session.problems());
      }
      sim = session.sim;
      cellName = "the workspace's cell";
      fromWorkspace.addAll(session.workspace.programs());
      Scenario wsCell = session.workspace.scenario();
      plcStart = wsCell.production().of(wsCell.robots().get(0).name()).filter(ProductionSetup.Robot::startFromPlc);
      if (program == null && plcStart.isEmpty()) {
        String ws = workspace.toString();
        program = wsCell.preload(0).mainProgram().orElse(null);
        if (program == null && wsCell.robots().stream().allMatch(r -> r.mainProgram().isEmpty())) {
          throw new UserError("--program: name the program to run (the workspace " + ws + " names no main program)");
        }
      }
      cell = wsCell;
    } else if (scenario != null) {
      org.robotrun.io.CellLoad.Loaded load = switch (ScenarioReader.readWithState(scenario)) {
        case org.robotrun.io.CellLoad.Loaded l -> l;
        case org.robotrun.io.CellLoad.Failed f -> throw new UserError(f.message());
      };
      Scenario sc = load.scenario();
      cellName = scenario.toString();
      try {
        sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
      } catch (FileFormatException | IllegalArgumentException e) {
        throw new UserError(scenario + ": " + e.getMessage());
      }
      // A saved controller state ("state", as a workspace keeps it) goes into every robot it names.
      load.state().ifPresent(st -> st.applyToCell(sim.controllers()));
      programFiles.addAll(sc.preload(0).programs());
      cell = sc;
      plcStart = sc.production().of(sc.robots().get(0).name()).filter(ProductionSetup.Robot::startFromPlc);
      if (program == null && plcStart.isEmpty()) {
        program = sc.preload(0).mainProgram().orElse(null);
        if (program == null && sc.robots().stream().allMatch(r -> r.mainProgram().isEmpty())) {
          throw new UserError("--program: name the program to run (the scenario " + scenario + " names no main program)");
        }
      }
    } else {
      sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
      cellName = "the default cell";
      if (program == null) {
        throw new UserError("--program: name the program to run (required without --scenario)");
      }
    }
    if (seed != null) {
      reseed(sim, cellName);
    }
    if (plcStart.isPresent() && program != null) {
      System.err.println("robotrun: warning: --program " + TerminalText.safe(program) + " is not used: the cell starts "
          + "from its PLC sequence (runStartsFromPlc, docs/production.md), which selects the program");
    }
    programFiles.addAll(programs);
    List<Program> loaded = new ArrayList<>(fromWorkspace);
    loaded.addAll(loadPrograms(programFiles));
    Controller c = sim.controllers().get(0);
    // Robot 1: --program or the main program; the others: their own main programs (docs/run-report.md).
    java.util.Map<Controller, String> toRun = new java.util.LinkedHashMap<>();
    if (program != null) {
      // Program names are upper case on the controller; accept 'pick3' for PICK3.
      String wanted = program;
      program = loaded.stream().map(Program::name).filter(n -> n.equalsIgnoreCase(wanted)).findFirst()
          .orElseThrow(() -> new UserError("--program: no program named " + wanted + " among the loaded files"
              + (loaded.isEmpty() ? " (give them with --programs)" : " (loaded: "
                  + String.join(", ", loaded.stream().map(Program::name).toList()) + ")")));
      toRun.put(c, program);
    }
    loaded.forEach(c::saveProgram);
    c.setOverridePct(overridePct);
    for (int i = 1; cell != null && i < cell.robots().size(); i++) {
      var setup = cell.robots().get(i);
      Controller other = sim.controllers().get(i);
      if (workspace == null) {
        loadPrograms(setup.programs()).forEach(other::saveProgram);
      }
      other.setOverridePct(overridePct);
      if (setup.mainProgram().isPresent()) {
        String main = setup.mainProgram().get();
        if (other.program(main).isEmpty()) {
          throw new UserError(setup.name() + ": main program " + main + " is not among its programs (loaded: "
              + String.join(", ", other.programNames()) + ")");
        }
        toRun.put(other, main);
      }
    }
    java.util.Optional<ProductionSetup.Robot> fromPlc = plcStart;
    if (fromPlc.isPresent()) {
      List<String> bad = ProductionRun.check(c.name(), fromPlc.get(), c);
      if (!bad.isEmpty()) {
        throw new UserError(scenario + ": " + String.join("; ", bad));
      }
    }

    WallClock clock = WallClock.start(maxWallSeconds);
    String wallReason = "stopped after --max-wall-seconds " + WallClock.format(maxWallSeconds) + " s of real time";
    HeadlessRun.CellResult[] result = new HeadlessRun.CellResult[1];
    try {
      if (trace != null) {
        // Streamed to a temporary file beside the old trace and renamed at the end: a killed run
        // leaves the old trace whole, never a truncated or partial one.
        writeOutput("--trace", trace, out -> {
          Writer w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
          TraceWriter tw = new TraceWriter(w, sim.controllers());
          tw.write(sim);
          result[0] = fromPlc.isPresent() ? ProductionRun.run(sim, c, maxSimSeconds, tw::write, clock::expired, wallReason)
              : HeadlessRun.runCell(sim, toRun, maxSimSeconds, tw::write, clock::expired, wallReason);
          w.flush();
        });
      } else {
        Consumer<Simulation> none = s -> {};
        result[0] = fromPlc.isPresent() ? ProductionRun.run(sim, c, maxSimSeconds, none, clock::expired, wallReason)
            : HeadlessRun.runCell(sim, toRun, maxSimSeconds, none, clock::expired, wallReason);
      }
    } catch (IllegalArgumentException e) {
      throw new UserError(e.getMessage());
    }
    HeadlessRun.CellResult r = result[0];
    if (report != null) {
      writeOutput("--report", report, out -> out.write(RunReport.bytes(r, sim)));
    }
    List<String> lines = new ArrayList<>();
    for (HeadlessRun.RobotResult rr : r.robots()) {
      String who = r.robots().size() > 1 ? rr.robot() + ": " : "";
      lines.add(who + switch (rr.status()) {
        case FINISHED -> String.format(Locale.ROOT, "finished %s in %.3f s of simulated time", rr.program(), rr.cycleTimeSec());
        case ALARM -> "alarm " + rr.alarm().orElseThrow().display();
        case STOPPED -> String.format(Locale.ROOT, "stopped in %s at %.3f s (another robot's alarm ended the run)",
            rr.program(), rr.cycleTimeSec());
      });
    }
    if (r.robots().size() > 1) {
      lines.add(String.format(Locale.ROOT, "cell cycle time %.3f s", r.cycleTimeSec()));
    }
    // WARN alarms (a refused RUN or PLC start): the programs went on, but the user must see them
    for (org.robotrun.sim.Controller rc : sim.controllers()) {
      String who = sim.controllers().size() > 1 ? rc.name() + ": " : "";
      rc.warnings().stream().limit(20).forEach(a -> lines.add(who + "warning " + a.display()));
      if (rc.warnings().size() > 20) {
        lines.add(who + "... " + (rc.warnings().size() - 20) + " more warnings (see --report)");
      }
    }
    lines.forEach(l -> System.out.println(TerminalText.safe(l)));
    if (session != null) {
      session.close();
    }
    return r.status() == HeadlessRun.Status.FINISHED ? Main.EXIT_OK : Main.EXIT_FAILED;
  }

  /** Refuses an output path that could not be written (missing folder, folder, device, no permission). */
  private static void checkOutput(String option, Path file) {
    if (file == null) {
      return;
    }
    try {
      AtomicFiles.checkWritable(file);
    } catch (IOException e) {
      throw new UserError(option + ": cannot write " + e.getMessage());
    }
  }

  /** Writes an output through {@link AtomicFiles}; a failure (full disk) is one clear message, exit 2. */
  private static void writeOutput(String option, Path file, AtomicFiles.Content content) {
    try {
      try {
        AtomicFiles.write(file, content);
      } catch (java.io.UncheckedIOException e) {
        throw e.getCause();
      }
    } catch (IOException e) {
      String why = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
      throw new UserError(option + ": could not write " + file + " (" + why + "); the old file, if any, is unchanged");
    }
  }

  /**
   * Reads every .LS file named or found in the named directories. A syntax error is bad input (a
   * controller refuses such a file too), and so is a program name defined by two files (which
   * one would run is not the user's choice). Other errors (a missing CALL target or label, an
   * unsupported statement) load, as on the controller: the line alarms when it runs.
   */
  static List<Program> loadPrograms(List<Path> paths) throws IOException {
    List<Path> files = new ArrayList<>();
    for (Path p : paths) {
      if (Files.isDirectory(p)) {
        int before = files.size();
        try (Stream<Path> s = Files.list(p)) {
          s.filter(f -> f.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".ls"))
              .filter(Files::isRegularFile)
              .sorted()
              .forEach(files::add);
        }
        if (files.size() == before) {
          throw new UserError("--programs: the directory " + p + " holds no .LS files");
        }
      } else if (Files.isRegularFile(p)) {
        files.add(p);
      } else {
        try {
          BoundedFiles.requireRegularFile(p);
        } catch (UnreadableFileException e) {
          throw new UserError("--programs: cannot read " + p + ": " + e.getMessage());
        }
        files.add(p);
      }
    }
    List<Program> out = new ArrayList<>();
    List<String> errors = new ArrayList<>();
    Map<String, Path> definedIn = new HashMap<>();
    Set<Path> seen = new HashSet<>();
    for (Path f : files) {
      LsReadResult r;
      try {
        if (!seen.add(f.toRealPath())) {
          continue;  // the same file named twice (a file and its directory, say)
        }
        r = LsReader.read(f);
      } catch (IOException e) {
        String why = e instanceof UnreadableFileException ? e.getMessage()
            : e instanceof java.nio.file.AccessDeniedException ? "permission denied" : e.getMessage();
        errors.add(f + ": cannot read: " + why);
        continue;
      }
      r.diagnostics().stream().filter(Diagnostic::blocksLoading).map(Diagnostic::toString).forEach(errors::add);
      if (!r.hasErrors()) {
        Path first = definedIn.putIfAbsent(r.program().name(), f);
        if (first != null) {
          errors.add(f + ":1: program " + r.program().name() + " is also defined in " + first);
        } else {
          out.add(r.program());
        }
      }
    }
    if (!errors.isEmpty()) {
      throw new UserError(String.join(System.lineSeparator(), errors));
    }
    return out;
  }
}
