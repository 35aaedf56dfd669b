package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Properties;
import org.junit.jupiter.api.Test;

/** The window's layout as numbers: side by side, never overlapping, at any size. */
class WindowLayoutTest {
  private static final float PENDANT = 496;
  private static final float MENU = 19;

  private static WindowLayout at(float w, float h, LayoutState s) {
    return WindowLayout.compute(w, h, MENU, 1f, PENDANT, s);
  }

  @Test
  void columnsSitSideBySideAndFillTheWindowBelowTheMenuBar() {
    for (float[] size : new float[][] {{1024, 640}, {1366, 768}, {1920, 1080}, {3840, 2160}, {640, 480}}) {
      WindowLayout l = at(size[0], size[1], new LayoutState());
      assertThat(l.sidebar().overlaps(l.view())).isFalse();
      assertThat(l.view().overlaps(l.pendant())).isFalse();
      assertThat(l.sidebar().overlaps(l.pendant())).isFalse();
      assertThat(l.sidebar().w() + l.view().w() + l.pendant().w()).isEqualTo(size[0]);
      assertThat(l.view().y()).isEqualTo(MENU);
      assertThat(l.view().bottom()).isEqualTo(size[1]);
      assertThat(l.view().w()).isGreaterThanOrEqualTo(size[0] * WindowLayout.MIN_VIEW_FRACTION - 0.01f);
    }
  }

  @Test
  void thePendantKeepsItsNaturalWidthAndTheLeftColumnGoesFirstOnANarrowWindow() {
    WindowLayout narrow = at(1024, 640, new LayoutState());
    assertThat(narrow.pendant().w()).isEqualTo(PENDANT);
    assertThat(narrow.sidebar().visible()).isFalse();
    WindowLayout wide = at(1366, 768, new LayoutState());
    assertThat(wide.sidebar().visible()).isTrue();
    assertThat(wide.pendant().w()).isEqualTo(PENDANT);
  }

  @Test
  void aHiDpiScreenScalesTheColumnsAndTheStudentsWidthsAreKeptWithinBounds() {
    LayoutState s = new LayoutState();
    WindowLayout l = WindowLayout.compute(2732, 1536, 2 * MENU, 2f, 2 * PENDANT, s);
    assertThat(l.sidebar().w()).isEqualTo(2 * WindowLayout.SIDEBAR_WIDTH);
    s.pendantWidth = 5000;  // dragged far too wide
    WindowLayout dragged = at(1366, 768, s);
    assertThat(dragged.view().w()).isGreaterThanOrEqualTo(1366 * WindowLayout.MIN_VIEW_FRACTION - 0.01f);
  }

  /** ImGui's default font and style at scale 1 (13 px font), and at a HiDPI scale of 2. */
  private static final PendantPanel.Metrics SCALE1 = new PendantPanel.Metrics(17, 19, 23, 4, 8);
  private static final PendantPanel.Metrics SCALE2 = new PendantPanel.Metrics(34, 38, 46, 8, 16);

  /** Every key row fits the pendant's height: the last row (jog -/+6, the override keys, SHIFT) is inside. */
  private static void assertEveryKeyShows(WindowLayout l, PendantPanel.Metrics m, float natural) {
    float keyH = PendantPanel.keyHeight(l.pendant().h(), m);
    assertThat(keyH).isGreaterThanOrEqualTo(m.minKeyH());
    assertThat(PendantPanel.contentHeight(keyH, m)).isLessThanOrEqualTo(l.pendant().h());
    assertThat(l.pendant().w()).as("the LCD's 64 columns").isGreaterThanOrEqualTo(natural);
  }

  @Test
  void theJogAndFunctionKeysShowAt1024x640AndAtTheWindowsMinimumSize() {
    assertEveryKeyShows(at(1024, 640, new LayoutState()), SCALE1, PENDANT);
    int[] min = WindowLayout.minimumSize(MENU, PENDANT, PendantPanel.minimumHeight(SCALE1));
    assertEveryKeyShows(at(min[0], min[1], new LayoutState()), SCALE1, PENDANT);
    // the left column forced open on the smallest window still leaves the pendant whole
    LayoutState side = new LayoutState();
    side.sidebarVisible = true;
    assertEveryKeyShows(at(min[0], min[1], side), SCALE1, PENDANT);
    // the minimum is no larger than it must be: a pixel less and the last row would be cut
    float keyH = PendantPanel.keyHeight(min[1] - 1 - MENU, SCALE1);
    assertThat(PendantPanel.contentHeight(keyH, SCALE1)).isGreaterThan(min[1] - 1 - MENU);
    assertThat(min[0]).isLessThanOrEqualTo(1024);
    assertThat(min[1]).isLessThanOrEqualTo(640);

    // at scale 2 the minimum doubles with the style, and the keys still show there
    int[] min2 = WindowLayout.minimumSize(2 * MENU, 2 * PENDANT, PendantPanel.minimumHeight(SCALE2));
    WindowLayout hi = WindowLayout.compute(min2[0], min2[1], 2 * MENU, 2f, 2 * PENDANT, new LayoutState());
    assertEveryKeyShows(hi, SCALE2, 2 * PENDANT);
  }

