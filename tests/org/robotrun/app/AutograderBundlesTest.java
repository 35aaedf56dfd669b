package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.ArrayList;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.HandIn;
import picocli.CommandLine;

/**
 * Each platform's autograder end to end: the bundle is built, the platform's folders are laid
 * out in a temporary root (the scripts take it from ROBOTRUN_AUTOGRADER_ROOT), the platform's
 * script runs on a good, a bad and a broken submission and on a broken task, and what it writes
 * is checked against the platform's published format ({@link PlatformSchemas}).
 */
class AutograderBundlesTest {
  private static final ObjectMapper JSON = new ObjectMapper();
  private static final String SUBS = "tests/resources/grade/";

  @TempDir static Path shared;
  private static Path jar;
  private static Path task;
  private static Path goodZip;
  private static Path twoPartsZip;

  private record Run(int exit, String out, String err) {}

  /**
   * A jar for the scripts' {@code java -jar}: only a manifest whose Class-Path names this test's
   * class path (the classes being tested, not a packaged jar that may be older).
   */
  private static Path testJar(Path dir) throws IOException {
    Manifest m = new Manifest();
    m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
    m.getMainAttributes().put(Attributes.Name.MAIN_CLASS, "org.robotrun.app.Main");
    List<String> urls = new ArrayList<>();
    for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
      if (!e.isEmpty()) {
        urls.add(Path.of(e).toAbsolutePath().toUri().toString());
      }
    }
    m.getMainAttributes().put(Attributes.Name.CLASS_PATH, String.join(" ", urls));
    Path j = dir.resolve("robotrun.jar");
    try (OutputStream out = Files.newOutputStream(j); JarOutputStream z = new JarOutputStream(out, m)) {
      // the manifest is the whole jar
    }
    return j;
  }

  /**
   * The example task with an "autograder" section: hidden checks shown after grades are published,
   * and the cycle-time leaderboard; its scenario and program copied beside it as in the repository.
   */
  private static Path exampleTask(Path dir) throws IOException {
    Files.createDirectories(dir.resolve("tasks"));
    Files.createDirectories(dir.resolve("programs"));
    Files.copy(Path.of("scenarios/pick-and-place.json"), dir.resolve("pick-and-place.json"));
    Files.copy(Path.of("scenarios/programs/PICKPLACE.LS"), dir.resolve("programs/PICKPLACE.LS"));
    String text = Files.readString(Path.of("scenarios/tasks/pick-and-place.task.json"));
    text = text.replaceFirst("\"format\": 1,", "\"format\": 1,\n  \"autograder\": {\"hiddenVisibility\": \"after_published\", "
        + "\"leaderboard\": true},");
    Path t = dir.resolve("tasks/pick-and-place.task.json");
    Files.writeString(t, text);
    return t;
  }

  @BeforeAll
  static void build() throws Exception {
    jar = testJar(shared);
    task = exampleTask(shared.resolve("course"));
    goodZip = handIn(SUBS + "reference", shared.resolve("ada.zip"));
    twoPartsZip = handIn(SUBS + "two-parts", shared.resolve("bob.zip"));
  }

  private static Path handIn(String workspace, Path zip) throws Exception {
    HandIn.write(Path.of(workspace), zip, zip.getFileName().toString().startsWith("ada") ? "Ada Lovelace" : "Bob Smith",
        "test", true);
    return zip;
  }

  private static Run robotrun(String... args) {
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    CommandLine cl = Main.commandLine();
    cl.setOut(new PrintWriter(out, true));
    cl.setErr(new PrintWriter(err, true));
    return new Run(cl.execute(args), out.toString(), err.toString());
  }

  /** Runs a bundle's script with bash, the root and this test's Java (or {@code java}) in its environment. */
  private static Run script(Path script, Path root, Map<String, String> env) throws Exception {
    ProcessBuilder pb = new ProcessBuilder("bash", script.toString());
    pb.environment().put(AutograderRunCommand.ROOT_ENV, root.toString());
    pb.environment().put("ROBOTRUN_JAVA", ProcessHandle.current().info().command().orElse("java"));
    pb.environment().remove("GITHUB_OUTPUT");
    pb.environment().putAll(env);
    Path out = Files.createTempFile(shared, "out", ".txt");
    Path err = Files.createTempFile(shared, "err", ".txt");
    pb.redirectOutput(out.toFile()).redirectError(err.toFile());
    Process p = pb.start();
    assertThat(p.waitFor(180, TimeUnit.SECONDS)).as("the script ends").isTrue();
    return new Run(p.exitValue(), Files.readString(out), Files.readString(err));
  }

  private static void unzip(Path zip, Path into) throws IOException {
    try (FileSystem fs = FileSystems.newFileSystem(URI.create("jar:" + zip.toUri()),
        Map.of("enablePosixFileAttributes", "true"))) {
      Path top = fs.getPath("/");
      try (Stream<Path> s = Files.walk(top)) {
        for (Path p : s.toList()) {
          Path to = into.resolve(top.relativize(p).toString());
          if (Files.isDirectory(p)) {
            Files.createDirectories(to);
          } else {
            Files.createDirectories(to.getParent());
            Files.copy(p, to);
            Files.setPosixFilePermissions(to, Files.getPosixFilePermissions(p));
          }
        }
      }
    }
  }

  // ---- Gradescope ----------------------------------------------------------------------------

  /** Gradescope's layout: the autograder zip unpacked in source/, run_autograder copied up, a submission. */
  private static Path gradescopeRoot(Path dir, Path autograderZip) throws IOException {
    Path root = Files.createDirectories(dir);
    unzip(autograderZip, root.resolve("source"));
    Files.copy(root.resolve("source/run_autograder"), root.resolve("run_autograder"));
    Files.createDirectories(root.resolve("submission"));
    return root;
  }

  private static JsonNode gradescopeResults(Path root) throws IOException {
    JsonNode r = JSON.readTree(root.resolve("results/results.json").toFile());
    PlatformSchemas.gradescope(r);
    return r;
  }

  private static Path gradescopeBundle() throws IOException {
    Path zip = shared.resolve("gradescope/autograder.zip");
    if (!Files.exists(zip)) {
      Run b = robotrun("autograder", "gradescope", "--task", task.toString(), "--out", zip.toString(), "--jar", jar.toString());
      assertThat(b.exit()).as(b.err()).isZero();
      assertThat(b.out()).contains("wrote " + zip + " (Gradescope autograder");
    }
    return zip;
  }

  @Test
  void gradescopeBundleHoldsTheScriptsExecutableTheJarTheTaskAndItsCell() throws Exception {
    Path zip = gradescopeBundle();
    try (FileSystem fs = FileSystems.newFileSystem(URI.create("jar:" + zip.toUri()),
        Map.of("enablePosixFileAttributes", "true"))) {
      assertThat(Files.getPosixFilePermissions(fs.getPath("/run_autograder"))).contains(PosixFilePermission.OWNER_EXECUTE);
      assertThat(Files.getPosixFilePermissions(fs.getPath("/setup.sh"))).contains(PosixFilePermission.OWNER_EXECUTE);
      for (String f : List.of("robotrun.jar", "robotrun-java.sh", "task/tasks/pick-and-place.task.json",
          "task/pick-and-place.json", "task/programs/PICKPLACE.LS")) {
        assertThat(Files.isRegularFile(fs.getPath(f))).as(f).isTrue();
      }
    }
  }

  @Test
  void gradescopeGradesAZippedHandInAndAnUnpackedOneWithDroppings() throws Exception {
    Path root = gradescopeRoot(shared.resolve("gs-good"), gradescopeBundle());
    Files.copy(goodZip, root.resolve("submission/ada.zip"));
    Run run = script(root.resolve("run_autograder"), root, Map.of());
    assertThat(run.exit()).as(run.err()).isZero();
    JsonNode r = gradescopeResults(root);
    assertThat(r.get("score").asDouble()).isEqualTo(105);
    assertThat(r.get("output").asText()).contains("105 of 105 points").contains("Ada Lovelace");
    assertThat(r.get("output_format").asText()).isEqualTo("md");
    double sum = 0;
    for (JsonNode t : r.get("tests")) {
      sum += t.get("score").asDouble();
      assertThat(t.get("status").asText()).isEqualTo("passed");
    }
    assertThat(sum).isEqualTo(105);
    // The task's hidden checks are shown once grades are published, as its autograder section says.
    assertThat(r.get("tests").findValuesAsText("visibility")).contains("after_published", "visible");
    JsonNode lb = r.get("leaderboard").get(0);
    assertThat(lb.get("name").asText()).isEqualTo("Cycle time (s)");
    assertThat(lb.get("order").asText()).isEqualTo("asc");
    assertThat(lb.get("value").asDouble()).isBetween(5.0, 10.0);

    // Gradescope unpacks an uploaded zip; a Mac adds __MACOSX/ and .DS_Store: ignored and listed.
    Path root2 = gradescopeRoot(shared.resolve("gs-unpacked"), gradescopeBundle());
    unzip(goodZip, root2.resolve("submission"));
    Files.createDirectories(root2.resolve("submission/__MACOSX/programs"));
    Files.write(root2.resolve("submission/__MACOSX/programs/._PICKPLACE.LS"), new byte[] {0, 5, 22, 7, 0});
    Files.write(root2.resolve("submission/.DS_Store"), new byte[] {0, 0, 0, 1, 'B', 'u', 'd', '1'});
    Files.write(root2.resolve("submission/programs/._PICKPLACE.LS"), new byte[] {0, 5, 22, 7, 0});
    Files.writeString(root2.resolve("submission_metadata.json"), "{\"users\": [{\"name\": \"Ada L.\"}]}");
    run = script(root2.resolve("run_autograder"), root2, Map.of());
    assertThat(run.exit()).as(run.err()).isZero();
    r = gradescopeResults(root2);
    assertThat(r.get("score").asDouble()).isEqualTo(105);
    JsonNode handIn = r.get("tests").get(0);
    assertThat(handIn.get("status").asText()).isEqualTo("passed");
    assertThat(handIn.get("output").asText()).contains("ignored (operating system or platform files")
        .contains("__MACOSX/").contains(".DS_Store").contains("programs/._PICKPLACE.LS");
  }

  @Test
  void gradescopeGradesABadHandInAndTakesTheNameFromTheMetadataWhenTheManifestHasNone() throws Exception {
    Path root = gradescopeRoot(shared.resolve("gs-bad"), gradescopeBundle());
    Files.copy(twoPartsZip, root.resolve("submission/bob.zip"));
    Run run = script(root.resolve("run_autograder"), root, Map.of());
    assertThat(run.exit()).as(run.err()).isZero();
    JsonNode r = gradescopeResults(root);
    assertThat(r.get("score").asDouble()).isEqualTo(90);
    JsonNode part3 = r.get("tests").get(7);
    assertThat(part3.get("name").asText()).isEqualTo("part3 on the tray");
    assertThat(part3.get("status").asText()).isEqualTo("failed");
    assertThat(part3.get("output").asText()).startsWith("part3 rests on the table");

    // A workspace folder (no manifest, so no student named): the name comes from Gradescope.
    Path root2 = gradescopeRoot(shared.resolve("gs-folder"), gradescopeBundle());
    Files.createDirectories(root2.resolve("submission/programs"));
    Files.copy(Path.of(SUBS + "two-parts/cell.json"), root2.resolve("submission/cell.json"));
    Files.copy(Path.of(SUBS + "two-parts/programs/PICKPLACE.LS"), root2.resolve("submission/programs/PICKPLACE.LS"));
    Files.writeString(root2.resolve("submission_metadata.json"),
        "{\"id\": 1, \"users\": [{\"email\": \"c@example.edu\", \"id\": 7, \"name\": \"Cleo Park\"}]}");
    run = script(root2.resolve("run_autograder"), root2, Map.of());
    r = gradescopeResults(root2);
    assertThat(r.get("score").asDouble()).isEqualTo(85);
    assertThat(r.get("output").asText()).contains("(Cleo Park)");
  }

  @Test
  void gradescopeGivesZeroAndAReasonForABrokenSubmissionABrokenTaskACrashAndATimeLimit() throws Exception {
    Path root = gradescopeRoot(shared.resolve("gs-broken"), gradescopeBundle());
    Files.writeString(root.resolve("submission/notes.txt"), "my programs are on my laptop");
    Run run = script(root.resolve("run_autograder"), root, Map.of());
    assertThat(run.exit()).as(run.err()).isZero();
    JsonNode r = gradescopeResults(root);
    assertThat(r.get("score").asDouble()).isZero();
    assertThat(r.get("tests").get(0).get("max_score").asDouble()).isEqualTo(105);
    assertThat(r.get("output").asText()).contains("No hand\\-in was found").contains("notes.txt");

    Path broken = gradescopeRoot(shared.resolve("gs-broken-task"), gradescopeBundle());
    Files.copy(goodZip, broken.resolve("submission/ada.zip"));
    Files.writeString(broken.resolve("source/task/tasks/pick-and-place.task.json"), "{\"format\": 1, \"checks\": [}");
    run = script(broken.resolve("run_autograder"), broken, Map.of());
    assertThat(run.exit()).isZero();
    r = gradescopeResults(broken);
    assertThat(r.get("score").asDouble()).isZero();
    assertThat(r.get("tests").get(0).get("output").asText()).startsWith("The task file does not load")
        .contains("pick-and-place.task.json:1:");

    // Java itself fails, or never ends: the script still writes results.
    Path fake = shared.resolve("fake-java");
    Files.writeString(fake, "#!/usr/bin/env bash\nif [ \"$1\" = -version ]; then echo 'openjdk version \"21.0.1\"' >&2; exit 0; fi\n"
        + "if [ -n \"${FAKE_SLEEP:-}\" ]; then sleep 30; fi\nexit 3\n");
    fake.toFile().setExecutable(true);
    Path crash = gradescopeRoot(shared.resolve("gs-crash"), gradescopeBundle());
    run = script(crash.resolve("run_autograder"), crash, Map.of("ROBOTRUN_JAVA", fake.toString()));
    assertThat(run.exit()).isZero();
    r = gradescopeResults(crash);
    assertThat(r.get("score").asDouble()).isZero();
    assertThat(r.get("output").asText()).contains("exited with code 3");
    run = script(crash.resolve("run_autograder"), crash, Map.of("ROBOTRUN_JAVA", fake.toString(), "FAKE_SLEEP", "1",
        "ROBOTRUN_AUTOGRADER_GUARD_SECONDS", "1"));
    r = gradescopeResults(crash);
    assertThat(r.get("output").asText()).contains("stopped (exit 124) after at most 1 s");
  }

  @Test
  void aRuntimeInTheBundleIsTheJavaTheScriptsUse() throws Exception {
    // A stand-in runtime: says it is Java 21, then fails, so the message shows it was the one run.
    Path runtime = Files.createDirectories(shared.resolve("runtime/bin"));
    Files.writeString(runtime.resolve("java"), "#!/usr/bin/env bash\n"
        + "if [ \"$1\" = -version ]; then echo 'openjdk version \"21.0.2\"' >&2; exit 0; fi\nexit 7\n");
    runtime.resolve("java").toFile().setExecutable(true);
    Path zip = shared.resolve("gs-runtime/autograder.zip");
    Run b = robotrun("autograder", "gradescope", "--task", task.toString(), "--out", zip.toString(), "--jar",
        jar.toString(), "--runtime", shared.resolve("runtime").toString());
    assertThat(b.exit()).as(b.err()).isZero();
    Path root = gradescopeRoot(shared.resolve("gs-runtime/root"), zip);
    assertThat(root.resolve("source/runtime/bin/java")).isExecutable();
    Files.copy(goodZip, root.resolve("submission/ada.zip"));
    script(root.resolve("run_autograder"), root, Map.of("ROBOTRUN_JAVA", ""));
    assertThat(gradescopeResults(root).get("output").asText()).contains("exited with code 7");
    assertThat(robotrun("autograder", "gradescope", "--task", task.toString(), "--out", zip.toString(), "--jar",
        jar.toString(), "--runtime", shared.toString()).err()).contains("--runtime: " + shared + " has no bin/java");
  }

  @Test
  void aBundleIsNeverWrittenOverAFolderThatHoldsFiles() throws Exception {
    // --out naming the instructor's course folder (or a template repository) must not delete it
    Path course = Files.createDirectories(shared.resolve("my-course"));
    Path mine = Files.writeString(course.resolve("syllabus.md"), "week 1: safety");
    Run b = robotrun("autograder", "prairielearn", "--task", task.toString(), "--out", course.toString(), "--jar",
        jar.toString());
    assertThat(b.exit()).isEqualTo(2);
    assertThat(b.err()).contains("the folder exists and is not empty").doesNotContain("Exception");
    assertThat(mine).hasContent("week 1: safety");
    assertThat(course.resolve("serverFilesCourse")).doesNotExist();
  }

  // ---- PrairieLearn --------------------------------------------------------------------------

  private static Path prairieLearnBundle() throws IOException {
    Path out = shared.resolve("pl-bundle");
    if (!Files.exists(out)) {
      Run b = robotrun("autograder", "prairielearn", "--task", task.toString(), "--out", out.toString(), "--jar",
          jar.toString());
      assertThat(b.exit()).as(b.err()).isZero();
    }
    return out;
  }

  /** PrairieLearn's /grade: serverFilesCourse/ and the question's tests/ copied in, the student's files in student/. */
  private static Path prairieLearnRoot(Path dir) throws IOException {
    Path bundle = prairieLearnBundle();
    copyTree(bundle.resolve("serverFilesCourse"), dir.resolve("serverFilesCourse"));
    copyTree(bundle.resolve("questions/pick-and-place/tests"), dir.resolve("tests"));
    Files.createDirectories(dir.resolve("student"));
    Files.createDirectories(dir.resolve("data"));
    return dir;
  }

  private static void copyTree(Path from, Path to) throws IOException {
    try (Stream<Path> s = Files.walk(from)) {
      for (Path p : s.toList()) {
        Path t = to.resolve(from.relativize(p).toString());
        if (Files.isDirectory(p)) {
          Files.createDirectories(t);
        } else {
          Files.copy(p, t);
          t.toFile().setExecutable(p.toFile().canExecute());
        }
      }
    }
  }

  private static JsonNode prairieLearnResults(Path root) throws IOException {
    byte[] bytes = Files.readAllBytes(root.resolve("results/results.json"));
    JsonNode r = JSON.readTree(bytes);
    PlatformSchemas.prairieLearn(bytes, r);
    return r;
  }

  @Test
  void prairieLearnQuestionAndGraderGradeGoodBadAndBrokenSubmissionsAndABrokenTask() throws Exception {
    Path bundle = prairieLearnBundle();
    JsonNode info = JSON.readTree(bundle.resolve("questions/pick-and-place/info.json").toFile());
    assertThat(info.get("gradingMethod").asText()).isEqualTo("External");
    assertThat(info.at("/externalGradingOptions/entrypoint").asText()).isEqualTo("/grade/serverFilesCourse/robotrun/run.sh");
    assertThat(info.at("/externalGradingOptions/timeout").asInt()).isBetween(30, 600);
    assertThat(Files.readString(bundle.resolve("questions/pick-and-place/question.html")))
        .contains("<pl-file-upload file-patterns=\"*.zip\">").contains("<pl-external-grader-results>");

    Path good = prairieLearnRoot(shared.resolve("pl-good"));
    Files.copy(twoPartsZip, good.resolve("student/bob.zip"));
    Path run = good.resolve("serverFilesCourse/robotrun/run.sh");
    Run r = script(run, good, Map.of());
    assertThat(r.exit()).as(r.err()).isZero();
    JsonNode res = prairieLearnResults(good);
    assertThat(res.get("score").asDouble()).isEqualTo(90.0 / 105);
    assertThat(res.get("tests")).hasSize(16);
    JsonNode part3 = res.get("tests").get(7);
    assertThat(part3.get("points").asDouble()).isZero();
    assertThat(part3.get("max_points").asDouble()).isEqualTo(10);
    assertThat(part3.get("message").asText()).startsWith("part3 rests on the table");
    // The cell, and where part3 ended in each run where its check failed (or why there are none).
    if (res.has("images")) {
      assertThat(res.get("images").get(0).get("url").asText()).startsWith("data:image/png;base64,");
      assertThat(res.get("images").get(0).get("label").asText()).isEqualTo("The cell at the end of the nominal run");
    } else {
      assertThat(res.get("message").asText()).contains("No pictures: OpenGL is not available here");
    }

    Path broken = prairieLearnRoot(shared.resolve("pl-broken"));
    Files.copy(goodZip, broken.resolve("student/ada.zip"));
    Files.copy(twoPartsZip, broken.resolve("student/bob.zip"));
    r = script(broken.resolve("serverFilesCourse/robotrun/run.sh"), broken, Map.of());
    res = prairieLearnResults(broken);
    assertThat(res.get("gradable").asBoolean()).isFalse();
    assertThat(res.get("message").asText()).contains("Several .zip files were handed in (ada.zip, bob.zip)");

    Path brokenTask = prairieLearnRoot(shared.resolve("pl-broken-task"));
    Files.copy(goodZip, brokenTask.resolve("student/ada.zip"));
    Files.writeString(brokenTask.resolve("tests/tasks/pick-and-place.task.json"), "not json");
    r = script(brokenTask.resolve("serverFilesCourse/robotrun/run.sh"), brokenTask, Map.of());
    res = prairieLearnResults(brokenTask);
    assertThat(res.get("gradable").asBoolean()).isFalse();
    assertThat(res.get("format_errors").get(0).asText()).startsWith("The task file does not load");
  }

  // ---- GitHub Classroom ----------------------------------------------------------------------

  private static Path githubBundle() throws IOException {
    Path out = shared.resolve("gh-bundle");
    if (!Files.exists(out)) {
      Run b = robotrun("autograder", "github-classroom", "--task", task.toString(), "--out", out.toString(), "--jar",
          jar.toString());
      assertThat(b.exit()).as(b.err()).isZero();
      assertThat(b.out()).contains("note: the task's scenario lists programs (programs/PICKPLACE.LS)");
    }
    return out;
  }

  /** The step outputs a run gave, decoded: runner name to its JSON. */
  private static Map<String, JsonNode> outputs(Path githubOutput) throws IOException {
    Map<String, JsonNode> out = new LinkedHashMap<>();
    for (String line : Files.readAllLines(githubOutput)) {
      int eq = line.indexOf('=');
      JsonNode j = JSON.readTree(new String(Base64.getDecoder().decode(line.substring(eq + 1)), StandardCharsets.UTF_8));
      PlatformSchemas.githubRunner(j);
      out.put(line.substring(0, eq), j);
    }
    return out;
  }

  @Test
  void githubClassroomWorkflowGivesEveryCheckItsRunnerAndPoints() throws Exception {
    Path bundle = githubBundle();
    String workflow = Files.readString(bundle.resolve(".github/workflows/classroom.yml"));
    assertThat(workflow).contains("uses: classroom-resources/autograding-grading-reporter@v1")
        .contains("run: bash .robotrun/grade.sh")
        .contains("PART3-ON-THE-TRAY_RESULTS: \"${{steps.robotrun.outputs.part3-on-the-tray}}\"")
        .contains("runners: hand-in,programs-read,runs-to-the-end,");

    // The student's repository: the template's files, a README and the hand-in zip committed.
    Path repo = Files.createDirectories(shared.resolve("gh-repo"));
    copyTree(bundle, repo);
    Files.writeString(repo.resolve("README.md"), "# Lab 3\n");
    Files.copy(twoPartsZip, repo.resolve("hand-in.zip"));
    Path gh = shared.resolve("gh-output.txt");
    Files.writeString(gh, "");
    Run r = script(repo.resolve(".robotrun/grade.sh"), repo, Map.of("GITHUB_OUTPUT", gh.toString()));
    assertThat(r.exit()).as(r.err()).isZero();
    Map<String, JsonNode> runners = outputs(gh);
    assertThat(runners).hasSize(16);
    // What the reporter sends to the classroom: the tests' scores over the runners' max scores.
    double total = runners.values().stream().mapToDouble(j -> j.get("tests").get(0).get("score").asDouble()).sum();
    double max = runners.values().stream().mapToDouble(j -> j.get("max_score").asDouble()).sum();
    assertThat(total).isEqualTo(90);
    assertThat(max).isEqualTo(105);
    assertThat(runners.get("part3-on-the-tray").get("status").asText()).isEqualTo("fail");
    assertThat(runners.get("hand-in").get("status").asText()).isEqualTo("pass");

    // A broken task: every runner still reports, as an error with zero points.
    Files.writeString(repo.resolve(".robotrun/task/tasks/pick-and-place.task.json"), "{}");
    Files.writeString(gh, "");
    r = script(repo.resolve(".robotrun/grade.sh"), repo, Map.of("GITHUB_OUTPUT", gh.toString()));
    assertThat(r.exit()).isZero();
    runners = outputs(gh);
    assertThat(runners).hasSize(16);
    assertThat(runners.values()).allSatisfy(j -> {
      assertThat(j.get("status").asText()).isEqualTo("error");
      assertThat(j.get("tests").get(0).get("score").asDouble()).isZero();
    });
    assertThat(r.err()).contains("The task file does not load");
  }

  @Test
  void aTaskThatDoesNotLoadMakesNoBundle() throws Exception {
    Path bad = shared.resolve("bad.task.json");
    Files.writeString(bad, "{\"format\": 1,\n \"scenario\": \"missing.json\", \"checks\": []}");
    Run r = robotrun("autograder", "gradescope", "--task", bad.toString(), "--out", shared.resolve("x.zip").toString(),
        "--jar", jar.toString());
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).contains(bad + ":2: scenario: scenario file not found");
    assertThat(shared.resolve("x.zip")).doesNotExist();
  }
}
