package org.robotrun.app;

import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.bench.LsBenchPrograms;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code robotrun bench parse}: a quick .LS parse throughput figure (the JMH class
 * {@code org.robotrun.io.bench.LsParseBenchmark} is the careful one).
 */
@Command(
    name = "parse",
    mixinStandardHelpOptions = true,
    description = {
      "Measure .LS parse throughput on a generated program, after a warm-up.",
      "Prints lines_per_sec (best wall-clock round) and lines_per_cpu_sec (best round in this thread's CPU time, which other processes do not inflate), then times.",
      "With --corpus DIR it reads every *.LS file of DIR instead and also prints how many files read with no syntax error and how many come back byte for byte when written without an edit."
    })
public final class BenchParseCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(names = "--lines", paramLabel = "N", defaultValue = "10000",
      description = "Lines in the generated program (default: ${DEFAULT-VALUE}).")
  int lines;

  @Option(names = "--rounds", paramLabel = "N", defaultValue = "20",
      description = "Timed parses after the warm-up (default: ${DEFAULT-VALUE}).")
  int rounds;

  @Option(names = "--warmup", paramLabel = "N", defaultValue = "20",
      description = "Untimed warm-up parses, to let the JIT compile the parser (default: ${DEFAULT-VALUE}).")
  int warmup;

  @Option(names = "--corpus", paramLabel = "DIR",
      description = "Read the *.LS files of DIR (as controllers wrote them) instead of a generated program.")
  java.nio.file.Path corpus;

  @Override
  public Integer call() {
    if (lines < 1 || rounds < 1 || warmup < 0) {
      throw new UserError("--lines and --rounds must be at least 1, --warmup at least 0");
    }
    if (corpus != null) {
      return corpus();
    }
    String text = LsBenchPrograms.program(lines);
    LsReadResult check = LsReader.parse("bench.ls", text);
    if (!check.diagnostics().isEmpty()) {
      throw new UserError("generated program has diagnostics: " + check.diagnostics().get(0), Main.EXIT_FAILED);
    }
    for (int i = 0; i < warmup; i++) {
      LsReader.parse("bench.ls", text);
    }
    // CPU time of this thread as well as wall time: on a busy machine the wall clock also counts
    // the time other processes held the core.
    ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    boolean cpu = threads.isCurrentThreadCpuTimeSupported();
    long best = Long.MAX_VALUE;
    long bestCpu = Long.MAX_VALUE;
    long total = 0;
    for (int i = 0; i < rounds; i++) {
      long c0 = cpu ? threads.getCurrentThreadCpuTime() : 0;
      long t0 = System.nanoTime();
      LsReadResult r = LsReader.parse("bench.ls", text);
      long dt = System.nanoTime() - t0;
      long dc = cpu ? threads.getCurrentThreadCpuTime() - c0 : dt;
      if (r.program().lineCount() != lines) {
        throw new IllegalStateException("parsed " + r.program().lineCount() + " lines, expected " + lines);
      }
      best = Math.min(best, dt);
      bestCpu = Math.min(bestCpu, Math.max(dc, 1));
      total += dt;
    }
    PrintWriter out = spec.commandLine().getOut();
    out.println(String.format(Locale.ROOT,
        "lines_per_sec=%.0f lines_per_cpu_sec=%.0f lines=%d rounds=%d best_ms=%.3f mean_ms=%.3f best_cpu_ms=%.3f",
        lines / (best / 1e9), lines / (bestCpu / 1e9), lines, rounds, best / 1e6, total / 1e6 / rounds, bestCpu / 1e6));
    out.flush();
    return Main.EXIT_OK;
  }

  private Integer corpus() {
    java.util.List<java.nio.file.Path> files;
    java.util.List<byte[]> contents = new java.util.ArrayList<>();
    try {
      files = CheckCommand.programsIn(corpus);
      for (java.nio.file.Path f : files) {
        contents.add(org.robotrun.io.BoundedFiles.read(f, org.robotrun.io.LsReader.MAX_FILE_BYTES, ".LS programs"));
      }
    } catch (java.io.IOException e) {
      throw new UserError("--corpus: cannot read " + corpus + " (" + e.getMessage() + ")");
    }
    if (files.isEmpty()) {
      throw new UserError("--corpus: no .LS files in " + corpus);
    }
    int clean = 0;
    int identical = 0;
    long totalLines = 0;
    for (int i = 0; i < files.size(); i++) {
      LsReadResult r = LsReader.read(files.get(i).toString(), contents.get(i));
      clean += r.diagnostics().stream().noneMatch(d -> d.kind() == org.robotrun.io.Diagnostic.Kind.SYNTAX) ? 1 : 0;
      identical += java.util.Arrays.equals(org.robotrun.io.LsWriter.bytes(r.program()), contents.get(i)) ? 1 : 0;
      totalLines += new String(contents.get(i), java.nio.charset.StandardCharsets.ISO_8859_1).lines().count();
    }
    for (int w = 0; w < warmup; w++) {
      for (int i = 0; i < files.size(); i++) {
        LsReader.read(files.get(i).toString(), contents.get(i));
      }
    }
    long best = Long.MAX_VALUE;
    for (int k = 0; k < rounds; k++) {
      long t0 = System.nanoTime();
      for (int i = 0; i < files.size(); i++) {
        LsReader.read(files.get(i).toString(), contents.get(i));
      }
      best = Math.min(best, System.nanoTime() - t0);
    }
    spec.commandLine().getOut().println(String.format(Locale.ROOT,
        "files=%d no_syntax_error=%d identical_after_round_trip=%d lines=%d lines_per_sec=%.0f best_ms=%.3f",
        files.size(), clean, identical, totalLines, totalLines / (best / 1e9), best / 1e6));
    return Main.EXIT_OK;
  }
}