  @Test
  void shrinkingThenGrowingGivesBackTheSameLayout() {
    LayoutState s = new LayoutState();
    WindowLayout before = at(1920, 1080, s);
    at(1024, 640, s);
    assertThat(at(1920, 1080, s)).isEqualTo(before);
  }

  @Test
  void theLayoutStateSurvivesItsPropertiesAndIgnoresNonsenseInThem() {
    LayoutState s = new LayoutState();
    s.sidebarVisible = false;
    s.pendantWidth = 520;
    s.welcomeSeen = true;
    s.editorOpen = true;
    LayoutState back = LayoutState.fromProperties(s.toProperties());
    assertThat(back.sidebarVisible).isFalse();
    assertThat(back.pendantWidth).isEqualTo(520);
    assertThat(back.welcomeSeen).isTrue();
    assertThat(back.editorOpen).isTrue();
    Properties bad = new Properties();
    bad.setProperty("pendantWidth", "NaN");
    bad.setProperty("sidebarWidth", "1e308");
    LayoutState d = LayoutState.fromProperties(bad);
    assertThat(d.pendantWidth).isZero();
    assertThat(d.sidebarWidth).isZero();
    s.reset();
    assertThat(s.sidebarVisible).isNull();
    assertThat(s.welcomeSeen).as("reset layout keeps the first-start card dismissed").isTrue();
  }

  @Test
  void labStepsOpenOverTheViewsTopRightCornerClearOfTheLeftColumnAndThePendant() {
    float em = 13;
    for (float[] size : new float[][] {{1024, 640}, {1366, 768}, {1920, 1080}}) {
      WindowLayout l = at(size[0], size[1], new LayoutState());
      WindowLayout.Rect steps = l.labSteps(em, size[1]);
      assertThat(steps.overlaps(l.sidebar())).as("left column at %s", size[0]).isFalse();
      assertThat(steps.overlaps(l.pendant())).as("pendant at %s", size[0]).isFalse();
      assertThat(steps.overlaps(l.menuBar())).isFalse();
      assertThat(steps.right()).isEqualTo(l.view().right());
      assertThat(steps.w()).isGreaterThanOrEqualTo(Math.min(em * 21, l.view().w() / 2));
      assertThat(steps.h()).isGreaterThan(em * 10);
    }
    // with the first-start card docked along the view's bottom (the layout's view is above it)
    WindowLayout l = at(1024, 640, new LayoutState());
    WindowLayout.Rect v = l.view();
    WindowLayout above = new WindowLayout(l.menuBar(), l.sidebar(), new WindowLayout.Rect(v.x(), v.y(), v.w(), v.h() - 300),
        l.pendant());
    assertThat(above.labSteps(em, 640).bottom()).isLessThanOrEqualTo(above.view().bottom());
  }

  @Test
  void labStepsTakeTheCornerThatCoversLeastOfTheRobotsAndParts() {
    float em = 13;
    WindowLayout l = at(1366, 768, new LayoutState());
    WindowLayout.Rect v = l.view();
    WindowLayout.Rect topRight = l.labSteps(em, 768);
    // nothing in the way: the top right corner
    assertThat(l.labSteps(em, 768, List.of())).isEqualTo(topRight);
    // lab 11 at 1366x768: robot2 stands in the view's upper right; the steps go to the top left
    WindowLayout.Rect robot2 = new WindowLayout.Rect(v.right() - 200, v.y() + 60, 150, 300);
    WindowLayout.Rect robot1 = new WindowLayout.Rect(v.x() + v.w() / 2 - 80, v.y() + 150, 160, 300);
    WindowLayout.Rect steps = l.labSteps(em, 768, List.of(robot1, robot2));
    assertThat(steps.overlapArea(robot2)).isZero();
    // the least covered of the four corners (an oracle over the corners, computed here)
    float cw = topRight.w(), h = topRight.h();
    double least = Double.POSITIVE_INFINITY;
    for (float[] xy : new float[][] {{v.x(), v.y()}, {v.right() - cw, v.y()}, {v.x(), v.bottom() - h}, {v.right() - cw, v.bottom() - h}}) {
      WindowLayout.Rect c = new WindowLayout.Rect(xy[0], xy[1], cw, h);
      least = Math.min(least, hidden(c, robot1) + hidden(c, robot2));
    }
    assertThat(hidden(steps, robot1) + hidden(steps, robot2)).isEqualTo(least);
    assertThat(topRight.overlapArea(robot2)).as("the old corner hid robot2").isPositive();
    // every corner hides some work: the one hiding least of it (here 25 % of one thing), still
    // clear of the column and the pendant
    float w = topRight.w();
    List<WindowLayout.Rect> everywhere = List.of(
        new WindowLayout.Rect(v.x() + w - 50, v.y() + 10, 100, 100),          // top left: half hidden
        new WindowLayout.Rect(v.right() - 150, v.y() + 10, 100, 100),         // top right: all
        new WindowLayout.Rect(v.x() + w - 25, v.bottom() - 110, 100, 100),    // bottom left: a quarter
        new WindowLayout.Rect(v.right() - w - 25, v.bottom() - 110, 100, 100)); // bottom right: three quarters
    WindowLayout.Rect fewest = l.labSteps(em, 768, everywhere);
    assertThat(fewest.x()).isEqualTo(v.x());
    assertThat(fewest.bottom()).isEqualTo(v.bottom());
    for (WindowLayout.Rect c : List.of(fewest, steps)) {
      assertThat(c.overlaps(l.sidebar())).isFalse();
      assertThat(c.overlaps(l.pendant())).isFalse();
      assertThat(c.overlaps(l.menuBar())).isFalse();
    }
  }

