package org.robotrun.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class DamageRegionTest {
  @Test
  void anEmptyRegionHasNoRectangles() {
    DamageRegion d = new DamageRegion(100, 50);
    d.add(10, 10, 10, 20).add(5, 5, 4, 8);
    assertThat(d.isEmpty()).isTrue();
    assertThat(d.area()).isZero();
  }

  @Test
  void rectanglesAreClippedToTheFramebuffer() {
    DamageRegion d = new DamageRegion(100, 50).add(-20, -5, 30, 500);
    assertThat(d.rects()).containsExactly(new int[] {0, 0, 30, 50});
    assertThat(new DamageRegion(100, 50).add(200, 0, 300, 10).isEmpty()).isTrue();
  }

  @Test
  void farApartRectanglesStaySeparateAndTouchingOnesMerge() {
    DamageRegion d = new DamageRegion(1000, 1000).add(0, 0, 10, 10).add(900, 900, 910, 910);
    assertThat(d.rects()).hasSize(2);
    assertThat(d.area()).isEqualTo(200);
    d.add(10, 0, 20, 10);  // shares an edge with the first
    assertThat(d.rects()).hasSize(2).anySatisfy(r -> assertThat(r).containsExactly(0, 0, 20, 10));
  }

  @Test
  void overlappingRectanglesBecomeTheirUnionSoNoPixelIsDrawnTwice() {
    DamageRegion d = new DamageRegion(1000, 1000).add(0, 0, 300, 300).add(200, 200, 500, 500);
    assertThat(d.rects()).containsExactly(new int[] {0, 0, 500, 500});
  }

  @Test
  void aMergeThatReachesAThirdRectangleTakesItToo() {
    DamageRegion d = new DamageRegion(1000, 1000).add(0, 0, 100, 100).add(300, 0, 400, 100);
    assertThat(d.rects()).hasSize(2);
    d.add(50, 0, 350, 100);
    assertThat(d.rects()).containsExactly(new int[] {0, 0, 400, 100});
  }

  @Test
  void neverMoreThanTheMostRectanglesAndEveryAddedPixelStaysCovered() {
    DamageRegion d = new DamageRegion(2000, 2000);
    int[][] added = new int[12][];
    for (int i = 0; i < added.length; i++) {
      int x = (i * 379) % 1800, y = (i * 641) % 1800;
      added[i] = new int[] {x, y, x + 20, y + 20};
      d.add(x, y, x + 20, y + 20);
    }
    List<int[]> rects = d.rects();
    assertThat(rects.size()).isLessThanOrEqualTo(DamageRegion.MAX_RECTS);
    for (int[] a : added) {
      assertThat(rects).anySatisfy(r -> assertThat(r[0] <= a[0] && r[1] <= a[1] && r[2] >= a[2] && r[3] >= a[3]).isTrue());
    }
    for (int i = 0; i < rects.size(); i++) {
      for (int j = i + 1; j < rects.size(); j++) {
        assertThat(DamageRegion.intersect(rects.get(i), rects.get(j))).isNull();
      }
    }
  }

  @Test
  void addAllCoversTheFramebufferAndIntersectsSeesEveryPart() {
    DamageRegion d = new DamageRegion(64, 32).addAll();
    assertThat(d.area()).isEqualTo(64 * 32);
    assertThat(d.intersects(63, 31, 70, 40)).isTrue();
    assertThat(new DamageRegion(64, 32).add(0, 0, 10, 10).intersects(10, 0, 20, 10)).isFalse();
  }

  @Test
  void intersectGivesTheCommonPartOrNull() {
    assertThat(DamageRegion.intersect(new int[] {0, 0, 10, 10}, new int[] {5, 5, 20, 20})).containsExactly(5, 5, 10, 10);
    assertThat(DamageRegion.intersect(new int[] {0, 0, 10, 10}, new int[] {10, 0, 20, 10})).isNull();
  }
}
