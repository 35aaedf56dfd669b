package org.robotrun.math;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class SinCosTest {
  @Test
  void agreesWithMathToAFewUlps() {
    // Method: 1e6 seeded angles in ±8π plus the quadrant boundaries; |error| ≤ 2 ulp of 1.
    SplittableRandom rnd = new SplittableRandom(99);
    double[] sc = new double[2];
    double worst = 0;
    for (int i = 0; i < 1_000_000; i++) {
      double x = (rnd.nextDouble() * 2 - 1) * 8 * Math.PI;
      SinCos.sinCos(x, sc, 0);
      worst = Math.max(worst, Math.max(Math.abs(sc[0] - Math.sin(x)), Math.abs(sc[1] - Math.cos(x))));
    }
    for (int k = -16; k <= 16; k++) {
      for (double d : new double[] {-1e-12, 0, 1e-12}) {
        double x = k * Math.PI / 4 + d;
        SinCos.sinCos(x, sc, 0);
        worst = Math.max(worst, Math.max(Math.abs(sc[0] - Math.sin(x)), Math.abs(sc[1] - Math.cos(x))));
      }
    }
    assertThat(worst).isLessThanOrEqualTo(2 * Math.ulp(1.0));
  }

  @Test
  void hugeAndSpecialArgumentsFallBackToMath() {
    double[] sc = new double[2];
    SinCos.sinCos(1e9, sc, 0);
    assertThat(sc).containsExactly(Math.sin(1e9), Math.cos(1e9));
    SinCos.sinCos(Double.NaN, sc, 0);
    assertThat(sc[0]).isNaN();
  }
}
