package org.robotrun.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.SceneSnapshots;

/** Every library model renders headless: its bodies fill the frame and follow J1 (skips outside CI without OpenGL). */
class RobotLibraryRenderTest {
  private static final int W = 240;
  private static final int H = 160;

  static Stream<String> models() {
    return RobotDefinitions.LIBRARY.stream();
  }

  @ParameterizedTest
  @MethodSource("models")
  void theArmIsDrawnAndTurnsWithJ1(String id) {
    RobotModel m = RobotDefinitions.load(id);
    double reach = RobotDefinitions.library().stream().filter(e -> e.id().equals(id)).findFirst().orElseThrow().reachMm();
    double[] q0 = {0, 0, 0, 0, -Math.PI / 2, 0};
    double[] q1 = {Math.PI, 0, 0, 0, -Math.PI / 2, 0};
    byte[] a;
    byte[] b;
    try (HeadlessRenderer r = GlTestSupport.rendererOrSkip(W, H)) {
      OrbitCamera cam = new OrbitCamera();
      // Looking from the side at the arm's middle, far enough back for the whole reach.
      cam.set(0, 0, (float) (-m.X_WB().z() * 0.2), (float) (2.6 * reach), (float) Math.toRadians(-90), (float) Math.toRadians(15));
      a = r.renderRgb(SceneSnapshots.singleRobot(m, q0, 0), cam);
      b = r.renderRgb(SceneSnapshots.singleRobot(m, q1, 0), cam);
    }
    int changed = 0;
    for (int i = 0; i < a.length; i += 3) {
      int d = Math.abs((a[i] & 0xff) - (b[i] & 0xff)) + Math.abs((a[i + 1] & 0xff) - (b[i + 1] & 0xff))
          + Math.abs((a[i + 2] & 0xff) - (b[i + 2] & 0xff));
      if (d > 30) {
        changed++;
      }
    }
    // The forearm swings from one side of the J1 axis to the other: a visible share of the frame.
    assertThat(changed).as(id + " pixels that change when J1 turns 180 deg").isGreaterThan(W * H / 100);
  }
}
