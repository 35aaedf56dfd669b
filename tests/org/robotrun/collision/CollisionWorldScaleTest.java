package org.robotrun.collision;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Issue 18: broad-phase memory grows with the bodies, not their square; no int overflow. */
class CollisionWorldScaleTest {
  @Test
  void fiftyThousandBodiesNeedLinearMemoryAndFindTheirContacts() {
    // Method: 50 000 boxes of 10 mm on a 12 mm grid in x (so neighbours do not touch) except
    // every 100th, which overlaps its neighbour; the n×n table would have needed 4 GiB and
    // overflowed int indices beyond 46 341 bodies.
    int n = 50_000;
    CollisionWorld w = new CollisionWorld((a, b) -> true);
    for (int i = 0; i < n; i++) {
      double x = 12.0 * (i % 1000) + (i % 100 == 1 ? -6 : 0);
      double y = 100.0 * (i / 1000);
      w.add(Body.fixture("b" + i, "b" + i), Obb.axisAligned(x, y, 0, 5, 5, 5));
    }
    int contacts = w.update();
    assertThat(contacts).isEqualTo(n / 100);
    assertThat(w.update()).isEqualTo(n / 100);
    // a hash table of the candidate pairs met, capped per body: far below n² bytes
    assertThat(w.cacheBytes()).isLessThan(64L * n * (Long.BYTES + 1));
  }
}
