package org.robotrun.grade;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import org.robotrun.io.CellLoad;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.LsProgramSet;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.ScenarioReader;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.FrameTable;
import org.robotrun.world.Scenario;

/**
 * Grades submissions against one task: loads the programs, runs the nominal cell and the seeded
 * variations (each in a fresh simulation), and scores every check. Thread-safe: a grader holds
 * only the immutable task, scenario and robot models, so one grader may grade many submissions
 * at once, each on its own thread.
 */
public final class Grader {
  private final Task task;
  private final Scenario scenario;
  private final Map<String, RobotModel> models = new ConcurrentHashMap<>();
  private final Function<String, RobotModel> modelLoader;

  public Grader(Task task, Scenario scenario) {
    this.task = task;
    this.scenario = scenario;
    this.modelLoader = id -> models.computeIfAbsent(id, RobotDefinitions::load);
  }

  public Task task() {
    return task;
  }

  public Scenario scenario() {
    return scenario;
  }

  /**
   * Grades one submission. Never throws for anything the submission holds: a broken zip, a
   * program that does not read, an alarm, an endless loop (time limits) or an internal error
   * becomes failed checks with a message.
   *
   * @param includeHidden false for a student's own check: hidden checks are left out entirely
   */
  public GradeResult grade(Submission sub, boolean includeHidden) {
    long t0 = System.nanoTime();
    List<Check> checks = task.checks().stream().filter(c -> includeHidden || !c.meta().hidden()).toList();
    if (sub.fatal().isPresent()) {
      String why = "The submission could not be graded: " + sub.fatal().get();
      List<CheckResult> out = checks.stream().map(c -> fail(c, why)).toList();
      return new GradeResult(sub.name(), sub.student(), out, List.of(), seconds(t0));
    }
    Loaded loaded = loadPrograms(sub, scenario);
    List<String> cellNotes = new ArrayList<>();
    Map<Integer, Position> positionRegisters = new TreeMap<>();
    Map<String, RobotRegisters> others = new TreeMap<>();
    Scenario cell = overlay(sub, cellNotes, positionRegisters, others);
    return gradeLoaded(sub.name(), sub.student(), loaded, sub.handInProblems(), cellNotes, cell, positionRegisters,
        others, checks, t0);
  }

  /**
   * A student's own check ("Check my work" in the window) on programs and frames held in memory:
   * the visible checks only, without the hand-in check (a hand-in is checked when it is handed in).
   *
   * @param programs the programs as the controller holds them (immutable)
   * @param toolFrames the student's tool frames UT[n] (flange to TCP), by number
   * @param userFrames the student's user frames UF[n] (in WORLD), by number
   * @param registers the student's data registers R[n] to start with
   */
  public GradeResult checkMyWork(List<Program> programs, Map<Integer, Transform> toolFrames,
      Map<Integer, Transform> userFrames, Map<Integer, Double> registers) {
    return checkMyWork(programs, toolFrames, userFrames, registers, Map.of());
  }

  /**
   * As {@link #checkMyWork(List, Map, Map, Map)}, with the student's position registers (those the
   * task writes as offset registers are overwritten by the task, as in grading).
   */
  public GradeResult checkMyWork(List<Program> programs, Map<Integer, Transform> toolFrames,
      Map<Integer, Transform> userFrames, Map<Integer, Double> registers, Map<Integer, Position> positionRegisters) {
    return checkMyWork(programs, toolFrames, userFrames, registers, positionRegisters, Map.of(), Map.of());
  }

  /**
   * The R[] and PR[] a robot after the first starts with (from a workspace's saved state, or
   * what the student has in the window).
   */
  public record RobotRegisters(Map<Integer, Double> registers, Map<Integer, Position> positionRegisters) {
    public RobotRegisters {
      registers = Map.copyOf(registers);
      positionRegisters = Map.copyOf(positionRegisters);
    }
  }

