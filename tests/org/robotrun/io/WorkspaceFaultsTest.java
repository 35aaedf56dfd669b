package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.program.Instruction;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;

/** Bad files, a second window, a newer format, a read-only folder and a full disk: each said once, nothing lost. */
class WorkspaceFaultsTest {
  private static Scenario cell() {
    return ((ScenarioLoad.Loaded) ScenarioReader.read(Path.of("scenarios/empty-cell.json"))).scenario();
  }

  private static Program program(String name, int lines) {
    List<Instruction> body = new ArrayList<>();
    for (int i = 0; i < lines; i++) {
      body.add(new Instruction.Comment("line " + i + " of " + name));
    }
    return Program.of(name, body);
  }

  private static WorkspaceSnapshot snapshot(Workspace ws, Program... programs) throws IOException {
    Map<String, Program> map = new java.util.LinkedHashMap<>();
    for (Program p : programs) {
      map.put(p.name(), p);
    }
    return new WorkspaceSnapshot(ScenarioWriter.toJson(ws.scenario(), java.util.Optional.of(SavedState.fresh("")), ws.folder()), map);
  }

  @Test
  void closingAnAutosaveTwiceSavesOnceAndDoesNotThrow(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    try (Workspace ws = Workspace.open(dir, cell())) {
      WorkspaceSnapshot snap = snapshot(ws, program("TWICE", 3));
      List<String> reports = new ArrayList<>();
      Autosave autosave = new Autosave(ws, () -> snap, reports::add);
      autosave.close();
      assertThat(dir.resolve("programs/TWICE.LS")).exists();
      autosave.close();  // the window closes it on Quit and again when the session ends
      assertThat(reports).noneMatch(r -> r.contains("NOT SAVED"));
    }
  }

  @Test
  void anUnreadableProgramIsReportedWithItsLineAndNeverWrittenOver(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    Workspace.open(dir, cell()).close();
    Path bad = dir.resolve("programs/BAD.LS");
    // (a P[] missing from /POS loads, as on a controller: the bad line is a syntax error)
    String badText = "/PROG  BAD\n/MN\n   1:  J P[1] 100% FINE ;\n   2:  R[1]=(1+ ;\n/POS\n/END\n";
    Files.writeString(bad, badText);
    Files.writeString(dir.resolve("programs/GOOD.LS"), LsWriter.write(program("GOOD", 1)));
    try (Workspace ws = Workspace.open(dir, cell())) {
      assertThat(ws.programs()).extracting(Program::name).containsExactly("GOOD");
      assertThat(String.join("\n", ws.problems())).contains("BAD.LS:").contains("kept as it is");
      // The window has a program of the same name (the student made a new BAD): the file still wins.
      ws.save(snapshot(ws, ws.programs().get(0), program("BAD", 2)));
    }
    assertThat(Files.readString(bad)).isEqualTo(badText);
    // The new BAD went beside it and comes back; the broken file is still reported and kept.
    try (Workspace ws = Workspace.open(dir, cell())) {
      assertThat(ws.programs()).extracting(Program::name).containsExactlyInAnyOrder("GOOD", "BAD");
      assertThat(ws.programFile("BAD").getFileName().toString()).isEqualTo("BAD-2.LS");
      assertThat(String.join("\n", ws.problems())).contains("BAD.LS:");
    }
    assertThat(Files.readString(bad)).isEqualTo(badText);
  }

  @Test
  void anUnreadableCellIsReportedWithItsJsonPathAndNeverWrittenOver(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    Workspace.open(dir, cell()).close();
    Files.writeString(dir.resolve("programs/GOOD.LS"), LsWriter.write(program("GOOD", 1)));
    String broken = Files.readString(dir.resolve("cell.json")).replace("\"lrmate200id\"", "\"no-such-robot\"");
    Files.writeString(dir.resolve("cell.json"), broken);
    try (Workspace ws = Workspace.open(dir, cell())) {
      assertThat(ws.cellBlocked()).isTrue();
      assertThat(String.join("\n", ws.problems())).contains("cell.json:").contains("robots[0].model");
      assertThat(ws.programs()).extracting(Program::name).containsExactly("GOOD");  // the rest opens
      ws.save(snapshot(ws, ws.programs().get(0), program("NEW", 1)));
      assertThat(dir.resolve("programs/NEW.LS")).exists();
    }
    assertThat(Files.readString(dir.resolve("cell.json"))).isEqualTo(broken);
  }

