package org.robotrun.app;

import java.io.PrintWriter;
import java.util.Locale;
import java.nio.file.Path;
import org.robotrun.collision.bench.CellScene;
import org.robotrun.io.ScenarioLoad;
import org.robotrun.io.ScenarioReader;
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
      "Time one collision update (broad phase, pair filter, separating-axis test) per tick.",
      "The cell is synthetic (2 robots x 8 boxes and 200 objects) or a scenario's; prints the median per tick."
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

  @Option(names = "--scenario", paramLabel = "FILE.json",
      description = "Time this scenario's objects and robots (joints swinging about their start) instead of the synthetic cell.")
  Path scenario;

  @Option(names = "--seed", defaultValue = "1", paramLabel = "S",
      description = "Seed placing the tables and parts (default: ${DEFAULT-VALUE}).")
  long seed;

  @Option(names = "--clock", defaultValue = "wall", paramLabel = "wall|cpu",
      description = "Time with the wall clock or with this thread's CPU time (steadier on a busy machine); default: ${DEFAULT-VALUE}.")
  String clockName;

  @Override
  public void run() {
    BenchClock clock = BenchClock.named(clockName);
    if (ticks < 1 || repeat < 1 || warmup < 0) {
      throw new UserError("--ticks and --repeat must be at least 1, --warmup at least 0");
    }
    java.util.function.IntUnaryOperator scene;
    int bodies;
    if (scenario == null) {
      CellScene cell = new CellScene(seed);
      scene = cell::tick;
      bodies = cell.bodies();
    } else {
      ScenarioCollisionScene s = switch (ScenarioReader.read(scenario)) {
        case ScenarioLoad.Loaded l -> new ScenarioCollisionScene(l.scenario());
        case ScenarioLoad.Failed f -> throw new UserError(f.message());
      };
      scene = s::tick;
      bodies = s.bodies();
    }
    for (int t = 0; t < warmup; t++) {
      scene.applyAsInt(t);
    }
    double usPerTick = clock.medianNanos(repeat, () -> {
      for (int t = 0; t < ticks; t++) {
        scene.applyAsInt(t);
      }
    }) / 1000.0 / ticks;
    long perTick = 0;
    for (int t = 0; t < ticks; t++) {
      perTick += scene.applyAsInt(t);
    }
    PrintWriter out = spec.commandLine().getOut();
    out.printf(Locale.ROOT, "bodies=%d ticks=%d contacts_per_tick=%.2f us_per_tick=%.2f%n",
        bodies, ticks, (double) perTick / ticks, usPerTick);
    out.flush();
  }
}
