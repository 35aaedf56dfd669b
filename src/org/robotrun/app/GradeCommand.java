package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicInteger;
import org.robotrun.grade.CheckResult;
import org.robotrun.grade.GradeResult;
import org.robotrun.grade.Grader;
import org.robotrun.grade.Grading;
import org.robotrun.grade.RunOutcome;
import org.robotrun.grade.SubmissionLoader;
import org.robotrun.grade.Task;
import org.robotrun.grade.TaskLoad;
import org.robotrun.grade.TaskReader;
import org.robotrun.io.AtomicFiles;
import org.robotrun.io.TerminalText;
import org.robotrun.render.GlUnavailableException;
import org.robotrun.world.Scenario;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code robotrun grade}: scores submissions against a task file, headless. */
@Command(
    name = "grade",
    mixinStandardHelpOptions = true,
    description = {
      "Grade submissions against a task file (docs/grading.md): run each on the task's scenario and its seeded "
          + "variations, score every check, and say what was measured.",
      "A submission is a hand-in .zip (as File > Hand in writes it), an unpacked hand-in or workspace folder "
          + "(cell.json and programs/*.LS), or a folder of .LS files. The cell (robots, fixtures, parts) always comes "
          + "from the task's scenario; a submission's cell.json adds its own frames and registers.",
      "In a cell of several robots every robot's main program runs at once (as 'run' does); the programs of a "
          + "robot after the first are in programs/ROBOT/*.LS, and robot checks name their robot.",
      "Submissions are graded in parallel, each in its own simulation, with the task's simulated-time and "
          + "wall-clock limits; a broken or hostile submission fails its checks and never stops the others.",
      "Exit codes: 0 every submission graded (whatever its score), 1 the reports could not be written after "
          + "grading, 2 bad task file or options, or an output (--out, --gradescope) that cannot be written (checked "
          + "before any grading)."
    })
public final class GradeCommand implements Callable<Integer> {
  @Spec CommandSpec spec;

  @Option(names = "--task", required = true, paramLabel = "TASK.json", description = "The task file.")
  Path taskFile;

  @Parameters(arity = "1..*", paramLabel = "SUBMISSION", description = "Hand-in .zip files or folders.")
  List<Path> submissions;

  @Option(names = "--out", paramLabel = "DIR",
      description = "Write DIR/summary.csv and, per submission, DIR/<name>/results.json (Gradescope) and report.html.")
  Path out;

  @Option(names = "--gradescope", paramLabel = "FILE",
      description = "Write the one submission's Gradescope results.json here (e.g. /autograder/results/results.json).")
  Path gradescope;

  @Option(names = "--jobs", paramLabel = "N", description = "Submissions graded at once (default: the number of cores).")
  Integer jobs;

  @Option(names = "--no-pictures", description = "Leave the pictures out of the HTML reports (faster; no OpenGL needed).")
  boolean noPictures;

  @Option(names = "--student-view", description = "Leave hidden checks out of everything, as a student's own check does.")
  boolean studentView;

  @Option(names = {"-q", "--quiet"}, description = "Print one line per submission, not every check.")
  boolean quiet;

  @Override
  public Integer call() throws IOException {
    NativeLibraries.prepare();  // the report's pictures are rendered with LWJGL
    PrintWriter w = spec.commandLine().getOut();
    int threads = jobs == null ? Runtime.getRuntime().availableProcessors() : jobs;
    if (threads < 1 || threads > 256) {
      throw new UserError("--jobs: expected 1 to 256, got " + threads);
    }
    if (gradescope != null && submissions.size() != 1) {
      throw new UserError("--gradescope: grade exactly one submission (got " + submissions.size() + ")");
    }
    // Every output is checked before any grading: a class is never graded into nowhere.
    if (out != null) {
      if (Files.exists(out) && !Files.isDirectory(out)) {
        throw new UserError("--out: " + out + " is a file; give a folder");
      }
      try {
        Files.createDirectories(out);
      } catch (IOException | RuntimeException e) {
        throw new UserError("--out: cannot create the folder " + out + " (" + why(e) + ")");
      }
      checkOutput("--out", out.resolve("summary.csv"));
    }
    if (gradescope != null) {
      Path dir = gradescope.toAbsolutePath().getParent();
      if (dir == null || !Files.isDirectory(dir)) {
        throw new UserError("--gradescope: the folder " + dir + " does not exist");
      }
      checkOutput("--gradescope", gradescope);
    }
    TaskLoad.Loaded loaded = switch (TaskReader.read(taskFile)) {
      case TaskLoad.Loaded l -> l;
      case TaskLoad.Failed f -> throw new UserError(f.message());
    };
    Task task = loaded.task();
    Grader grader = new Grader(task, loaded.scenario());
    AtomicInteger done = new AtomicInteger();
    List<GradeResult> results = Grading.gradeAll(grader, new SubmissionLoader(), submissions, threads, !studentView,
        r -> {
          int n = done.incrementAndGet();
          if (submissions.size() > 10 && n % 10 == 0) {
            System.err.printf(Locale.ROOT, "graded %d of %d%n", n, submissions.size());
          }
        });
    for (GradeResult r : results) {
      print(w, r);
    }
    w.flush();
    try {
      if (gradescope != null) {
        AtomicFiles.write(gradescope, GradeReports.gradescope(task, results.get(0)));
      }
      if (out != null) {
        writeOut(task, loaded.scenario(), results, w);
      }
    } catch (IOException | java.io.UncheckedIOException e) {
      // the disk filled (or the folder went away) while grading: the scores printed above stand
      throw new UserError("could not write the reports (" + why(e) + "); the scores are printed above", Main.EXIT_FAILED);
    }
    return Main.EXIT_OK;
  }

