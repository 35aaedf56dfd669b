package org.robotrun.io.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.LsWriter;

/**
 * .LS parse throughput in lines per second: one operation is one /MN line, so JMH's ops/s is
 * lines/s. Also the writer, for comparison.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class LsParseBenchmark {
  static final int LINES = 10_000;

  private String text;
  private LsReadResult parsed;

  @Setup
  public void setUp() {
    text = LsBenchPrograms.program(LINES);
    parsed = LsReader.parse("bench.ls", text);
    if (!parsed.diagnostics().isEmpty()) {
      throw new IllegalStateException("benchmark program has diagnostics: " + parsed.diagnostics().get(0));
    }
  }

  @Benchmark
  @OperationsPerInvocation(LINES)
  public LsReadResult parseLines() {
    return LsReader.parse("bench.ls", text);
  }

  @Benchmark
  @OperationsPerInvocation(LINES)
  public String writeLines() {
    return LsWriter.write(parsed.program());
  }
}
