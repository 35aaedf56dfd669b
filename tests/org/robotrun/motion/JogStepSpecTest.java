package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.JointConvention;

/**
 * FINE/VFINE jog steps (docs/motion.md: one increment per key press, Jogger.step) against the
 * frames they move in (issue 31): a joint step turns that joint alone (J2 keeps the pendant's J3),
 * a Cartesian step moves the TCP by the increment along WORLD's, the tool's or the user frame's
 * axis with the orientation kept, a rotation step turns about that axis through the TCP, and a
 * step past a joint limit is refused with the joint named and the arm left where it was.
 */
class JogStepSpecTest {
  static final Transform TOOL = MotionRunnerTest.TOOL;
  static final double[] START = {0.3, 0.2, -0.1, 0.4, -1.2, 0.5};

  static Transform tcp(double[] q) {
    return ForwardKinematics.flangePoseInWorld(MotionRunnerTest.MODEL, q).compose(TOOL);
  }

  @Test
  void jointStepsTurnOneJointAndJ2KeepsThePendantsJ3() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    for (int axis = 0; axis < 6; axis++) {
      for (int sign : new int[] {1, -1}) {
        double[] q = START.clone();
        double[] before = JointConvention.kinematicToPendant(MotionRunnerTest.MODEL, q);
        assertThat(jog.step(q, JogFrame.JOINT, axis, sign, 1, 0.01, TOOL, Transform.IDENTITY)).isInstanceOf(JogResult.Moving.class);
        double[] after = JointConvention.kinematicToPendant(MotionRunnerTest.MODEL, q);
        for (int j = 0; j < 6; j++) {
          assertThat(after[j] - before[j]).as("axis %d sign %d joint %d", axis, sign, j).isCloseTo(j == axis ? sign * 0.01 : 0, within(1e-12));
        }
      }
    }
  }

  @Test
  void cartesianStepsMoveTheTcpAlongTheFramesAxisAndKeepTheOrientation() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    Transform user = Transform.fromRpy(100, -50, 20, 0.3, 0.2, 1.1);
    for (JogFrame frame : new JogFrame[] {JogFrame.WORLD, JogFrame.TOOL, JogFrame.USER, JogFrame.JGFRM}) {
      for (int axis = 0; axis < 3; axis++) {
        double[] q = START.clone();
        Transform before = tcp(q);
        Transform axes = frame == JogFrame.WORLD ? Transform.IDENTITY : frame == JogFrame.TOOL ? before : user;
        assertThat(jog.step(q, frame, axis, -1, 2.5, 0.01, TOOL, user)).isInstanceOf(JogResult.Moving.class);
        Transform after = tcp(q);
        Vec3 moved = after.translationVector().minus(before.translationVector());
        assertThat(moved.distanceTo(axes.axis(axis).times(-2.5))).as("%s axis %d", frame, axis).isLessThan(1e-4);
        assertThat(after.rotationAngleTo(before)).isLessThan(1e-7);
      }
      for (int axis = 3; axis < 6; axis++) {
        double[] q = START.clone();
        Transform before = tcp(q);
        Transform axes = frame == JogFrame.WORLD ? Transform.IDENTITY : frame == JogFrame.TOOL ? before : user;
        assertThat(jog.step(q, frame, axis, 1, 2.5, 0.02, TOOL, user)).isInstanceOf(JogResult.Moving.class);
        Transform after = tcp(q);
        assertThat(after.translationVector().distanceTo(before.translationVector())).as("%s axis %d", frame, axis).isLessThan(1e-4);
        Vec3 a = axes.axis(axis - 3);
        Transform expected = Transform.rotation(a.x(), a.y(), a.z(), 0.02).compose(before.withTranslation(0, 0, 0));
        assertThat(after.rotationAngleTo(expected)).as("%s axis %d", frame, axis).isLessThan(1e-7);
      }
    }
  }

  @Test
  void aStepPastAJointLimitIsRefusedAndTheArmStays() {
    Jogger jog = new Jogger(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS);
    double[] q = START.clone();
    q[0] = MotionRunnerTest.MODEL.joint(0).upperRad() - 0.005;
    double[] before = q.clone();
    JogResult r = jog.step(q, JogFrame.JOINT, 0, 1, 1, 0.01, TOOL, Transform.IDENTITY);
    assertThat(r).isInstanceOf(JogResult.Stopped.class);
    assertThat(((JogResult.Stopped) r).message()).contains("J1");
    assertThat(q).containsExactly(before);
    assertThat(jog.step(q, JogFrame.JOINT, 0, 1, 1, 0.004, TOOL, Transform.IDENTITY)).isInstanceOf(JogResult.Moving.class);
  }
}
