package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class RealTimeStepperTest {
  @Test
  void simulatedTimeTracksWallTimeAcrossUnevenFrames() {
    RealTimeStepper s = new RealTimeStepper(0.004, 50);
    int ticks = 0;
    // 600 frames alternating 15 ms and 18.333 ms: 10 s of wall time.
    for (int i = 0; i < 600; i++) {
      ticks += s.ticksFor(i % 2 == 0 ? 0.015 : 0.05 / 3 * 2 - 0.015);
    }
    assertThat(ticks).isBetween(2499, 2500);
  }

  @Test
  void aStallRunsAtMostTheCapAndDropsTheRest() {
    RealTimeStepper s = new RealTimeStepper(0.004, 50);
    assertThat(s.ticksFor(2.0)).isEqualTo(50);
    assertThat(s.ticksFor(0.004)).isEqualTo(1);
  }
}
