package org.robotrun.robot;

import java.util.List;
import org.robotrun.math.Transform;

/**
 * An arm's inverse kinematics as the controller uses it: every solution of a flange pose with
 * its FANUC {@link Config}, the solution in a taught CONFIG, and the solution nearest the
 * current joints (jogging and linear moves, so the arm never changes configuration on its own).
 * Targets are flange poses in the robot base frame B (mm); joints in the kinematic convention
 * (rad).
 *
 * <p>{@link #forModel} chooses the solver from the chain when a model is loaded: the OPW closed
 * form where the chain is ortho-parallel with a spherical wrist (parameters derived from the
 * chain, see {@link OpwDerivation}), the one-dimensional search of {@link OffsetWristIk} for
 * the CRX layout (offset wrist), the closed form of {@link UrTypeIk} for three parallel axes
 * with an offset wrist (the UR layout), else the numeric solver ({@link NumericSolver}). Solvers hold
 * scratch arrays: one per thread.
 */
public interface IkSolver {

  /** A labelled solution. */
  record Solution(double[] q, Config config) {}

  /** The model this solver was built for. */
  RobotModel model();

  /** Which solver this is, for listings and reports: "closed-form", "offset-wrist", "ur-type", "numeric". */
  String kind();

  /** The CONFIG of a joint vector. */
  Config configOf(double[] q);

  /**
   * The solution in {@code config} (flags and turn numbers), for taught positions; where two
   * solutions share that CONFIG, the one nearest {@code qNear}. A solver that cannot tell
   * branches apart (numeric) returns the solution it reaches from {@code qNear}.
   */
  IkResult solve(Transform X_BF, Config config, double[] qNear);

  /** The solution nearest {@code qCurrent} over every branch and turn inside the limits. */
  IkResult solveNearest(Transform X_BF, double[] qCurrent);

  /** Every solution inside the limits, each turn variant separately (allocates). */
  List<Solution> allSolutions(Transform X_BF);

  /** The solver for a model, chosen from its chain. */
  static IkSolver forModel(RobotModel model) {
    if (model.opw().isPresent()) {
      return new ClosedFormIk(model);
    }
    if (OffsetWristIk.applies(model)) {
      return new OffsetWristIk(model);
    }
    if (UrTypeIk.applies(model)) {
      return new UrTypeIk(model);
    }
    return new NumericSolver(model);
  }

  /** The solver kind {@link #forModel} picks, without building it. */
  static String kindFor(RobotModel model) {
    return model.opw().isPresent() ? ClosedFormIk.KIND : OffsetWristIk.applies(model) ? OffsetWristIk.KIND
        : UrTypeIk.applies(model) ? UrTypeIk.KIND : NumericSolver.KIND;
  }
}