  /**
   * "Check my work" in a cell of several robots: as {@link #checkMyWork(List, Map, Map, Map, Map)}
   * for the first robot, with the programs and registers each robot after the first has now.
   *
   * @param otherPrograms robot name to its programs, for the robots after the first
   * @param otherRegisters robot name to its R[] and PR[], for the robots after the first
   */
  public GradeResult checkMyWork(List<Program> programs, Map<Integer, Transform> toolFrames,
      Map<Integer, Transform> userFrames, Map<Integer, Double> registers, Map<Integer, Position> positionRegisters,
      Map<String, List<Program>> otherPrograms, Map<String, RobotRegisters> otherRegisters) {
    long t0 = System.nanoTime();
    List<Check> checks = task.checks().stream()
        .filter(c -> !c.meta().hidden() && !(c instanceof Check.HandIn)).toList();
    TreeMap<Integer, Double> regs = new TreeMap<>(scenario.registers());
    regs.putAll(registers);
    TreeMap<Integer, Transform> tool = new TreeMap<>(scenario.toolFrames());
    tool.putAll(toolFrames);
    TreeMap<Integer, Transform> user = new TreeMap<>(scenario.userFrames());
    user.putAll(userFrames);
    Scenario cell = scenario.withPresets(regs, tool, user);
    Map<String, List<Program>> others = new LinkedHashMap<>();
    otherPrograms.forEach((r, ps) -> others.put(r, List.copyOf(ps)));
    return gradeLoaded("your workspace", "", new Loaded(List.copyOf(programs), List.of(), others), List.of(), List.of(),
        cell, Map.copyOf(positionRegisters), Map.copyOf(otherRegisters), checks, t0);
  }

  /**
   * @param cellNotes why the submission's cell.json could not be used (its frames and registers
   *     then come from the task): shown with the hand-in and frame checks, failing neither by itself
   */
  private GradeResult gradeLoaded(String name, String student, Loaded loaded, List<String> handInProblems,
      List<String> cellNotes, Scenario cell, Map<Integer, Position> positionRegisters,
      Map<String, RobotRegisters> otherRegisters, List<Check> checks, long t0) {
    long deadline = t0 + (long) (task.limits().wallSeconds() * 1e9);
    // The runs, nominal first; a run that could not happen leaves its reason.
    List<RunOutcome> runs = new ArrayList<>();
    List<String> notRun = new ArrayList<>();
    Optional<String> cannotRun = loaded.cannotRun(task.program(), task.otherPrograms(), several());
    Map<String, CellRunner.RobotStart> starts = new LinkedHashMap<>();
    task.otherPrograms().forEach((robot, main) -> {
      RobotRegisters rr = otherRegisters.getOrDefault(robot, new RobotRegisters(Map.of(), Map.of()));
      starts.put(robot, new CellRunner.RobotStart(main, loaded.programsOf(robot), rr.registers(),
          rr.positionRegisters()));
    });
    boolean needVariations = checks.stream().anyMatch(c -> c.meta().runs() != Check.Runs.NOMINAL);
    int count = needVariations ? task.variations().count() : 0;
    if (task.program().isEmpty()) {
      notRun.add("the task runs no program");
    } else if (cannotRun.isEmpty()) {
      for (int i = 0; i <= count; i++) {
        CellRunner.Variant v = i == 0 ? CellRunner.nominal(cell, task.variations())
            : CellRunner.variation(cell, task.variations(), i);
        try {
          runs.add(CellRunner.run(v, modelLoader, loaded.programs(), positionRegisters, task.program(), starts,
              task.limits().simSeconds(), deadline));
        } catch (CellRunner.WallClockExceeded e) {
          notRun.add(v.label() + ": stopped after " + fmt(task.limits().wallSeconds())
              + " s of wall-clock time (the grader's limit per submission)");
          break;
        } catch (IllegalArgumentException e) {
          notRun.add(v.label() + ": the program could not start: " + e.getMessage());
          break;
        } catch (RuntimeException | StackOverflowError e) {
          notRun.add(v.label() + ": the simulator failed (" + e.getClass().getSimpleName() + "); please report this");
          break;
        }
      }
    } else {
      notRun.add(cannotRun.get());
    }
    Context ctx = new Context(loaded, handInProblems, cellNotes, runs, notRun, cell, positionRegisters);
    List<CheckResult> out = new ArrayList<>();
    for (Check c : checks) {
      out.add(evaluate(c, ctx));
    }
    return new GradeResult(name, student, out, runs, seconds(t0));
  }

