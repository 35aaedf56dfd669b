package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.ui.LabelLayout.Box;
import org.robotrun.ui.LabelLayout.Label;
import org.robotrun.ui.LabelLayout.Placed;

/** The camera view's label layout: no overlap, nothing off the image, each label near its part. */
class LabelLayoutTest {
  /** A found pose's label as the camera view writes it: about 190 x 17 pixels. */
  private static final double W = 190, H = 17;

  @Test
  void aLoneLabelSitsRightOfItsPointWithNoLeader() {
    List<Optional<Placed>> p = LabelLayout.place(List.of(new Label(100, 100, W, H)), 640, 480, List.of());
    Box b = p.get(0).orElseThrow().box();
    assertThat(b.x()).isGreaterThan(100);
    assertThat(b.y()).isLessThan(100).isGreaterThan(100 - H);
    assertThat(p.get(0).get().leader()).isFalse();
  }

  @Test
  void aLabelAtTheRightEdgeGoesLeftOfItsPointInsideTheImage() {
    // the old layout wrote it at u + 14 and ran off the image
    Box b = LabelLayout.place(List.of(new Label(600, 200, W, H)), 640, 480, List.of()).get(0).orElseThrow().box();
    assertThat(b.inside(640, 480)).isTrue();
    assertThat(b.right()).isLessThan(600);
  }

  @Test
  void aLabelAtTheTopLeftCornerStaysInside() {
    Box b = LabelLayout.place(List.of(new Label(2, 2, W, H)), 640, 480, List.of()).get(0).orElseThrow().box();
    assertThat(b.inside(640, 480)).isTrue();
  }

  @Test
  void partsSideBySideGetLabelsThatDoNotOverlapAndMovedOnesGetALeader() {
    // six parts in a row 40 px apart: the labels (190 px wide) cannot all go to the right
    List<Label> labels = new ArrayList<>();
    for (int i = 0; i < 6; i++) {
      labels.add(new Label(200 + 40 * i, 240, W, H));
    }
    List<Optional<Placed>> p = LabelLayout.place(labels, 640, 480, List.of());
    assertInvariants(labels, p, 640, 480, List.of());
    assertThat(p).allMatch(Optional::isPresent);
    assertThat(p).anyMatch(x -> x.get().leader());
    for (int i = 0; i < p.size(); i++) {
      Placed x = p.get(i).get();
      if (!x.leader()) {
        // beside its point or at a corner of it: within the gap and the point's free square
        assertThat(x.box().distanceTo(labels.get(i).pointX(), labels.get(i).pointY()))
            .isLessThanOrEqualTo(Math.sqrt(2) * (LabelLayout.GAP + LabelLayout.POINT_HALF) + 1e-9);
      }
    }
  }

  @Test
  void labelsGoBesideTheirPartAndOffEveryPartWhenThereIsRoom() {
    // four 40 px parts of a tray, two by two, as RUN_FIND outlines them
    List<Label> labels = new ArrayList<>();
    for (int i = 0; i < 4; i++) {
      double cx = 250 + 60 * (i % 2), cy = 150 + 100 * (i / 2);
      labels.add(new Label(cx, cy, W, H, new Box(cx - 20, cy - 20, 40, 40)));
    }
    List<Optional<Placed>> p = LabelLayout.place(labels, 640, 480, List.of());
    assertInvariants(labels, p, 640, 480, List.of());
    for (int i = 0; i < 4; i++) {
      Box b = p.get(i).orElseThrow().box();
      for (Label other : labels) {
        assertThat(b.overlaps(other.part())).as("label %d off every part", i).isFalse();
      }
      if (!p.get(i).get().leader()) {
        // touching its part's side, within the gap
        assertThat(b.distanceTo(labels.get(i).pointX(), labels.get(i).pointY()))
            .isLessThanOrEqualTo(Math.hypot(20, 20) + LabelLayout.GAP + 1e-9);
      }
    }
    // parts that fill the image: the labels still find room, over parts if they must, never over each other
    List<Label> packed = List.of(new Label(100, 60, 150, H, new Box(0, 0, 200, 120)),
        new Label(100, 180, 150, H, new Box(0, 120, 200, 120)));
    List<Optional<Placed>> q = LabelLayout.place(packed, 200, 240, List.of());
    assertInvariants(packed, q, 200, 240, List.of());
    assertThat(q).allMatch(Optional::isPresent);
  }

