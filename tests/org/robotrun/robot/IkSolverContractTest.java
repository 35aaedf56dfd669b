package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * What every closed-form solver promises through {@link IkSolver}, checked on its public API only
 * (so it holds whichever class keeps the joint-range helpers): the OPW closed form (LR Mate), the
 * offset-wrist search (CRX-10iA) and the UR-type closed form (a UR5 built here from its published
 * DH parameters). Each answer is checked against forward kinematics of the joints it returns and
 * against limits set in the test: every listed solution reaches the pose, is inside the limits, is
 * labelled with its own CONFIG and is listed once, with every 360° turn variant the limits allow;
 * solving by a listed CONFIG returns it; the nearest solution to a listed one is itself; narrowing
 * a joint's limits removes exactly the solutions outside them and turns their CONFIG into a joint
 * limit answer naming the joint; a pose beyond reach is out of reach everywhere.
 */
class IkSolverContractTest {
  static final double MM = 1e-6;
  static final double RAD = 1e-9;

  /** UR5 (Universal Robots' published DH: d1 89.159, a2 −425, a3 −392.25, d4 109.15, d5 94.65, d6 82.3 mm). */
  static RobotModel ur5(double elbowLimit) {
    double[] d = {89.159, 0, 0, 109.15, 94.65, 82.3};
    double[] a = {0, -425, -392.25, 0, 0, 0};
    double[] alpha = {Math.PI / 2, 0, 0, Math.PI / 2, -Math.PI / 2, 0};
    List<JointSpec> joints = new ArrayList<>();
    List<LinkSpec> links = new ArrayList<>();
    links.add(new LinkSpec("base", List.of()));
    for (int i = 0; i < 6; i++) {
      // Joint i+1's frame in link i: Tz(d_i)·Tx(a_i)·Rx(alpha_i) of the previous joint (DH).
      Transform origin = i == 0 ? Transform.IDENTITY
          : Transform.translation(0, 0, d[i - 1]).compose(Transform.translation(a[i - 1], 0, 0))
              .compose(Transform.rotation(1, 0, 0, alpha[i - 1]));
      double lim = i == 2 ? elbowLimit : 2 * Math.PI;
      joints.add(new JointSpec("J" + (i + 1), origin, org.robotrun.math.Vec3.Z, -lim, lim, Math.PI));
      links.add(new LinkSpec("link" + (i + 1), List.of()));
    }
    return RobotModel.fromChain("ur5-dh", "UR5 from DH", joints, Transform.translation(0, 0, d[5]),
        Transform.IDENTITY, links, false);
  }

  static Stream<String> arms() {
    return Stream.of("lrmate200id", "crx10ia", "ur5");
  }

  static RobotModel arm(String id) {
    return id.equals("ur5") ? ur5(Math.PI) : RobotDefinitions.load(id);
  }

  static String expectedKind(String id) {
    return switch (id) {
      case "lrmate200id" -> ClosedFormIk.KIND;
      case "crx10ia" -> OffsetWristIk.KIND;
      default -> UrTypeIk.KIND;
    };
  }

