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
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.NumericIk;
import org.robotrun.robot.RobotModel;

/**
 * JMH: one numeric IK solve on the default robot, from home and from a random start, and the
 * verdict on a target beyond reach (the issue bounds it at 1 ms).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class NumericIkBench {
  private NumericIk ik;
  private KinematicsTargets targets;
  private final double[] home = new double[6];
  private final Transform far = Xyzwpr.ofDegrees(1500, 200, 330, 180, 0, 0).toTransform();
  private int i;

  @Setup
  public void setUp() {
    RobotModel model = RobotDefinitions.defaultRobot();
    ik = new NumericIk(model);
    targets = new KinematicsTargets(model);
  }

  @Benchmark
  public IkResult solveFromHome() {
    int k = i++ & (KinematicsTargets.COUNT - 1);
    return ik.solve(targets.X_BF[k], home);
  }

  @Benchmark
  public IkResult solveFromRandomStart() {
    int k = i++ & (KinematicsTargets.COUNT - 1);
    return ik.solve(targets.X_BF[k], targets.randomStart[k]);
  }

  @Benchmark
  public IkResult unreachableVerdict() {
    return ik.solve(far, home);
  }
}