  /** Refuses an output that cannot be written (read-only folder, full disk, /proc), before any grading. */
  private static void checkOutput(String option, Path file) {
    try {
      AtomicFiles.checkWritable(file);
    } catch (IOException e) {
      throw new UserError(option + ": cannot write " + e.getMessage());
    }
  }

  private static String why(Throwable e) {
    Throwable t = e instanceof java.io.UncheckedIOException u ? u.getCause() : e;
    return switch (t) {
      case java.nio.file.AccessDeniedException x -> "permission denied";
      case java.nio.file.NoSuchFileException x -> "a folder on the way does not exist or cannot hold new folders";
      case java.nio.file.FileSystemException x when x.getReason() != null -> x.getReason();
      default -> t.getMessage() == null ? t.getClass().getSimpleName() : t.getMessage();
    };
  }

  /** Submission names, student names and messages come from students' files: escaped for the terminal. */
  private void print(PrintWriter w, GradeResult r) {
    w.print(TerminalText.safe(String.format(Locale.ROOT, "%s%s: %s of %s points%n", r.submission(),
        r.student().isEmpty() ? "" : " (" + r.student() + ")", GradeReports.fmt(r.score()), GradeReports.fmt(r.maxScore()))));
    if (quiet) {
      return;
    }
    for (CheckResult c : r.checks()) {
      w.printf(Locale.ROOT, "  %s %s/%s %s%s%n", c.passed() ? "PASS" : "FAIL", GradeReports.fmt(c.score()),
          GradeReports.fmt(c.maxScore()), TerminalText.safe(c.name()), c.hidden() ? " (hidden)" : "");
      for (String line : c.feedback().split("\n")) {
        w.println("       " + TerminalText.safe(line));
      }
    }
  }

  private void writeOut(Task task, Scenario scenario, List<GradeResult> results, PrintWriter w) throws IOException {
    Files.createDirectories(out);
    List<String> folders = new ArrayList<>();
    Set<String> used = new HashSet<>();
    used.add("summary.csv");  // the class summary lives beside the folders
    for (GradeResult r : results) {
      folders.add(uniqueFolder(r.submission(), used));
    }
    GradePictures pictures = null;
    String note = "";
    if (!noPictures) {
      try {
        pictures = new GradePictures(scenario);
      } catch (GlUnavailableException | UnsatisfiedLinkError | IllegalStateException e) {
        note = "No pictures: OpenGL is not available here (" + e.getMessage() + ").";
        System.err.println("robotrun grade: " + note);
      }
    }
    try {
      for (int i = 0; i < results.size(); i++) {
        GradeResult r = results.get(i);
        Path dir = out.resolve(folders.get(i));
        Files.createDirectories(dir);
        AtomicFiles.write(dir.resolve("results.json"), GradeReports.gradescope(task, r));
        String overview = "";
        Map<String, String> partPictures = new LinkedHashMap<>();
        if (pictures != null && !r.runs().isEmpty()) {
          overview = pictures.overview(r.runs().get(0).scene());
          for (CheckResult c : r.checks()) {
            if (!c.passed() && c.focus_C().isPresent() && c.failedRun().isPresent()) {
              RunOutcome run = r.runs().get(c.failedRun().get());
              partPictures.put(c.name(), pictures.closeUp(run.scene(), c.focus_C().get()));
            }
          }
        }
        String why = pictures == null ? (noPictures ? "" : note) : r.runs().isEmpty() ? "No pictures: nothing was run." : "";
        AtomicFiles.write(dir.resolve("report.html"), GradeReports.html(task, r, overview, partPictures, why));
      }
    } finally {
      if (pictures != null) {
        pictures.close();
      }
    }
    AtomicFiles.write(out.resolve("summary.csv"), GradeReports.summaryCsv(task, results, folders));
    w.println("wrote " + out.resolve("summary.csv") + " and " + results.size() + " report folder(s)");
  }

  /** A folder name made of safe characters from the submission's name, unique in this run. */
  static String uniqueFolder(String submission, Set<String> used) {
    String base = submission.replaceFirst("(?i)\\.zip$", "").replaceAll("[^A-Za-z0-9._-]", "_");
    if (base.isEmpty() || base.startsWith(".")) {
      base = "submission" + base;
    }
    if (base.length() > 80) {
      base = base.substring(0, 80);
    }
    String name = base;
    for (int k = 2; !used.add(name.toLowerCase(Locale.ROOT)); k++) {
      name = base + "-" + k;
    }
    return name;
  }
}
