package org.robotrun.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.IkTargetsCsv;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;

class ForwardKinematicsTest {
  private final RobotModel robot = RobotDefinitions.defaultRobot();

  static List<IkTargetsCsv.Target> referenceTargets() throws Exception {
    return IkTargetsCsv.read(referenceFile());
  }

  static Path referenceFile() throws URISyntaxException {
    return Path.of(ForwardKinematicsTest.class.getResource("/ik_targets_lrmate200id.csv").toURI());
  }

  @Test
  void allZeroJointsPutTheFlangeWhereTheControllerSays() {
    // shared/robots/README.md: q = 0 gives X=465, Y=0, Z=365 mm, W,P,R = (180, -90, 0) in WORLD.
    Transform X_WF = ForwardKinematics.flangePoseInWorld(robot, new double[6]);
    Transform expected = Xyzwpr.ofDegrees(465, 0, 365, 180, -90, 0).toTransform();
    assertThat(X_WF.distanceTo(expected)).isLessThan(1e-9);
    assertThat(X_WF.rotationAngleTo(expected)).isLessThan(1e-12);
  }

  @Test
  void flangePoseMatchesEveryReferenceRow() throws Exception {
    // Method: compare FK of each row's q with the stored base_link pose. Tolerance 1e-6 mm, 1e-9 rad.
    List<IkTargetsCsv.Target> targets = referenceTargets();
    assertThat(targets).hasSize(2000);
    double worstMm = 0;
    double worstRad = 0;
    for (IkTargetsCsv.Target t : targets) {
      Transform X_BF = ForwardKinematics.flangePoseInBase(robot, t.q());
      worstMm = Math.max(worstMm, X_BF.distanceTo(t.X_BF()));
      worstRad = Math.max(worstRad, X_BF.rotationAngleTo(t.X_BF()));
    }
    assertThat(worstMm).isLessThan(1e-6);
    assertThat(worstRad).isLessThan(1e-9);
  }

  @Test
  void coupledJ3KeepsTheForearmLevelWhenOnlyJ2Moves() {
    // README worked example: pendant (0, 30, 0, 0, 0, 0) deg is kinematic (0, 30, 30, 0, 0, 0).
    double[] pendant = {0, Math.toRadians(30), 0, 0, 0, 0};
    double[] q = JointConvention.pendantToKinematic(robot, pendant);
    assertThat(q[2]).isCloseTo(Math.toRadians(30), within(1e-15));
    assertThat(JointConvention.kinematicToPendant(robot, q)).containsExactly(pendant, within(1e-15));
    // The forearm (link 4's x axis) stays horizontal.
    Transform X_B4 = ForwardKinematics.linkPosesInBase(robot, q)[4];
    assertThat(X_B4.axis(0).z()).isCloseTo(0, within(1e-12));
  }
}
