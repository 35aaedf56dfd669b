package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;

/**
 * The numeric solver's caps and give-up answers as NumericIk.Settings and docs/kinematics.md state
 * them, on the LR Mate without its closed form (so nothing rejects the target before iterating)
 * and a pose only reachable behind the robot past J1's limit: with a cap of 50 iterations in all it
 * stops after exactly 50 and says "iteration cap"; with a CPU-time cap of 1 ns (counted from the
 * end of the first attempt) it stops after the second attempt, at most 2 × 20 iterations, and says
 * "time cap"; without caps it tries every seed and the polish (113 attempts, fewer than 2000
 * iterations) and says "all seeds tried"; and the reason names J1 stopped at its limit, where the
 * best attempt behind the robot must end.
 */
class NumericIkCapsTest {
  static final RobotModel LRMATE = RobotDefinitions.defaultRobot();
  static final RobotModel NO_OPW = new RobotModel(LRMATE.id(), LRMATE.displayName(), LRMATE.joints(), LRMATE.X_6F(),
      LRMATE.X_WB(), LRMATE.links(), Optional.empty(), LRMATE.coupledJ3());
  static final Transform BEHIND = Xyzwpr.ofDegrees(-100, 0, 900, 180, 0, 0).toTransform();
  static final Pattern DETAIL = Pattern.compile("best error (\\S+) mm, (\\S+) rad after (\\d+) iterations \\((.+)\\)$");

  static Matcher detail(IkResult r) {
    assertThat(r).isInstanceOf(IkResult.Unreachable.class);
    Matcher m = DETAIL.matcher(((IkResult.Unreachable) r).message());
    assertThat(m.find()).as(((IkResult.Unreachable) r).message()).isTrue();
    return m;
  }

  @Test
  void anIterationCapOfFiftyStopsAfterFiftyIterations() {
    NumericIk ik = new NumericIk(NO_OPW, new NumericIk.Settings(1e-6, 1e-9, 20, 50, 20_000_000_000L, 300, 0.1, 0.95));
    Matcher m = detail(ik.solve(BEHIND, new double[6]));
    assertThat(m.group(3)).isEqualTo("50");
    assertThat(m.group(4)).isEqualTo("iteration cap");
    assertThat(((IkResult.Unreachable) ik.solve(BEHIND, new double[6])).reason()).isEqualTo(IkResult.Reason.JOINT_LIMIT);
  }

  @Test
  void aTimeCapStopsAfterTheSecondAttempt() {
    NumericIk ik = new NumericIk(NO_OPW, new NumericIk.Settings(1e-6, 1e-9, 20, 2000, 1, 300, 0.1, 0.95));
    Matcher m = detail(ik.solve(BEHIND, new double[6]));
    assertThat(m.group(4)).isEqualTo("time cap");
    assertThat(Integer.parseInt(m.group(3))).isBetween(2, 40);
  }

  @Test
  void withoutCapsEverySeedIsTriedAndTheEndIsNamed() {
    IkResult r = new NumericIk(NO_OPW).solve(BEHIND, new double[6]);
    Matcher m = detail(r);
    assertThat(m.group(4)).isEqualTo("all seeds tried");
    // 1 + 64 + 32 + 16 attempts of at most 20 iterations, and a polish of up to 800: never the 2000 cap.
    assertThat(Integer.parseInt(m.group(3))).isBetween(113, 1999);
    // Behind the robot the best attempt ends with J1 pressed against its limit, and says so.
    IkResult.Unreachable u = (IkResult.Unreachable) r;
    assertThat(u.reason()).isEqualTo(IkResult.Reason.JOINT_LIMIT);
    assertThat(u.message()).startsWith("no solution found inside the joint limits; J1 stopped at its limit; best error ");
  }
}
