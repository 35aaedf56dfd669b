package org.robotrun.collision;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;

/** Ray against oriented box (slab method); tolerances 1e-9 mm. */
class ObbRayTest {
  @Test
  void aRayAlongXHitsTheNearFaceOfAnAxisAlignedBox() {
    Obb b = Obb.axisAligned(100, 0, 0, 10, 20, 30);
    assertThat(b.rayHit(0, 0, 0, 1, 0, 0)).isCloseTo(90, within(1e-9));
    assertThat(b.rayHit(0, 25, 0, 1, 0, 0)).isNaN();
    assertThat(b.rayHit(0, 0, 0, -1, 0, 0)).as("box behind the origin").isNaN();
    assertThat(b.rayHit(100, 0, 0, 0, 0, 1)).as("starting inside").isEqualTo(0);
  }

  @Test
  void aRotatedBoxIsHitByItsOwnAxesNotTheCellsOnes() {
    // a thin plate 100 x 2 x 100 mm turned 90 deg about z: it now spans 100 mm along y
    Obb b = Obb.of(Transform.rotation(0, 0, 1, Math.PI / 2), 50, 1, 50);
    assertThat(b.rayHit(-10, 40, 0, 1, 0, 0)).isCloseTo(9, within(1e-9));
    assertThat(b.rayHit(40, -10, 0, 0, 1, 0)).isNaN();
  }
}
