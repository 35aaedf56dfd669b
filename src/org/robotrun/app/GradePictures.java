package org.robotrun.app;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.Base64;
import javax.imageio.ImageIO;
import org.robotrun.math.Vec3;
import org.robotrun.render.HeadlessRenderer;
import org.robotrun.render.OrbitCamera;
import org.robotrun.sim.SceneSnapshot;
import org.robotrun.world.Scenario;

/**
 * Pictures for the grading reports, drawn after the simulations with one headless (OSMesa)
 * renderer on the calling thread: GL contexts are not shared between threads, so the pictures
 * of all submissions are drawn one after the other.
 */
final class GradePictures implements AutoCloseable {
  static final int WIDTH = 640;
  static final int HEIGHT = 400;

  private final HeadlessRenderer renderer;
  private final Scenario scenario;

  /** @throws org.robotrun.render.GlUnavailableException when no OpenGL can be had */
  GradePictures(Scenario scenario) {
    this.renderer = new HeadlessRenderer(WIDTH, HEIGHT);
    this.scenario = scenario;
  }

  /** The whole cell as the scenario's camera shows it, as a PNG data URI. */
  String overview(SceneSnapshot scene) {
    OrbitCamera camera = new OrbitCamera();
    scenario.camera().ifPresent(v -> ScenarioFiles.applyCamera(v, camera));
    return dataUri(scene, camera);
  }

  /** A close view centred on {@code p_C} (cell frame, mm), as a PNG data URI. */
  String closeUp(SceneSnapshot scene, Vec3 p_C) {
    OrbitCamera camera = new OrbitCamera();
    float yaw = (float) Math.toRadians(-150);
    float pitch = (float) Math.toRadians(35);
    if (scenario.camera().isPresent()) {
      yaw = (float) scenario.camera().get().yawRad();
      pitch = (float) scenario.camera().get().pitchRad();
    }
    camera.set((float) p_C.x(), (float) p_C.y(), (float) p_C.z(), 700f, yaw, pitch);
    return dataUri(scene, camera);
  }

  private String dataUri(SceneSnapshot scene, OrbitCamera camera) {
    byte[] rgb = renderer.renderRgb(scene, camera);
    BufferedImage img = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_RGB);
    for (int y = 0, i = 0; y < HEIGHT; y++) {
      for (int x = 0; x < WIDTH; x++, i += 3) {
        img.setRGB(x, y, (rgb[i] & 0xff) << 16 | (rgb[i + 1] & 0xff) << 8 | (rgb[i + 2] & 0xff));
      }
    }
    ByteArrayOutputStream png = new ByteArrayOutputStream();
    try {
      ImageIO.write(img, "png", png);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    return "data:image/png;base64," + Base64.getEncoder().encodeToString(png.toByteArray());
  }

  @Override
  public void close() {
    renderer.close();
  }
}
