package org.robotrun.grade;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
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
    Loaded loaded = loadPrograms(sub);
    List<String> cellNotes = new ArrayList<>();
    Map<Integer, Position> positionRegisters = new TreeMap<>();
    Scenario cell = overlay(sub, cellNotes, positionRegisters);
    return gradeLoaded(sub.name(), sub.student(), loaded, sub.handInProblems(), cellNotes, cell, positionRegisters,
        checks, t0);
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
    long t0 = System.nanoTime();
    List<Check> checks = task.checks().stream()
        .filter(c -> !c.meta().hidden() && !(c instanceof Check.HandIn)).toList();
    TreeMap<Integer, Double> regs = new TreeMap<>(scenario.registers());
    regs.putAll(registers);
    TreeMap<Integer, Transform> tool = new TreeMap<>(scenario.toolFrames());
    tool.putAll(toolFrames);
    TreeMap<Integer, Transform> user = new TreeMap<>(scenario.userFrames());
    user.putAll(userFrames);
    Scenario cell = new Scenario(scenario.name(), scenario.description(), scenario.robots(), scenario.world(),
        scenario.programs(), scenario.mainProgram(), regs, tool, user, scenario.camera(), scenario.onCollision()).withExtrasOf(scenario);
    return gradeLoaded("your workspace", "", new Loaded(List.copyOf(programs), List.of()), List.of(), List.of(), cell,
        Map.copyOf(positionRegisters), checks, t0);
  }

  /**
   * @param cellNotes why the submission's cell.json could not be used (its frames and registers
   *     then come from the task): shown with the hand-in and frame checks, failing neither by itself
   */
  private GradeResult gradeLoaded(String name, String student, Loaded loaded, List<String> handInProblems,
      List<String> cellNotes, Scenario cell, Map<Integer, Position> positionRegisters, List<Check> checks, long t0) {
    long deadline = t0 + (long) (task.limits().wallSeconds() * 1e9);
    // The runs, nominal first; a run that could not happen leaves its reason.
    List<RunOutcome> runs = new ArrayList<>();
    List<String> notRun = new ArrayList<>();
    Optional<String> cannotRun = loaded.cannotRun(task.program());
    boolean needVariations = checks.stream().anyMatch(c -> c.meta().runs() != Check.Runs.NOMINAL);
    int count = needVariations ? task.variations().count() : 0;
    if (cannotRun.isEmpty()) {
      for (int i = 0; i <= count; i++) {
        CellRunner.Variant v = i == 0 ? CellRunner.nominal(cell, task.variations())
            : CellRunner.variation(cell, task.variations(), i);
        try {
          runs.add(CellRunner.run(v, modelLoader, loaded.programs(), positionRegisters, task.program(),
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
    Context ctx = new Context(loaded, handInProblems, cellNotes, runs, notRun, cell);
    List<CheckResult> out = new ArrayList<>();
    for (Check c : checks) {
      out.add(evaluate(c, ctx));
    }
    return new GradeResult(name, student, out, runs, seconds(t0));
  }

  /** What a grade needs besides the check. */
  private record Context(Loaded loaded, List<String> handInProblems, List<String> cellNotes, List<RunOutcome> runs,
      List<String> notRun, Scenario cell) {
    String notes() {
      return cellNotes.isEmpty() ? "" : "\nnote: " + String.join("\nnote: ", cellNotes);
    }
  }

  private CheckResult evaluate(Check c, Context ctx) {
    return switch (c) {
      case Check.HandIn h -> ctx.handInProblems().isEmpty()
          ? pass(c, "a valid hand-in: every file matches its SHA-256 in manifest.json" + ctx.notes())
          : fail(c, String.join("\n", ctx.handInProblems()) + ctx.notes());
      case Check.ProgramsCheck p -> ctx.loaded().programs().isEmpty() && ctx.loaded().errors().isEmpty()
          ? fail(c, "no .LS program found in the submission")
          : ctx.loaded().errors().isEmpty()
          ? pass(c, ctx.loaded().programs().size() + " program(s) read without errors")
          : fail(c, ctx.loaded().errors().size() + " error(s):\n" + String.join("\n", limit(ctx.loaded().errors(), 20)));
      case Check.ProgramUse u -> ProgramUse.evaluate(u, ctx.loaded().programs(), task.program())
          .map(why -> fail(c, why)).orElseGet(() -> pass(c, ProgramUse.describe(u)));
      case Check.Frame f -> frame(f, ctx);
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
      frames = ctx.runs().get(0).frames();
    } else {
      frames = new FrameTable();
      ctx.cell().toolFrames().forEach((n, t) -> frames.setTransform(FrameKind.TOOL, n, t));
      ctx.cell().userFrames().forEach((n, t) -> frames.setTransform(FrameKind.USER, n, t));
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

  // ---- programs and cell -------------------------------------------------------------------

  /** The programs that read cleanly, and every error as {@code programs/X.LS:line: message}. */
  record Loaded(List<Program> programs, List<String> errors) {
    Optional<String> cannotRun(String main) {
      if (!errors.isEmpty()) {
        return Optional.of("the programs have errors (see the programs check), so nothing was run");
      }
      if (programs.stream().noneMatch(p -> p.name().equalsIgnoreCase(main))) {
        return Optional.of("there is no program " + main + " (programs found: "
            + (programs.isEmpty() ? "none" : String.join(", ", programs.stream().map(Program::name).toList())) + ")");
      }
      return Optional.empty();
    }
  }

  private static Loaded loadPrograms(Submission sub) {
    List<Path> files = new ArrayList<>();
    List<String> errors = new ArrayList<>();
    try (DirectoryStream<Path> s = Files.newDirectoryStream(sub.programsDir())) {
      for (Path p : s) {
        if (SubmissionLoader.isLs(p.getFileName().toString()) && Files.isRegularFile(p)) {
          files.add(p);
        }
      }
    } catch (IOException | RuntimeException e) {
      errors.add("cannot list the programs: " + SubmissionLoader.describe(e));
    }
    files.sort(Comparator.comparing(p -> p.getFileName().toString()));
    String prefix = sub.programsDir().toString() + java.io.File.separator;
    String shown = sub.kind() == Submission.Kind.PROGRAMS ? "" : "programs/";
    List<LsReadResult> read = new ArrayList<>();
    for (Path f : files) {
      String name = shown + f.getFileName();
      try {
        if (Files.size(f) > SubmissionLoader.Limits.DEFAULT.entryBytes()) {
          errors.add(name + ": larger than " + (SubmissionLoader.Limits.DEFAULT.entryBytes() >> 20) + " MB; not a program");
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
    return new Loaded(programs, errors);
  }

  /**
   * The task's cell with the student's own frames and registers from cell.json laid over it (and
   * the R[] and PR[] of its saved state, into {@code positionRegisters}):
   * the robots, fixtures and parts always come from the task, so nobody passes by moving the tray.
   */
  private Scenario overlay(Submission sub, List<String> problems, Map<Integer, Position> positionRegisters) {
    if (sub.cell().isEmpty()) {
      return scenario;
    }
    Scenario own;
    TreeMap<Integer, Double> stateRegisters = new TreeMap<>();
    switch (ScenarioReader.readCell(sub.cell().get())) {
      case CellLoad.Loaded l -> {
        own = l.scenario();
        // A workspace's saved controller state (docs/scenario-format.md, "state"): its R[] and PR[].
        l.state().ifPresent(st -> {
          st.registers().forEach((n, r) -> stateRegisters.put(n, r.value()));
          positionRegisters.putAll(st.positionRegisters());
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
    return new Scenario(scenario.name(), scenario.description(), scenario.robots(), scenario.world(),
        scenario.programs(), scenario.mainProgram(), registers, tool, user, scenario.camera(), scenario.onCollision()).withExtrasOf(scenario);
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
