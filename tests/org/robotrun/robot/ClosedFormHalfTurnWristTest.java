package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * The other wrist singularity of the OPW closed form: J5 = 180°, the J6 axis folded back onto
 * the J4 axis (reachable on an LR Mate whose J5 range is widened to ±200°). There, as at J5 = 0,
 * only a difference of J4 and J6 is fixed by the pose (J6 turns against J4 about the same line),
 * so the closed form keeps J4 (ClosedFormIk: "keep θ4"): the nearest solution keeps the current
 * J4, and every answer must still reach the pose by FK. Base solutions are wrapped into
 * (−180°, 180°] (solveAllBase), so a half-turn J5 is +180°, never −180°; CONFIG's F is J5 &gt; 0
 * on the wrapped value. Also: the tool-to-flange target formula, the model the solver was built
 * for, and the message for an arm without OPW parameters.
 */
class ClosedFormHalfTurnWristTest {
  static final RobotModel LRMATE = RobotDefinitions.load("lrmate200id");
  static final RobotModel WIDE = IkSolverContractTest.narrowed(LRMATE, 4, Math.toRadians(-200), Math.toRadians(200));

  @Test
  void atJ5HalfATurnTheNearestSolutionKeepsJ4AndReachesThePose() {
    ClosedFormIk ik = new ClosedFormIk(WIDE);
    for (double[] q : new double[][] {{0.4, 0.3, -0.2, 0.7, Math.PI, -0.5}, {-1.1, -0.4, 0.6, -2.0, -Math.PI, 2.5}}) {
      Transform X = ForwardKinematics.flangePoseInBase(WIDE, q);
      for (double dj4 : new double[] {0, 0.25, -0.6}) {
        double[] current = q.clone();
        current[3] += dj4;
        IkResult r = ik.solveNearest(X, current);
        assertThat(r).as("J4 moved by %s", dj4).isInstanceOf(IkResult.Solved.class);
        double[] got = ((IkResult.Solved) r).q();
        IkSolverContractTest.reaches(WIDE, got, X, "nearest, J4 moved by " + dj4);
        assertThat(got[3]).as("J4 kept").isCloseTo(current[3], within(1e-9));
        assertThat(Math.abs(ClosedFormIk.wrap(got[4]))).isCloseTo(Math.PI, within(1e-9));
        // J6 turns against J4 (both about the same line, J6's axis now folded back onto J4's).
        assertThat(ClosedFormIk.wrap(got[5] - q[5] - (got[3] - q[3]))).isCloseTo(0, within(1e-9));
      }
      // Solving by F and by N both land on the pose (the two wrists are the same posture there).
      for (boolean flip : new boolean[] {true, false}) {
        Config c = new Config(flip, ik.configOf(q).up(), ik.configOf(q).top(), 0, 0, 0);
        IkResult r = ik.solve(X, c);
        assertThat(r).as("%s", c).isInstanceOf(IkResult.Solved.class);
        IkSolverContractTest.reaches(WIDE, ((IkResult.Solved) r).q(), X, c.toString());
      }
    }
  }

  @Test
  void baseSolutionsAreWrappedIntoTheHalfOpenTurnSoAHalfTurnJ5IsPlus180() {
    ClosedFormIk ik = new ClosedFormIk(WIDE);
    double[] q = {0.4, 0.3, -0.2, 0.7, Math.PI, -0.5};
    Transform X = ForwardKinematics.flangePoseInBase(WIDE, q);
    double[] out = new double[48];
    int valid = ik.solveAllBase(X, out);
    assertThat(valid).isEqualTo(0xFF);
    int halfTurns = 0;
    for (int k = 0; k < 8; k++) {
      for (int i = 0; i < 6; i++) {
        double v = out[6 * k + i];
        assertThat(v).as("solution %d J%d", k, i + 1).isGreaterThan(-Math.PI).isLessThanOrEqualTo(Math.PI);
      }
      if (Math.abs(Math.abs(out[6 * k + 4]) - Math.PI) < 1e-9) {
        halfTurns++;
        assertThat(out[6 * k + 4]).isEqualTo(Math.PI);
        double[] s = java.util.Arrays.copyOfRange(out, 6 * k, 6 * k + 6);
        assertThat(ForwardKinematics.flangePoseInBase(WIDE, s).distanceTo(X)).as("solution %d", k).isLessThan(1e-6);
        assertThat(ik.configOf(s).flip()).as("J5 = +180 deg is F").isTrue();
      }
    }
    // Only the arm (J1, J2, J3) that made the pose has the folded wrist, and both its wrists are
    // that one posture: θ5 = π and its twin −θ5 = −π, wrapped to +π.
    assertThat(halfTurns).isEqualTo(2);
    // −180° and +180° are the same J5: wrapped, both are F.
    double[] minus = q.clone();
    minus[4] = -Math.PI;
    assertThat(ik.configOf(minus).flip()).isTrue();
    assertThat(ik.configOf(q).flip()).isTrue();
  }

  @Test
  void aToolTargetGivesTheFlangeThatPutsTheToolThere() {
    Transform tool = Transform.translation(12, -30, 140).compose(Transform.rotation(0, 0.6, 0.8, 0.9));
    double[] q = {0.2, 0.1, 0.3, -0.4, -0.9, 1.1};
    Transform flange = ForwardKinematics.flangePoseInBase(LRMATE, q);
    Transform toolInBase = flange.compose(tool);
    Transform asked = ClosedFormIk.flangeTarget(toolInBase, tool);
    assertThat(asked.distanceTo(flange)).isLessThan(1e-9);
    assertThat(asked.rotationAngleTo(flange)).isLessThan(1e-12);
  }

  @Test
  void theSolverKnowsItsArmAndRefusesOneWithoutTheClosedForm() {
    ClosedFormIk ik = new ClosedFormIk(LRMATE);
    assertThat(ik.model()).isSameAs(LRMATE);
    assertThat(ik.kind()).isEqualTo(ClosedFormIk.KIND);
    RobotModel ur5 = IkSolverContractTest.ur5(Math.PI);
    assertThatThrownBy(() -> new ClosedFormIk(ur5)).isInstanceOf(IllegalArgumentException.class)
        .hasMessage(ur5.id() + ": no OPW parameters, the closed-form solver does not apply");
  }
}
