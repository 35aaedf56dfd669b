package org.robotrun.collision.bench;

import java.util.List;
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
import org.robotrun.collision.Obb;
import org.robotrun.collision.SeparatingAxisTest;

/** JMH: the separating-axis test per pair, over 4096 seeded pairs of the generator's mix. */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class SatBenchmark {
  private static final int PAIRS = 4096;

  private double[] a;
  private double[] b;
  private Obb[] objA;
  private Obb[] objB;

  @Setup
  public void setUp() {
    List<ObbPairGenerator.LabeledPair> pairs = new ObbPairGenerator(1).pairs(PAIRS);
    a = new double[PAIRS * Obb.STRIDE];
    b = new double[PAIRS * Obb.STRIDE];
    objA = new Obb[PAIRS];
    objB = new Obb[PAIRS];
    for (int i = 0; i < PAIRS; i++) {
      pairs.get(i).a().writeTo(a, i);
      pairs.get(i).b().writeTo(b, i);
      objA[i] = pairs.get(i).a();
      objB[i] = pairs.get(i).b();
    }
  }

  /** Flat arrays, as the broad phase and {@code bench collision} use. */
  @Benchmark
  @OperationsPerInvocation(PAIRS)
  public int flatArrays() {
    int n = 0;
    for (int i = 0; i < PAIRS; i++) {
      n += SeparatingAxisTest.overlap(a, i, b, i) ? 1 : 0;
    }
    return n;
  }

  /** Obb records. */
  @Benchmark
  @OperationsPerInvocation(PAIRS)
  public int records() {
    int n = 0;
    for (int i = 0; i < PAIRS; i++) {
      n += SeparatingAxisTest.overlap(objA[i], objB[i]) ? 1 : 0;
    }
    return n;
  }
}
