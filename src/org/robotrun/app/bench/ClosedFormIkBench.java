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
import org.robotrun.robot.ClosedFormIk;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.RobotModel;

/**
 * JMH: one closed-form solve on the default robot, by CONFIG (taught positions) and nearest to
 * the true joints (jogging). Lives in app because robot may not import io (the robot loader).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class ClosedFormIkBench {
  private ClosedFormIk ik;
  private KinematicsTargets targets;
  private int i;

  @Setup
  public void setUp() {
    RobotModel model = RobotDefinitions.defaultRobot();
    ik = new ClosedFormIk(model);
    targets = new KinematicsTargets(model);
  }

  @Benchmark
  public IkResult solveByConfig() {
    int k = i++ & (KinematicsTargets.COUNT - 1);
    return ik.solve(targets.X_BF[k], targets.config[k]);
  }

  @Benchmark
  public IkResult solveNearest() {
    int k = i++ & (KinematicsTargets.COUNT - 1);
    return ik.solveNearest(targets.X_BF[k], targets.q[k]);
  }
}
