package org.robotrun.app;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.robotrun.collision.Obb;
import org.robotrun.collision.SeparatingAxisTest;
import org.robotrun.collision.bench.ObbPairGenerator;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.ObbPairsCsv;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code robotrun bench collision}: the separating-axis test over a file of box pairs. Warms
 * up, then times whole passes over the batch and reports the median per pair.
 */
@Command(
    name = "collision",
    mixinStandardHelpOptions = true,
    description = {
      "Time the OBB separating-axis test on box pairs from a CSV file.",
      "Prints 'pairs=N overlapping=K ns_per_pair=X' (median of the timed passes).",
      "CSV: a header line, then 30 columns per pair, box A then box B:",
      "cx,cy,cz (mm), hx,hy,hz (half extents, mm), r11..r33 (row-major rotation).",
      "Touching boxes count as overlapping."
    })
public final class BenchCollisionCommand implements Runnable {
  @Spec CommandSpec spec;

  @Option(names = "--pairs", required = true, paramLabel = "FILE.csv",
      description = "Box pairs to test (written first when --generate is given).")
  Path pairsFile;

  @Option(names = "--out", paramLabel = "results.csv",
      description = "Write one line per pair: 1 if the boxes overlap or touch, else 0.")
  Path outFile;

  @Option(names = "--generate", paramLabel = "N",
      description = "Write N seeded random pairs (general, touching, nested, edge-edge ...) to --pairs first.")
  Integer generate;

  @Option(names = "--seed", defaultValue = "1", paramLabel = "S",
      description = "Seed for --generate (default: ${DEFAULT-VALUE}).")
  long seed;

  @Option(names = "--repeat", defaultValue = "15", paramLabel = "R",
      description = "Timed passes over the whole batch; the median is reported (default: ${DEFAULT-VALUE}).")
  int repeat;

  @Option(names = "--clock", defaultValue = "wall", paramLabel = "wall|cpu",
      description = "Time with the wall clock or with this thread's CPU time (steadier on a busy machine); default: ${DEFAULT-VALUE}.")
  String clockName;

  @Override
  public void run() {
    BenchClock clock = BenchClock.named(clockName);
    if (repeat < 1) {
      throw new UserError("--repeat must be at least 1, got " + repeat);
    }
    if (generate != null) {
      writeGenerated();
    }
    ObbPairsCsv.Pairs pairs;
    try {
      pairs = ObbPairsCsv.read(pairsFile);
    } catch (FileFormatException e) {
      throw new UserError(e.getMessage());
    } catch (org.robotrun.io.UnreadableFileException e) {
      throw new UserError(pairsFile + ": " + e.getMessage());
    } catch (IOException e) {
      throw new UserError(pairsFile + ": cannot read: " + e.getMessage());
    }
    if (pairs.count() == 0) {
      throw new UserError(pairsFile + ": no pairs after the header line");
    }
    boolean[] overlap = new boolean[pairs.count()];
    double nsPerPair = time(pairs, overlap, clock);
    int overlapping = 0;
    for (boolean o : overlap) {
      overlapping += o ? 1 : 0;
    }
    if (outFile != null) {
      writeResults(overlap);
    }
    PrintWriter out = spec.commandLine().getOut();
    out.printf(Locale.ROOT, "pairs=%d overlapping=%d ns_per_pair=%.2f%n", pairs.count(), overlapping, nsPerPair);
    out.flush();
  }

  private double time(ObbPairsCsv.Pairs pairs, boolean[] overlap, BenchClock clock) {
    // Warm up with at least 2 million tests and half a second (at most 5 s), so that the JIT's
    // optimised code is in place even when the compiler thread has to wait for a core.
    long warmStart = System.nanoTime();
    long tested = 0;
    while ((tested < 2_000_000 || System.nanoTime() - warmStart < 500_000_000L)
        && System.nanoTime() - warmStart < 5_000_000_000L) {
      pass(pairs, overlap);
      tested += overlap.length;
    }
    return (double) clock.medianNanos(repeat, () -> pass(pairs, overlap)) / pairs.count();
  }

  private static void pass(ObbPairsCsv.Pairs pairs, boolean[] overlap) {
    double[] a = pairs.a();
    double[] b = pairs.b();
    for (int i = 0; i < overlap.length; i++) {
      overlap[i] = SeparatingAxisTest.overlap(a, i, b, i);
    }
  }

  private void writeGenerated() {
    if (generate < 1) {
      throw new UserError("--generate must be at least 1, got " + generate);
    }
    List<Obb> a = new ArrayList<>(generate);
    List<Obb> b = new ArrayList<>(generate);
    for (ObbPairGenerator.LabeledPair p : new ObbPairGenerator(seed).pairs(generate)) {
      a.add(p.a());
      b.add(p.b());
    }
    try {
      ObbPairsCsv.write(pairsFile, a, b);
    } catch (IOException e) {
      throw new UserError(pairsFile + ": cannot write: " + e.getMessage());
    }
  }

  private void writeResults(boolean[] overlap) {
    StringBuilder sb = new StringBuilder(2 * overlap.length);
    for (boolean o : overlap) {
      sb.append(o ? "1\n" : "0\n");
    }
    try {
      org.robotrun.io.AtomicFiles.write(outFile, sb.toString().getBytes(StandardCharsets.UTF_8));
    } catch (IOException e) {
      throw new UserError(outFile + ": cannot write: " + e.getMessage());
    }
  }
}
