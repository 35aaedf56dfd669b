package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.world.LocalBox;
import org.robotrun.world.VisionSetup;

/**
 * The camera view of docs/vision.md: every part the last RUN_FIND of the camera's processes found
 * is outlined in green by a wire box 10 % larger than the part's box at its found pose, and
 * labelled {@code k: M<model> X.. Y.. R..} (the found position in the process's user frame) at its
 * found origin's image point (a pinhole camera looking along +z, columns along +x, rows along +y,
 * the field of view vertical: scenario-format.md). Process names are not case-sensitive.
 */
class VisionViewTest {

  private static Simulation noiseFreeCell() {
    VisionSetup v = VisionSystemTest.LAB.vision();
    return VisionSystemTest.cell(VisionSystemTest.withCamera(v, VisionSystemTest.camera(v, 0, 0, 0)));
  }

  @Test
  void foundPartsAreOutlinedTenPercentLargerAtTheirFoundPoseInGreen() {
    Simulation sim = noiseFreeCell();
    VisionSystem vs = sim.vision().orElseThrow();
    String cam = vs.setup().cameras().get(0).name();
    DrawItem other = new DrawItem("table", new DrawShape.Box(new Vec3(1, 1, 1), false), Transform.IDENTITY,
        DrawItem.Color.rgb(1, 1, 1));
    SceneSnapshot scene = new SceneSnapshot(1.5, List.of(other), -7);
    // nothing found yet: nothing outlined
    assertThat(vs.withOutlines(scene, cam).items()).containsExactly(other);
    List<VisionSystem.Detection> found = VisionSystemTest.find(sim);
    assertThat(found).isNotEmpty();
    SceneSnapshot view = vs.withOutlines(scene, cam);
    assertThat(view.simTimeSec()).isEqualTo(1.5);
    assertThat(view.floorZ()).isEqualTo(-7);
    assertThat(view.items()).hasSize(1 + found.size());
    assertThat(view.items().get(0)).isEqualTo(other);
    for (int i = 0; i < found.size(); i++) {
      String part = found.get(i).part();
      DrawItem d = view.items().get(i + 1);
      LocalBox box = sim.world().find(part).orElseThrow().shape().boundingBox();
      assertThat(d.name()).isEqualTo("vision/" + part);
      assertThat(d.color()).isEqualTo(VisionSystem.FOUND_COLOR);
      DrawShape.WireBox w = (DrawShape.WireBox) d.shape();
      assertThat(w.size().x()).isCloseTo(1.1 * 2 * box.hxMm(), within(1e-9));
      assertThat(w.size().y()).isCloseTo(1.1 * 2 * box.hyMm(), within(1e-9));
      assertThat(w.size().z()).isCloseTo(1.1 * 2 * box.hzMm(), within(1e-9));
      // noise-free: the found pose is the part's pose in the cell
      Transform want = sim.world().poseInCell(part).compose(box.X_LB());
      assertThat(d.X_WS().distanceTo(want)).isLessThan(1e-6);
    }
    // another camera's view has no outlines
    assertThat(vs.withOutlines(scene, "NOSUCHCAM").items()).containsExactly(other);
  }

  @Test
  void labelsNameTheModelAndFoundPositionAtTheFoundOriginsImagePoint() {
    Simulation sim = noiseFreeCell();
    VisionSystem vs = sim.vision().orElseThrow();
    VisionSetup.Camera cam = vs.setup().cameras().get(0);
    assertThat(vs.labels(cam)).isEmpty();
    List<VisionSystem.Detection> found = VisionSystemTest.find(sim);
    List<VisionSystem.Label> labels = vs.labels(cam);
    assertThat(labels).hasSize(found.size());
    Transform X_KC = vs.cameraPose(cam).inverse();
    double f = cam.heightPx() / 2.0 / Math.tan(cam.fovRad() / 2); // vertical field of view
    for (int k = 0; k < found.size(); k++) {
      VisionSystem.Detection d = found.get(k);
      Xyzwpr t = VisionSystemTest.truePose(sim, d.part());
      VisionSystem.Label l = labels.get(k);
      assertThat(l.text()).isEqualTo(String.format(Locale.ROOT, "%d: M%d X%.1f Y%.1f R%.1f", k + 1,
          d.result().modelId(), t.x(), t.y(), t.rDeg()));
      Vec3 p = X_KC.apply(sim.world().poseInCell(d.part()).translationVector());
      assertThat(l.u()).isCloseTo(cam.widthPx() / 2.0 + f * p.x() / p.z(), within(1e-6));
      assertThat(l.v()).isCloseTo(cam.heightPx() / 2.0 + f * p.y() / p.z(), within(1e-6));
      // the outline: the four corners of the part's top face, in the image
      LocalBox box = sim.world().find(d.part()).orElseThrow().shape().boundingBox();
      Transform X_KB = X_KC.compose(sim.world().poseInCell(d.part())).compose(box.X_LB());
      double[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (int c = 0; c < 4; c++) {
        Vec3 q = X_KB.apply(new Vec3(corners[c][0] * box.hxMm(), corners[c][1] * box.hyMm(), box.hzMm()));
        assertThat(l.outline()[2 * c]).isCloseTo(cam.widthPx() / 2.0 + f * q.x() / q.z(), within(1e-6));
        assertThat(l.outline()[2 * c + 1]).isCloseTo(cam.heightPx() / 2.0 + f * q.y() / q.z(), within(1e-6));
      }
    }
  }

  @Test
  void processNamesAreNotCaseSensitiveAndAnUnknownOneIsRefused() {
    Simulation sim = noiseFreeCell();
    VisionSystem vs = sim.vision().orElseThrow();
    String name = vs.setup().processes().get(0).name();
    assertThat(vs.lastFound(name)).isEmpty();
    List<VisionSystem.Detection> found = vs.runFind(sim.controllers().get(0), name.toUpperCase(Locale.ROOT));
    assertThat(found).isNotEmpty();
    assertThat(vs.lastFound(name.toLowerCase(Locale.ROOT))).isEqualTo(found);
    assertThat(vs.lastFoundBy(vs.setup().cameras().get(0).name())).isEqualTo(found);
    assertThat(vs.lastFoundBy("NOSUCHCAM")).isEmpty();
    assertThatThrownBy(() -> vs.runFind(sim.controllers().get(0), "nope"))
        .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("'nope'");
    // a program naming a process the cell does not have: CVIS-015
    Controller c = sim.controllers().get(0);
    c.saveProgram(TaskProgs.program("FINDX", false, "VISION RUN_FIND 'NOPE'"));
    c.run("FINDX", 1, true);
    for (int i = 0; i < 3; i++) {
      sim.step();
    }
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("CVIS-015");
    assertThat(c.activeAlarms().get(0).message()).contains("'NOPE'");
  }
}
