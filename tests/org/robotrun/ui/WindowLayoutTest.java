package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

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
}
