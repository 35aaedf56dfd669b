package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * An arm is its joint axis lines, not the way its file writes them. The same machine can be
 * written with every link frame turned (a URDF whose joint origins carry other rpy and whose
 * axes are not unit x, y or z), with a joint's origin slid along its own axis, with an axis
 * written the other way round (the joint then turns the same way for the negated angle, and its
 * limits are negated; J1 is left as written, since its direction is "up" in the U/D definition,
 * z1 below), with the base frame put elsewhere and with another flange frame. Here each
 * solver family (the OPW closed form on the LR Mate, the offset-wrist search on the CRX-10iA, the
 * UR-type closed form on a UR5 from its published DH and on an oblique arm of the family) is
 * written again that way, and the rewritten arm must be the same arm:
 * <ul>
 *   <li>its FK is M · FK(q) · H for the same joints with the flipped ones negated (composed here);
 *   <li>the same solver family applies;
 *   <li>its CONFIG is the original's by the definitions in docs/kinematics.md: U/D and T/B are
 *       positions of the elbow and wrist point (unchanged), F/N is the sign of J5 (swapped when J5
 *       is written the other way round), the turn numbers those of the rewritten J1, J4, J6;
 *   <li>the pose M · X · H has exactly the solutions of X, mapped the same way, with those
 *       labels; solving by CONFIG and the nearest solution are the mapped joints.
 * </ul>
 * With every frame turned, the solvers' terms that vanish on the usual axis-aligned frames (a
 * joint axis along z of its frame, J1 at the base origin, W on the flange's z axis) are all
 * non-zero. Flipping J2 on the CRX turns {@link ChainConfig}'s J2 × J1 backwards (σ = −1).
 */
class ReframedChainInvarianceTest {

  /** A rewriting: base change M, flange change H, a turn per link frame, a sign per joint. */
  record Rewrite(Transform base, Transform flange, long seed, int[] sign) {
    double[] map(double[] q) {
      double[] out = new double[6];
      for (int i = 0; i < 6; i++) {
        out[i] = sign[i] * q[i];
      }
      return out;
    }

    @Override
    public String toString() {
      return "signs " + Arrays.toString(sign) + ", seed " + seed;
    }
  }

  static final Transform BASE = Transform.translation(-140, 95, 60).compose(Transform.rotation(2.0 / 3, -1.0 / 3, 2.0 / 3, 0.9));
  static final Transform FLANGE = Transform.translation(12, -7, 25).compose(Transform.rotation(-2.0 / 7, 6.0 / 7, 3.0 / 7, 1.1));

  static Stream<org.junit.jupiter.params.provider.Arguments> cases() {
    List<org.junit.jupiter.params.provider.Arguments> out = new ArrayList<>();
    int[] none = {1, 1, 1, 1, 1, 1};
    int[] j2 = {1, -1, 1, 1, 1, 1};
    int[] most = {1, -1, 1, -1, -1, 1};
    int[] others = {1, 1, -1, 1, 1, -1};
    for (String id : new String[] {"lrmate200id", "crx10ia", "ur5", "ur-oblique"}) {
      out.add(org.junit.jupiter.params.provider.Arguments.of(id, new Rewrite(Transform.IDENTITY, Transform.IDENTITY, 7, none)));
      out.add(org.junit.jupiter.params.provider.Arguments.of(id, new Rewrite(BASE, FLANGE, 11, none)));
      out.add(org.junit.jupiter.params.provider.Arguments.of(id, new Rewrite(Transform.IDENTITY, FLANGE, 13, j2)));
      out.add(org.junit.jupiter.params.provider.Arguments.of(id, new Rewrite(BASE, Transform.IDENTITY, 17, most)));
      out.add(org.junit.jupiter.params.provider.Arguments.of(id, new Rewrite(BASE, FLANGE, 19, others)));
    }
    return out.stream();
  }

  static RobotModel arm(String id) {
    return switch (id) {
      case "ur5" -> IkSolverContractTest.ur5(Math.PI);
      case "ur-oblique" -> UrTypeGeneralLayoutTest.oblique();
      default -> RobotDefinitions.load(id);
    };
  }

  /** A rotation about a random oblique axis by 0.4 to 2.6 rad. */
  static Transform randomTurn(Random rnd) {
    Vec3 a = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalized();
    return Transform.rotation(a.x(), a.y(), a.z(), 0.4 + 2.2 * rnd.nextDouble());
  }

