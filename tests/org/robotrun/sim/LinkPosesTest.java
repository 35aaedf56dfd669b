package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.RobotModel;

class LinkPosesTest {
  @Test
  void sameLinkPosesAsForwardKinematics() {
    RobotModel model = ControllerTest.MODEL;
    Transform X_CW = Transform.rotation(0, 0, 1, 0.7).withTranslation(1200, -300, 50);
    LinkPoses poses = new LinkPoses(model, X_CW);
    Random random = new Random(5);
    Transform[] out = new Transform[8];
    for (int k = 0; k < 1000; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = model.joint(i).lowerRad() + random.nextDouble() * (model.joint(i).upperRad() - model.joint(i).lowerRad());
      }
      poses.compute(q, out);
      Transform[] ref = ForwardKinematics.linkPosesInWorld(model, q);
      for (int i = 0; i < 7; i++) {
        // Same pose to 1e-9 mm / 1e-12 rad (rounding only).
        assertThat(out[i].distanceTo(X_CW.compose(ref[i]))).isLessThan(1e-9);
        assertThat(out[i].rotationAngleTo(X_CW.compose(ref[i]))).isLessThan(1e-12);
      }
      Transform flange = X_CW.compose(ForwardKinematics.flangePoseInWorld(model, q));
      assertThat(out[7].distanceTo(flange)).isLessThan(1e-9);
    }
  }
}
