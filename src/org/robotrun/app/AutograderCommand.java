package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.Callable;
import org.robotrun.grade.Task;
import org.robotrun.grade.TaskLoad;
import org.robotrun.grade.TaskReader;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robotrun autograder}: turnkey autograder bundles for the course platforms
 * (docs/grading.md), and {@code autograder run}, what their scripts run.
 */
@Command(
    name = "autograder",
    mixinStandardHelpOptions = true,
    description = {
      "Build an autograder for a course platform from a task file (docs/grading.md): the scripts the platform "
          + "runs, the RobotRun jar, the task and its cell. Students hand in the .zip that File > Hand in writes.",
      "Every script takes its root from $" + AutograderRunCommand.ROOT_ENV + " (default: the platform's own) and "
          + "writes the platform's results whatever goes wrong."
    },
    subcommands = {
      AutograderCommand.Gradescope.class,
      AutograderCommand.PrairieLearn.class,
      AutograderCommand.GithubClassroom.class,
      AutograderRunCommand.class
    })
public final class AutograderCommand implements Runnable {
  /** Heap for grading one hand-in (measured peak well under it; docs/grading.md). */
  static final int DEFAULT_HEAP_MB = 384;
  /** Seconds the scripts allow beyond the task's wall-clock limit: JVM start, loading, pictures. */
  static final int STARTUP_MARGIN_SEC = 90;

  @Spec CommandSpec spec;

  @Override
  public void run() {
    throw new CommandLine.ParameterException(spec.commandLine(),
        "name a platform: gradescope, prairielearn or github-classroom (or run)");
  }

  /** The options every bundle takes. */
  static final class Common {
    @Option(names = "--task", required = true, paramLabel = "TASK.json", description = "The task file.")
    Path task;

    @Option(names = "--out", required = true, paramLabel = "FILE.zip|DIR",
        description = "Where to write the bundle: a .zip, or a folder for any other name.")
    Path out;

    @Option(names = "--jar", paramLabel = "robotrun.jar",
        description = "The RobotRun jar to put in (default: the jar this command runs from).")
    Path jar;

    @Option(names = "--heap-mb", defaultValue = "" + DEFAULT_HEAP_MB, paramLabel = "MB",
        description = "Java heap for grading one hand-in (default: ${DEFAULT-VALUE}).")
    int heapMb;

    /** The task, loaded; a task that does not load is refused with its problems. */
    TaskLoad.Loaded load() {
      if (heapMb < 64 || heapMb > 16384) {
        throw new UserError("--heap-mb: expected 64 to 16384, got " + heapMb);
      }
      return switch (TaskReader.read(task)) {
        case TaskLoad.Loaded l -> l;
        case TaskLoad.Failed f -> throw new UserError(f.message());
      };
    }

    /** The jar: --jar, else the one RobotRun runs from. */
    Path jar() {
      Path j = jar;
      if (j == null) {
        try {
          j = Path.of(AutograderCommand.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException | RuntimeException e) {
          j = null;
        }
        if (j == null || !Files.isRegularFile(j) || !j.toString().endsWith(".jar")) {
          throw new UserError("--jar: RobotRun is not running from its jar here; give the jar to put in the "
              + "autograder (./mvnw -B package writes target/robotrun.jar)");
        }
      }
      if (!Files.isRegularFile(j)) {
        throw new UserError("--jar: no such file: " + j);
      }
      return j;
    }

    /** The task's files, checked to load from the bundle on their own. */
    AutograderBundle.TaskFiles taskFiles(TaskLoad.Loaded loaded) throws IOException {
      AutograderBundle.TaskFiles files = AutograderBundle.gather(task, loaded);
      String problems = AutograderBundle.verify(files);
      if (!problems.isEmpty()) {
        throw new UserError("the task does not load from the bundle (a file it needs is not found next to it):"
            + System.lineSeparator() + problems);
      }
      return files;
    }

    int guardSeconds(Task t) {
      return (int) Math.ceil(t.limits().wallSeconds()) + STARTUP_MARGIN_SEC;
    }

    String javaScript() {
      return AutograderBundle.template("robotrun-java.sh", Map.of("XMX_MB", Integer.toString(heapMb)));
    }

    void report(PrintWriter w, AutograderBundle b, String platform) throws IOException {
      long size = Files.isDirectory(out) ? folderSize(out) : Files.size(out);
      w.printf(Locale.ROOT, "wrote %s (%s autograder, %.1f MB, %d files)%n", out, platform, size / 1048576.0,
          b.paths().size());
    }

    private static long folderSize(Path dir) throws IOException {
      try (var s = Files.walk(dir)) {
        return s.filter(Files::isRegularFile).mapToLong(p -> p.toFile().length()).sum();
      }
    }
  }

