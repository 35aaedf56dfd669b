package org.robotrun.app.bench;

import java.util.SplittableRandom;
import org.robotrun.robot.ClosedFormIk;
import org.robotrun.robot.Config;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.RobotModel;
import org.robotrun.math.Transform;

/**
 * Benchmark inputs: joint vectors drawn uniformly inside the limits with a fixed seed (as the
 * reference targets are), their flange poses and CONFIGs, and an independent random start.
 * The reference CSV lives with the tests, not in the jar, so JMH makes its own.
 */
final class KinematicsTargets {
  static final int COUNT = 1024;

  final double[][] q = new double[COUNT][];
  final double[][] randomStart = new double[COUNT][];
  final Transform[] X_BF = new Transform[COUNT];
  final Config[] config = new Config[COUNT];

  KinematicsTargets(RobotModel model) {
    SplittableRandom rnd = new SplittableRandom(20140101);
    ClosedFormIk ik = new ClosedFormIk(model);
    double[] lo = model.lowerLimits(), hi = model.upperLimits();
    for (int i = 0; i < COUNT; i++) {
      q[i] = new double[6];
      randomStart[i] = new double[6];
      for (int j = 0; j < 6; j++) {
        q[i][j] = lo[j] + rnd.nextDouble() * (hi[j] - lo[j]);
        randomStart[i][j] = lo[j] + rnd.nextDouble() * (hi[j] - lo[j]);
      }
      X_BF[i] = ForwardKinematics.flangePoseInBase(model, q[i]);
      config[i] = ik.configOf(q[i]);
    }
  }
}
