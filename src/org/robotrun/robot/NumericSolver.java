package org.robotrun.robot;

import java.util.List;
import org.robotrun.math.Transform;

/**
 * The last resort for an arm that is neither OPW nor of the CRX layout: the damped least
 * squares solver ({@link NumericIk}) behind the {@link IkSolver} interface. It finds one
 * solution, the one its iteration reaches from the start it is given, so it cannot honour a
 * taught CONFIG: {@link #solve(Transform, Config, double[])} starts from {@code qNear} and the
 * result's CONFIG may differ (a program names the joints it expects by a nearby position).
 */
public final class NumericSolver implements IkSolver {
  /** {@link IkSolver#kind()} of this solver. */
  public static final String KIND = "numeric";

  private final RobotModel model;
  private final NumericIk ik;
  private final ChainConfig config;

  public NumericSolver(RobotModel model) {
    this.model = model;
    this.ik = new NumericIk(model);
    this.config = new ChainConfig(new KinematicChain(model));
  }

  @Override
  public RobotModel model() {
    return model;
  }

  @Override
  public String kind() {
    return KIND;
  }

  @Override
  public Config configOf(double[] q) {
    return config.configOf(q);
  }

  @Override
  public IkResult solve(Transform X_BF, Config wanted, double[] qNear) {
    return ik.solve(X_BF, qNear);
  }

  @Override
  public IkResult solveNearest(Transform X_BF, double[] qCurrent) {
    return ik.solve(X_BF, qCurrent);
  }

  @Override
  public List<Solution> allSolutions(Transform X_BF) {
    return ik.solve(X_BF, new double[6]) instanceof IkResult.Solved s
        ? List.of(new Solution(s.q(), configOf(s.q()))) : List.of();
  }
}
