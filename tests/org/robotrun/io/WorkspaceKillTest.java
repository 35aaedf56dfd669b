package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;

/**
 * Crash safety: a child JVM edits a workspace in a loop with autosave on and is killed
 * (SIGKILL) at a random moment — during start-up, while opening, between edits or in the middle
 * of a save — 50 times. After every kill the workspace opens without a problem, every file is
 * whole, and what is on disk is a prefix of the edits made: programs P1..Pm with nothing
 * missing in between, each complete, and R[1] in cell.json at most m (the cell is written
 * after the programs of the same save). Every tenth child runs 2.2–2.6 s and must have lost at
 * most the edits of its last 2 s. Two children run at a time to keep the test short.
 */
class WorkspaceKillTest {
  private static final int KILLS = 50;

  @Test
  void killedAtRandomMomentsTheWorkspaceAlwaysOpensWithAPrefixOfTheEdits(@TempDir Path tmp) throws Exception {
    ExecutorService pool = Executors.newFixedThreadPool(2);
    try {
      List<Future<Integer>> cycles = new ArrayList<>();
      for (int kill = 0; kill < KILLS; kill++) {
        int k = kill;
        cycles.add(pool.submit(() -> cycle(tmp.resolve("ws" + k), new Random(1000 + k), k)));
      }
      int saved = 0;
      for (Future<Integer> f : cycles) {
        saved += f.get(120, TimeUnit.SECONDS);
      }
      assertThat(saved).as("saves did land before kills").isGreaterThan(KILLS);
    } finally {
      pool.shutdownNow();
    }
  }

  /** One child, killed at a random moment; returns how many edits were on disk afterwards. */
  private static int cycle(Path dir, Random random, int kill) throws Exception {
    String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
    int mustBeSaved = 0;
    Process p = new ProcessBuilder(java, "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-Xshare:auto",
        "-cp", System.getProperty("java.class.path"), WorkspaceEditLoop.class.getName(), dir.toString(),
        "scenarios/empty-cell.json").redirectError(ProcessBuilder.Redirect.DISCARD).start();
    try {
      if (kill % 10 == 9) {
        // A long run: every edit made more than 2 s before the kill must be on disk.
        BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        assertThat(out.readLine()).as("child %d started", kill).startsWith("ready");
        long start = System.nanoTime();
        long until = start + 2_200_000_000L + (long) (random.nextDouble() * 400e6);
        for (String line; System.nanoTime() < until && (line = out.readLine()) != null; ) {
          // The edit was made no later than it was read here.
          if (System.nanoTime() < until - 2_000_000_000L) {
            mustBeSaved = Integer.parseInt(line.strip());
          }
        }
      } else if (random.nextInt(5) == 0) {
        Thread.sleep(random.nextInt(400));  // while the JVM starts or the workspace is being created
      } else {
        BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        assertThat(out.readLine()).as("child %d started", kill).startsWith("ready");
        // Among edits, up to 0.6 s in (autosave checks every 0.5 s, so some kills land mid-save).
        long until = System.nanoTime() + (long) (random.nextDouble() * 600e6);
        while (System.nanoTime() < until && out.readLine() != null) {
          // let it edit
        }
      }
    } finally {
      p.destroyForcibly();
      p.waitFor(10, TimeUnit.SECONDS);
    }
    if (!Files.exists(dir)) {
      return 0;  // killed before it made the folder
    }
    Scenario cell = ((ScenarioLoad.Loaded) ScenarioReader.read(Path.of("scenarios/empty-cell.json"))).scenario();
    try (Workspace ws = Workspace.open(dir, cell)) {
      assertThat(ws.problems()).as("after kill %d", kill).isEmpty();
      List<Integer> numbers = new ArrayList<>();
      for (Program prog : ws.programs()) {
        int i = Integer.parseInt(prog.name().substring(1));
        assertThat(prog.lines()).as("P%d is whole", i).isEqualTo(WorkspaceEditLoop.program(i).lines());
        numbers.add(i);
      }
      numbers.sort(null);
      int m = numbers.size();
      for (int k = 0; k < m; k++) {
        assertThat(numbers.get(k)).as("kill %d: the programs on disk are P1..P%d, no gaps", kill, m).isEqualTo(k + 1);
      }
      int r1 = ws.state().map(s -> s.registers().containsKey(1) ? (int) s.registers().get(1).value() : 0).orElse(0);
      assertThat(r1).as("kill %d: R[1] was saved after its programs", kill).isLessThanOrEqualTo(m);
      assertThat(m).as("kill %d: at most the last 2 s of edits are lost", kill).isGreaterThanOrEqualTo(mustBeSaved);
      return m;
    }
  }
}