  /** The part of {@code thing} that {@code window} hides (0..1). */
  private static double hidden(WindowLayout.Rect window, WindowLayout.Rect thing) {
    return window.overlapArea(thing) / (thing.w() * thing.h());
  }

  @Test
  void aWholeSmallPartHiddenWeighsAsMuchAsAWholeArm() {
    float em = 13;
    WindowLayout l = at(1024, 640, new LayoutState());
    WindowLayout.Rect v = l.view();
    WindowLayout.Rect topRight = l.labSteps(em, 640);
    // a small part wholly under the top right corner, an arm's tip a little under the top left one
    WindowLayout.Rect part = new WindowLayout.Rect(topRight.x() + 20, topRight.y() + 20, 20, 20);
    WindowLayout.Rect arm = new WindowLayout.Rect(v.x() + 150, v.y() + 200, 300, 300);
    WindowLayout.Rect steps = l.labSteps(em, 640, List.of(part, arm));
    assertThat(steps.overlapArea(part)).as("the part stays in sight, though its area is small").isZero();
  }

  @Test
  void atTheWindowsMinimumSizeTheStepsStayWideEnoughToRead() {
    float em = 13;
    int[] min = WindowLayout.minimumSize(MENU, PENDANT, PendantPanel.minimumHeight(SCALE1));
    WindowLayout l = at(min[0], min[1], new LayoutState());
    WindowLayout.Rect steps = l.labSteps(em, min[1]);
    assertThat(steps.w()).isGreaterThanOrEqualTo(Math.min(em * 15, l.view().w()));
    assertThat(steps.x()).isGreaterThanOrEqualTo(l.view().x());
    assertThat(steps.overlaps(l.pendant())).isFalse();
  }

  @Test
  void aResizeKeepsTheStepsWhereTheStudentPutThemOnlyInsideTheWindowAndOffThePendant() {
    WindowLayout big = at(1920, 1080, new LayoutState());
    // the student dragged the steps over the left column, low down
    WindowLayout.Rect placed = new WindowLayout.Rect(10, 500, 270, 300);
    assertThat(big.keepInside(placed, 1080)).isEqualTo(placed);
    // a smaller window: it stays where it was as far as the window lets it
    WindowLayout small = at(1024, 640, new LayoutState());
    WindowLayout.Rect kept = small.keepInside(placed, 640);
    assertThat(kept.x()).isEqualTo(10);
    assertThat(kept.bottom()).isEqualTo(640);
    assertThat(kept.w()).isEqualTo(270);
    // put over where the pendant now is: moved left of it, whole
    WindowLayout.Rect overPendant = new WindowLayout.Rect(small.pendant().x() + 20, 100, 270, 300);
    WindowLayout.Rect moved = small.keepInside(overPendant, 640);
    assertThat(moved.overlaps(small.pendant())).isFalse();
    assertThat(moved.right()).isEqualTo(small.pendant().x());
    assertThat(moved.y()).isEqualTo(100);
    // above the menu bar, or taller than the window: inside, under the menu bar
    WindowLayout.Rect tall = small.keepInside(new WindowLayout.Rect(0, -50, 200, 2000), 640);
    assertThat(tall.y()).isEqualTo(small.menuBar().bottom());
    assertThat(tall.bottom()).isLessThanOrEqualTo(640);
  }

  @Test
  void theFirstStartCardKeepsItsColumnsWideEnoughToRead() {
    float em = 13;
    assertThat(WindowLayout.welcomeColumns(528, em, true)).isEqualTo(3);  // 1024x640: not four narrow strips
    assertThat(WindowLayout.welcomeColumns(800, em, true)).isEqualTo(4);
    assertThat(WindowLayout.welcomeColumns(800, em, false)).isEqualTo(3);
    assertThat(WindowLayout.welcomeColumns(400, em, true)).isEqualTo(1);
    for (float w = 100; w < 2000; w += 7) {
      for (boolean task : new boolean[] {true, false}) {
        int n = WindowLayout.welcomeColumns(w, em, task);
        assertThat(n == 1 || w / n >= em * 12).as("%s px in %s columns", w, n).isTrue();
      }
    }
  }
}
