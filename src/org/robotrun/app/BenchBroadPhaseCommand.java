package org.robotrun.app;

import java.io.PrintWriter;
import java.util.Arrays;
import java.util.Locale;
import org.robotrun.collision.bench.CellScene;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code robotrun bench broadphase}: the whole-cell collision check per tick on a synthetic
 * cell of 2 robots × 8 boxes and 200 objects (see {@link CellScene}).
 */
@Command(
    name = "broadphase",
    mixinStandardHelpOptions = true,
    description = {
      "Time one collision update (sort-and-sweep broad phase, pair filter, separating-axis test)",
      "on a synthetic cell of 2 robots x 8 boxes and 200 objects; prints the median per tick."
    })
public final class BenchBroadPhaseCommand implements Runnable {
  @Spec CommandSpec spec;

  @Option(names = "--ticks", defaultValue = "20000", paramLabel = "N",
      description = "Ticks per timed pass (default: ${DEFAULT-VALUE}).")
  int ticks;

  @Option(names = "--repeat", defaultValue = "9", paramLabel = "R",
      description = "Timed passes; the median is reported (default: ${DEFAULT-VALUE}).")
  int repeat;

  @Option(names = "--warmup", defaultValue = "50000", paramLabel = "W",
      description = "Untimed ticks first, so the JIT has compiled the check (default: ${DEFAULT-VALUE}).")
  int warmup;

  @Option(names = "--seed", defaultValue = "1", paramLabel = "S",
      description = "Seed placing the tables and parts (default: ${DEFAULT-VALUE}).")
  long seed;

  @Override
  public void run() {
    if (ticks < 1 || repeat < 1 || warmup < 0) {
      throw new UserError("--ticks and --repeat must be at least 1, --warmup at least 0");
    }
    CellScene scene = new CellScene(seed);
    long contacts = 0;
    for (int t = 0; t < warmup; t++) {
      contacts += scene.tick(t);
    }
    long[] ns = new long[repeat];
    for (int r = 0; r < repeat; r++) {
      long t0 = System.nanoTime();
      for (int t = 0; t < ticks; t++) {
        contacts += scene.tick(t);
      }
      ns[r] = System.nanoTime() - t0;
    }
    Arrays.sort(ns);
    double usPerTick = ns[repeat / 2] / 1000.0 / ticks;
    long perTick = 0;
    for (int t = 0; t < ticks; t++) {
      perTick += scene.tick(t);
    }
    PrintWriter out = spec.commandLine().getOut();
    out.printf(Locale.ROOT, "bodies=%d ticks=%d contacts_per_tick=%.2f us_per_tick=%.2f%n",
        scene.bodies(), ticks, (double) perTick / ticks, usPerTick);
    out.flush();
  }
}
