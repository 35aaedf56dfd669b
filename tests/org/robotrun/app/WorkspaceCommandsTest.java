package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
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
    Files.writeString(ws.resolve("cell.json"), cell.replace("\"overridePct\" : 100", "\"overridePct\" : 700"));
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
}
