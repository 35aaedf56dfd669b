package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.math.Vec3;

/**
 * Whether three points make a circle is a property of their shape, not of their size
 * (docs/alarms.md, SIMU-006: start, via and target "lie on one line or two are the same, so no
 * circle passes through them"; PathShape.Arc: nearly on one line means the sine of the angle at
 * the start below about 1e-6). The same triangle scaled from 1 mm to 10 m keeps its verdict: a
 * via point 1e-7 of the chord off the line is a line at every size, one 1e-3 off (a 0.1 mm bulge
 * over 100 mm) is a circle at every size.
 */
class CircularPathScaleSpecTest {

  /** Start, via and end of a chord of {@code size} mm along x, the via {@code sine}·size off it in y. */
  static PathShape.Arc through(double size, double sine) {
    Vec3 p0 = new Vec3(300, -50, 200);
    Vec3 via = p0.plus(new Vec3(0.5 * size, sine * size, 0));
    Vec3 end = p0.plus(new Vec3(size, 0, 0));
    return PathShape.Arc.through(p0, via, end);
  }

  @Test
  void aNearlyStraightTriangleIsALineAtEverySize() {
    for (double size : new double[] {1, 10, 100, 1000, 10_000}) {
      assertThat(through(size, 1e-7)).as("%s mm, sine 1e-7", size).isNull();
      assertThat(through(size, 2e-8)).as("%s mm, sine 2e-8", size).isNull();
    }
  }

  @Test
  void aSlightlyBentTriangleIsACircleAtEverySize() {
    for (double size : new double[] {1, 10, 100, 1000, 10_000}) {
      PathShape.Arc arc = through(size, 1e-3);
      assertThat(arc).as("%s mm, sine 1e-3", size).isNotNull();
      // The circle through a chord c with sagitta s: radius (c²/4 + s²) / 2s, a half-chord of 0.5·size.
      double s = 1e-3 * size;
      double half = 0.5 * size;
      assertThat(arc.radius()).isCloseTo((half * half + s * s) / (2 * s), org.assertj.core.data.Offset.offset(1e-6 * arc.radius()));
    }
  }
}
