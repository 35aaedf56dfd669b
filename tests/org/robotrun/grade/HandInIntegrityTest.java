package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledOnOs;
import org.junit.jupiter.api.condition.OS;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.HandIn;
import org.robotrun.io.HandInException;
import org.robotrun.io.HandInFiles;

/**
 * Issue 26, grading integrity: a submission is graded only from its own files (no link out, no
 * special file, no mesh outside it), the hand-in rules are one (the reader {@code run} and
 * {@code grade} share), what RobotRun writes is always graded, and no temporary copy stays.
 */
class HandInIntegrityTest {
  private static final Path TASK = Path.of("scenarios/tasks/pick-and-place.task.json");
  private static final Path REFERENCE = Path.of("tests/resources/grade/reference");
  private static Grader grader;

  @TempDir Path dir;

  @BeforeAll
  static void loadTask() {
    TaskLoad.Loaded task = (TaskLoad.Loaded) TaskReader.read(TASK);
    grader = new Grader(task.task(), task.scenario());
  }

  /** An unpacked hand-in (as Gradescope gives it) of the reference's cell.json and this PICKPLACE.LS. */
  private Path unpacked(String name, byte[] programBytes) throws Exception {
    Path u = Files.createDirectories(dir.resolve(name + "/programs")).getParent();
    Files.copy(REFERENCE.resolve("cell.json"), u.resolve("cell.json"));
    Files.write(u.resolve("programs/PICKPLACE.LS"), programBytes);
    Map<String, byte[]> files = new LinkedHashMap<>();
    files.put("cell.json", Files.readAllBytes(u.resolve("cell.json")));
    files.put("programs/PICKPLACE.LS", programBytes);
    Path zip = HandIns.zip(files, "Eve", dir.resolve(name + ".zip"));
    try (var z = new java.util.zip.ZipFile(zip.toFile())) {
      Files.write(u.resolve("manifest.json"), z.getInputStream(z.getEntry("manifest.json")).readAllBytes());
    }
    return u;
  }

  private static String fatal(Path p) {
    try (Submission s = new SubmissionLoader().load(p)) {
      assertThat(s.fatal()).as("refused").isPresent();
      assertThat(s.tempDir()).isEmpty();
      return s.fatal().get();
    }
  }