  @Command(
      name = "gradescope",
      mixinStandardHelpOptions = true,
      description = {
        "Write the autograder .zip for a Gradescope Programming Assignment: setup.sh (installs a Java 21 and "
            + "Mesa's OSMesa on Gradescope's Ubuntu image, only what is missing), run_autograder (grades "
            + "/autograder/submission, writes /autograder/results/results.json, whatever goes wrong), the "
            + "RobotRun jar, and the task with its cell in task/.",
        "The scripts take their root from $" + AutograderRunCommand.ROOT_ENV + " (default /autograder)."
      })
  static final class Gradescope implements Callable<Integer> {
    @Spec CommandSpec spec;
    @Mixin Common common;

    @Option(names = "--runtime", paramLabel = "DIR",
        description = "A Java 21+ runtime folder (bin/java) to put in as runtime/, for images without one.")
    Path runtime;

    @Override
    public Integer call() throws IOException {
      TaskLoad.Loaded loaded = common.load();
      Task task = loaded.task();
      AutograderBundle.TaskFiles files = common.taskFiles(loaded);
      AutograderBundle b = new AutograderBundle();
      b.add("setup.sh", AutograderBundle.template("setup.sh", Map.of("DEFAULT_ROOT", "/autograder", "SOURCE_DIR", "source")),
          true);
      b.add("run_autograder", AutograderBundle.template("gradescope-run_autograder", Map.of(
          "TASK", "task/" + files.task(), "MAX_SCORE", GradeReports.fmt(task.maxPoints()),
          "GUARD_SECONDS", Integer.toString(common.guardSeconds(task)))), true);
      b.add("robotrun-java.sh", common.javaScript(), false);
      b.copy("robotrun.jar", common.jar(), false);
      files.files().forEach((rel, p) -> b.copy("task/" + rel, p, false));
      if (runtime != null) {
        if (!Files.isExecutable(runtime.resolve("bin/java"))) {
          throw new UserError("--runtime: " + runtime + " has no bin/java");
        }
        b.copyTree("runtime/", runtime);
      }
      b.write(common.out);
      PrintWriter w = spec.commandLine().getOut();
      common.report(w, b, "Gradescope");
      w.printf(Locale.ROOT, "Gradescope: upload it under Configure Autograder; keep the autograder timeout above %d s "
          + "(the task's wall-clock limit plus start-up).%n", common.guardSeconds(task));
      return Main.EXIT_OK;
    }
  }

  @Command(
      name = "prairielearn",
      mixinStandardHelpOptions = true,
      description = {
        "Write the files to copy into a PrairieLearn course for external grading: "
            + "serverFilesCourse/robotrun/ (run.sh, the RobotRun jar), questions/QUESTION/ (info.json, "
            + "question.html with a .zip upload, tests/ with the task and its cell) and "
            + "robotrun-grader-image/ (a Dockerfile for an image with the pictures' OpenGL).",
        "The grader takes its root from $" + AutograderRunCommand.ROOT_ENV + " (default /grade)."
      })
  static final class PrairieLearn implements Callable<Integer> {
    /** PrairieLearn's largest external-grading timeout. */
    static final int MAX_TIMEOUT_SEC = 600;

    @Spec CommandSpec spec;
    @Mixin Common common;

    @Option(names = "--question", paramLabel = "NAME",
        description = "The question's folder name (default: from the task file's name).")
    String question;

    @Option(names = "--image", defaultValue = "eclipse-temurin:21-jre", paramLabel = "IMAGE",
        description = "The grading image (default: ${DEFAULT-VALUE}, Java without OpenGL: no pictures; "
            + "build robotrun-grader-image/ for pictures).")
    String image;

