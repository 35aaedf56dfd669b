package org.robotrun.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.sim.DrawItem;
import org.robotrun.sim.DrawShape;

class StillLayerTest {
  private static final DrawShape BOX = new DrawShape.Box(new Vec3(100, 100, 100), false);
  private static final DrawItem.Color GREY = DrawItem.Color.rgb(0.5, 0.5, 0.5);
  private static final StillLayer.View VIEW = new StillLayer.View(800, 600, 0, 0, 800, 600, 0, new Matrix4f());

  private final StillLayer layer = new StillLayer();

  private static List<DrawItem> scene(double armX) {
    List<DrawItem> items = new ArrayList<>();
    items.add(new DrawItem("table", BOX, Transform.IDENTITY, GREY));
    items.add(new DrawItem("robot1/link1", BOX, Transform.translation(armX, 0, 0), GREY));
    items.add(new DrawItem("part1", BOX, Transform.translation(500, 0, 0), GREY));
    return items;
  }

  @Test
  void theFirstFrameDrawsEveryOpaqueItemIntoTheLayer() {
    StillLayer.Plan p = layer.next(scene(0), VIEW);
    assertThat(p.rebuild()).isTrue();
    assertThat(p.inLayer()).containsExactly(true, true, true);
    StillLayer.Plan again = layer.next(scene(0), VIEW);
    assertThat(again.rebuild()).isFalse();
    assertThat(again.movedOutside()).isFalse();
  }

  @Test
  void aMovingItemLeavesTheLayerOnceThenOnlyItsRectangleIsDamaged() {
    layer.next(scene(0), VIEW);
    StillLayer.Plan first = layer.next(scene(10), VIEW);
    assertThat(first.rebuild()).isTrue();
    assertThat(first.inLayer()).containsExactly(true, false, true);
    for (int f = 2; f < 10; f++) {
      StillLayer.Plan p = layer.next(scene(10 * f), VIEW);
      assertThat(p.rebuild()).isFalse();
      assertThat(p.movedOutside()).isTrue();
      assertThat(p.inLayer()).containsExactly(true, false, true);
    }
  }

  @Test
  void anItemThatStopsReturnsToTheLayerAfterStandingStillLongEnough() {
    layer.next(scene(0), VIEW);
    layer.next(scene(10), VIEW);
    int frames = 0;
    StillLayer.Plan p;
    do {
      p = layer.next(scene(10), VIEW);
      frames++;
      if (!p.rebuild()) {
        assertThat(p.movedOutside()).isFalse();
      }
    } while (!p.rebuild() && frames < 100);
    assertThat(frames).isEqualTo(StillLayer.STILL_FRAMES_TO_SETTLE);
    assertThat(p.inLayer()).containsExactly(true, true, true);
  }

  @Test
  void anyChangeToTheViewDrawsTheLayerAgain() {
    layer.next(scene(0), VIEW);
    assertThat(layer.next(scene(0), new StillLayer.View(800, 600, 0, 0, 800, 600, 0, new Matrix4f().rotateZ(0.01f))).rebuild())
        .as("camera orbit").isTrue();
    assertThat(layer.next(scene(0), new StillLayer.View(801, 600, 0, 0, 800, 600, 0, new Matrix4f().rotateZ(0.01f))).rebuild())
        .as("window size").isTrue();
    assertThat(layer.next(scene(0), new StillLayer.View(801, 600, 10, 0, 790, 600, 0, new Matrix4f().rotateZ(0.01f))).rebuild())
        .as("panel resized, view moved").isTrue();
    assertThat(layer.next(scene(0), new StillLayer.View(801, 600, 10, 0, 790, 600, 5, new Matrix4f().rotateZ(0.01f))).rebuild())
        .as("floor").isTrue();
    assertThat(layer.next(scene(0), new StillLayer.View(801, 600, 10, 0, 790, 600, 5, new Matrix4f().rotateZ(0.01f))).rebuild())
        .as("nothing changed").isFalse();
  }

  @Test
  void aColourChangeOfAStillItemDrawsTheLayerAgain() {
    layer.next(scene(0), VIEW);
    List<DrawItem> highlighted = scene(0);
    highlighted.set(2, new DrawItem("part1", BOX, Transform.translation(500, 0, 0), DrawItem.Color.rgb(1, 0, 0)));
    StillLayer.Plan p = layer.next(highlighted, VIEW);
    assertThat(p.rebuild()).as("collision highlight").isTrue();
    assertThat(p.inLayer()).as("a changed item is drawn over the layer until it settles").containsExactly(true, true, false);
    assertThat(layer.next(scene(0), VIEW).rebuild()).as("the highlight goes").isFalse();
  }

  @Test
  void anItemAddedOrRemovedDrawsTheLayerAgainWithEverything() {
    layer.next(scene(0), VIEW);
    List<DrawItem> more = scene(0);
    more.add(new DrawItem("part2", BOX, Transform.translation(0, 500, 0), GREY));
    StillLayer.Plan p = layer.next(more, VIEW);
    assertThat(p.rebuild()).isTrue();
    assertThat(p.inLayer()).containsExactly(true, true, true, true);
    assertThat(layer.next(scene(0), VIEW).rebuild()).isTrue();
  }

  @Test
  void translucentItemsAreNeverInTheLayer() {
    List<DrawItem> withBoxes = scene(0);
    withBoxes.add(new DrawItem("collision box", BOX, Transform.IDENTITY, new DrawItem.Color(1, 0, 0, 0.3f)));
    assertThat(layer.next(withBoxes, VIEW).inLayer()).containsExactly(true, true, true, false);
    for (int f = 0; f < 2 * StillLayer.STILL_FRAMES_TO_SETTLE; f++) {
      StillLayer.Plan p = layer.next(withBoxes, VIEW);
      assertThat(p.rebuild()).isFalse();
      assertThat(p.movedOutside()).isFalse();
      assertThat(p.inLayer()[3]).isFalse();
    }
  }
}