  /** What a grade needs besides the check. */
  private record Context(Loaded loaded, List<String> handInProblems, List<String> cellNotes, List<RunOutcome> runs,
      List<String> notRun, Scenario cell, Map<Integer, Position> positionRegisters) {
    String notes() {
      return cellNotes.isEmpty() ? "" : "\nnote: " + String.join("\nnote: ", cellNotes);
    }
  }

  /** Whether the task's cell has several robots: robot checks then name their robot. */
  private boolean several() {
    return scenario.robots().size() > 1;
  }

  /** The robot a robot check looks at, by name. */
  /** The index of the robot named {@code name} in {@code cell}, or -1. */
  private static int robotIndex(Scenario cell, String name) {
    for (int i = 0; i < cell.robots().size(); i++) {
      if (cell.robots().get(i).name().equals(name)) {
        return i;
      }
    }
    return -1;
  }

  private String robotOf(Check c) {
    return c.meta().robot().orElse(scenario.robots().get(0).name());
  }

  /** In a cell of several robots, a robot check's result starts with its robot's name. */
  private CheckResult evaluate(Check c, Context ctx) {
    CheckResult r = evaluateOne(c, ctx);
    if (!several() || !isRobotCheck(c)) {
      return r;
    }
    String robot = robotOf(c);
    String measured = r.measured();
    int at = measured.startsWith("In the ") ? measured.indexOf(": ") + 2 : 0;
    String named = measured.substring(0, at) + robot + ": " + measured.substring(at);
    return new CheckResult(c, r.passed(), r.score(), named, r.failedRun(), r.focus_C());
  }

  /** The checks that look at one robot (the others look at the cell's parts, collisions, files). */
  static boolean isRobotCheck(Check c) {
    return c instanceof Check.RunsToEnd || c instanceof Check.NoMotionStop || c instanceof Check.CycleTime
        || c instanceof Check.ProgramUse || c instanceof Check.EndState || c instanceof Check.Frame;
  }

  private CheckResult evaluateOne(Check c, Context ctx) {
    return switch (c) {
      case Check.HandIn h -> ctx.handInProblems().isEmpty()
          ? pass(c, "a valid hand-in: every file matches its SHA-256 in manifest.json" + ctx.notes())
          : fail(c, String.join("\n", ctx.handInProblems()) + ctx.notes());
      case Check.ProgramsCheck p -> ctx.loaded().programs().isEmpty() && ctx.loaded().errors().isEmpty()
          ? fail(c, "no .LS program found in the submission")
          : ctx.loaded().errors().isEmpty()
          ? pass(c, programsRead(ctx.loaded()))
          : fail(c, ctx.loaded().errors().size() + " error(s):\n" + String.join("\n", limit(ctx.loaded().errors(), 20)));
      case Check.ProgramUse u -> ProgramUse.evaluate(u, ctx.loaded().programsOf(robotOf(u)), mainOf(robotOf(u)))
          .map(why -> fail(c, why)).orElseGet(() -> pass(c, ProgramUse.describe(u)));
      case Check.Frame f -> frame(f, ctx);
      case Check.PositionRegister r -> positionRegister(r, ctx);
      default -> overRuns(c, ctx);
    };
  }

