package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class DrawListCopyTest {
  /** A glyph-like quad at (x, y), 8 × 13, with a texture coordinate that stands for its letter. */
  private record Quad(float x, float y, float letter) {}

  /** Commands: each {clip x0, y0, x1, y1, texture, number of quads}. */
  private static DrawListCopy list(List<Quad> quads, float[][] commands) {
    DrawListCopy c = new DrawListCopy();
    c.reserve(quads.size() * 4, quads.size() * 6, 2, commands.length);
    for (int q = 0; q < quads.size(); q++) {
      Quad g = quads.get(q);
      float[][] corners = {{g.x(), g.y()}, {g.x() + 8, g.y()}, {g.x() + 8, g.y() + 13}, {g.x(), g.y() + 13}};
      for (int k = 0; k < 4; k++) {
        int at = (q * 4 + k) * DrawListCopy.VERT_BYTES;
        c.vtx.putFloat(at, corners[k][0]);
        c.vtx.putFloat(at + 4, corners[k][1]);
        c.vtx.putFloat(at + 8, g.letter());
        c.vtx.putFloat(at + 12, k);
        c.vtx.putInt(at + 16, 0xffffffff);
      }
      int[] idx = {0, 1, 2, 0, 2, 3};
      for (int k = 0; k < 6; k++) {
        c.idx.putShort((q * 6 + k) * 2, (short) (q * 4 + idx[k]));
      }
    }
    int offset = 0;
    for (int k = 0; k < commands.length; k++) {
      System.arraycopy(commands[k], 0, c.clip, 4 * k, 4);
      c.texture[k] = (int) commands[k][4];
      c.elemCount[k] = (int) commands[k][5] * 6;
      c.idxOffset[k] = offset;
      offset += c.elemCount[k];
    }
    return c;
  }

  /** The union of the changed areas; null when nothing changed. */
  private static float[] changed(DrawListCopy old, DrawListCopy now) {
    float[] u = null;
    for (float[] a : DrawListCopy.changedAreas(old, now)) {
      u = DrawListCopy.union(u, a);
    }
    return u;
  }

  private static float[][] oneCommand(int quads) {
    return new float[][] {{0, 0, 400, 300, 1, quads}};
  }

  /** A text line of digits at y: one quad per character. */
  private static List<Quad> line(List<Quad> into, float y, String text) {
    for (int i = 0; i < text.length(); i++) {
      into.add(new Quad(10 + 8 * i, y, text.charAt(i)));
    }
    return into;
  }

  private static List<Quad> panel(String j1) {
    return panel(j1, "385.000");
  }

  private static List<Quad> panel(String j1, String world) {
    List<Quad> q = new ArrayList<>();
    line(q, 10, "JOINT");
    line(q, 30, "J1 " + j1);
    line(q, 50, "J2 0.000");
    line(q, 200, "WORLD " + world);
    return q;
  }

  /** Whether two {x0, y0, x1, y1} rectangles share a pixel. */
  private static boolean meet(float[] a, float[] b) {
    return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
  }

  @Test
  void theSameListChangedNothing() {
    List<Quad> p = panel("5.490");
    assertThat(changed(list(p, oneCommand(p.size())), list(p, oneCommand(p.size())))).isNull();
  }

  @Test
  void aChangedNumberDamagesOnlyItsGlyphs() {
    List<Quad> a = panel("5.490"), b = panel("5.613");
    float[] area = changed(list(a, oneCommand(a.size())), list(b, oneCommand(b.size())));
    assertThat(area).isNotNull();
    // the glyphs "490"/"613": x from 10 + 8 * 5 to 10 + 8 * 8, on the J1 line (y 30..43), a pixel more each side
    assertThat(area).containsExactly(49, 29, 75, 44);
  }

  @Test
  void aNumberThatGrowsDamagesItsLineNotTheLinesBelowIt() {
    List<Quad> a = panel("5.490"), b = panel("15.490");
    float[] area = changed(list(a, oneCommand(a.size())), list(b, oneCommand(b.size())));
    assertThat(area).isNotNull();
    assertThat(area[1]).isEqualTo(29);
    assertThat(area[3]).isEqualTo(44);
    assertThat(area[0]).isLessThanOrEqualTo(10 + 8 * 3 - 1);
    assertThat(area[2]).isGreaterThanOrEqualTo(10 + 8 * 9);
  }

  @Test
  void aListWithOtherCommandsDamagesAllEitherDraws() {
    List<Quad> a = panel("5.490");
    DrawListCopy one = list(a, oneCommand(a.size()));
    float[][] two = {{0, 0, 400, 100, 1, 5}, {0, 100, 400, 300, 1, a.size() - 5}};
    DrawListCopy split = list(a, two);
    float[] area = changed(one, split);
    // everything the list draws: from the first glyph to the last, within the clip rectangles
    assertThat(area).containsExactly(9, 9, 10 + 8 * 13 + 1, 214);
  }

  @Test
  void anotherTextureIsAChangeOfTheWholeList() {
    List<Quad> a = panel("5.490");
    float[][] otherTexture = {{0, 0, 400, 300, 2, a.size()}};
    assertThat(changed(list(a, oneCommand(a.size())), list(a, otherTexture))).isNotNull()
        .containsExactly(9, 9, 10 + 8 * 13 + 1, 214);
  }

  @Test
  void aClipRectangleCutsWhatAListDraws() {
    List<Quad> a = panel("5.490");
    DrawListCopy c = list(a, new float[][] {{0, 0, 400, 100, 1, a.size()}});
    assertThat(c.drawnBounds()).containsExactly(9, 9, 10 + 8 * 13 + 1, 100);
  }

  @Test
  void aMovedWindowDamagesWhereItWasAndWhereItIs() {
    List<Quad> a = new ArrayList<>(), b = new ArrayList<>();
    line(a, 10, "TOOLTIP");
    for (Quad q : a) {
      b.add(new Quad(q.x() + 200, q.y() + 100, q.letter()));
    }
    float[] area = changed(list(a, oneCommand(a.size())), list(b, oneCommand(b.size())));
    assertThat(area).containsExactly(9, 9, 10 + 200 + 8 * 7 + 1, 10 + 100 + 13 + 1);
  }

  @Test
  void aChangedColourIsAChange() {
    List<Quad> a = panel("5.490");
    DrawListCopy before = list(a, oneCommand(a.size()));
    DrawListCopy after = list(a, oneCommand(a.size()));
    // the fourth quad (J of "JOINT" is quad 0; quad 3 is the "N"), its first vertex's colour
    after.vtx.putInt(3 * 4 * DrawListCopy.VERT_BYTES + 16, 0xff0000ff);
    assertThat(changed(before, after)).containsExactly(33, 9, 43, 24);
  }

  @Test
  void twoChangedNumbersAreTwoAreasNotOneOverTheLinesBetweenThem() {
    // J1 5.490 -> 5.613 and WORLD 385.000 -> 386.000: J2's line between them is the same
    List<Quad> a = panel("5.490", "385.000"), b = panel("5.613", "386.000");
    List<float[]> areas = DrawListCopy.changedAreas(list(a, oneCommand(a.size())), list(b, oneCommand(b.size())));
    assertThat(areas).hasSize(2);
    // "490"/"613" on the J1 line, and the "5"/"6" of WORLD's number (its 9th character), a pixel more each side
    assertThat(areas).anySatisfy(r -> assertThat(r).containsExactly(49, 29, 75, 44));
    assertThat(areas).anySatisfy(r -> assertThat(r).containsExactly(10 + 8 * 8 - 1, 199, 10 + 8 * 9 + 1, 214));
    float[] j2Line = {10, 50, 10 + 8 * 8, 63};
    assertThat(areas).noneMatch(r -> meet(r, j2Line));
  }

  @Test
  void glyphsThatStayBetweenTwoChangedGlyphsOfALineAreNotDamaged() {
    // 5.490 -> 6.491: the ".49" between the changed "5" and "0" is drawn the same
    List<Quad> a = panel("5.490"), b = panel("6.491");
    List<float[]> areas = DrawListCopy.changedAreas(list(a, oneCommand(a.size())), list(b, oneCommand(b.size())));
    float[] unchanged = {10 + 8 * 4 + 2, 30, 10 + 8 * 7 - 2, 43};
    assertThat(areas).hasSize(2).noneMatch(r -> meet(r, unchanged));
  }

  @Test
  void manyScatteredChangesAreBoundedTogether() {
    // every other glyph of 26 lines changes: more separate areas than a frame should draw one by one
    List<Quad> a = new ArrayList<>(), b = new ArrayList<>();
    for (int k = 0; k < 26; k++) {
      line(a, 10 + 20 * k, "A B");
      line(b, 10 + 20 * k, "C B");
    }
    List<float[]> areas = DrawListCopy.changedAreas(list(a, oneCommand(a.size())), list(b, oneCommand(b.size())));
    assertThat(areas).hasSize(1);
    assertThat(areas.get(0)).containsExactly(9, 9, 19, 10 + 20 * 25 + 14);
  }
}