  @Test
  void aNewerFormatIsNamedAndKept(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    Workspace.open(dir, cell()).close();
    String newer = Files.readString(dir.resolve("cell.json")).replace("\"format\" : 1", "\"format\" : 2");
    Files.writeString(dir.resolve("cell.json"), newer);
    try (Workspace ws = Workspace.open(dir, cell())) {
      assertThat(String.join("\n", ws.problems())).contains("unsupported format 2");
      ws.save(snapshot(ws));
    }
    assertThat(Files.readString(dir.resolve("cell.json"))).isEqualTo(newer);
  }

  @Test
  void aSecondOpenIsReadOnlyAndWritesNothing(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    try (Workspace first = Workspace.open(dir, cell()); Workspace second = Workspace.open(dir, cell())) {
      assertThat(first.readOnly()).isFalse();
      assertThat(second.readOnly()).isTrue();
      assertThat(second.readOnlyReason()).contains("read-only");
      assertThat(second.save(snapshot(second, program("X", 1)))).isEmpty();
      assertThat(dir.resolve("programs/X.LS")).doesNotExist();
    }
    try (Workspace again = Workspace.open(dir, cell())) {
      assertThat(again.readOnly()).as("the lock goes with the first window").isFalse();
    }
  }

  @Test
  void aFolderThatIsNotAWorkspaceIsRefused(@TempDir Path tmp) throws Exception {
    Files.writeString(tmp.resolve("notes.txt"), "mine");
    assertThatThrownBy(() -> Workspace.open(tmp, cell())).isInstanceOf(WorkspaceException.class)
        .hasMessageContaining("not empty").hasMessageContaining("cell.json");
    assertThat(Files.readString(tmp.resolve("notes.txt"))).isEqualTo("mine");
  }

  @Test
  void aDeletedProgramFileIsWrittenAgain(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    try (Workspace ws = Workspace.open(dir, cell())) {
      Program a = program("A", 2);
      ws.save(snapshot(ws, a));
      Files.delete(dir.resolve("programs/A.LS"));
      assertThat(ws.externalChanges()).anySatisfy(ch -> assertThat(ch.deleted()).isTrue());
      ws.save(snapshot(ws, a));
      assertThat(dir.resolve("programs/A.LS")).exists();
    }
  }

  @Test
  void aProgramEditedOutsideIsNoticed(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    try (Workspace ws = Workspace.open(dir, cell())) {
      Program a = program("A", 2);
      ws.save(snapshot(ws, a));
      assertThat(ws.externalChanges()).isEmpty();
      assertThat(ws.isSaved("A", a)).isTrue();
      Files.writeString(dir.resolve("programs/A.LS"), LsWriter.write(program("A", 5)));
      var changes = ws.externalChanges();
      assertThat(changes).extracting(Workspace.ExternalChange::programName).containsExactly("A");
      List<String> problems = new ArrayList<>();
      assertThat(ws.reread(changes.get(0).file(), problems).orElseThrow().lineCount()).isEqualTo(5);
      assertThat(ws.externalChanges()).isEmpty();
    }
  }

  // ---- real file systems: a read-only mount and a full disk (root only: they need mount) ----

  private static boolean mount(Path dir, String options) throws Exception {
    Process p = new ProcessBuilder("mount", "-t", "tmpfs", "-o", options, "tmpfs", dir.toString())
        .redirectErrorStream(true).start();
    return p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0;
  }

  private static void run(String... cmd) throws Exception {
    new ProcessBuilder(cmd).redirectErrorStream(true).start().waitFor(10, TimeUnit.SECONDS);
  }