  /** A run-based check over the runs it names: passes only when it passes in each. */
  private CheckResult overRuns(Check c, Context ctx) {
    List<Integer> which = new ArrayList<>();
    Check.Runs r = c.meta().runs();
    if (r != Check.Runs.VARIATIONS) {
      which.add(0);
    }
    if (r != Check.Runs.NOMINAL) {
      for (int i = 1; i <= task.variations().count(); i++) {
        which.add(i);
      }
    }
    if (which.isEmpty()) {
      return fail(c, "the task has no variations to run this check on");
    }
    String lastPass = "";
    for (int i : which) {
      if (i >= ctx.runs().size()) {
        return fail(c, "not run: " + String.join("; ", ctx.notRun()));
      }
      RunOutcome run = ctx.runs().get(i);
      RunChecks.Eval e = RunChecks.evaluate(c, run);
      if (!e.pass()) {
        String where = which.size() > 1 || i > 0 ? "In the " + run.label() + ": " : "";
        return new CheckResult(c, false, 0, where + e.measured(), Optional.of(i), e.focus_C());
      }
      lastPass = e.measured();
    }
    String summary = which.size() > 1 ? "passed in all " + which.size() + " runs"
        + (r == Check.Runs.VARIATIONS ? " (seeded variations)" : " (nominal and " + (which.size() - 1) + " variations)")
        + "; nominal or last: " + lastPass : lastPass;
    return pass(c, summary);
  }

  private CheckResult frame(Check.Frame f, Context ctx) {
    FrameTable frames;
    if (!ctx.runs().isEmpty()) {
      frames = ctx.runs().get(0).robot(f.meta().robot()).frames();
    } else {
      frames = new FrameTable();
      int robot = robotIndex(ctx.cell(), robotOf(f));
      if (robot >= 0) {
        Scenario.Preload preload = ctx.cell().preload(robot);
        preload.toolFrames().forEach((n, t) -> frames.setTransform(FrameKind.TOOL, n, t));
        preload.userFrames().forEach((n, t) -> frames.setTransform(FrameKind.USER, n, t));
      }
    }
    Transform taught = frames.transform(f.tool() ? FrameKind.TOOL : FrameKind.USER, f.number());
    double d = taught.distanceTo(f.truth());
    double a = Math.toDegrees(taught.rotationAngleTo(f.truth()));
    String name = (f.tool() ? "UT[" : "UF[") + f.number() + "]";
    String m = String.format(Locale.ROOT, "%s is %.2f mm and %.2f deg from the true frame (allowed %s mm, %s deg)",
        name, d, a, fmt(f.toleranceMm()), fmt(f.toleranceDeg()));
    m += ctx.notes();
    return d <= f.toleranceMm() && a <= f.toleranceDeg() ? pass(f, m) : fail(f, m);
  }

  private CheckResult positionRegister(Check.PositionRegister r, Context ctx) {
    String name = "PR[" + r.number() + "]";
    Position p = ctx.positionRegisters().get(r.number());
    if (p == null) {
      return fail(r, name + " was never recorded (it holds zeros)" + ctx.notes());
    }
    if (!(p instanceof Position.Cartesian c)) {
      return fail(r, name + " holds joint angles, not X, Y, Z: record it with the pendant in a Cartesian "
          + "representation (DATA, Position Reg, SHIFT+F3 RECORD)" + ctx.notes());
    }
    double d = new Vec3(c.xMm(), c.yMm(), c.zMm()).minus(r.position()).norm();
    String m = String.format(Locale.ROOT, "%s is %.2f mm from the point (X %.1f Y %.1f Z %.1f, allowed %s mm)",
        name, d, c.xMm(), c.yMm(), c.zMm(), fmt(r.toleranceMm())) + ctx.notes();
    return d <= r.toleranceMm() ? pass(r, m) : fail(r, m);
  }

  // ---- programs and cell -------------------------------------------------------------------

  /** The programs that read cleanly, and every error as {@code programs/X.LS:line: message}. */
  /**
   * @param programs the first robot's (programs/*.LS)
   * @param others the programs of each robot after the first (programs/ROBOT/*.LS), by robot name
   */
  record Loaded(List<Program> programs, List<String> errors, Map<String, List<Program>> others) {
    Loaded(List<Program> programs, List<String> errors) {
      this(programs, errors, Map.of());
    }

    /** A robot's programs; the first robot's for a name not among the others. */
    List<Program> programsOf(String robot) {
      return others.getOrDefault(robot, programs);
    }

