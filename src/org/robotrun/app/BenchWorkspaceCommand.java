package org.robotrun.app;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.robotrun.io.AtomicFiles;
import org.robotrun.program.Instruction;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun bench workspace}: how fast a change reaches the disk, and how long a big workspace takes to open. */
@Command(
    name = "workspace",
    mixinStandardHelpOptions = true,
    description = {
      "Measure workspace persistence in a temporary folder, in wall-clock time.",
      "Two figures:",
      "change-to-disk: a register is set or a program made while frames (16 ms apart) poll the autosave, until the file on disk holds it;",
      "open: opening a workspace with --programs copies of scenarios/programs/PICKPLACE.LS and building its cell (run from the project folder)."
    })
public final class BenchWorkspaceCommand implements Callable<Integer> {
  @Option(names = "--changes", defaultValue = "20", description = "Changes to time (default: ${DEFAULT-VALUE}).")
  int changes;

  @Option(names = "--programs", defaultValue = "100", description = "Programs in the workspace opened (default: ${DEFAULT-VALUE}).")
  int programs;

  @Option(names = "--opens", defaultValue = "7", description = "Times it is opened (default: ${DEFAULT-VALUE}).")
  int opens;

  @Override
  public Integer call() throws Exception {
    if (changes < 1 || programs < 0 || opens < 1) {
      throw new UserError("--changes and --opens must be at least 1, --programs at least 0");
    }
    Path tmp = Files.createTempDirectory("robotrun-bench-ws");
    try {
      double[] latencyMs = changeToDisk(tmp.resolve("changes"));
      Arrays.sort(latencyMs);
      System.out.printf(Locale.ROOT, "workspace change-to-disk: median %.0f ms, max %.0f ms over %d changes%n",
          latencyMs[latencyMs.length / 2], latencyMs[latencyMs.length - 1], latencyMs.length);
      double[] openMs = open(tmp.resolve("big"));
      Arrays.sort(openMs);
      System.out.printf(Locale.ROOT, "workspace open with %d programs: median %.0f ms, max %.0f ms over %d opens%n",
          programs, openMs[openMs.length / 2], openMs[openMs.length - 1], openMs.length);
    } finally {
      try (var s = Files.walk(tmp)) {
        s.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
      }
    }
    return Main.EXIT_OK;
  }

  private double[] changeToDisk(Path dir) throws Exception {
    double[] out = new double[changes];
    try (WorkspaceSession s = WorkspaceSession.open(dir, false, Optional::empty, m -> System.err.println(m))) {
      Controller c = s.sim.controllers().get(0);
      java.util.Random random = new java.util.Random(3);
      for (int i = 0; i < changes; i++) {
        // A change lands at a random moment of the autosave's cycle.
        long wait = System.nanoTime() + (long) (random.nextDouble() * 600e6);
        while (System.nanoTime() < wait) {
          s.autosave.poll(System.nanoTime());
          Thread.sleep(16);
        }
        long t0 = System.nanoTime();
        boolean program = i % 2 == 1;
        String needle;
        Path file;
        if (program) {
          c.saveProgram(Program.of("B" + i, List.of(new Instruction.Comment("change " + i))));
          file = dir.resolve("programs/B" + i + ".LS");
          needle = "change " + i;
        } else {
          c.registers().setInteger(1, 1000 + i);
          file = dir.resolve("cell.json");
          needle = "\"1\" : " + (1000 + i);
        }
        while (true) {
          s.autosave.poll(System.nanoTime());
          if (Files.exists(file) && Files.readString(file, StandardCharsets.UTF_8).contains(needle)) {
            break;
          }
          Thread.sleep(16);
          if (System.nanoTime() - t0 > 10_000_000_000L) {
            throw new UserError("a change was not on disk after 10 s", Main.EXIT_FAILED);
          }
        }
        out[i] = (System.nanoTime() - t0) / 1e6;
      }
    }
    return out;
  }

  private double[] open(Path dir) throws IOException {
    try (WorkspaceSession s = WorkspaceSession.open(dir, false, Optional::empty, m -> {})) {
      // made through the session so the cell is a real one
    }
    // Each program a copy of the pick-and-place example (motions, positions, I/O, a loop).
    String template = Files.readString(Path.of("scenarios/programs/PICKPLACE.LS"), StandardCharsets.UTF_8);
    for (int p = 0; p < programs; p++) {
      AtomicFiles.write(dir.resolve("programs/P" + p + ".LS"),
          template.replace("PICKPLACE", "P" + p).getBytes(StandardCharsets.UTF_8));
    }
    double[] out = new double[opens];
    for (int i = 0; i < opens; i++) {
      long t0 = System.nanoTime();
      try (WorkspaceSession s = WorkspaceSession.open(dir, false, Optional::empty, m -> {})) {
        if (s.sim.controllers().get(0).programNames().size() != programs) {
          throw new UserError("opened " + s.sim.controllers().get(0).programNames().size() + " programs, expected " + programs,
              Main.EXIT_FAILED);
        }
        out[i] = (System.nanoTime() - t0) / 1e6;
      }
    }
    return out;
  }
}