  /**
   * Mounts a 512 KiB tmpfs on {@code dir}, or skips the test outside CI saying why. In CI
   * ({@code CI=true}, where .ci/run runs as root) a tmpfs that cannot be mounted fails the test:
   * the full-disk and read-only checks must really run there, not skip silently.
   */
  private static void mountedOrSkipped(Path dir, String why) throws Exception {
    boolean mounted = canMount(dir);
    if (!mounted && "true".equals(System.getenv("CI"))) {
      throw new AssertionError("CI must run this test for real, but no tmpfs could be mounted (user "
          + System.getProperty("user.name") + "; .ci/run runs as root): " + why);
    }
    assumeTrue(mounted, why);
  }

  private static boolean canMount(Path dir) throws Exception {
    boolean root = "root".equals(System.getProperty("user.name"));
    return root && mount(dir, "size=512k");
  }

  @Test
  void aFullDiskLeavesEveryFileWholeAndSavesOnceThereIsRoom(@TempDir Path tmp) throws Exception {
    Path mnt = tmp.resolve("small");
    Files.createDirectories(mnt);
    mountedOrSkipped(mnt, "needs root and mount to make a 512 KiB tmpfs; skipped on this machine (not root or no mount)");
    try {
      Path dir = mnt.resolve("ws");
      List<String> reports = new ArrayList<>();
      try (Workspace ws = Workspace.open(dir, cell())) {
        Program small = program("P", 3);
        ws.save(snapshot(ws, small));
        String before = Files.readString(dir.resolve("programs/P.LS"));
        // Fill the disk, then try to save a program too big for what is left.
        Path filler = mnt.resolve("filler");
        try (var out = Files.newOutputStream(filler)) {
          byte[] block = new byte[4096];
          while (true) {
            out.write(block);
          }
        } catch (IOException full) {
          // the disk is full now
        }
        Program big = program("P", 2000);
        WorkspaceSnapshot snap = snapshot(ws, big);
        Autosave autosave = new Autosave(ws, () -> snap, reports::add);
        String problem = autosave.saveNow(5000);
        assertThat(problem).contains("the disk is full").contains("P.LS");
        assertThat(reports).hasSize(1);
        assertThat(Files.readString(dir.resolve("programs/P.LS"))).as("the old file is whole").isEqualTo(before);
        try (var files = Files.list(dir.resolve("programs"))) {
          assertThat(files.map(f -> f.getFileName().toString())).containsExactly("P.LS");  // no temp left behind
        }
        Files.delete(filler);
        assertThat(autosave.saveNow(5000)).isEmpty();
        assertThat(reports).last().asString().startsWith("saved again");
        assertThat(LsReader.read(dir.resolve("programs/P.LS")).program().lineCount()).isEqualTo(2000);
        autosave.close();
      }
    } finally {
      run("umount", mnt.toString());
    }
  }

  @Test
  void aReadOnlyFolderOpensReadOnlyAndSaysWhy(@TempDir Path tmp) throws Exception {
    Path mnt = tmp.resolve("ro");
    Files.createDirectories(mnt);
    mountedOrSkipped(mnt, "needs root and mount for a read-only tmpfs (root ignores file permissions); skipped here");
    try {
      Path dir = mnt.resolve("ws");
      Workspace.open(dir, cell()).close();
      Files.delete(dir.resolve(Workspace.LOCK));
      String cellText = Files.readString(dir.resolve("cell.json"));
      run("mount", "-o", "remount,ro", mnt.toString());
      try (Workspace ws = Workspace.open(dir, cell())) {
        assertThat(ws.readOnly()).isTrue();
        assertThat(ws.readOnlyReason()).contains("not writable").contains("read-only");
        assertThat(ws.save(snapshot(ws, program("X", 1)))).isEmpty();
      }
      assertThat(Files.readString(dir.resolve("cell.json"))).isEqualTo(cellText);
      assertThatThrownBy(() -> Workspace.open(mnt.resolve("new"), cell())).isInstanceOf(WorkspaceException.class)
          .hasMessageContaining("cannot create the workspace");
    } finally {
      run("umount", mnt.toString());
    }
  }
}
