package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Optional;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.lifecycle.AddLifecycleHook;
import net.jqwik.api.constraints.DoubleRange;
import org.junit.jupiter.api.Test;
import org.robotrun.io.IkTargetsCsv;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Angles;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;

// Under mutation testing each property runs at most PitScale.PIT_TRIES tries (verify: all).
@AddLifecycleHook(org.robotrun.PitScale.Tries.class)
class NumericIkTest {
  private final RobotModel robot = RobotDefinitions.defaultRobot();
  private final NumericIk ik = new NumericIk(robot);

  @Property(seed = "5", tries = 1000)
  void fkThenNumericIkFromHomeReachesThePoseInsideTheLimits(
      @ForAll @DoubleRange(min = -170, max = 170) double j1,
      @ForAll @DoubleRange(min = -100, max = 145) double j2,
      @ForAll @DoubleRange(min = -70, max = 205) double j3,
      @ForAll @DoubleRange(min = -190, max = 190) double j4,
      @ForAll @DoubleRange(min = -125, max = 125) double j5,
      @ForAll @DoubleRange(min = -360, max = 360) double j6) {
    // Method: FK of random in-limit joints, numeric IK from q = 0; pose back to 1e-6 mm, 1e-8 rad.
    double[] q = Angles.toRadians(new double[] {j1, j2, j3, j4, j5, j6});
    Transform X_BF = ForwardKinematics.flangePoseInBase(robot, q);
    IkResult r = ik.solve(X_BF, new double[6]);
    assertThat(r).isInstanceOf(IkResult.Solved.class);
    double[] sol = ((IkResult.Solved) r).q();
    Transform reached = ForwardKinematics.flangePoseInBase(robot, sol);
    assertThat(reached.distanceTo(X_BF)).isLessThan(1e-6);
    assertThat(reached.rotationAngleTo(X_BF)).isLessThan(1e-8);
    assertThat(robot.firstJointOutsideLimits(sol)).isEqualTo(-1);
  }

  @Test
  void everyReferenceRowSolvesInsideTheLimitsFromEachStart() throws Exception {
    // Method: the benchmark criteria (0.1 mm, 0.01 rad, in limits) from home, random and near.
    List<IkTargetsCsv.Target> targets = ForwardKinematicsTest.referenceTargets();
    for (String start : List.of("home", "random", "near")) {
      int ok = 0;
      for (IkTargetsCsv.Target t : targets) {
        double[] q0 = switch (start) {
          case "random" -> t.randomStart();
          case "near" -> t.nearStart();
          default -> new double[6];
        };
        if (ik.solve(t.X_BF(), q0) instanceof IkResult.Solved s) {
          Transform reached = ForwardKinematics.flangePoseInBase(robot, s.q());
          if (reached.distanceTo(t.X_BF()) < 0.1 && reached.rotationAngleTo(t.X_BF()) < 0.01
              && robot.firstJointOutsideLimits(s.q()) < 0) {
            ok++;
          }
        }
      }
      assertThat(ok).as("start %s", start).isEqualTo(targets.size());
    }
  }

  @Test
  void nearStartStaysInTheSameConfiguration() throws Exception {
    // From q + U(±0.1 rad) the solver should land on q itself (1e-6 rad), not another branch.
    int same = 0;
    List<IkTargetsCsv.Target> targets = ForwardKinematicsTest.referenceTargets();
    for (IkTargetsCsv.Target t : targets) {
      if (ik.solve(t.X_BF(), t.nearStart()) instanceof IkResult.Solved s
          && ClosedFormIkTest.maxDiff(s.q(), t.q()) < 1e-6) {
        same++;
      }
    }
    assertThat(same).isGreaterThan(targets.size() * 98 / 100);
  }

  @Test
  void beyondReachIsOutOfReachWithoutRestarts() {
    Transform far = Xyzwpr.ofDegrees(1500, 200, 330, 180, 0, 0).toTransform();
    assertReasonQuickly(ik, far, IkResult.Reason.OUT_OF_REACH);
  }

  @Test
  void insideTheBaseFromBelowIsAJointLimitWithoutRestarts() {
    Transform underBase = Xyzwpr.ofDegrees(0, 0, -150, 0, 0, 0).toTransform();
    assertReasonQuickly(ik, underBase, IkResult.Reason.JOINT_LIMIT);
  }