    @Override
    public Integer call() throws IOException {
      TaskLoad.Loaded loaded = common.load();
      Task task = loaded.task();
      AutograderBundle.TaskFiles files = common.taskFiles(loaded);
      String q = question != null ? question : common.task.getFileName().toString()
          .replaceFirst("(?i)(\\.task)?\\.json$", "");
      if (!q.matches("[A-Za-z0-9][A-Za-z0-9_.-]{0,79}")) {
        throw new UserError("--question: use letters, digits, '_', '.', '-' (got \"" + q + "\")");
      }
      int guard = common.guardSeconds(task);
      if (guard > MAX_TIMEOUT_SEC) {
        throw new UserError("the task's limits.wallSeconds (" + task.limits().wallSeconds() + " s) plus "
            + STARTUP_MARGIN_SEC + " s of start-up is more than PrairieLearn's " + MAX_TIMEOUT_SEC + " s timeout");
      }
      AutograderBundle b = new AutograderBundle();
      String server = "serverFilesCourse/robotrun/";
      b.add(server + "run.sh", AutograderBundle.template("prairielearn-run.sh", Map.of(
          "TASK", files.task(), "GUARD_SECONDS", Integer.toString(guard))), true);
      b.add(server + "robotrun-java.sh", common.javaScript(), false);
      b.copy(server + "robotrun.jar", common.jar(), false);
      String dir = "questions/" + q + "/";
      b.add(dir + "info.json", infoJson(task, q, guard), false);
      b.add(dir + "question.html", questionHtml(task), false);
      files.files().forEach((rel, p) -> b.copy(dir + "tests/" + rel, p, false));
      b.add("robotrun-grader-image/Dockerfile", dockerfile(), false);
      b.add("robotrun-grader-image/setup.sh", AutograderBundle.template("setup.sh",
          Map.of("DEFAULT_ROOT", "/opt", "SOURCE_DIR", "robotrun")), true);
      b.add("robotrun-grader-image/robotrun-java.sh", common.javaScript(), false);
      b.write(common.out);
      PrintWriter w = spec.commandLine().getOut();
      common.report(w, b, "PrairieLearn");
      w.printf(Locale.ROOT, "PrairieLearn: copy serverFilesCourse/ and questions/ into the course repository; the "
          + "question's external-grading timeout is %d s.%n", Math.min(MAX_TIMEOUT_SEC, guard + 30));
      return Main.EXIT_OK;
    }

    private String infoJson(Task task, String q, int guard) throws IOException {
      var json = new com.fasterxml.jackson.databind.ObjectMapper();
      var root = json.createObjectNode();
      root.put("uuid", UUID.nameUUIDFromBytes(("robotrun:" + q + ":" + task.title()).getBytes(StandardCharsets.UTF_8))
          .toString());
      root.put("title", task.title().isEmpty() ? "RobotRun task" : task.title());
      root.put("topic", "RobotRun");
      root.putArray("tags").add("robotrun");
      root.put("type", "v3");
      root.put("gradingMethod", "External");
      root.put("singleVariant", true);
      var ext = root.putObject("externalGradingOptions");
      ext.put("enabled", true);
      ext.put("image", image);
      ext.putArray("serverFilesCourse").add("robotrun/");
      ext.put("entrypoint", "/grade/serverFilesCourse/robotrun/run.sh");
      ext.put("timeout", Math.min(MAX_TIMEOUT_SEC, guard + 30));
      return json.writerWithDefaultPrettyPrinter().writeValueAsString(root) + "\n";
    }

    private static String questionHtml(Task task) {
      return "<pl-question-panel>\n  <p>" + GradeReports.esc(task.title()) + "</p>\n"
          + "  <p>In RobotRun, use <b>File &gt; Hand in</b> and upload the <code>.zip</code> it writes here. "
          + "Your programs run on the task's cell, nominal and with the parts moved as the task says; "
          + "each check below says what was measured.</p>\n</pl-question-panel>\n\n"
          + "<pl-file-upload file-patterns=\"*.zip\"></pl-file-upload>\n\n"
          + "<pl-submission-panel>\n  <pl-external-grader-results></pl-external-grader-results>\n"
          + "</pl-submission-panel>\n";
    }