    Optional<String> cannotRun(String main, Map<String, String> otherMains, boolean several) {
      if (!errors.isEmpty()) {
        return Optional.of("the programs have errors (see the programs check), so nothing was run");
      }
      List<String> missing = new ArrayList<>();
      if (programs.stream().noneMatch(p -> p.name().equalsIgnoreCase(main))) {
        missing.add("there is no program " + main + " (programs found" + (several ? " in programs/" : "") + ": "
            + names(programs) + ")");
      }
      otherMains.forEach((robot, m) -> {
        List<Program> ps = others.getOrDefault(robot, List.of());
        if (ps.stream().noneMatch(p -> p.name().equalsIgnoreCase(m))) {
          String folder = "programs/" + org.robotrun.io.Workspace.robotFolder(robot) + "/";
          boolean misplaced = programs.stream().anyMatch(p -> p.name().equalsIgnoreCase(m));
          missing.add("there is no program " + m + " for " + robot + " (programs found in " + folder + ": " + names(ps)
              + ")" + (misplaced ? "; " + m + " is among the first robot's programs in programs/, but " + robot
              + "'s programs go in " + folder : ""));
        }
      });
      return missing.isEmpty() ? Optional.empty() : Optional.of(String.join("; ", missing));
    }

    private static String names(List<Program> ps) {
      return ps.isEmpty() ? "none" : String.join(", ", ps.stream().map(Program::name).toList());
    }
  }

  /** The first robot's program, or the program the task runs on a robot after it. */
  private String mainOf(String robot) {
    return task.otherPrograms().getOrDefault(robot, task.program());
  }

  private String programsRead(Loaded l) {
    if (!several()) {
      return l.programs().size() + " program(s) read without errors";
    }
    List<String> parts = new ArrayList<>();
    parts.add(scenario.robots().get(0).name() + ": " + l.programs().size());
    for (int i = 1; i < scenario.robots().size(); i++) {
      String r = scenario.robots().get(i).name();
      parts.add(r + ": " + l.others().getOrDefault(r, List.of()).size());
    }
    return "program(s) read without errors (" + String.join(", ", parts) + ")";
  }

  /**
   * The first robot's programs from the programs folder; in a cell of several robots, each other
   * robot's from its subfolder {@code programs/ROBOT/} (as a workspace keeps them). Every robot's
   * programs are checked on their own, as each controller holds only its own.
   */
  private static Loaded loadPrograms(Submission sub, Scenario scenario) {
    List<String> errors = new ArrayList<>();
    String shown = sub.kind() == Submission.Kind.PROGRAMS ? "" : "programs/";
    List<Program> first = loadFolder(sub.programsDir(), shown, errors);
    Map<String, List<Program>> others = new LinkedHashMap<>();
    for (int i = 1; i < scenario.robots().size(); i++) {
      String robot = scenario.robots().get(i).name();
      String folder = org.robotrun.io.Workspace.robotFolder(robot);
      Path dir = sub.programsDir().resolve(folder);
      others.put(robot, Files.isDirectory(dir, java.nio.file.LinkOption.NOFOLLOW_LINKS)
          ? loadFolder(dir, shown + folder + "/", errors) : List.of());
    }
    return new Loaded(first, errors, others);
  }

  private static List<Program> loadFolder(Path folder, String shown, List<String> errors) {
    List<Path> files = new ArrayList<>();
    try (DirectoryStream<Path> s = Files.newDirectoryStream(folder)) {
      for (Path p : s) {
        if (SubmissionLoader.isLs(p.getFileName().toString()) && Files.isRegularFile(p)) {
          files.add(p);
          if (files.size() > SubmissionLoader.DEFAULT_LIMITS.entries()) {
            errors.add(shown + ": more than " + SubmissionLoader.DEFAULT_LIMITS.entries() + " .LS files");
            return List.of();
          }
        }
      }
    } catch (IOException | RuntimeException e) {
      errors.add("cannot list the programs: " + SubmissionLoader.describe(e));
    }
    files.sort(Comparator.comparing(p -> p.getFileName().toString()));
    String prefix = folder.toString() + java.io.File.separator;
    List<LsReadResult> read = new ArrayList<>();
    for (Path f : files) {
      String name = shown + f.getFileName();
      try {
        if (Files.size(f) > SubmissionLoader.DEFAULT_LIMITS.entryBytes()) {
          errors.add(name + ": larger than " + (SubmissionLoader.DEFAULT_LIMITS.entryBytes() >> 20) + " MB; not a program");
          continue;
        }
        read.add(LsReader.readCheckingFileName(f));
      } catch (IOException | RuntimeException e) {
        errors.add(name + ": cannot read: " + SubmissionLoader.describe(e));
      }
    }
    List<Program> programs = new ArrayList<>();
    Set<String> names = new HashSet<>();
    for (LsReadResult r : LsProgramSet.crossCheck(read, Set.of())) {
      for (Diagnostic d : r.diagnostics()) {
        if (d.isError()) {
          errors.add(d.toString().replace(prefix, shown));
        }
      }
      if (!r.hasErrors() && names.add(r.program().name().toUpperCase(Locale.ROOT))) {
        programs.add(r.program());
      }
    }
    return programs;
  }

