package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;

/**
 * {@link NewtonPolish} as its comment promises, measured by {@link ForwardKinematics}: from a start
 * a fraction of a degree off (each joint, or only the wrist's roll, or only the position) it brings
 * the joints onto the target to 1e-9 mm and 1e-12 rad and says so; with no steps allowed it only
 * judges the start (1e-6 mm, 1e-9 rad) and leaves it alone; a start beyond its give-up distances is
 * another answer's and is refused untouched; at a singular posture (J5 = 0) a start on the target is kept.
 */
class NewtonPolishTest {
  static final RobotModel ARM = RobotDefinitions.load("lrmate200id");

  static double[] packed(Transform x) {
    double[] a = new double[12];
    KinematicChain.pack(x, a, 0);
    return a;
  }

  static double[] randomQ(Random rnd) {
    double[] q = new double[6];
    for (int i = 0; i < 6; i++) {
      q[i] = 0.8 * (ARM.joint(i).lowerRad() + rnd.nextDouble() * (ARM.joint(i).upperRad() - ARM.joint(i).lowerRad()));
    }
    q[4] = (rnd.nextBoolean() ? 1 : -1) * (0.3 + rnd.nextDouble());
    return q;
  }

  @Test
  void aStartAFractionOfADegreeOffIsBroughtOntoTheTarget() {
    Random rnd = new Random(71);
    NewtonPolish polish = new NewtonPolish(new KinematicChain(ARM));
    for (int k = 0; k < 30; k++) {
      double[] q = randomQ(rnd);
      Transform X = ForwardKinematics.flangePoseInBase(ARM, q);
      double[] start = q.clone();
      switch (k % 3) {
        case 0 -> {
          for (int i = 0; i < 6; i++) {
            start[i] += 4e-3 * (rnd.nextDouble() - 0.5);
          }
        }
        case 1 -> start[5] += 3e-3; // the flange turned about its own axis: orientation only
        default -> start[0] += 2e-3; // the whole arm swung: position and orientation
      }
      assertThat(polish.polish(start, packed(X))).as("start %d", k).isTrue();
      Transform Y = ForwardKinematics.flangePoseInBase(ARM, start);
      assertThat(Y.distanceTo(X)).as("start %d mm", k).isLessThan(1e-9);
      assertThat(Y.rotationAngleTo(X)).as("start %d rad", k).isLessThan(1e-12);
      assertThat(IkSolverContractTest.maxDiff(start, q)).as("start %d: back to the joints", k).isLessThan(1e-8);
    }
  }

  @Test
  void withNoStepsItOnlyJudgesTheStart() {
    NewtonPolish none = new NewtonPolish(new KinematicChain(ARM), 0, 10, 0.05);
    double[] q = {0.3, 0.2, -0.4, 0.5, -0.9, 1.1};
    double[] X = packed(ForwardKinematics.flangePoseInBase(ARM, q));
    double[] exact = q.clone();
    assertThat(none.polish(exact, X)).isTrue();
    assertThat(exact).containsExactly(q);
    double[] off = q.clone();
    off[1] += 1e-6; // about 0.4 µm at the flange: above 1e-6 mm
    assertThat(none.polish(off, X)).isFalse();
    assertThat(off[1]).isEqualTo(q[1] + 1e-6);
    // One step from there is enough.
    NewtonPolish one = new NewtonPolish(new KinematicChain(ARM), 1, 10, 0.05);
    assertThat(one.polish(off, X)).isTrue();
    assertThat(ForwardKinematics.flangePoseInBase(ARM, off).distanceTo(KinematicChain.unpack(X))).isLessThan(1e-6);
  }

  @Test
  void aStartBeyondTheGiveUpDistancesIsRefusedUntouched() {
    NewtonPolish polish = new NewtonPolish(new KinematicChain(ARM), 6, 1, 1e-2);
    double[] q = {0.3, 0.2, -0.4, 0.5, -0.9, 1.1};
    double[] X = packed(ForwardKinematics.flangePoseInBase(ARM, q));
    // J6 turned 0.02 rad: the flange does not move (its origin is on J6's axis) but turns 0.02 > 0.01 rad.
    double[] turned = q.clone();
    turned[5] += 0.02;
    assertThat(polish.polish(turned, X)).isFalse();
    assertThat(turned[5]).isEqualTo(q[5] + 0.02);
    // J1 swung 0.005 rad: the flange moves about 3 mm (> 1 mm) while turning only 0.005 rad.
    double[] swung = q.clone();
    swung[0] += 0.005;
    assertThat(polish.polish(swung, X)).isFalse();
    assertThat(swung[0]).isEqualTo(q[0] + 0.005);
    // Within both, it polishes.
    double[] close = q.clone();
    close[5] += 0.005;
    assertThat(polish.polish(close, X)).isTrue();
  }

  @Test
  void atTheWristSingularityAStartOnTheTargetIsKept() {
    // J5 = 0: J4 and J6 in line, the Jacobian singular. Exactly there the start is the answer;
    // a hair off in J4 and back in J6 is the same pose (only J4 + J6 counts), so it is kept.
    NewtonPolish polish = new NewtonPolish(new KinematicChain(ARM));
    double[] q = {0.3, 0.2, -0.4, 0.5, 0, 1.1};
    double[] X = packed(ForwardKinematics.flangePoseInBase(ARM, q));
    double[] same = q.clone();
    assertThat(polish.polish(same, X)).isTrue();
    double[] shifted = q.clone();
    shifted[3] += 0.01;
    shifted[5] -= 0.01; // J4 and J6 turn the same way at J5 = 0 on the LR Mate (both about -x)
    Transform Y = ForwardKinematics.flangePoseInBase(ARM, shifted);
    assertThat(Y.distanceTo(KinematicChain.unpack(X))).isLessThan(1e-9);
    assertThat(Y.rotationAngleTo(KinematicChain.unpack(X))).isLessThan(1e-12);
    assertThat(polish.polish(shifted, X)).isTrue();
    assertThat(shifted[3] + shifted[5]).isCloseTo(q[3] + q[5], org.assertj.core.api.Assertions.within(1e-9));
  }
}