  @Test
  void limitOnlyPoseIsAJointLimitWithoutRestarts() {
    Transform behind = Xyzwpr.ofDegrees(-100, 0, 900, 180, 0, 0).toTransform();
    assertReasonQuickly(ik, behind, IkResult.Reason.JOINT_LIMIT);
  }

  @Test
  void armWithoutClosedFormUsesTheReachSphereAndCapsItsWork() {
    RobotModel noOpw = new RobotModel(robot.id(), robot.displayName(), robot.joints(), robot.X_6F(),
        robot.X_WB(), robot.links(), Optional.empty(), robot.coupledJ3());
    NumericIk generic = new NumericIk(noOpw);
    assertReasonQuickly(generic, Xyzwpr.ofDegrees(1500, 200, 330, 180, 0, 0).toTransform(),
        IkResult.Reason.OUT_OF_REACH);
    // A limit-only pose costs the whole budget of restarts but still ends with a reason.
    IkResult r = generic.solve(Xyzwpr.ofDegrees(-100, 0, 900, 180, 0, 0).toTransform(), new double[6]);
    assertThat(r).isInstanceOfSatisfying(IkResult.Unreachable.class,
        u -> assertThat(u.reason()).isIn(IkResult.Reason.JOINT_LIMIT, IkResult.Reason.NO_CONVERGENCE));
    // And a reachable pose still solves without the closed form's help.
    double[] q = {0.4, 0.3, 0.5, -1.0, 0.7, 2.0};
    assertThat(generic.solve(ForwardKinematics.flangePoseInBase(robot, q), new double[6]))
        .isInstanceOf(IkResult.Solved.class);
  }

  @Test
  void justBeyondTheStretchedArmIsSingularWithoutTheClosedForm() {
    // Straight up, flange facing up: the stretched arm puts the flange at z = 330 + 330 +
    // sqrt(335² + 35²) + 80 = 1076.8 mm above x = 50 mm. Ask 2 mm higher: inside the reach
    // sphere, so the solver iterates and ends on the elbow singularity.
    RobotModel noOpw = new RobotModel(robot.id(), robot.displayName(), robot.joints(), robot.X_6F(),
        robot.X_WB(), robot.links(), Optional.empty(), robot.coupledJ3());
    Transform up = Xyzwpr.ofDegrees(50, 0, 1078.8, 0, 0, 0).toTransform();
    IkResult r = new NumericIk(noOpw).solve(up, new double[6]);
    assertThat(r).isInstanceOfSatisfying(IkResult.Unreachable.class, u -> {
      assertThat(u.reason()).isEqualTo(IkResult.Reason.SINGULAR);
      assertThat(u.message()).contains("singular");
    });
    // With the closed form's verdict the same target is simply out of reach.
    assertThat(ik.solve(up, new double[6])).isInstanceOfSatisfying(IkResult.Unreachable.class,
        u -> assertThat(u.reason()).isEqualTo(IkResult.Reason.OUT_OF_REACH));
  }

  /**
   * The issue bounds the time to recognise an unreachable target at 1 ms. The behaviour behind
   * that bound is asserted here: a target beyond reach gets its verdict from the reach check after
   * the first attempt, with no restarts (an answer after iterating always says "after N
   * iterations (why)"); any other unreachable target gets its verdict from that check too, or ends
   * because every seed was tried within the iteration budget, never by running into the
   * iteration or time cap. The time itself is a
   * benchmark figure (NumericIkBench.unreachableVerdict), not a test.
   */
  private static void assertReasonQuickly(NumericIk solver, Transform target, IkResult.Reason reason) {
    IkResult r = solver.solve(target, new double[6]);
    assertThat(r).isInstanceOfSatisfying(IkResult.Unreachable.class, u -> {
      assertThat(u.reason()).isEqualTo(reason);
      java.util.regex.Matcher m = java.util.regex.Pattern.compile("after (\\d+) iterations \\((.+)\\)$")
          .matcher(u.message());
      if (reason == IkResult.Reason.OUT_OF_REACH) {
        assertThat(m.find()).as(u.message()).isFalse();
      } else if (m.find()) {
        assertThat(m.group(2)).isEqualTo("all seeds tried");
        assertThat(Integer.parseInt(m.group(1))).isLessThan(NumericIk.Settings.defaults().maxIterations());
      }
    });
  }
}
