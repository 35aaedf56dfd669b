package org.robotrun.app;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.robotrun.io.ScenarioLoad;
import org.robotrun.io.ScenarioReader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code robotrun bench scenario}: how long loading (parsing and checking) a scenario takes. */
@Command(
    name = "scenario",
    mixinStandardHelpOptions = true,
    description = "Load a scenario file repeatedly and print the median load time (first load reported apart).")
public final class BenchScenarioCommand implements Runnable {
  @Spec CommandSpec spec;

  @Option(names = "--file", required = true, paramLabel = "SCENARIO.json", description = "The scenario to load.")
  Path file;

  @Option(names = "--repeat", defaultValue = "200", paramLabel = "R",
      description = "Timed loads after the first; the median is reported (default: ${DEFAULT-VALUE}).")
  int repeat;

  @Override
  public void run() {
    if (repeat < 1) {
      throw new UserError("--repeat must be at least 1, got " + repeat);
    }
    long t0 = System.nanoTime();
    ScenarioLoad first = ScenarioReader.read(file);
    long firstNs = System.nanoTime() - t0;
    if (first instanceof ScenarioLoad.Failed f) {
      throw new UserError(f.message());
    }
    long[] ns = new long[repeat];
    for (int r = 0; r < repeat; r++) {
      long s = System.nanoTime();
      ScenarioReader.read(file);
      ns[r] = System.nanoTime() - s;
    }
    Arrays.sort(ns);
    PrintWriter out = spec.commandLine().getOut();
    out.printf(Locale.ROOT, "file=%s first_load_ms=%.2f load_ms=%.3f%n", file, firstNs / 1e6, ns[repeat / 2] / 1e6);
    out.flush();
  }
}