  @Test
  void labelsKeepOffObstaclesAndEveryPoint() {
    List<Label> labels = List.of(new Label(300, 200, W, H), new Label(320, 205, W, H), new Label(100, 400, W, H));
    List<Box> obstacles = List.of(new Box(305, 150, 250, 100));
    List<Optional<Placed>> p = LabelLayout.place(labels, 640, 480, obstacles);
    assertInvariants(labels, p, 640, 480, obstacles);
    assertThat(p).allMatch(Optional::isPresent);
  }

  @Test
  void aLabelThatFitsNowhereIsLeftOutRatherThanOverlapping() {
    // room for two labels at most in a 200 x 40 image
    List<Label> labels = List.of(new Label(10, 10, W, H), new Label(20, 20, W, H), new Label(30, 30, W, H));
    List<Optional<Placed>> p = LabelLayout.place(labels, 200, 40, List.of());
    assertInvariants(labels, p, 200, 40, List.of());
    assertThat(p.stream().filter(Optional::isEmpty).count()).isGreaterThanOrEqualTo(1);
    assertThat(LabelLayout.place(List.of(new Label(10, 10, 300, H)), 200, 40, List.of()).get(0)).isEmpty();
  }

  @Test
  void randomCrowdsNeverOverlapNorLeaveTheImageAndStayNearTheirPart() {
    Random rnd = new Random(29);
    for (int round = 0; round < 200; round++) {
      double width = 320 + rnd.nextInt(400), height = 240 + rnd.nextInt(300);
      int n = 1 + rnd.nextInt(10);
      List<Label> labels = new ArrayList<>();
      // clustered parts, as a tray of found parts is
      double cx = rnd.nextDouble() * width, cy = rnd.nextDouble() * height;
      for (int i = 0; i < n; i++) {
        double x = Math.max(0, Math.min(width, cx + rnd.nextGaussian() * 40));
        double y = Math.max(0, Math.min(height, cy + rnd.nextGaussian() * 40));
        labels.add(new Label(x, y, 120 + rnd.nextInt(100), H));
      }
      List<Optional<Placed>> p = LabelLayout.place(labels, width, height, List.of());
      assertInvariants(labels, p, width, height, List.of());
      // in an image this size ten labels always find room
      assertThat(p).as("round %d", round).allMatch(Optional::isPresent);
      for (int i = 0; i < n; i++) {
        // near: no farther than needed to clear the crowd (the labels' stacked height plus a label)
        double far = n * (H + LabelLayout.GAP) + 220 + 2 * H;
        assertThat(p.get(i).get().box().distanceTo(labels.get(i).pointX(), labels.get(i).pointY()))
            .as("round %d label %d", round, i).isLessThan(far);
      }
    }
  }

  private static void assertInvariants(List<Label> labels, List<Optional<Placed>> p, double width, double height,
      List<Box> obstacles) {
    assertThat(p).hasSize(labels.size());
    for (int i = 0; i < p.size(); i++) {
      if (p.get(i).isEmpty()) {
        continue;
      }
      Box a = p.get(i).get().box();
      assertThat(a.inside(width, height)).as("label %d inside", i).isTrue();
      assertThat(a.w()).isEqualTo(labels.get(i).w());
      for (int j = i + 1; j < p.size(); j++) {
        if (p.get(j).isPresent()) {
          assertThat(a.overlaps(p.get(j).get().box())).as("labels %d and %d", i, j).isFalse();
        }
      }
      for (Label other : labels) {
        assertThat(a.distanceTo(other.pointX(), other.pointY())).as("label %d off every point", i).isGreaterThan(0);
      }
      for (Box o : obstacles) {
        assertThat(a.overlaps(o)).as("label %d off the obstacle", i).isFalse();
      }
    }
  }
}
