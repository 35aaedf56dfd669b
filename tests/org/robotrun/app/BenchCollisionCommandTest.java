package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.collision.Obb;
import org.robotrun.collision.SeparatingAxisTest;
import org.robotrun.io.ObbPairsCsv;
import picocli.CommandLine;

class BenchCollisionCommandTest {
  @TempDir Path dir;

  private record Run(int exit, String out, String err) {}

  private static Run run(String... args) {
    CommandLine cl = Main.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cl.setOut(new PrintWriter(out));
    cl.setErr(new PrintWriter(err));
    int exit = cl.execute(args);
    return new Run(exit, out.toString(), err.toString());
  }

  @Test
  void generatesTimesAndWritesOneResultPerPair() throws Exception {
    Path pairs = dir.resolve("pairs.csv");
    Path results = dir.resolve("results.csv");
    Run r = run("bench", "collision", "--generate", "500", "--seed", "3", "--pairs", pairs.toString(),
        "--out", results.toString(), "--repeat", "3", "--clock", "cpu");
    assertThat(r.exit()).as(r.err()).isZero();
    assertThat(r.out()).matches("pairs=500 overlapping=\\d+ ns_per_pair=\\d+\\.\\d\\d\\R");
    List<String> lines = Files.readAllLines(results);
    assertThat(lines).hasSize(500).allMatch(l -> l.equals("0") || l.equals("1"));
    // Each line is the SAT answer for the pair read back from the file.
    ObbPairsCsv.Pairs read = ObbPairsCsv.read(pairs);
    int overlapping = 0;
    for (int i = 0; i < 500; i++) {
      boolean o = SeparatingAxisTest.overlap(Obb.readFrom(read.a(), i), Obb.readFrom(read.b(), i));
      assertThat(lines.get(i)).isEqualTo(o ? "1" : "0");
      overlapping += o ? 1 : 0;
    }
    assertThat(r.out()).contains("overlapping=" + overlapping + " ");
  }

  @Test
  void badRowIsOneLineNamingFileAndLineWithExitTwo() throws Exception {
    Path pairs = dir.resolve("bad.csv");
    String good = "0,0,0,1,1,1,1,0,0,0,1,0,0,0,1,";
    Files.writeString(pairs, ObbPairsCsv.header() + "\n" + good + good.substring(0, good.length() - 1) + "\n"
        + good + "0,0,0,1,1,1,1,0,0,0,1,0,0,0,x\n");
    Run r = run("bench", "collision", "--pairs", pairs.toString());
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err().strip()).isEqualTo("robotrun: " + pairs + ":3: column b_r33: expected a number, got 'x'");
  }

  @Test
  void unknownClockIsExitTwo() {
    Run r = run("bench", "broadphase", "--clock", "sundial");
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err().strip()).isEqualTo("robotrun: --clock: expected wall or cpu, got 'sundial'");
  }

  @Test
  void missingFileIsExitTwo() {
    Run r = run("bench", "collision", "--pairs", dir.resolve("nope.csv").toString());
    assertThat(r.exit()).isEqualTo(2);
    assertThat(r.err()).contains("nope.csv: no such file");
  }

  @Test
  void broadPhaseAndScenarioBenchmarksPrintTheirFigures() {
    Run bp = run("bench", "broadphase", "--ticks", "50", "--repeat", "1", "--warmup", "10", "--clock", "cpu");
    assertThat(bp.exit()).as(bp.err()).isZero();
    assertThat(bp.out()).matches("bodies=216 ticks=50 contacts_per_tick=\\d+\\.\\d\\d us_per_tick=\\d+\\.\\d\\d\\R");
    // The pick-and-place cell: 5 objects and the LR Mate's 14 link shapes.
    Run cell = run("bench", "broadphase", "--scenario", "scenarios/pick-and-place.json", "--ticks", "20",
        "--repeat", "1", "--warmup", "0");
    assertThat(cell.exit()).as(cell.err()).isZero();
    assertThat(cell.out()).startsWith("bodies=19 ticks=20 ");
    Run sc = run("bench", "scenario", "--file", "scenarios/pick-and-place.json", "--repeat", "2");
    assertThat(sc.exit()).as(sc.err()).isZero();
    assertThat(sc.out()).startsWith("file=scenarios/pick-and-place.json first_load_ms=");
  }
}
