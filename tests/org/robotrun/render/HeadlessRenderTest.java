package org.robotrun.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.SceneSnapshots;

class HeadlessRenderTest {
  private static final int W = 320;
  private static final int H = 200;
  private final RobotModel robot = RobotDefinitions.defaultRobot();

  @Test
  void writesAPngOfTheRequestedSizeWithTheYellowArmNearTheCentre(@TempDir Path dir) throws Exception {
    Path out = dir.resolve("shot.png");
    try (HeadlessRenderer r = GlTestSupport.rendererOrSkip(W, H)) {
      r.renderPng(SceneSnapshots.singleRobot(robot, new double[6], 0), new OrbitCamera(), out);
    }
    assertThat(Files.size(out)).isPositive();
    BufferedImage img = ImageIO.read(out.toFile());
    assertThat(img.getWidth()).isEqualTo(W);
    assertThat(img.getHeight()).isEqualTo(H);
    // Robot yellow: strong red and green, little blue. Look in the middle half of the image.
    int yellow = 0;
    for (int y = H / 4; y < 3 * H / 4; y++) {
      for (int x = W / 4; x < 3 * W / 4; x++) {
        if (isArmYellow(img.getRGB(x, y))) {
          yellow++;
        }
      }
    }
    assertThat(yellow).as("arm-yellow pixels near the centre").isGreaterThan(200);
  }

  @Test
  void turningJ1ChangesThePixelsWhereTheArmIs() {
    double[] q0 = {0, 0, 0, 0, -Math.PI / 4, 0};
    double[] q90 = {Math.PI / 2, 0, 0, 0, -Math.PI / 4, 0};
    byte[] a;
    byte[] b;
    try (HeadlessRenderer r = GlTestSupport.rendererOrSkip(W, H)) {
      OrbitCamera cam = new OrbitCamera();
      a = r.renderRgb(SceneSnapshots.singleRobot(robot, q0, 0), cam);
      b = r.renderRgb(SceneSnapshots.singleRobot(robot, q90, 0), cam);
    }
    int yellowOnlyInA = 0;
    int changed = 0;
    for (int i = 0; i < a.length; i += 3) {
      boolean ya = isArmYellow(rgb(a, i));
      boolean yb = isArmYellow(rgb(b, i));
      if (ya && !yb) {
        yellowOnlyInA++;
      }
      if (a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2]) {
        changed++;
      }
    }
    // The forearm swings from +X to +Y: many yellow pixels of the first pose are background later.
    assertThat(yellowOnlyInA).isGreaterThan(300);
    assertThat(changed).isGreaterThan(yellowOnlyInA);
  }

  private static int rgb(byte[] px, int i) {
    return (px[i] & 0xff) << 16 | (px[i + 1] & 0xff) << 8 | (px[i + 2] & 0xff);
  }

  static boolean isArmYellow(int rgb) {
    int r = (rgb >> 16) & 0xff, g = (rgb >> 8) & 0xff, b = rgb & 0xff;
    return r > 150 && g > 100 && b < 90 && r - b > 100;
  }
}
