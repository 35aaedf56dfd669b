package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The same CRX written with other joint frames is the same machine. A chain file may put each
 * joint's frame anywhere on its axis and turned any way about it; only the axis line matters.
 * Here every joint frame J_i is replaced by J_i · C_i, with C_i a shift along the joint's own axis
 * and a turn about an oblique direction (both made up in the test), the next joint's origin and
 * the flange compensated by C_i⁻¹ (so link i becomes L_i · C_i: a turn about the axis commutes
 * with a shift along it). The joint axes are then no longer coordinate axes of their frames, and
 * the joint origins lie off the arm plane, so no term of the search's vector algebra vanishes.
 *
 * <p>Expected (nothing from the solver's own output): the test's FK of both chains agrees; the
 * offset-wrist search still applies; for each pose, the re-framed arm's solutions are exactly
 * the original arm's (the same joint values, since each joint still turns the same way), the
 * joints that made the pose are among them, each solution reaches the pose, and solving by
 * CONFIG near the truth and nearest the truth return the truth.
 */
class OffsetWristReframedTest {

  /** The model with joint i's frame moved by C_i (shift along its axis, then an oblique turn). */
  static RobotModel reframed(RobotModel m, long seed) {
    Random rnd = new Random(seed);
    Transform prev = Transform.IDENTITY;
    List<JointSpec> js = new ArrayList<>();
    for (int i = 0; i < 6; i++) {
      JointSpec j = m.joint(i);
      Vec3 a = j.axis();
      // An oblique direction (no coordinate axis stays put) and an angle of 0.6..1.2 rad.
      Vec3 dir = new Vec3(1 + rnd.nextDouble(), -1 - rnd.nextDouble(), 0.5 + rnd.nextDouble()).normalized();
      Transform turn = Transform.rotation(dir.x(), dir.y(), dir.z(), 0.6 + 0.6 * rnd.nextDouble());
      double shift = 40 + 80 * rnd.nextDouble();
      Transform c = Transform.translation(a.x() * shift, a.y() * shift, a.z() * shift).compose(turn);
      js.add(new JointSpec(j.name(), prev.inverse().compose(j.X_PJ()).compose(c), turn.inverse().rotate(a),
          j.lowerRad(), j.upperRad(), j.maxSpeedRadPerSec()));
      prev = c;
    }
    return RobotModel.fromChain(m.id() + "-reframed", m.displayName(), js, prev.inverse().compose(m.X_6F()), m.X_WB(),
        m.links(), m.coupledJ3());
  }

  static boolean among(List<double[]> set, double[] q, double tol) {
    return set.stream().anyMatch(s -> OffsetWristCompletenessTest.wrappedDiff(s, q) < tol);
  }

  @ParameterizedTest
  @ValueSource(strings = {"crx10ia", "crx10ial"})
  void otherJointFramesOnTheSameAxesGiveTheSameSolutions(String id) {
    RobotModel m = RobotDefinitions.load(id);
    RobotModel r = reframed(m, 31 + id.length());
    for (int i = 0; i < 6; i++) {
      Vec3 a = r.joint(i).axis();
      assertThat(Math.max(Math.abs(a.x()), Math.max(Math.abs(a.y()), Math.abs(a.z())))).as("J%d axis oblique", i + 1)
          .isLessThan(0.95);
    }
    assertThat(r.wristKind()).isEqualTo("offset");
    IkSolver solver = IkSolver.forModel(r);
    assertThat(solver.kind()).isEqualTo(OffsetWristIk.KIND);
    assertThat(solver.model()).isSameAs(r);
    OffsetWristIk plain = new OffsetWristIk(m);
    OffsetWristIk moved = (OffsetWristIk) solver;
    List<double[]> poses = new ArrayList<>(OffsetWristCompletenessTest.poses(m, 900 + id.length()));
    poses.addAll(IkSolverContractTest.samples(m, 910 + id.length(), 6));
    for (double[] q : poses) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      String what = id + " reframed, pose " + Arrays.toString(q);
      Transform Y = ForwardKinematics.flangePoseInBase(r, q);
      assertThat(Y.distanceTo(X)).as("%s: FK", what).isLessThan(1e-9);
      assertThat(Y.rotationAngleTo(X)).as("%s: FK", what).isLessThan(1e-12);
      List<double[]> a = plain.baseSolutions(X);
      List<double[]> b = moved.baseSolutions(X);
      assertThat(among(b, q, 1e-6)).as("%s: its own joints", what).isTrue();
      assertThat(b).as("%s: solution count", what).hasSameSizeAs(a);
      for (double[] s : a) {
        assertThat(among(b, s, 1e-7)).as("%s: %s", what, Arrays.toString(s)).isTrue();
      }
      for (double[] s : b) {
        Transform Z = ForwardKinematics.flangePoseInBase(r, s);
        assertThat(Z.distanceTo(X)).as("%s: solution %s", what, Arrays.toString(s)).isLessThan(1e-6);
        assertThat(Z.rotationAngleTo(X)).isLessThan(1e-9);
      }
      Config c = moved.configOf(q);
      assertThat(c).as("%s: CONFIG", what).isEqualTo(plain.configOf(q));
      IkResult byConfig = moved.solve(X, c, q);
      assertThat(byConfig).as("%s: solve %s", what, c).isInstanceOf(IkResult.Solved.class);
      // Wrapped: at J4 = ±180° both turns are turn 0 within rounding.
      assertThat(OffsetWristCompletenessTest.wrappedDiff(((IkResult.Solved) byConfig).q(), q)).as("%s: by CONFIG", what)
          .isLessThan(1e-6);
      IkResult near = moved.solveNearest(X, q);
      assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), q)).as("%s: nearest", what).isLessThan(1e-6);
    }
  }
}
