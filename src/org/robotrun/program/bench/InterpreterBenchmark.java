package org.robotrun.program.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Interpreter throughput on non-motion statements (issue 4 target: at least 20 million
 * instructions/s on one core). One operation is one executed TP line.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class InterpreterBenchmark {
  /** Loop iterations per invocation. */
  static final int LOOPS = 100_000;
  /** Lines one invocation executes (InterpreterWorkload.linesPerRun() for LOOPS, checked in a test). */
  static final int LINES = 757_145;

  private InterpreterWorkload workload;

  @Setup(Level.Trial)
  public void setUp() {
    workload = new InterpreterWorkload(LOOPS);
    if (workload.linesPerRun() != LINES) {
      throw new IllegalStateException("LINES is stale: workload runs " + workload.linesPerRun());
    }
  }

  @Benchmark
  @OperationsPerInvocation(LINES)
  public double nonMotionLines() {
    workload.run();
    return workload.checksum();
  }
}