  /** Joints inside the limits, away from the limits and from J5 = 0 (plain, non-singular poses). */
  static List<double[]> samples(RobotModel m, long seed, int n) {
    Random rnd = new Random(seed);
    List<double[]> out = new ArrayList<>();
    while (out.size() < n) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        double lo = Math.max(m.joint(i).lowerRad(), -Math.PI) + 0.1;
        double hi = Math.min(m.joint(i).upperRad(), Math.PI) - 0.1;
        q[i] = lo + rnd.nextDouble() * (hi - lo);
      }
      if (Math.abs(Math.sin(q[4])) > 0.2 && Math.abs(Math.sin(q[2])) > 0.1) {
        out.add(q);
      }
    }
    return out;
  }

  static double maxDiff(double[] a, double[] b) {
    double w = 0;
    for (int i = 0; i < 6; i++) {
      w = Math.max(w, Math.abs(a[i] - b[i]));
    }
    return w;
  }

  static void reaches(RobotModel m, double[] q, Transform X, String what) {
    reachesWithin(m, q, X, MM, RAD, what);
  }

  static void reachesWithin(RobotModel m, double[] q, Transform X, double mm, double rad, String what) {
    Transform Y = ForwardKinematics.flangePoseInBase(m, q);
    assertThat(Y.distanceTo(X)).as("%s: position", what).isLessThan(mm);
    assertThat(Y.rotationAngleTo(X)).as("%s: orientation", what).isLessThan(rad);
    assertThat(m.firstJointOutsideLimits(q)).as("%s: in limits", what).isEqualTo(-1);
  }

  @ParameterizedTest
  @MethodSource("arms")
  void everyListedSolutionIsCorrectLabelledUniqueAndSolvable(String id) {
    RobotModel m = arm(id);
    IkSolver ik = IkSolver.forModel(m);
    assertThat(ik.kind()).isEqualTo(expectedKind(id));
    for (double[] q0 : samples(m, 310 + id.length(), 3)) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q0);
      List<IkSolver.Solution> all = ik.allSolutions(X);
      assertThat(all).as(id).isNotEmpty();
      boolean foundTruth = false;
      for (int k = 0; k < all.size(); k++) {
        IkSolver.Solution s = all.get(k);
        reaches(m, s.q(), X, id + " solution " + k);
        assertThat(ik.configOf(s.q())).as("%s solution %d label", id, k).isEqualTo(s.config());
        foundTruth |= maxDiff(s.q(), q0) < 1e-6;
        for (int j = 0; j < k; j++) {
          assertThat(maxDiff(all.get(j).q(), s.q())).as("%s solutions %d and %d differ", id, j, k).isGreaterThan(1e-6);
        }
        // Every 360° variant inside the limits is listed too.
        for (int i = 0; i < 6; i++) {
          for (double turn : new double[] {-2 * Math.PI, 2 * Math.PI}) {
            double v = s.q()[i] + turn;
            if (v > m.joint(i).lowerRad() + 1e-9 && v < m.joint(i).upperRad() - 1e-9) {
              int joint = i;
              assertThat(all.stream().anyMatch(o -> Math.abs(o.q()[joint] - v) < 1e-6 && sameExcept(o.q(), s.q(), joint)))
                  .as("%s solution %d: J%d turned by %.0f deg listed", id, k, i + 1, Math.toDegrees(turn)).isTrue();
            }
          }
        }
        // Solving by its CONFIG near it gives it back; the nearest solution to it is itself.
        IkResult byConfig = ik.solve(X, s.config(), s.q());
        assertThat(byConfig).as("%s solve %s", id, s.config()).isInstanceOf(IkResult.Solved.class);
        assertThat(maxDiff(((IkResult.Solved) byConfig).q(), s.q())).as("%s solve %s", id, s.config()).isLessThan(1e-6);
        assertThat(((IkResult.Solved) byConfig).positionErrorMm()).isLessThan(MM);
        IkResult near = ik.solveNearest(X, s.q());
        assertThat(maxDiff(((IkResult.Solved) near).q(), s.q())).as("%s nearest to solution %d", id, k).isLessThan(1e-6);
      }
      assertThat(foundTruth).as("%s: the joints that made the pose are among the solutions", id).isTrue();
      // Solving by CONFIG from home still lands in that CONFIG.
      Config c = ik.configOf(q0);
      IkResult fromHome = ik.solve(X, c, new double[6]);
      assertThat(fromHome).isInstanceOf(IkResult.Solved.class);
      reaches(m, ((IkResult.Solved) fromHome).q(), X, id + " from home");
      assertThat(ik.configOf(((IkResult.Solved) fromHome).q())).isEqualTo(c);
    }
  }

  static boolean sameExcept(double[] a, double[] b, int joint) {
    for (int i = 0; i < 6; i++) {
      if (i != joint && Math.abs(a[i] - b[i]) > 1e-6) {
        return false;
      }
    }
    return true;
  }

  /** The model with joint {@code j}'s limits set to [lo, hi]. */
  static RobotModel narrowed(RobotModel m, int j, double lo, double hi) {
    List<JointSpec> js = new ArrayList<>(m.joints());
    JointSpec o = js.get(j);
    js.set(j, new JointSpec(o.name(), o.X_PJ(), o.axis(), lo, hi, o.maxSpeedRadPerSec()));
    return new RobotModel(m.id() + "-narrow", m.displayName(), js, m.X_6F(), m.X_WB(), m.links(), m.opw(), m.coupledJ3(),
        m.maxLinearSpeedMmPerSec());
  }

  @ParameterizedTest
  @MethodSource("arms")
  void narrowingAJointRemovesExactlyTheSolutionsOutsideIt(String id) {
    RobotModel m = arm(id);
    IkSolver wide = IkSolver.forModel(m);
    for (double[] q0 : samples(m, 320 + id.length(), 2)) {
      Transform X = ForwardKinematics.flangePoseInBase(m, q0);
      for (int j : new int[] {0, 1, 3, 5}) {
        double lo = q0[j] - 0.05;
        double hi = q0[j] + 0.05;
        RobotModel n = narrowed(m, j, lo, hi);
        IkSolver ik = IkSolver.forModel(n);
        assertThat(ik.kind()).isEqualTo(wide.kind());
        List<IkSolver.Solution> all = wide.allSolutions(X);
        List<IkSolver.Solution> kept = ik.allSolutions(X);
        List<IkSolver.Solution> inside = all.stream().filter(s -> s.q()[j] >= lo && s.q()[j] <= hi).toList();
        assertThat(kept).as("%s J%d in [%.3f, %.3f]", id, j + 1, lo, hi).hasSameSizeAs(inside);
        for (IkSolver.Solution s : inside) {
          assertThat(kept.stream().anyMatch(k -> maxDiff(k.q(), s.q()) < 1e-6)).isTrue();
        }
        // The nearest to the truth is still the truth; solving its CONFIG still works.
        IkResult near = ik.solveNearest(X, q0);
        assertThat(maxDiff(((IkResult.Solved) near).q(), q0)).as("%s nearest, J%d narrowed", id, j + 1).isLessThan(1e-6);
        // A listed solution now outside: its CONFIG is a joint-limit answer naming the joint.
        for (IkSolver.Solution s : all) {
          boolean out = s.q()[j] < lo || s.q()[j] > hi;
          boolean sameConfigInside = inside.stream().anyMatch(i -> i.config().equals(s.config()));
          if (out && !sameConfigInside) {
            IkResult r = ik.solve(X, s.config(), s.q());
            assertThat(r).as("%s %s with J%d narrowed", id, s.config(), j + 1).isInstanceOf(IkResult.Unreachable.class);
            IkResult.Unreachable u = (IkResult.Unreachable) r;
            assertThat(u.reason()).isEqualTo(IkResult.Reason.JOINT_LIMIT);
            assertThat(u.message()).contains("J" + (j + 1));
            // It says the value the joint would need and the limits, in degrees (never NaN).
            assertThat(u.message()).as("%s %s", id, s.config())
                .matches(".*needs J" + (j + 1) + " = -?\\d+\\.\\d deg, outside -?\\d+\\.\\d\\.\\.-?\\d+\\.\\d deg.*");
          }
        }
      }
    }
  }

  @ParameterizedTest
  @MethodSource("arms")
  void aPoseBeyondReachIsOutOfReachEverywhere(String id) {
    RobotModel m = arm(id);
    IkSolver ik = IkSolver.forModel(m);
    double[] q0 = samples(m, 330, 1).get(0);
    Transform X = ForwardKinematics.flangePoseInBase(m, q0);
    Transform far = X.withTranslation(X.x() + 5000, X.y() - 3000, X.z() + 4000);
    assertThat(ik.allSolutions(far)).isEmpty();
    IkResult r = ik.solve(far, ik.configOf(q0), q0);
    assertThat(r).isInstanceOf(IkResult.Unreachable.class);
    assertThat(((IkResult.Unreachable) r).reason()).isEqualTo(IkResult.Reason.OUT_OF_REACH);
    IkResult n = ik.solveNearest(far, q0);
    assertThat(n).isInstanceOf(IkResult.Unreachable.class);
    assertThat(((IkResult.Unreachable) n).reason()).isEqualTo(IkResult.Reason.OUT_OF_REACH);
  }

  @ParameterizedTest
  @MethodSource("arms")
  void everyJointAtItsLimitIsStillSolved(String id) {
    // A limit is inclusive: joints exactly at a limit are a solution, listed and nearest.
    RobotModel m = arm(id);
    IkSolver ik = IkSolver.forModel(m);
    double[] q = samples(m, 340, 1).get(0);
    for (int j : new int[] {0, 3, 5}) {
      double[] at = q.clone();
      at[j] = m.joint(j).upperRad();
      Transform X = ForwardKinematics.flangePoseInBase(m, at);
      IkResult near = ik.solveNearest(X, at);
      assertThat(near).as("%s J%d at its upper limit", id, j + 1).isInstanceOf(IkResult.Solved.class);
      reaches(m, ((IkResult.Solved) near).q(), X, id + " at the limit");
      assertThat(maxDiff(((IkResult.Solved) near).q(), at)).isLessThan(1e-6);
    }
  }

  @ParameterizedTest
  @MethodSource("arms")
  void aStraightWristIsSolvedKeepingTheCurrentJoints(String id) {
    // J5 = 0: J4 and J6 (or, on the UR, J6 and J2..J4) turn about one line, so only their sum is
    // fixed by the pose; the joints the arm stands at are one answer, and the nearest.
    RobotModel m = arm(id);
    IkSolver ik = IkSolver.forModel(m);
    for (double[] q : samples(m, 350 + id.length(), 3)) {
      q[4] = 0;
      Transform X = ForwardKinematics.flangePoseInBase(m, q);
      IkResult near = ik.solveNearest(X, q);
      assertThat(near).as("%s straight wrist", id).isInstanceOf(IkResult.Solved.class);
      // At the singularity the UR form's acos(cos J5) near 1 keeps only half the digits (2.9e-6 mm,
      // 1.5e-8 rad seen): 1e-5 mm and 1e-7 rad here.
      reachesWithin(m, ((IkResult.Solved) near).q(), X, 1e-5, 1e-7, id + " straight wrist");
      assertThat(maxDiff(((IkResult.Solved) near).q(), q)).as("%s straight wrist nearest", id).isLessThan(1e-6);
      IkResult byConfig = ik.solve(X, ik.configOf(q), q);
      assertThat(byConfig).isInstanceOf(IkResult.Solved.class);
      reachesWithin(m, ((IkResult.Solved) byConfig).q(), X, 1e-5, 1e-7, id + " straight wrist by CONFIG");
    }
  }
}
