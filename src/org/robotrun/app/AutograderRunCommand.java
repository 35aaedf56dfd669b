package org.robotrun.app;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
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
import org.robotrun.io.BoundedFiles;
import org.robotrun.io.HandInDroppings;
import org.robotrun.io.TerminalText;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robotrun autograder run}: what an autograder bundle's script runs inside the course
 * platform's container. Finds the student's hand-in in the platform's submission folder (zipped or
 * unpacked, past operating-system and platform files), grades it against the task and writes the
 * platform's results. Whatever goes wrong (the task does not load, no hand-in is found, the grader
 * fails), it writes valid results with zero points and a message saying what to do.
 */
@Command(
    name = "run",
    mixinStandardHelpOptions = true,
    description = {
      "Grade the one submission a course platform hands its autograder and write the platform's results "
          + "(what the scripts of 'robotrun autograder gradescope|prairielearn|github-classroom' run; docs/grading.md).",
      "The root is --root, else $ROBOTRUN_AUTOGRADER_ROOT, else the platform's own: gradescope /autograder "
          + "(reads submission/, writes results/results.json), prairielearn /grade (reads student/, writes "
          + "results/results.json), github-classroom the current folder (the repository; writes "
          + ".robotrun/results.json and the step outputs in $GITHUB_OUTPUT).",
      "A broken task, a missing hand-in or a failure inside the grader still gives results: zero points "
          + "and a message for the instructor.",
      "Exit codes: 0 results written (whatever the score), 1 the results could not be written."
    })
public final class AutograderRunCommand implements Callable<Integer> {
  /** The environment variable every bundle script takes its root from. */
  public static final String ROOT_ENV = "ROBOTRUN_AUTOGRADER_ROOT";

  /** A course platform, with where it puts a submission and where it wants the results. */
  enum Platform {
    GRADESCOPE("gradescope", "/autograder", "submission", "results/results.json"),
    PRAIRIELEARN("prairielearn", "/grade", "student", "results/results.json"),
    GITHUB_CLASSROOM("github-classroom", ".", ".", ".robotrun/results.json");

    final String id;
    final String defaultRoot;
    final String submission;
    final String results;

    Platform(String id, String defaultRoot, String submission, String results) {
      this.id = id;
      this.defaultRoot = defaultRoot;
      this.submission = submission;
      this.results = results;
    }

    static Platform of(String id) {
      for (Platform p : values()) {
        if (p.id.equals(id)) {
          return p;
        }
      }
      throw new UserError("--platform: expected gradescope, prairielearn or github-classroom, got \"" + id + "\"");
    }
  }

  @Spec CommandSpec spec;

  @Option(names = "--platform", required = true, paramLabel = "PLATFORM",
      description = "gradescope, prairielearn or github-classroom.")
  String platformId;

  @Option(names = "--task", required = true, paramLabel = "TASK.json", description = "The task file.")
  Path taskFile;

  @Option(names = "--root", paramLabel = "DIR",
      description = "The platform's root folder (default: $" + ROOT_ENV + ", else the platform's own).")
  Path root;

  @Option(names = "--no-pictures", description = "PrairieLearn: no pictures in the results (no OpenGL needed).")
  boolean noPictures;

  /** The environment, for tests (the root and GITHUB_OUTPUT). */
  Map<String, String> env = System.getenv();

