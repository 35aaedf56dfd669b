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

  @Test
  void edgeSmoothingChangesOnlyPixelsAtHighContrastEdges() {
    double[] q = {0.3, 0.2, -0.1, 0, -0.6, 0};
    byte[] hard = render(AntiAliasing.NONE, q);
    byte[] smooth = render(AntiAliasing.FXAA, q);
    int changed = 0;
    for (int y = 0; y < H; y++) {
      for (int x = 0; x < W; x++) {
        int i = 3 * (y * W + x);
        if (hard[i] == smooth[i] && hard[i + 1] == smooth[i + 1] && hard[i + 2] == smooth[i + 2]) {
          continue;
        }
        changed++;
        // Same threshold family as fxaa.frag: a changed pixel had a neighbour at least 1/24
        // of full scale (about 10 of 255 in luma) away.
        assertThat(maxNeighbourLumaStep(hard, x, y)).as("luma step around changed pixel (%d, %d)", x, y)
            .isGreaterThanOrEqualTo(10);
      }
    }
    // Only the solids' outlines and creases: the floor's grid lines are left alone.
    assertThat(changed).as("pixels softened").isGreaterThan(100).isLessThan(W * H / 20);
  }

  @Test
  void fourTimesMultisamplingDrawsTheSameArm() {
    double[] q = {0.3, 0.2, -0.1, 0, -0.6, 0};
    byte[] hard = render(AntiAliasing.NONE, q);
    byte[] msaa = render(AntiAliasing.MSAA4, q);
    int yellowHard = 0;
    int yellowMsaa = 0;
    for (int i = 0; i < hard.length; i += 3) {
      yellowHard += isArmYellow(rgb(hard, i)) ? 1 : 0;
      yellowMsaa += isArmYellow(rgb(msaa, i)) ? 1 : 0;
    }
    // Only edge pixels may differ: the yellow areas agree within a few percent.
    assertThat(yellowHard).isGreaterThan(500);
    assertThat((double) yellowMsaa).isCloseTo(yellowHard, org.assertj.core.data.Percentage.withPercentage(10));
  }

  @Test
  void orientationTriadInTheBottomLeftCornerShowsABlueZBar() {
    byte[] px = render(AntiAliasing.DEFAULT, new double[6]);
    int size = OrientationGizmo.sizePx(W, H) + 20;
    int blueInCorner = 0;
    int blueElsewhere = 0;
    for (int y = 0; y < H; y++) {
      for (int x = 0; x < W; x++) {
        int c = rgb(px, 3 * (y * W + x));
        int r = (c >> 16) & 0xff, g = (c >> 8) & 0xff, b = c & 0xff;
        boolean blue = b > 120 && b > r + 60 && b > g + 30;
        // Rows are top first: the bottom-left corner is high y, low x.
        if (x < size && y >= H - size) {
          blueInCorner += blue ? 1 : 0;
        } else {
          blueElsewhere += blue ? 1 : 0;
        }
      }
    }
    assertThat(blueInCorner).isGreaterThan(15);
    assertThat(blueElsewhere).isZero();
  }

  private byte[] render(AntiAliasing mode, double[] q) {
    try (HeadlessRenderer r = GlTestSupport.rendererOrSkip(W, H, mode)) {
      return r.renderRgb(SceneSnapshots.singleRobot(robot, q, 0), new OrbitCamera());
    }
  }

  private static int maxNeighbourLumaStep(byte[] px, int x, int y) {
    int centre = luma(px, x, y);
    int best = 0;
    int[][] offsets = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int[] d : offsets) {
      int nx = Math.max(0, Math.min(W - 1, x + d[0]));
      int ny = Math.max(0, Math.min(H - 1, y + d[1]));
      best = Math.max(best, Math.abs(luma(px, nx, ny) - centre));
    }
    return best;
  }

  private static int luma(byte[] px, int x, int y) {
    int i = 3 * (y * W + x);
    return (int) Math.round(0.299 * (px[i] & 0xff) + 0.587 * (px[i + 1] & 0xff) + 0.114 * (px[i + 2] & 0xff));
  }

  private static int rgb(byte[] px, int i) {
    return (px[i] & 0xff) << 16 | (px[i + 1] & 0xff) << 8 | (px[i + 2] & 0xff);
  }

  static boolean isArmYellow(int rgb) {
    int r = (rgb >> 16) & 0xff, g = (rgb >> 8) & 0xff, b = rgb & 0xff;
    return r > 150 && g > 100 && b < 90 && r - b > 100;
  }
}
