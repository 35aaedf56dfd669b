package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;

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
class JacobianTest {
  private final RobotModel robot = RobotDefinitions.defaultRobot();
  private final Transform tool = Xyzwpr.ofDegrees(12, -30, 150, 10, 20, 30).toTransform();

  @Property(seed = "11", tries = 300)
  void analyticJacobianMatchesCentralDifferences(
      @ForAll @DoubleRange(min = -170, max = 170) double j1,
      @ForAll @DoubleRange(min = -100, max = 145) double j2,
      @ForAll @DoubleRange(min = -70, max = 205) double j3,
      @ForAll @DoubleRange(min = -190, max = 190) double j4,
      @ForAll @DoubleRange(min = -125, max = 125) double j5,
      @ForAll @DoubleRange(min = -360, max = 360) double j6) {
    // Method: central differences of the reference FK (h = 1e-6 rad) with a tool offset;
    // linear rows to 1e-4 mm/rad, angular rows to 1e-8 (1/1).
    double[] q = Angles.toRadians(new double[] {j1, j2, j3, j4, j5, j6});
    double[] J = Jacobian.tcpJacobianInBase(robot, q, tool);
    double h = 1e-6;
    for (int i = 0; i < 6; i++) {
      double[] qp = q.clone();
      double[] qm = q.clone();
      qp[i] += h;
      qm[i] -= h;
      Transform Xp = ForwardKinematics.flangePoseInBase(robot, qp).compose(tool);
      Transform Xm = ForwardKinematics.flangePoseInBase(robot, qm).compose(tool);
      double[] lin = {(Xp.x() - Xm.x()) / (2 * h), (Xp.y() - Xm.y()) / (2 * h), (Xp.z() - Xm.z()) / (2 * h)};
      // ω = vee(Ṙ·Rᵀ), Ṙ·Rᵀ ≈ (Rp − Rm)/(2h) · Rᵀ.
      double[] rp = Xp.rotationRowMajor(), rm = Xm.rotationRowMajor();
      Transform X = ForwardKinematics.flangePoseInBase(robot, q).compose(tool);
      double[] r = X.rotationRowMajor();
      double[][] w = new double[3][3];
      for (int a = 0; a < 3; a++) {
        for (int b = 0; b < 3; b++) {
          double s = 0;
          for (int k = 0; k < 3; k++) {
            s += (rp[a * 3 + k] - rm[a * 3 + k]) / (2 * h) * r[b * 3 + k];
          }
          w[a][b] = s;
        }
      }
      double[] ang = {w[2][1], w[0][2], w[1][0]};
      for (int row = 0; row < 3; row++) {
        assertThat(J[row * 6 + i]).as("linear row %d col %d", row, i).isCloseTo(lin[row], org.assertj.core.api.Assertions.within(1e-4));
        assertThat(J[(row + 3) * 6 + i]).as("angular row %d col %d", row, i).isCloseTo(ang[row], org.assertj.core.api.Assertions.within(1e-8));
      }
    }
  }

  @Test
  void packedChainMatchesTheReferenceForwardKinematicsOnEveryRow() throws Exception {
    // Method: KinematicChain.flangePose vs ForwardKinematics on all 2000 reference joints; 1e-9 mm.
    KinematicChain chain = new KinematicChain(robot);
    double[] X = new double[12];
    for (IkTargetsCsv.Target t : ForwardKinematicsTest.referenceTargets()) {
      chain.flangePose(t.q(), X, null);
      Transform expected = ForwardKinematics.flangePoseInBase(robot, t.q());
      assertThat(KinematicChain.unpack(X).distanceTo(expected)).isLessThan(1e-9);
      assertThat(KinematicChain.unpack(X).rotationAngleTo(expected)).isLessThan(1e-12);
    }
  }

  @Test
  void theTcpPoseItFillsIsTheFlangePoseTimesTheTool() {
    // The pose output (used by the resolved-rate and numeric solvers) element by element against
    // the reference FK composed with the tool, with and without a tool.
    KinematicChain chain = new KinematicChain(robot);
    double[] packedTool = new double[12];
    KinematicChain.pack(tool, packedTool, 0);
    java.util.Random rnd = new java.util.Random(12);
    for (int k = 0; k < 20; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = robot.joint(i).lowerRad() + rnd.nextDouble() * (robot.joint(i).upperRad() - robot.joint(i).lowerRad());
      }
      double[] J = new double[36];
      double[] X = new double[12];
      Jacobian.tcpJacobianInBase(chain, q, packedTool, J, X, new double[Jacobian.SCRATCH]);
      double[] want = new double[12];
      KinematicChain.pack(ForwardKinematics.flangePoseInBase(robot, q).compose(tool), want, 0);
      for (int e = 0; e < 12; e++) {
        assertThat(X[e]).as("element %d", e).isCloseTo(want[e], org.assertj.core.api.Assertions.within(e < 9 ? 1e-12 : 1e-9));
      }
      Jacobian.tcpJacobianInBase(chain, q, null, J, X, new double[Jacobian.SCRATCH]);
      KinematicChain.pack(ForwardKinematics.flangePoseInBase(robot, q), want, 0);
      for (int e = 0; e < 12; e++) {
        assertThat(X[e]).as("element %d, no tool", e).isCloseTo(want[e], org.assertj.core.api.Assertions.within(e < 9 ? 1e-12 : 1e-9));
      }
    }
  }
}
