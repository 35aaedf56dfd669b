package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

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
 * The OPW closed form on the parts of its family the FANUC library leaves at zero
 * (Brandstötter et al. 2014; ClosedFormIk's and OpwParameters' comments):
 * <ul>
 *   <li>a lateral shoulder offset b (the LR Mate with its arm moved 100 mm along the J2 axis):
 *       every pose made by FK comes back with all eight branches, each reaching the pose by FK,
 *       one flag triple each, and the joints that made it among them;
 *   <li>joint zeros that are not OPW's (each joint origin turned about its own axis, so
 *       q = sign·(θ + offset) with offsets that are not 0): the same arm read that much higher,
 *       so the same postures, the same U/D and T/B (positions of the wrist centre), and at the
 *       wrist singularity the nearest solution still keeps the current J4;
 *   <li>the packed-pose entry points give what the Transform ones give.
 * </ul>
 */
class ClosedFormReshapedArmTest {
  static final RobotModel LRMATE = RobotDefinitions.load("lrmate200id");

  static RobotModel shouldered() {
    List<JointSpec> js = new ArrayList<>(LRMATE.joints());
    JointSpec j2 = js.get(1);
    js.set(1, new JointSpec(j2.name(), Transform.translation(0, 100, 0).compose(j2.X_PJ()), j2.axis(), j2.lowerRad(),
        j2.upperRad(), j2.maxSpeedRadPerSec()));
    return RobotModel.fromChain("lrmate-shoulder", "LR Mate, shoulder offset", js, LRMATE.X_6F(), LRMATE.X_WB(),
        LRMATE.links(), false);
  }

  static final double[] ZERO = {0.3, -0.4, 0.5, 0.6, 0, -0.8};

  static RobotModel zerosTurned() {
    List<JointSpec> js = new ArrayList<>();
    for (int i = 0; i < 6; i++) {
      JointSpec j = LRMATE.joint(i);
      Vec3 a = j.axis();
      js.add(new JointSpec(j.name(), j.X_PJ().compose(Transform.rotation(a.x(), a.y(), a.z(), -ZERO[i])), a,
          j.lowerRad() + ZERO[i], j.upperRad() + ZERO[i], j.maxSpeedRadPerSec()));
    }
    return RobotModel.fromChain("lrmate-zeros", "LR Mate, zeros turned", js, LRMATE.X_6F(), LRMATE.X_WB(),
        LRMATE.links(), false);
  }

