package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * The edges of the UR-type closed form's promise (UrTypeIk's class comment, docs/kinematics.md):
 * <ul>
 *   <li>a chain of the family only to within its file's rounding (axes up to 1e-4 rad off
 *       parallel, J5 and J6 up to 0.05 mm apart) still gets the closed form, every answer finished
 *       on the real chain: each solution reaches the pose by FK to 1e-6 mm and 1e-9 rad;
 *   <li>what is not of the family is refused with the reason (J2, J3, J4 not parallel; J1 parallel
 *       to J2; J5 parallel to J6; J5 not changing J6's angle to J2; an arm link of zero length);
 *   <li>a CONFIG that no branch of the pose has is OUT_OF_REACH "only other configurations reach
 *       it"; a pose whose every solution is outside the limits is JOINT_LIMIT;
 *   <li>with J1, J4, J6 turning ±630°, every 360° variant inside the limits is listed: as many
 *       solutions as the turn variants counted here.
 * </ul>
 */
class UrTypeFamilyEdgesTest {
  static final RobotModel UR5 = IkSolverContractTest.ur5(Math.PI);

  static RobotModel changed(RobotModel m, String id, int joint, Transform before) {
    List<JointSpec> js = new ArrayList<>(m.joints());
    JointSpec j = js.get(joint);
    js.set(joint, new JointSpec(j.name(), before.compose(j.X_PJ()), j.axis(), j.lowerRad(), j.upperRad(), j.maxSpeedRadPerSec()));
    return RobotModel.fromChain(id, id, js, m.X_6F(), m.X_WB(), m.links(), false);
  }

  /** UR5 with J3's frame tilted 2e-5 rad off parallel and the J6 axis moved 0.01 mm off J5's. */
  static RobotModel rounded() {
    RobotModel tilted = changed(UR5, "ur5-tilted", 2, Transform.rotation(1, 0, 0, 2e-5));
    return changed(tilted, "ur5-rounded", 5, Transform.translation(0.01, 0, 0));
  }

  static void exact(RobotModel m, double[] q, Transform X, String what) {
    Transform Y = ForwardKinematics.flangePoseInBase(m, q);
    assertThat(Y.distanceTo(X)).as("%s: position", what).isLessThan(1e-6);
    assertThat(Y.rotationAngleTo(X)).as("%s: orientation", what).isLessThan(1e-9);
  }

  @Test
  void anArmOfTheFamilyOnlyToWithinRoundingGetsTheClosedFormAndExactAnswers() {
    RobotModel m = rounded();
    assertThat(UrTypeIk.applies(m)).isTrue();
    IkSolver ik = IkSolver.forModel(m);
    assertThat(ik.kind()).isEqualTo(UrTypeIk.KIND);
    UrTypeIk ur = new UrTypeIk(m);
    for (double[] q : IkSolverContractTest.samples(m, 601, 5)) {
      String what = "pose of " + Arrays.toString(q);
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      List<double[]> base = ur.baseSolutions(X);
      assertThat(base.stream().anyMatch(s -> OffsetWristCompletenessTest.wrappedDiff(s, q) < 1e-7)).as("%s: its joints", what).isTrue();
      for (double[] s : base) {
        exact(m, s, X, what + " base solution " + Arrays.toString(s));
      }
      List<IkSolver.Solution> all = ik.allSolutions(X);
      assertThat(all).isNotEmpty();
      for (IkSolver.Solution s : all) {
        exact(m, s.q(), X, what + " solution " + Arrays.toString(s.q()));
        assertThat(ik.configOf(s.q())).isEqualTo(s.config());
      }
      Config c = ik.configOf(q);
      IkResult byConfig = ik.solve(X, c, new double[6]);
      assertThat(byConfig).as("%s: solve %s", what, c).isInstanceOf(IkResult.Solved.class);
      exact(m, ((IkResult.Solved) byConfig).q(), X, what + " by CONFIG");
      assertThat(((IkResult.Solved) byConfig).positionErrorMm()).isLessThan(1e-6);
      // The reported error is the answer's own, whatever the solver was asked before.
      ik.configOf(new double[6]);
      IkResult near = ik.solveNearest(X, q);
      assertThat(near).isInstanceOf(IkResult.Solved.class);
      exact(m, ((IkResult.Solved) near).q(), X, what + " nearest");
      assertThat(((IkResult.Solved) near).positionErrorMm()).isLessThan(1e-6);
      assertThat(((IkResult.Solved) near).orientationErrorRad()).isLessThan(1e-9);
      assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), q)).isLessThan(1e-7);
    }
  }

  @Test
  void whatIsNotOfTheFamilyIsRefusedWithTheReason() {
    RobotModel lrmate = RobotDefinitions.load("lrmate200id");
    assertThat(UrTypeIk.applies(lrmate)).isFalse();
    assertThatThrownBy(() -> new UrTypeIk(lrmate)).isInstanceOf(IllegalArgumentException.class)
        .hasMessage("lrmate200id: not a three-parallel-axes arm (J2, J3 and J4 are not parallel)");
    double[] d = {89.159, 0, 0, 109.15, 94.65, 82.3};
    double[] a = {0, -425, -392.25, 0, 0, 0};
    double h = Math.PI / 2;
    String[][] cases = {
      {"0", "0", "0", "1.5707963267948966", "-1.5707963267948966", "J1 is parallel to J2"},
      {"1.5707963267948966", "0", "0", "1.5707963267948966", "0", "J5 is parallel to J6"},
      {"1.5707963267948966", "0", "0", "0", "-1.5707963267948966", "J5 does not change J6's angle to J2"},
    };
    for (String[] c : cases) {
      double[] alpha = {Double.parseDouble(c[0]), 0, 0, Double.parseDouble(c[3]), Double.parseDouble(c[4]), 0};
      RobotModel m = UrTypeGeneralLayoutTest.dhArm("not-ur", d, a, alpha, 2 * Math.PI);
      assertThat(UrTypeIk.applies(m)).as(c[5]).isFalse();
      assertThatThrownBy(() -> new UrTypeIk(m)).isInstanceOf(IllegalArgumentException.class)
          .hasMessage("not-ur: not a three-parallel-axes arm (" + c[5] + ")");
    }
    RobotModel noUpperArm = UrTypeGeneralLayoutTest.dhArm("not-ur", d, new double[] {0, 0, -392.25, 0, 0, 0},
        new double[] {h, 0, 0, h, -h, 0}, 2 * Math.PI);
    assertThatThrownBy(() -> new UrTypeIk(noUpperArm)).isInstanceOf(IllegalArgumentException.class)
        .hasMessage("not-ur: not a three-parallel-axes arm (an arm link of zero length)");
    UrTypeIk ur = new UrTypeIk(UR5);
    assertThat(ur.model()).isSameAs(UR5);
    assertThat(ur.kind()).isEqualTo(UrTypeIk.KIND);
  }

  @Test
  void aConfigNoBranchHasIsOutOfReachAndAPoseOutsideTheLimitsIsAJointLimit() {
    UrTypeIk ur = new UrTypeIk(UR5);
    int checked = 0;
    for (double[] q : IkSolverContractTest.samples(UR5, 602, 40)) {
      Transform X = ForwardKinematics.flangePoseInBase(UR5, q);
      List<double[]> base = ur.baseSolutions(X);
      Set<String> have = new HashSet<>();
      for (double[] s : base) {
        have.add(ur.configOf(s).toString().substring(0, 5));
      }
      if (base.size() == UrTypeIk.BASE_SOLUTIONS) {
        continue;
      }
      for (boolean f : new boolean[] {true, false}) {
        for (boolean u : new boolean[] {true, false}) {
          for (boolean t : new boolean[] {true, false}) {
            Config c = new Config(f, u, t, 0, 0, 0);
            IkResult r = ur.solve(X, c, q);
            if (have.contains(c.toString().substring(0, 5))) {
              assertThat(r).as("%s", c).isInstanceOf(IkResult.Solved.class);
            } else {
              checked++;
              assertThat(r).as("%s", c).isInstanceOf(IkResult.Unreachable.class);
              IkResult.Unreachable un = (IkResult.Unreachable) r;
              assertThat(un.reason()).isEqualTo(IkResult.Reason.OUT_OF_REACH);
              assertThat(un.message()).isEqualTo("the pose is out of reach in CONFIG '" + c + "' (only other configurations reach it)");
            }
          }
        }
      }
    }
    assertThat(checked).as("flag triples missing from a pose").isPositive();
    // J1 narrowed to a band that none of the pose's J1 values (nor their turns) falls in.
    double[] q = {0.3, -1.2, 1.4, -0.6, 1.1, 0.4};
    Transform X = ForwardKinematics.flangePoseInBase(UR5, q);
    double lo = Double.NaN;
    for (double c = -3.0; c < 3.0 && Double.isNaN(lo); c += 0.05) {
      double mid = c + 0.05;
      boolean free = true;
      for (double[] s : ur.baseSolutions(X)) {
        free &= Math.abs(Math.IEEEremainder(s[0] - mid, 2 * Math.PI)) > 0.2;
      }
      lo = free ? c : Double.NaN;
    }
    RobotModel narrow = IkSolverContractTest.narrowed(UR5, 0, lo, lo + 0.1);
    UrTypeIk nur = new UrTypeIk(narrow);
    IkResult near = nur.solveNearest(X, q);
    assertThat(near).isInstanceOf(IkResult.Unreachable.class);
    assertThat(((IkResult.Unreachable) near).reason()).isEqualTo(IkResult.Reason.JOINT_LIMIT);
    assertThat(((IkResult.Unreachable) near).message()).isEqualTo("the pose is within reach but every solution has a joint outside its limits");
    IkResult byConfig = nur.solve(X, ur.configOf(q), q);
    assertThat(((IkResult.Unreachable) byConfig).reason()).isEqualTo(IkResult.Reason.JOINT_LIMIT);
    assertThat(((IkResult.Unreachable) byConfig).message()).contains("J1");
  }

  @Test
  void jointsThatTurnFurtherListEveryTurnInsideTheLimits() {
    // J1, J4 and J6 turn ±630°, J2, J3 and J5 ±360° (a UR's range).
    double[] lims = {Math.toRadians(630), 2 * Math.PI, 2 * Math.PI, Math.toRadians(630), 2 * Math.PI, Math.toRadians(630)};
    RobotModel m = UR5;
    for (int i = 0; i < 6; i++) {
      m = IkSolverContractTest.narrowed(m, i, -lims[i], lims[i]);
    }
    UrTypeIk ur = new UrTypeIk(m);
    double[] q = {0.3, -1.2, 1.4, -0.6, 1.1, 0.4};
    Transform X = ForwardKinematics.flangePoseInBase(m, q);
    int expected = 0;
    for (double[] s : ur.baseSolutions(X)) {
      int variants = 1;
      for (int i = 0; i < 6; i++) {
        int n = 0;
        for (int t = -3; t <= 3; t++) {
          double v = s[i] + 2 * Math.PI * t;
          n += v >= -lims[i] && v <= lims[i] ? 1 : 0;
        }
        variants *= n;
      }
      expected += variants;
    }
    List<IkSolver.Solution> all = ur.allSolutions(X);
    assertThat(all).hasSize(expected);
    // Each joint reaches beyond ±540°: the ±2-turn variants are there.
    assertThat(all.stream().anyMatch(s -> Math.abs(s.q()[0]) > 3 * Math.PI)).isTrue();
    assertThat(all.stream().anyMatch(s -> Math.abs(s.q()[2]) > Math.PI)).isTrue();
    assertThat(all.stream().anyMatch(s -> Math.abs(s.q()[5]) > 3 * Math.PI)).isTrue();
    for (IkSolver.Solution s : all.subList(0, Math.min(all.size(), 50))) {
      exact(m, s.q(), X, "variant " + Arrays.toString(s.q()));
    }
  }
}
