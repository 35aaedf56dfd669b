package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.HandIn;

/** pendant --workspace saves what a script does; run --workspace runs a folder or a hand-in as the window would. */
class WorkspaceCommandsTest {
  record Run(int exitCode, String out, String err) {}

  private static Run run(String... args) {
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    var cl = Main.commandLine();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(err));
    int code = cl.execute(args);
    return new Run(code, out.toString(), err.toString());
  }

  @Test
  void aScriptOnAWorkspaceIsSavedAndRunsHeadlessAfterwardsAlsoFromAHandIn(@TempDir Path tmp) throws Exception {
    Path ws = tmp.resolve("ws");
    Path keys = tmp.resolve("make.keys");
    Files.writeString(keys, """
        SELECT
        F1
        TYPE DEMO
        ENTER
        SHIFT+F1
        SHOW
        """);
    Run made = run("pendant", "--workspace", ws.toString(), "--keys", keys.toString());
    assertThat(made.exitCode()).as(made.err()).isZero();
    assertThat(ws.resolve("programs/DEMO.LS")).exists();
    assertThat(Files.readString(ws.resolve("cell.json"))).contains("\"mainProgram\" : \"DEMO\"");

    // A second script on the same workspace starts from what the first one left.
    Path list = tmp.resolve("list.keys");
    Files.writeString(list, "SELECT\nSHOW\n");
    assertThat(run("pendant", "--workspace", ws.toString(), "--keys", list.toString()).out()).contains("DEMO");

    Run ran = run("run", "--workspace", ws.toString());
    assertThat(ran.exitCode()).as(ran.err()).isZero();

    Path zip = tmp.resolve("hand-in.zip");
    HandIn.write(ws, zip, "Ada", "test", false);
    Run fromZip = run("run", "--workspace", zip.toString(), "--report", tmp.resolve("r.json").toString());
    assertThat(fromZip.exitCode()).as(fromZip.err()).isZero();
    assertThat(Files.readString(tmp.resolve("r.json"))).contains("DEMO");
  }

  @Test
  void badWorkspacesAreExit2WithOneLine(@TempDir Path tmp) throws Exception {
    Files.writeString(tmp.resolve("notes.txt"), "x");
    Run notWs = run("run", "--workspace", tmp.toString());
    assertThat(notWs.exitCode()).isEqualTo(2);
    assertThat(notWs.err()).contains("not a workspace").doesNotContain("Exception");
    Run noZip = run("run", "--workspace", tmp.resolve("missing.zip").toString());
    assertThat(noZip.exitCode()).isEqualTo(2);
    assertThat(noZip.err()).contains("no such file");
    Path fake = tmp.resolve("fake.zip");
    Files.writeString(fake, "not a zip");
    Run bad = run("run", "--workspace", fake.toString());
    assertThat(bad.exitCode()).isEqualTo(2);
    assertThat(bad.err()).contains("fake.zip");
    Run both = run("run", "--workspace", tmp.toString(), "--scenario", "scenarios/empty-cell.json");
    assertThat(both.exitCode()).isEqualTo(2);
  }

  @Test
  void aBrokenCellIsNamedWithItsPathAndNotRun(@TempDir Path tmp) throws Exception {
    Path ws = tmp.resolve("ws");
    Path keys = tmp.resolve("k.keys");
    Files.writeString(keys, "SELECT\nF1\nTYPE A\nENTER\n");
    assertThat(run("pendant", "--workspace", ws.toString(), "--keys", keys.toString()).exitCode()).isZero();
    String cell = Files.readString(ws.resolve("cell.json"));
    // the pendant cold-started the workspace at 10 %: whatever it saved, make it out of range
    assertThat(cell).containsPattern("\"overridePct\" : \\d+");
    Files.writeString(ws.resolve("cell.json"), cell.replaceAll("\"overridePct\" : \\d+", "\"overridePct\" : 700"));
    Run r = run("run", "--workspace", ws.toString());
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.err()).contains("state.overridePct").contains("1..100");
  }

  @Test
  void aScenarioOpensAsANewWorkspaceAndTheScenarioIsNotChanged(@TempDir Path tmp) throws Exception {
    Path scenario = Path.of("scenarios/pick-and-place.json");
    byte[] before = Files.readAllBytes(scenario);
    Path ws = WorkspaceFiles.createFromScenario(scenario, tmp.resolve("copy"));
    assertThat(ws.resolve("programs/PICKPLACE.LS")).hasSameBinaryContentAs(Path.of("scenarios/programs/PICKPLACE.LS"));
    assertThat(Files.readAllBytes(scenario)).isEqualTo(before);
    Run r = run("run", "--workspace", ws.toString());
    assertThat(r.exitCode()).as(r.err()).isZero();
  }

  // ---- issue 26: a script whose work cannot be saved is never run ----

  private static Path script(Path tmp) throws Exception {
    return Files.writeString(tmp.resolve("make.keys"), "SELECT\nF1\nTYPE LOSTNOT\nENTER\n");
  }

  @Test
  void aWorkspaceHeldByAnotherRobotRunIsWaitedForThenExit1BeforeTheScriptRuns(@TempDir Path tmp) throws Exception {
    Path ws = tmp.resolve("ws");
    Path keys = script(tmp);
    double wait = PendantCommand.lockWaitSeconds;
    PendantCommand.lockWaitSeconds = 0.5;
    try (org.robotrun.io.Workspace holder = org.robotrun.io.Workspace.open(ws, WorkspaceSession.newCell())) {
      assertThat(holder.readOnly()).isFalse();
      Run second = run("pendant", "--workspace", ws.toString(), "--keys", keys.toString());
      assertThat(second.exitCode()).isEqualTo(1);
      assertThat(second.err()).contains("--workspace: " + ws + ": this workspace is already open in this RobotRun;"
          + " the script was not run, since nothing it did could be saved").doesNotContain("\tat ");
      assertThat(second.out()).as("the script did not run").isEmpty();
    } finally {
      PendantCommand.lockWaitSeconds = wait;
    }
    // once let go, the same script runs and is saved
    Run again = run("pendant", "--workspace", ws.toString(), "--keys", keys.toString());
    assertThat(again.exitCode()).as(again.err()).isZero();
    assertThat(ws.resolve("programs/LOSTNOT.LS")).exists();
  }

  @Test
  @org.junit.jupiter.api.condition.EnabledOnOs({org.junit.jupiter.api.condition.OS.LINUX,
      org.junit.jupiter.api.condition.OS.MAC})
  void aLockFileThatIsAFifoAFolderOrALinkIsNeverOpened(@TempDir Path tmp) throws Exception {
    Path keys = script(tmp);
    for (String kind : List.of("fifo", "folder", "link")) {
      Path ws = tmp.resolve("ws-" + kind);
      Files.createDirectories(ws);
      Files.writeString(ws.resolve("cell.json"), Files.readString(Path.of("scenarios/empty-cell.json")));
      Path lock = ws.resolve(".robotrun.lock");
      Files.deleteIfExists(lock);
      switch (kind) {
        case "fifo" -> assertThat(new ProcessBuilder("mkfifo", lock.toString()).start().waitFor()).isZero();
        case "folder" -> Files.createDirectory(lock);
        default -> Files.createSymbolicLink(lock, tmp.resolve("elsewhere"));
      }
      long t0 = System.nanoTime();
      Run r = run("pendant", "--workspace", ws.toString(), "--keys", keys.toString());
      assertThat((System.nanoTime() - t0) / 1e9).as(kind + ": seconds").isLessThan(20);
      assertThat(r.exitCode()).as(kind + ": " + r.err()).isEqualTo(1);
      assertThat(r.err()).as(kind).contains("the lock file " + lock + " is ").contains("not a regular file (remove it)")
          .contains("the script was not run");
      assertThat(ws.resolve("programs/LOSTNOT.LS")).doesNotExist();
      assertThat(tmp.resolve("elsewhere")).doesNotExist();
    }
  }

  @Test
  void aScriptOnAHandInZipIsRefusedBeforeItRuns(@TempDir Path tmp) throws Exception {
    Path ws = tmp.resolve("ws");
    Path keys = script(tmp);
    assertThat(run("pendant", "--workspace", ws.toString(), "--keys", keys.toString()).exitCode()).isZero();
    Path zip = tmp.resolve("h.zip");
    HandIn.write(ws, zip, "Ada", "test", false);
    Run r = run("pendant", "--workspace", zip.toString(), "--keys", keys.toString());
    assertThat(r.exitCode()).isEqualTo(1);
    assertThat(r.err()).contains("a hand-in opens read-only").contains("the script was not run");
  }

  /** Issue 26: an unpacked hand-in (a folder with manifest.json, as Gradescope gives it) took the script's edits. */
  @Test
  void aScriptOnAnUnpackedHandInFolderIsRefusedAndTheFolderIsUntouched(@TempDir Path tmp) throws Exception {
    Path ws = tmp.resolve("ws");
    Path keys = script(tmp);
    assertThat(run("pendant", "--workspace", ws.toString(), "--keys", keys.toString()).exitCode()).isZero();
    Path zip = tmp.resolve("h.zip");
    HandIn.write(ws, zip, "Ada", "test", false);
    // unpacked as unzip (and Gradescope) do: every entry, manifest.json included
    Path unpacked = tmp.resolve("unpacked");
    try (java.util.zip.ZipFile z = new java.util.zip.ZipFile(zip.toFile())) {
      for (var e : java.util.Collections.list(z.entries())) {
        Path out = unpacked.resolve(e.getName());
        if (e.isDirectory()) {
          Files.createDirectories(out);
          continue;
        }
        Files.createDirectories(out.getParent());
        try (var in = z.getInputStream(e)) {
          Files.copy(in, out);
        }
      }
    }
    assertThat(unpacked.resolve(HandIn.MANIFEST)).isRegularFile();
    java.util.Map<Path, String> before = new java.util.TreeMap<>();
    try (var files = Files.walk(unpacked)) {
      for (Path f : files.filter(Files::isRegularFile).toList()) {
        before.put(unpacked.relativize(f), Files.readString(f));
      }
    }
    Run r = run("pendant", "--workspace", unpacked.toString(), "--keys", keys.toString());
    assertThat(r.exitCode()).as(r.err()).isEqualTo(1);
    assertThat(r.err()).contains("a hand-in opens read-only").contains("the script was not run");
    java.util.Map<Path, String> after = new java.util.TreeMap<>();
    try (var files = Files.walk(unpacked)) {
      for (Path f : files.filter(Files::isRegularFile).toList()) {
        after.put(unpacked.relativize(f), Files.readString(f));
      }
    }
    assertThat(after).isEqualTo(before);
    // run --workspace still runs it (read-only: nothing is written)
    assertThat(run("run", "--workspace", unpacked.toString()).err()).doesNotContain("Exception");
  }

  /** Issue 26: a programs/ that is a file let the script run, then lost its programs. */
  @Test
  void aScriptOnAWorkspaceWhoseProgramsIsAFileIsRefusedBeforeItRuns(@TempDir Path tmp) throws Exception {
    Path ws = tmp.resolve("ws");
    Path keys = script(tmp);
    assertThat(run("pendant", "--workspace", ws.toString(), "--keys", keys.toString()).exitCode()).isZero();
    Path programs = ws.resolve("programs");
    try (var files = Files.list(programs)) {
      for (Path f : files.toList()) {
        Files.delete(f);
      }
    }
    Files.delete(programs);
    Files.writeString(programs, "x");
    Run r = run("pendant", "--workspace", ws.toString(), "--keys", keys.toString());
    assertThat(r.exitCode()).as(r.err()).isEqualTo(1);
    assertThat(r.err()).contains("programs is not a folder").contains("the script was not run");
    assertThat(Files.readString(programs)).isEqualTo("x");
  }

  /** Issue 26: a cell.json that cannot be read let the script run on the default cell, exit 0. */
  @Test
  void aScriptOnAWorkspaceWhoseCellCannotBeReadIsRefusedAndTheFileKept(@TempDir Path tmp) throws Exception {
    Path ws = tmp.resolve("ws");
    Path keys = script(tmp);
    assertThat(run("pendant", "--workspace", ws.toString(), "--keys", keys.toString()).exitCode()).isZero();
    Path cell = ws.resolve("cell.json");
    Files.writeString(cell, "{broken");
    Run r = run("pendant", "--workspace", ws.toString(), "--keys", keys.toString());
    assertThat(r.exitCode()).as(r.err()).isEqualTo(1);
    assertThat(r.err()).contains("cell.json:1: not valid JSON").contains("the script was not run")
        .doesNotContain("Exception");
    assertThat(Files.readString(cell)).isEqualTo("{broken");
  }

  /** Issue 26: a scenario that is a loop of links was reported as "no such file". */
  @Test
  void aScenarioThatIsALoopOfLinksIsNamedSo(@TempDir Path tmp) throws Exception {
    Path a = tmp.resolve("a.json");
    Path b = tmp.resolve("b.json");
    Files.createSymbolicLink(a, b);
    Files.createSymbolicLink(b, a);
    Path keys = script(tmp);
    for (String[] args : new String[][] {{"run", "--scenario", a.toString()},
        {"pendant", "--scenario", a.toString(), "--keys", keys.toString()}}) {
      Run r = run(args);
      assertThat(r.exitCode()).as(r.err()).isEqualTo(2);
      assertThat(r.err()).as(args[0]).contains(a.toString()).contains("symbolic link").doesNotContain("no such file")
          .doesNotContain("Exception");
    }
  }
}