  /**
   * The model written again: link i's frame becomes L_i · G_i (G_i a turn and a slide along
   * joint i's axis), so joint i's origin is G_(i−1)⁻¹ · X_PJ · G_i and its axis G_i⁻¹ · axis (times
   * its sign); the base frame becomes M · B and the flange G_6⁻¹ · X_6F · H.
   */
  static RobotModel rewritten(RobotModel m, Rewrite w) {
    Random rnd = new Random(w.seed());
    List<JointSpec> js = new ArrayList<>();
    Transform prevInv = w.base();
    for (int i = 0; i < 6; i++) {
      JointSpec j = m.joint(i);
      Transform turn = randomTurn(rnd);
      Vec3 along = j.axis().times(-60 + 120 * rnd.nextDouble());
      Transform g = Transform.translation(along.x(), along.y(), along.z()).compose(turn);
      Vec3 axis = g.inverse().rotate(j.axis()).times(w.sign()[i]);
      double lo = w.sign()[i] > 0 ? j.lowerRad() : -j.upperRad();
      double hi = w.sign()[i] > 0 ? j.upperRad() : -j.lowerRad();
      js.add(new JointSpec(j.name(), prevInv.compose(j.X_PJ()).compose(g), axis, lo, hi, j.maxSpeedRadPerSec()));
      prevInv = g.inverse();
    }
    Transform x6f = prevInv.compose(m.X_6F()).compose(w.flange());
    return RobotModel.fromChain(m.id() + "-rewritten", m.displayName(), js, x6f, m.X_WB().compose(w.base().inverse()),
        m.links(), m.coupledJ3());
  }

  /** The original CONFIG carried to the rewritten joints (see the class comment). */
  static Config expected(Config c, double[] qMapped, Rewrite w) {
    return new Config(w.sign()[4] > 0 ? c.flip() : !c.flip(), c.up(), c.top(),
        Config.turnOf(qMapped[0]), Config.turnOf(qMapped[3]), Config.turnOf(qMapped[5]));
  }

  @ParameterizedTest
  @MethodSource("cases")
  void theArmWrittenAnotherWayHasTheSameSolutionsAndTheSameConfig(String id, Rewrite w) {
    RobotModel m = arm(id);
    RobotModel r = rewritten(m, w);
    IkSolver plain = IkSolver.forModel(m);
    IkSolver other = IkSolver.forModel(r);
    assertThat(other.kind()).as("%s %s: solver", id, w).isEqualTo(plain.kind());
    assertThat(r.wristKind()).isEqualTo(m.wristKind());
    for (double[] q : IkSolverContractTest.samples(m, 500 + id.length(), 4)) {
      String what = id + " " + w + " at " + Arrays.toString(q);
      double[] qm = w.map(q);
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      Transform Y = w.base().compose(X).compose(w.flange());
      assertThat(ForwardKinematics.flangePoseInBase(r, qm).distanceTo(Y)).as("%s: FK", what).isLessThan(1e-9);
      assertThat(ForwardKinematics.flangePoseInBase(r, qm).rotationAngleTo(Y)).as("%s: FK", what).isLessThan(1e-12);
      Config c = plain.configOf(q);
      assertThat(other.configOf(qm)).as("%s: CONFIG", what).isEqualTo(expected(c, qm, w));
      List<IkSolver.Solution> a = plain.allSolutions(X);
      List<IkSolver.Solution> b = other.allSolutions(Y);
      assertThat(b).as("%s: solution count", what).hasSameSizeAs(a);
      for (IkSolver.Solution s : a) {
        double[] sm = w.map(s.q());
        Config cm = expected(s.config(), sm, w);
        assertThat(b.stream().anyMatch(o -> IkSolverContractTest.maxDiff(o.q(), sm) < 1e-6 && o.config().equals(cm)))
            .as("%s: solution %s (%s) rewritten", what, Arrays.toString(sm), cm).isTrue();
      }
      for (IkSolver.Solution s : b) {
        IkSolverContractTest.reaches(r, s.q(), Y, what + " rewritten solution");
        assertThat(other.configOf(s.q())).isEqualTo(s.config());
      }
      Config cm = expected(c, qm, w);
      IkResult byConfig = other.solve(Y, cm, new double[6]);
      assertThat(byConfig).as("%s: solve %s", what, cm).isInstanceOf(IkResult.Solved.class);
      IkResult.Solved bs = (IkResult.Solved) byConfig;
      assertThat(other.configOf(bs.q())).as("%s: solve %s", what, cm).isEqualTo(cm);
      IkSolverContractTest.reaches(r, bs.q(), Y, what + " by CONFIG");
      IkResult near = other.solveNearest(Y, qm);
      assertThat(near).as("%s: nearest", what).isInstanceOf(IkResult.Solved.class);
      IkResult.Solved ns = (IkResult.Solved) near;
      assertThat(IkSolverContractTest.maxDiff(ns.q(), qm)).as("%s: nearest", what).isLessThan(1e-6);
      Transform got = ForwardKinematics.flangePoseInBase(r, ns.q());
      assertThat(ns.positionErrorMm()).isLessThan(1e-6)
          .isCloseTo(got.distanceTo(Y), org.assertj.core.api.Assertions.within(1e-9));
      assertThat(ns.orientationErrorRad()).isLessThan(1e-9)
          .isCloseTo(got.rotationAngleTo(Y), org.assertj.core.api.Assertions.within(1e-9));
    }
  }
}