  /**
   * The task's cell with the student's own frames and registers from cell.json laid over it (and
   * the R[] and PR[] of its saved state, into {@code positionRegisters}):
   * the robots, fixtures and parts always come from the task, so nobody passes by moving the tray.
   */
  private Scenario overlay(Submission sub, List<String> problems, Map<Integer, Position> positionRegisters,
      Map<String, RobotRegisters> others) {
    if (sub.cell().isEmpty()) {
      return scenario;
    }
    Scenario own;
    TreeMap<Integer, Double> stateRegisters = new TreeMap<>();
    switch (ScenarioReader.readHandInCell(sub.cell().get())) {
      case CellLoad.Loaded l -> {
        own = l.scenario();
        // A workspace's saved controller state (docs/scenario-format.md, "state"): its R[] and PR[].
        l.state().ifPresent(st -> {
          st.registers().forEach((n, r) -> stateRegisters.put(n, r.value()));
          positionRegisters.putAll(st.positionRegisters());
          // Each other robot's saved R[] and PR[] (state.robots), for the robots of the task's cell.
          st.robots().forEach((robot, rs) -> {
            Map<Integer, Double> r = new TreeMap<>();
            rs.registers().forEach((n, x) -> r.put(n, x.value()));
            others.put(robot, new RobotRegisters(r, rs.positionRegisters()));
          });
        });
      }
      case CellLoad.Failed f -> {
        String prefix = sub.cell().get().toString();
        f.errors().stream().limit(10).forEach(e -> problems.add(e.toString().replace(prefix, "cell.json")
            + " (so the task's frames and registers were used)"));
        return scenario;
      }
    }
    TreeMap<Integer, Double> registers = new TreeMap<>(scenario.registers());
    registers.putAll(own.registers());
    registers.putAll(stateRegisters);
    TreeMap<Integer, Transform> tool = new TreeMap<>(scenario.toolFrames());
    tool.putAll(own.toolFrames());
    TreeMap<Integer, Transform> user = new TreeMap<>(scenario.userFrames());
    user.putAll(own.userFrames());
    return scenario.withPresets(registers, tool, user);
  }

  // ---- helpers -----------------------------------------------------------------------------

  private static CheckResult pass(Check c, String measured) {
    return new CheckResult(c, true, c.meta().points(), measured, Optional.empty(), Optional.<Vec3>empty());
  }

  private static CheckResult fail(Check c, String measured) {
    return new CheckResult(c, false, 0, measured, Optional.empty(), Optional.<Vec3>empty());
  }

  private static List<String> limit(List<String> lines, int n) {
    if (lines.size() <= n) {
      return lines;
    }
    List<String> out = new ArrayList<>(lines.subList(0, n));
    out.add("... and " + (lines.size() - n) + " more");
    return out;
  }

  private static double seconds(long t0) {
    return (System.nanoTime() - t0) / 1e9;
  }

  static String fmt(double d) {
    if (d == Math.rint(d) && Math.abs(d) < 1e15) {
      return Long.toString((long) d);
    }
    return new java.math.BigDecimal(d).round(new java.math.MathContext(3)).stripTrailingZeros().toPlainString();
  }
}
