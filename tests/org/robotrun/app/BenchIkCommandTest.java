package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

class BenchIkCommandTest {
  @TempDir Path dir;

  private record Run(int code, String out, String err) {}

  private Run run(String... args) {
    CommandLine cl = Main.commandLine();
    StringWriter out = new StringWriter(), err = new StringWriter();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(err));
    int code = cl.execute(args);
    return new Run(code, out.toString(), err.toString());
  }

  /** The first {@code rows} targets of the reference file, to keep the test short. */
  private Path smallTargets(int rows) throws Exception {
    Path ref = Path.of(getClass().getResource("/ik_targets_lrmate200id.csv").toURI());
    List<String> lines = Files.readAllLines(ref).subList(0, rows + 1);
    Path f = dir.resolve("targets.csv");
    Files.write(f, lines);
    return f;
  }

  @Test
  void closedFormPrintsOneSummaryLineAndWritesSolutions() throws Exception {
    Path targets = smallTargets(50);
    Path out = dir.resolve("solutions.csv");
    Run r = run("bench", "ik", "--targets", targets.toString(), "--warmup", "1", "--warmup-ms", "0", "--out", out.toString());
    assertThat(r.code()).isZero();
    assertThat(r.out().lines()).hasSize(1);
    assertThat(r.out()).matches(
        "solved=50/50 in_limits=50/50 same_config=50/50 median_us=[0-9.]+ p99_us=[0-9.]+ robot=lrmate200id solver=closed-form\\R");
    List<String> written = Files.readAllLines(out);
    assertThat(written).hasSize(51);
    assertThat(written.get(0)).isEqualTo("id,q1,q2,q3,q4,q5,q6");
    assertThat(written.get(1).split(",")).hasSize(7);
  }

  @Test
  void everyLibraryArmSolvesGeneratedTargetsWithItsOwnSolverInTheGroundTruthConfig() throws Exception {
    for (String id : org.robotrun.io.RobotDefinitions.LIBRARY) {
      Path t = dir.resolve(id + ".csv");
      Run r = run("bench", "ik", "--robot", id, "--generate", "200", "--seed", "7", "--write-targets", t.toString(),
          "--warmup", "1", "--warmup-ms", "0");
      assertThat(r.code()).as(id + r.err()).isZero();
      String kind = id.startsWith("crx") ? "offset-wrist" : "closed-form";
      assertThat(r.out()).as(id).matches("solved=200/200 in_limits=200/200 same_config=200/200 median_us=[0-9.]+ p99_us=[0-9.]+ robot="
          + id + " solver=" + kind + "\\R");
      // The written file reads back as --targets and gives the same counts.
      Run again = run("bench", "ik", "--robot", id, "--targets", t.toString(), "--warmup", "0", "--warmup-ms", "0");
      assertThat(again.out()).as(id).startsWith("solved=200/200 in_limits=200/200 same_config=200/200 ");
    }
  }

  @Test
  void urdfArmsGetTheirClosedFormsThroughTheBench() throws Exception {
    // A UR-layout package and a FANUC chain in the ROS-I layout with only a flange link (a flange correction).
    Path ur = org.robotrun.io.TestArms.offsetPackage(dir);
    Run r = run("bench", "ik", "--robot", ur.toString(), "--generate", "300", "--seed", "24", "--warmup", "1", "--warmup-ms", "0");
    assertThat(r.code()).as(r.err()).isZero();
    assertThat(r.out()).matches("solved=300/300 in_limits=300/300 same_config=300/300 median_us=[0-9.]+ p99_us=[0-9.]+ robot=ur_like solver=ur-type\\R");
    Run forced = run("bench", "ik", "--robot", ur.toString(), "--generate", "5", "--solver", "ur-type", "--warmup", "0", "--warmup-ms", "0");
    assertThat(forced.code()).isZero();
    Run wrong = run("bench", "ik", "--robot", "lrmate200id", "--generate", "5", "--solver", "ur-type");
    assertThat(wrong.err().strip()).isEqualTo(
        "robotrun: lrmate200id does not have three parallel axes with an offset wrist: use --solver auto or numeric");
    Path fanuc = dir.resolve("m10ia_flange.urdf");
    org.robotrun.io.RosIndustrialLayoutTest.writeLayout(fanuc, "m10ia", "FLANGE_ONLY");
    Run f = run("bench", "ik", "--robot", fanuc.toString(), "--generate", "300", "--seed", "24", "--warmup", "1", "--warmup-ms", "0");
    assertThat(f.out()).as(f.err()).matches(
        "solved=300/300 in_limits=300/300 same_config=300/300 median_us=[0-9.]+ p99_us=[0-9.]+ robot=m10ia_flange_only solver=closed-form\\R");
  }

  @Test
  void aClosedFormAskedOfAnOffsetWristArmIsOneLine() {
    Run r = run("bench", "ik", "--robot", "crx10ia", "--generate", "5", "--solver", "closed-form");
    assertThat(r.code()).isEqualTo(1);
    assertThat(r.err().strip()).isEqualTo("robotrun: crx10ia is not an OPW arm (no closed form): use --solver auto or numeric");
  }

  @Test
  void numericFromEachStartSolvesEveryRow() throws Exception {
    Path targets = smallTargets(50);
    for (String start : List.of("home", "random", "near")) {
      Run r = run("bench", "ik", "--targets", targets.toString(), "--solver", "numeric", "--start", start, "--warmup", "1", "--warmup-ms", "0");
      assertThat(r.code()).as(start).isZero();
      assertThat(r.out()).as(start).startsWith("solved=50/50 in_limits=50/50 same_config=");
    }
  }

  @Test
  void resolvedRatePrintsItsOwnLine() throws Exception {
    Run r = run("bench", "ik", "--targets", smallTargets(20).toString(), "--solver", "resolved-rate", "--warmup", "1", "--warmup-ms", "0");
    assertThat(r.code()).isZero();
    assertThat(r.out()).matches("steps=20 damped=\\d+ median_us=[0-9.]+ p99_us=[0-9.]+\\R");
  }

  @Test
  void unsolvedRowsLeaveEmptyFieldsInTheOutput() throws Exception {
    // A row whose pose is far beyond reach: the solver fails and --out keeps the id only.
    Path ref = smallTargets(2);
    List<String> lines = Files.readAllLines(ref);
    String[] f = lines.get(2).split(",");
    f[7] = "3.0"; // x = 3 m
    lines.set(2, String.join(",", f));
    Files.write(ref, lines);
    Path out = dir.resolve("s.csv");
    Run r = run("bench", "ik", "--targets", ref.toString(), "--warmup", "0", "--warmup-ms", "0", "--out", out.toString());
    assertThat(r.code()).isZero();
    assertThat(r.out()).startsWith("solved=1/2 in_limits=1/2 same_config=1/2 ");
    assertThat(Files.readAllLines(out).get(2)).isEqualTo(f[0] + ",,,,,,");
  }

  @Test
  void badFileIsOneLineAndExitTwo() throws Exception {
    Path bad = dir.resolve("bad.csv");
    Files.writeString(bad, "id,q1\n1,2\n");
    Run r = run("bench", "ik", "--targets", bad.toString());
    assertThat(r.code()).isEqualTo(2);
    assertThat(r.err().lines()).hasSize(1);
    assertThat(r.err()).contains("bad.csv:1: header is missing column");

    Run missing = run("bench", "ik", "--targets", dir.resolve("nope.csv").toString());
    assertThat(missing.code()).isEqualTo(2);
    assertThat(missing.err()).contains("nope.csv: no such file");
  }

  @Test
  void unknownSolverIsABadArgument() throws Exception {
    Run r = run("bench", "ik", "--targets", smallTargets(1).toString(), "--solver", "magic");
    assertThat(r.code()).isEqualTo(2);
    assertThat(r.err()).contains("--solver: expected auto, closed-form, offset-wrist, ur-type, numeric or resolved-rate");
  }

  @Test
  void helpListsEveryOption() {
    Run r = run("bench", "ik", "--help");
    assertThat(r.code()).isZero();
    assertThat(r.out()).contains("--targets", "--start", "--solver", "--out", "--warmup", "--warmup-ms", "resolved-rate");
  }
}