  @Test
  void aLinkOutOfAnUnpackedHandInIsRefusedNamingTheEntry() throws Exception {
    Path solution = REFERENCE.resolve("programs/PICKPLACE.LS").toAbsolutePath();
    Path u = unpacked("linked", Files.readAllBytes(solution));
    Files.delete(u.resolve("programs/PICKPLACE.LS"));
    Files.createSymbolicLink(u.resolve("programs/PICKPLACE.LS"), solution);
    assertThat(fatal(u)).isEqualTo("\"programs/PICKPLACE.LS\" is a symbolic link; a submission is read only from its own"
        + " files, never through a link");
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), u, true);
    assertThat(r.score()).isZero();
    assertThat(r.runs()).isEmpty();

    // a link to any other file: its first line never reaches the feedback
    Files.delete(u.resolve("programs/PICKPLACE.LS"));
    Files.createSymbolicLink(u.resolve("programs/PICKPLACE.LS"), Path.of("/etc/hostname"));
    r = Grading.gradeOne(grader, new SubmissionLoader(), u, true);
    assertThat(r.checks()).allSatisfy(c -> assertThat(c.feedback()).contains("is a symbolic link"));

    // the programs folder itself, cell.json, the manifest: the same
    Path w = unpacked("linkedFolder", Files.readAllBytes(solution));
    Path elsewhere = Files.createDirectories(dir.resolve("elsewhere"));
    Files.move(w.resolve("programs/PICKPLACE.LS"), elsewhere.resolve("PICKPLACE.LS"));
    Files.delete(w.resolve("programs"));
    Files.createSymbolicLink(w.resolve("programs"), elsewhere);
    assertThat(fatal(w)).startsWith("\"programs\" is a symbolic link");
    Path c = unpacked("linkedCell", Files.readAllBytes(solution));
    Files.delete(c.resolve("cell.json"));
    Files.createSymbolicLink(c.resolve("cell.json"), REFERENCE.resolve("cell.json").toAbsolutePath());
    assertThat(fatal(c)).startsWith("\"cell.json\" is a symbolic link");
    // a workspace folder and a plain folder of programs too
    Files.delete(c.resolve("manifest.json"));
    assertThat(fatal(c)).startsWith("\"cell.json\" is a symbolic link");
    Path plain = Files.createDirectories(dir.resolve("plain"));
    Files.createSymbolicLink(plain.resolve("PICKPLACE.LS"), solution);
    assertThat(fatal(plain)).startsWith("\"PICKPLACE.LS\" is a symbolic link");
  }

  @Test
  @EnabledOnOs({OS.LINUX, OS.MAC})
  void aFifoOrDeviceInASubmissionIsRefusedWithoutOpeningIt() throws Exception {
    Path u = unpacked("fifo", new byte[0]);
    Files.delete(u.resolve("programs/PICKPLACE.LS"));
    Process p = new ProcessBuilder("mkfifo", u.resolve("programs/PICKPLACE.LS").toString()).start();
    assertThat(p.waitFor(10, TimeUnit.SECONDS)).isTrue();
    long t0 = System.nanoTime();
    assertThat(fatal(u)).isEqualTo("\"programs/PICKPLACE.LS\" is a named pipe (FIFO), not a regular file");
    // a FIFO under a name grading would not read is refused as well: nothing special is ever opened
    Files.move(u.resolve("programs/PICKPLACE.LS"), u.resolve("programs/notes.txt"));
    assertThat(fatal(u)).isEqualTo("\"programs/notes.txt\" is a named pipe (FIFO), not a regular file");
    assertThat((System.nanoTime() - t0) / 1e9).isLessThan(10);
  }

  @Test
  void aHandInsMeshIsReadOnlyFromInsideTheHandIn() throws Exception {
    String cell = Files.readString(REFERENCE.resolve("cell.json"));
    // a mesh object pointing at a file of the grader's machine
    String evil = cell.replaceFirst("\"objects\"\\s*:\\s*\\[", "\"objects\": [{\"name\": \"spy\", \"kind\": \"fixture\","
        + " \"shape\": \"mesh\", \"file\": \"../../../../../../../../etc/passwd\", \"pose\": {\"x\": 0, \"y\": 0, \"z\": 0}},");
    assertThat(evil).isNotEqualTo(cell);
    Map<String, byte[]> files = new LinkedHashMap<>();
    files.put("cell.json", evil.getBytes(StandardCharsets.UTF_8));
    files.put("programs/PICKPLACE.LS", Files.readAllBytes(REFERENCE.resolve("programs/PICKPLACE.LS")));
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), HandIns.zip(files, "Eve", dir.resolve("mesh.zip")), true);
    String handIn = HandIns.check(r, "Hand-in").feedback();
    assertThat(handIn).contains("is outside the hand-in: a hand-in's files are read only from inside it");
    assertThat(handIn).doesNotContain("root:");
  }

  @Test
  void aHandInsRobotComesFromTheLibraryNeverFromAFileOfTheGrader() throws Exception {
    String cell = Files.readString(REFERENCE.resolve("cell.json"));
    // a robot file (RobotRun JSON or URDF) names meshes of its own: it would read the grader's files
    String evil = cell.replaceFirst("\"model\"\\s*:\\s*\"[a-z0-9]+\"", "\"model\": \"../../../../../../../tmp/evil.urdf\"");
    assertThat(evil).isNotEqualTo(cell);
    Map<String, byte[]> files = new LinkedHashMap<>();
    files.put("cell.json", evil.getBytes(StandardCharsets.UTF_8));
    files.put("programs/PICKPLACE.LS", Files.readAllBytes(REFERENCE.resolve("programs/PICKPLACE.LS")));
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), HandIns.zip(files, "Eve", dir.resolve("robot.zip")), true);
    String handIn = HandIns.check(r, "Hand-in").feedback();
    assertThat(handIn).contains("a hand-in names its robot by a library id");
  }

  @Test
  void aManifestTwiceIsRefusedByGradeAsByRun() throws Exception {
    Path good = HandIns.zip(REFERENCE, "Ada", dir.resolve("good.zip"));
    java.io.ByteArrayOutputStream raw = new java.io.ByteArrayOutputStream();
    try (var z = new java.util.zip.ZipFile(good.toFile()); var out = new HandIns.DuplicateNameZip(raw)) {
      out.put("manifest.json", "{\"format\":1,\"student\":\"Mallory\"}".getBytes(StandardCharsets.UTF_8));
      var it = z.entries();
      while (it.hasMoreElements()) {
        var e = it.nextElement();
        out.put(e.getName(), z.getInputStream(e).readAllBytes());
      }
    }
    Path twice = Files.write(dir.resolve("twice.zip"), raw.toByteArray());
    assertThat(fatal(twice)).isEqualTo("the zip holds \"manifest.json\" twice");
    assertThatThrownBy(() -> HandIn.unpack(twice, dir.resolve("x"))).isInstanceOf(HandInException.class)
        .hasMessage(twice + ": the zip holds \"manifest.json\" twice");
    // any other name twice, the same
    java.io.ByteArrayOutputStream raw2 = new java.io.ByteArrayOutputStream();
    try (var z = new java.util.zip.ZipFile(good.toFile()); var out = new HandIns.DuplicateNameZip(raw2)) {
      var it = z.entries();
      while (it.hasMoreElements()) {
        var e = it.nextElement();
        out.put(e.getName(), z.getInputStream(e).readAllBytes());
      }
      out.put("cell.json", "{}".getBytes(StandardCharsets.UTF_8));
    }
    assertThat(fatal(Files.write(dir.resolve("twice2.zip"), raw2.toByteArray()))).isEqualTo("the zip holds \"cell.json\" twice");
  }

  @Test
  void aHandInRobotRunWritesWith250ProgramsIsGraded() throws Exception {
    Path ws = Files.createDirectories(dir.resolve("ws/programs")).getParent();
    Files.copy(REFERENCE.resolve("cell.json"), ws.resolve("cell.json"));
    Files.copy(REFERENCE.resolve("programs/PICKPLACE.LS"), ws.resolve("programs/PICKPLACE.LS"));
    for (int i = 1; i < 250; i++) {
      Files.writeString(ws.resolve("programs/P" + i + ".LS"), "/PROG  P" + i + "\n/ATTR\n/MN\n   1:  R[1]=" + i
          + " ;\n/POS\n/END\n");
    }
    Path zip = dir.resolve("many.zip");
    HandIn.write(ws, zip, "Ada Lovelace", "test", false);
    try (Submission s = new SubmissionLoader().load(zip)) {
      assertThat(s.fatal()).isEmpty();
      assertThat(s.handInProblems()).isEmpty();
    }
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), zip, true);
    assertThat(HandIns.check(r, "Hand-in").passed()).isTrue();
    assertThat(HandIns.check(r, "Programs read").feedback()).contains("250");
    HandIn.unpack(zip, dir.resolve("unpacked"));  // and run --workspace takes it too
  }

  @Test
  void aWorkspaceTooLargeForAHandInIsRefusedWhenWritten() throws Exception {
    Path ws = Files.createDirectories(dir.resolve("big/programs")).getParent();
    Files.copy(REFERENCE.resolve("cell.json"), ws.resolve("cell.json"));
    int n = HandInFiles.Limits.DEFAULT.entries();
    for (int i = 0; i < n; i++) {
      Files.writeString(ws.resolve("programs/P" + i + ".LS"), "/PROG  P" + i + "\n/MN\n/POS\n/END\n");
    }
    assertThatThrownBy(() -> HandIn.write(ws, dir.resolve("big.zip"), "Ada", "test", false))
        .isInstanceOf(HandInException.class).hasMessageContaining("a hand-in holds at most " + (n - 1));
    assertThat(dir.resolve("big.zip")).doesNotExist();
  }

  @Test
  void noTemporaryCopyStaysWhateverHappened() throws Exception {
    // a zip holding programs/A.LS both as a file and as a folder: refused before anything is written
    Map<String, byte[]> files = new LinkedHashMap<>();
    files.put("cell.json", Files.readAllBytes(REFERENCE.resolve("cell.json")));
    files.put("programs/A.LS", "/PROG A\n/MN\n/END\n".getBytes(StandardCharsets.UTF_8));
    files.put("programs/A.LS/B.LS", "/PROG B\n/MN\n/END\n".getBytes(StandardCharsets.UTF_8));
    Path nest = HandIns.zip(files, "Eve", dir.resolve("nest.zip"));
    assertThat(fatal(nest)).isEqualTo("the zip holds \"programs/A.LS\" both as a file and as the folder of"
        + " \"programs/A.LS/B.LS\"");
    assertThatThrownBy(() -> HandIn.unpack(nest, dir.resolve("n"))).hasMessageContaining("both as a file");
    assertThat(dir.resolve("n")).doesNotExist();
    // graded (or not): the copy is gone after close
    Path temp;
    try (Submission s = new SubmissionLoader().load(HandIns.zip(REFERENCE, "Ada", dir.resolve("ok.zip")))) {
      temp = s.tempDir().orElseThrow();
      assertThat(temp.resolve("programs/PICKPLACE.LS")).exists();
    }
    assertThat(temp).doesNotExist();
  }
}