  @Test
  void aShoulderOffsetArmGetsAllEightBranches() {
    RobotModel m = shouldered();
    OpwParameters p = m.opw().orElseThrow();
    assertThat(Math.abs(p.b())).isCloseTo(100, org.assertj.core.api.Assertions.within(1e-9));
    ClosedFormIk ik = new ClosedFormIk(m);
    int eight = 0;
    for (double[] q : IkSolverContractTest.samples(m, 631, 8)) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      double[] out = new double[48];
      int valid = ik.solveAllBase(X, out);
      Set<String> flags = new HashSet<>();
      boolean truth = false;
      for (int k = 0; k < 8; k++) {
        if ((valid & (1 << k)) == 0) {
          continue;
        }
        double[] s = Arrays.copyOfRange(out, 6 * k, 6 * k + 6);
        Transform Y = ForwardKinematics.flangePoseInBase(m, s);
        assertThat(Y.distanceTo(X)).as("branch %d of %s", k, Arrays.toString(q)).isLessThan(1e-6);
        assertThat(Y.rotationAngleTo(X)).isLessThan(1e-9);
        flags.add(ik.configOf(s).toString().substring(0, 5));
        truth |= OffsetWristCompletenessTest.wrappedDiff(s, q) < 1e-9;
      }
      assertThat(truth).as("its joints among the branches of %s", Arrays.toString(q)).isTrue();
      assertThat(flags).hasSize(Integer.bitCount(valid));
      eight += valid == 0xFF ? 1 : 0;
      Config c = ik.configOf(q);
      IkResult r = ik.solve(X, c);
      assertThat(r).isInstanceOf(IkResult.Solved.class);
      assertThat(OffsetWristCompletenessTest.wrappedDiff(((IkResult.Solved) r).q(), q)).isLessThan(1e-9);
    }
    assertThat(eight).isPositive();
  }

  @Test
  void jointZerosThatAreNotOpwsAreOffsets() {
    RobotModel m = zerosTurned();
    assertThat(m.opw()).isPresent();
    ClosedFormIk plain = new ClosedFormIk(LRMATE);
    ClosedFormIk ik = new ClosedFormIk(m);
    for (double[] q : IkSolverContractTest.samples(LRMATE, 632, 8)) {
      double[] qt = q.clone();
      for (int i = 0; i < 6; i++) {
        qt[i] += ZERO[i];
      }
      Transform X = ForwardKinematics.flangePoseInBase(LRMATE, q);
      assertThat(ForwardKinematics.flangePoseInBase(m, qt).distanceTo(X)).isLessThan(1e-9);
      Config c = plain.configOf(q);
      Config ct = ik.configOf(qt);
      assertThat(ct.up()).as("U/D at %s", Arrays.toString(q)).isEqualTo(c.up());
      assertThat(ct.top()).as("T/B at %s", Arrays.toString(q)).isEqualTo(c.top());
      assertThat(ct.flip()).isEqualTo(c.flip());
      IkResult near = ik.solveNearest(X, qt);
      assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), qt)).isLessThan(1e-9);
    }
    // The wrist in line (J5 = 0): J4 is kept from the current joints, J6 takes the rest.
    double[] q = {0.5, 0.1, 0.7, 0.9, 0, 0.4};
    Transform X = ForwardKinematics.flangePoseInBase(m, q);
    double[] current = q.clone();
    current[3] += 0.3;
    IkResult r = ik.solveNearest(X, current);
    double[] got = ((IkResult.Solved) r).q();
    IkSolverContractTest.reaches(m, got, X, "singular wrist");
    assertThat(got[3]).isCloseTo(current[3], org.assertj.core.api.Assertions.within(1e-9));
  }

  @Test
  void packedPosesGiveWhatTransformsGive() {
    ClosedFormIk ik = new ClosedFormIk(LRMATE);
    for (double[] q : IkSolverContractTest.samples(LRMATE, 633, 4)) {
      Transform X = ForwardKinematics.flangePoseInBase(LRMATE, q);
      double[] packed = new double[12];
      KinematicChain.pack(X, packed, 0);
      Config c = ik.configOf(q);
      // Another pose solved first, so nothing is left over from the call before.
      ik.solve(ForwardKinematics.flangePoseInBase(LRMATE, new double[6]), c);
      IkResult byConfig = ik.solve(packed, c);
      assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) byConfig).q(), q)).isLessThan(1e-9);
      ik.solveNearest(ForwardKinematics.flangePoseInBase(LRMATE, new double[6]), new double[6]);
      IkResult near = ik.solveNearest(packed, q);
      assertThat(IkSolverContractTest.maxDiff(((IkResult.Solved) near).q(), q)).isLessThan(1e-9);
    }
  }

  @Test
  void jointsThatTurnFurtherListEveryTurnInsideTheLimitsAndJ5ZeroIsN() {
    // J1, J4 and J6 turning ±630°: every 360° variant inside the limits, counted here, is listed.
    double lim = Math.toRadians(630);
    RobotModel m = LRMATE;
    for (int i : new int[] {0, 3, 5}) {
      m = IkSolverContractTest.narrowed(m, i, -lim, lim);
    }
    ClosedFormIk ik = new ClosedFormIk(m);
    double[] q = {0.3, 0.2, 0.4, -0.6, 1.1, 0.4};
    Transform X = ForwardKinematics.flangePoseInBase(m, q);
    List<IkSolver.Solution> all = ik.allSolutions(X);
    double[] out = new double[48];
    int valid = ik.solveAllBase(X, out);
    int expected = 0;
    for (int k = 0; k < 8; k++) {
      if ((valid & (1 << k)) == 0) {
        continue;
      }
      boolean inside = true;
      for (int i : new int[] {1, 2, 4}) {
        double v = out[6 * k + i];
        boolean any = false;
        for (int t = -1; t <= 1; t++) {
          any |= m.joint(i).withinLimits(v + 2 * Math.PI * t);
        }
        inside &= any;
      }
      int variants = inside ? 1 : 0;
      for (int i : new int[] {0, 3, 5}) {
        int n = 0;
        for (int t = -3; t <= 3; t++) {
          n += m.joint(i).withinLimits(out[6 * k + i] + 2 * Math.PI * t) ? 1 : 0;
        }
        variants *= n;
      }
      expected += variants;
    }
    assertThat(all).hasSize(expected);
    assertThat(all.stream().anyMatch(s -> Math.abs(s.q()[0]) > 3 * Math.PI)).isTrue();
    assertThat(all.stream().anyMatch(s -> Math.abs(s.q()[3]) > 3 * Math.PI)).isTrue();
    assertThat(all.stream().anyMatch(s -> Math.abs(s.q()[5]) > 3 * Math.PI)).isTrue();
    for (IkSolver.Solution s : all) {
      IkSolverContractTest.reaches(m, s.q(), X, "variant " + Arrays.toString(s.q()));
    }
    // "F when J5 > 0, N when J5 ≤ 0": the wrist exactly in line is N.
    assertThat(ik.configOf(new double[] {0.3, 0.2, 0.4, -0.6, 0, 0.4}).flip()).isFalse();
  }
}