  @Override
  public Integer call() {
    long t0 = System.nanoTime();
    Platform platform = Platform.of(platformId);
    Path base = root != null ? root : Path.of(Optional.ofNullable(env.get(ROOT_ENV)).filter(s -> !s.isBlank())
        .orElse(platform.defaultRoot));
    Path results = base.resolve(platform.results);
    PrintWriter out = spec.commandLine().getOut();
    Task task = null;
    try {
      TaskLoad load = TaskReader.read(taskFile);
      if (load instanceof TaskLoad.Failed f) {
        fail(platform, results, null, "The task file does not load, so nothing was graded. Instructor: fix it, "
            + "check it with 'robotrun grade --task TASK.json SUBMISSION', rebuild the autograder and regrade.\n"
            + f.message());
        return Main.EXIT_OK;
      }
      TaskLoad.Loaded loaded = (TaskLoad.Loaded) load;
      task = loaded.task();
      List<String> notes = new ArrayList<>();
      Path submission = locate(base.resolve(platform.submission), notes);
      Grader grader = new Grader(task, loaded.scenario());
      GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), submission, true);
      String students = r.student().isEmpty() && platform == Platform.GRADESCOPE
          ? gradescopeStudents(base.resolve("submission_metadata.json")) : r.student();
      double seconds = (System.nanoTime() - t0) / 1e9;
      switch (platform) {
        case GRADESCOPE -> AtomicFiles.write(results(results), PlatformResults.gradescope(task, r, students, notes, seconds));
        case PRAIRIELEARN -> AtomicFiles.write(results(results),
            PlatformResults.prairieLearn(task, r, notes, noPictures ? List.of() : pictures(loaded, r, notes)));
        case GITHUB_CLASSROOM -> writeGithub(results, PlatformResults.githubClassroom(task, r));
      }
      out.printf(Locale.ROOT, "%s%s: %s of %s points%n", TerminalText.safe(r.submission()),
          students.isEmpty() ? "" : " (" + TerminalText.safe(students) + ")", GradeReports.fmt(r.score()),
          GradeReports.fmt(r.maxScore()));
      for (CheckResult c : r.checks()) {
        out.printf(Locale.ROOT, "  %s %s/%s %s%n", c.passed() ? "PASS" : "FAIL", GradeReports.fmt(c.score()),
            GradeReports.fmt(c.maxScore()), TerminalText.safe(c.name()));
      }
      out.flush();
      return Main.EXIT_OK;
    } catch (NoHandIn e) {
      return fail(platform, results, task, e.getMessage());
    } catch (IOException | RuntimeException | Error e) {
      if (e instanceof OutOfMemoryError) {
        System.gc();
      }
      return fail(platform, results, task, "The grader failed (" + e.getClass().getSimpleName()
          + (e.getMessage() == null ? "" : ": " + e.getMessage()) + "). Instructor: regrade this submission; "
          + "if it fails again, report it with the submission and the task.");
    }
  }

  /** Writes the failure results; 0 when written, 1 when even that failed. */
  private int fail(Platform platform, Path results, Task task, String message) {
    System.err.println("robotrun autograder: " + message);
    try {
      switch (platform) {
        case GRADESCOPE -> AtomicFiles.write(results(results), PlatformResults.gradescopeFailure(
            task == null ? "" : task.title(), task == null ? 0 : task.maxPoints(), message));
        case PRAIRIELEARN -> AtomicFiles.write(results(results), PlatformResults.prairieLearnFailure(message));
        case GITHUB_CLASSROOM -> {
          if (task == null) {
            AtomicFiles.write(results(results), ("{\"error\": " + new ObjectMapper().writeValueAsString(message) + "}\n")
                .getBytes(StandardCharsets.UTF_8));
          } else {
            writeGithub(results, PlatformResults.githubClassroomFailure(task, message));
          }
        }
      }
      return Main.EXIT_OK;
    } catch (IOException | RuntimeException e) {
      System.err.println("robotrun autograder: cannot write " + results + ": " + e.getMessage());
      return Main.EXIT_FAILED;
    }
  }

  /** The results file, its folder made (PrairieLearn does not make /grade/results). */
  private static Path results(Path file) throws IOException {
    Files.createDirectories(file.toAbsolutePath().getParent());
    return file;
  }

  /**
   * GitHub Classroom: every runner's JSON in one file (for the log and for tests), and each as a
   * step output {@code NAME=BASE64} in {@code $GITHUB_OUTPUT} when the workflow gives one.
   */
  private void writeGithub(Path results, Map<String, byte[]> runners) throws IOException {
    ObjectMapper json = new ObjectMapper();
    var all = json.createObjectNode();
    StringBuilder outputs = new StringBuilder();
    for (Map.Entry<String, byte[]> e : runners.entrySet()) {
      all.set(e.getKey(), json.readTree(e.getValue()));
      outputs.append(e.getKey()).append('=').append(PlatformResults.base64(e.getValue())).append('\n');
    }
    AtomicFiles.write(results(results), json.writerWithDefaultPrettyPrinter().writeValueAsBytes(all));
    String gh = env.get("GITHUB_OUTPUT");
    if (gh != null && !gh.isBlank()) {
      Files.writeString(Path.of(gh), outputs, StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
    }
  }

  /** No hand-in could be found in the submission folder; the message says what was there. */
  static final class NoHandIn extends Exception {
    NoHandIn(String message) {
      super(message);
    }
  }

  /**
   * The hand-in inside a platform's submission folder: the folder itself when it holds
   * {@code manifest.json} or {@code cell.json} (an unpacked hand-in or workspace), else its one
   * {@code .zip}, else the folder when it holds {@code .LS} files, else the one folder inside it
   * (a zip of a folder unpacks to one), at most three levels down. Operating-system and platform
   * files are passed over and said in {@code notes}.
   */
  static Path locate(Path dir, List<String> notes) throws NoHandIn, IOException {
    Path cur = dir;
    for (int depth = 0; depth < 3; depth++) {
      if (!Files.isDirectory(cur)) {
        throw new NoHandIn("The submission folder " + cur + " does not exist: nothing was handed in.");
      }
      List<Path> files = new ArrayList<>();
      List<Path> dirs = new ArrayList<>();
      try (DirectoryStream<Path> s = Files.newDirectoryStream(cur)) {
        int n = 0;
        for (Path p : s) {
          if (++n > 1000) {
            break;
          }
          String name = p.getFileName().toString();
          boolean isDir = Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS);
          if (HandInDroppings.isDropping(isDir ? name + "/" : name)) {
            continue;
          }
          (isDir ? dirs : files).add(p);
        }
      }
      files.sort(null);
      dirs.sort(null);
      if (Files.isRegularFile(cur.resolve("manifest.json")) || Files.isRegularFile(cur.resolve("cell.json"))) {
        return cur;
      }
      List<Path> zips = files.stream().filter(p -> p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".zip"))
          .toList();
      if (zips.size() == 1) {
        if (files.size() > 1) {
          notes.add("Graded " + zips.get(0).getFileName() + " (the one .zip handed in).");
        }
        return zips.get(0);
      }
      if (zips.size() > 1) {
        throw new NoHandIn("Several .zip files were handed in (" + names(zips) + "): hand in only the one .zip that "
            + "File > Hand in writes.");
      }
      if (files.stream().anyMatch(p -> p.getFileName().toString().toUpperCase(Locale.ROOT).endsWith(".LS"))) {
        return cur;
      }
      if (dirs.size() == 1 && files.isEmpty()) {
        cur = dirs.get(0);
        continue;
      }
      break;
    }
    List<Path> seen = new ArrayList<>();
    try (DirectoryStream<Path> s = Files.newDirectoryStream(dir)) {
      for (Path p : s) {
        if (seen.size() < 10) {
          seen.add(p);
        }
      }
    }
    throw new NoHandIn("No hand-in was found in what was handed in (" + (seen.isEmpty() ? "nothing" : names(seen))
        + "): hand in the .zip that File > Hand in writes.");
  }

  private static String names(List<Path> paths) {
    return String.join(", ", paths.stream().map(p -> TerminalText.safe(String.valueOf(p.getFileName()))).toList());
  }

  /** The names of the users in Gradescope's submission_metadata.json ("" when it cannot be read). */
  static String gradescopeStudents(Path metadata) {
    try {
      if (!Files.isRegularFile(metadata)) {
        return "";
      }
      JsonNode m = new ObjectMapper().readTree(BoundedFiles.read(metadata, 1 << 20, "submission metadata"));
      List<String> names = new ArrayList<>();
      for (JsonNode u : m.path("users")) {
        String n = u.path("name").asText("").strip();
        if (!n.isEmpty()) {
          names.add(n);
        }
      }
      return String.join(", ", names);
    } catch (IOException | RuntimeException e) {
      return "";
    }
  }

  /**
   * PrairieLearn's pictures: the cell at the end of the nominal run, then where each failed part
   * check's part ended; none (and a note) when OpenGL is not available.
   */
  private static List<PlatformResults.Picture> pictures(TaskLoad.Loaded loaded, GradeResult r, List<String> notes) {
    if (r.runs().isEmpty()) {
      return List.of();
    }
    List<PlatformResults.Picture> out = new ArrayList<>();
    try {
      NativeLibraries.prepare();
      try (GradePictures pictures = new GradePictures(loaded.scenario())) {
        out.add(new PlatformResults.Picture("The cell at the end of the nominal run",
            pictures.overview(r.runs().get(0).scene())));
        for (CheckResult c : r.checks()) {
          if (!c.passed() && !c.hidden() && c.focus_C().isPresent() && c.failedRun().isPresent()) {
            RunOutcome run = r.runs().get(c.failedRun().get());
            out.add(new PlatformResults.Picture(c.name() + ": where it ended (" + run.label() + ")",
                pictures.closeUp(run.scene(), c.focus_C().get())));
          }
        }
      }
    } catch (RuntimeException | LinkageError e) {
      notes.add("No pictures: OpenGL is not available here (" + e.getClass().getSimpleName() + ").");
    }
    return out;
  }
}