    private static String dockerfile() {
      return "# A PrairieLearn grading image for RobotRun with the pictures' OpenGL (Mesa's OSMesa) and Java 21:\n"
          + "#   docker build -t YOURNAME/robotrun-grader robotrun-grader-image/ && docker push YOURNAME/robotrun-grader\n"
          + "# then name it in the question's info.json (externalGradingOptions.image).\n"
          + "FROM ubuntu:24.04\n"
          + "COPY setup.sh robotrun-java.sh /opt/robotrun/\n"
          + "RUN bash /opt/robotrun/setup.sh && rm -rf /var/lib/apt/lists/*\n";
    }
  }

  @Command(
      name = "github-classroom",
      mixinStandardHelpOptions = true,
      description = {
        "Write the files of a GitHub Classroom assignment's template repository: "
            + ".github/workflows/classroom.yml (Java 21, the grading step, GitHub's autograding reporter with "
            + "one runner per check, so each check's points reach the classroom) and .robotrun/ (the script, "
            + "the RobotRun jar, the task and its cell).",
        "The script takes its root from $" + AutograderRunCommand.ROOT_ENV + " (default the repository)."
      })
  static final class GithubClassroom implements Callable<Integer> {
    @Spec CommandSpec spec;
    @Mixin Common common;

    @Override
    public Integer call() throws IOException {
      TaskLoad.Loaded loaded = common.load();
      Task task = loaded.task();
      AutograderBundle.TaskFiles files = common.taskFiles(loaded);
      int guard = common.guardSeconds(task);
      AutograderBundle b = new AutograderBundle();
      b.add(".github/workflows/classroom.yml", workflow(task, guard), false);
      b.add(".robotrun/grade.sh", AutograderBundle.template("github-classroom-grade.sh", Map.of(
          "TASK", "task/" + files.task(), "GUARD_SECONDS", Integer.toString(guard),
          "RUNNERS", AutograderBundle.runnerWords(task))), true);
      b.add(".robotrun/robotrun-java.sh", common.javaScript(), false);
      b.copy(".robotrun/robotrun.jar", common.jar(), false);
      files.files().forEach((rel, p) -> b.copy(".robotrun/task/" + rel, p, false));
      b.write(common.out);
      PrintWriter w = spec.commandLine().getOut();
      common.report(w, b, "GitHub Classroom");
      w.println("GitHub Classroom: commit these files to the assignment's template repository; students commit "
          + "the .zip of File > Hand in and push.");
      List<String> programs = files.files().keySet().stream().filter(f -> f.toUpperCase(Locale.ROOT).endsWith(".LS"))
          .toList();
      if (!programs.isEmpty()) {
        w.println("note: the task's scenario lists programs (" + String.join(", ", programs) + "); they are in "
            + ".robotrun/task/, which students can read: give the task a scenario without a solution in them.");
      }
      return Main.EXIT_OK;
    }

    /** The workflow GitHub Classroom's own autograding writes, with RobotRun's step and one runner per check. */
    static String workflow(Task task, int guardSeconds) {
      List<String> names = PlatformResults.runnerNames(task);
      StringBuilder y = new StringBuilder();
      y.append("# RobotRun autograding (written by `robotrun autograder github-classroom`, docs/grading.md).\n")
          .append("name: Autograding Tests\n")
          .append("'on':\n- push\n- repository_dispatch\n")
          .append("permissions:\n  checks: write\n  actions: read\n  contents: read\n")
          .append("jobs:\n  run-autograding-tests:\n    runs-on: ubuntu-latest\n")
          .append("    if: github.actor != 'github-classroom[bot]'\n")
          .append("    steps:\n")
          .append("    - name: Checkout code\n      uses: actions/checkout@v4\n")
          .append("    - name: Java 21\n      uses: actions/setup-java@v4\n      with:\n")
          .append("        distribution: temurin\n        java-version: '21'\n")
          .append("    - name: Grade with RobotRun\n      id: robotrun\n")
          .append("      timeout-minutes: ").append(guardSeconds / 60 + 2).append('\n')
          .append("      run: bash .robotrun/grade.sh\n")
          .append("    - name: Autograding Reporter\n      uses: classroom-resources/autograding-grading-reporter@v1\n")
          .append("      env:\n");
      for (String n : names) {
        y.append("        ").append(n.toUpperCase(Locale.ROOT)).append("_RESULTS: \"${{steps.robotrun.outputs.")
            .append(n).append("}}\"\n");
      }
      y.append("      with:\n        runners: ").append(String.join(",", names)).append('\n');
      return y.toString();
    }
  }
}
