package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.robotrun.render.GlTestSupport;

/**
 * Renders the pictures of the lab guides (docs/labs/img/) from each lab's own starting cell with
 * the current code, so they never go stale: an overview from the cell's camera, and for the labs
 * whose targets are small a close view. Needs headless OpenGL (Mesa's OSMesa): without it the test
 * is skipped outside CI, as every render test is. The pictures are written into docs/labs/img/;
 * a change in the renderer or a cell shows up as a changed file in the working tree.
 */
class LabPicturesTest {
  static final Path COURSE = Path.of("scenarios/labs");
  static final Path IMG = Path.of("docs/labs/img");
  static final ObjectMapper JSON = new ObjectMapper();

  /** Close views: lab to {target x, y, z, distance, yaw, pitch}. */
  static final Map<String, double[]> CLOSE = Map.of(
      "01-safety", new double[] {400, 0, -80, 700, -30, 35},
      "02-jogging", new double[] {380, 0, -60, 520, -25, 50},
      "03-tool-frame", new double[] {400, 0, -20, 450, -30, 15},
      "04-user-frame", new double[] {380, 0, -60, 520, -25, 50},
      "05-first-program", new double[] {410, 0, -90, 520, -20, 55},
      "06-registers", new double[] {410, 0, -90, 520, -20, 55});

  @Test
  void everyLabGuideHasItsPicturesRenderedFromItsOwnCell() throws Exception {
    GlTestSupport.rendererOrSkip(16, 16).close();
    Files.createDirectories(IMG);
    JsonNode course = JSON.readTree(COURSE.resolve("course.json").toFile());
    for (JsonNode lab : course.get("labs")) {
      String id = lab.get("id").asText();
      Path cell = COURSE.resolve(lab.get("cell").asText());
      Path overview = IMG.resolve(id + ".png");
      LabsTest.run("render", "--scenario", cell.toString(), "--out", overview.toString(), "--width", "800", "--height", "480");
      assertThat(ImageIO.read(overview.toFile()).getWidth()).isEqualTo(800);
      double[] c = CLOSE.get(id);
      if (c != null) {
        // The same cell seen from closer: a copy beside it with another camera, removed at once.
        ObjectNode scenario = (ObjectNode) JSON.readTree(cell.toFile());
        ObjectNode camera = scenario.putObject("camera");
        camera.putObject("target").put("x", c[0]).put("y", c[1]).put("z", c[2]);
        camera.put("distance", c[3]).put("yawDeg", c[4]).put("pitchDeg", c[5]);
        Path copy = cell.resolveSibling(".close-view.json");
        try {
          Files.writeString(copy, JSON.writeValueAsString(scenario));
          Path close = IMG.resolve(id + "-close.png");
          LabsTest.run("render", "--scenario", copy.toString(), "--out", close.toString(), "--width", "800", "--height", "480");
          assertThat(ImageIO.read(close.toFile()).getHeight()).isEqualTo(480);
        } finally {
          Files.deleteIfExists(copy);
        }
      }
    }
  }
}
