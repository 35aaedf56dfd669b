package org.robotrun.app.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.robot.ResolvedRate;
import org.robotrun.robot.RobotModel;

/** JMH: one resolved-rate step (Jacobian, manipulability, damped solve) on the default robot. */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class ResolvedRateBench {
  private ResolvedRate rr;
  private KinematicsTargets targets;
  private final double[] twist = {100, 0, 0, 0, 0, 0.2};
  private final double[] qDot = new double[6];
  private int i;

  @Setup
  public void setUp() {
    RobotModel model = RobotDefinitions.defaultRobot();
    rr = new ResolvedRate(model);
    targets = new KinematicsTargets(model);
  }

  @Benchmark
  public double[] step() {
    int k = i++ & (KinematicsTargets.COUNT - 1);
    rr.step(targets.q[k], twist, null, qDot);
    return qDot;
  }
}
