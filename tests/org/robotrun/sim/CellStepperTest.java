package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class CellStepperTest {
  private final Simulation sim = ControllerTest.cell();
  private final CellStepper stepper = new CellStepper(sim);

  @Test
  void simulatedTimeTracksWallTimeAcrossUnevenFrames() {
    int ticks = 0;
    // 600 frames alternating 15 ms and 18.333 ms: 10 s of wall time.
    for (int i = 0; i < 600; i++) {
      ticks += stepper.advanceRealTime(i % 2 == 0 ? 0.015 : 0.05 / 3 * 2 - 0.015);
    }
    assertThat(ticks).isBetween(2499, 2500);
    assertThat(sim.ticks()).isEqualTo(ticks);
  }

  @Test
  void aStalledFrameAdvancesAtMostTheCap() {
    assertThat(stepper.advanceRealTime(2.0)).isEqualTo((int) Math.round(CellStepper.MAX_FRAME_SEC / sim.tickSec()));
    assertThat(stepper.advanceRealTime(-1)).isZero();
  }

  @Test
  void aRemainderUnderOneTickCarriesOverAndEachTickIsReported() {
    int[] seen = {0};
    stepper.setAfterTick(s -> seen[0]++);
    assertThat(stepper.advance(0.003)).isZero();
    assertThat(stepper.advance(0.003)).isEqualTo(1);
    assertThat(stepper.advance(0.002)).isEqualTo(1);
    assertThat(seen[0]).isEqualTo(2);
    assertThat(sim.timeSec()).isCloseTo(0.008, org.assertj.core.data.Offset.offset(1e-12));
    assertThatThrownBy(() -> stepper.advance(Double.NaN)).isInstanceOf(IllegalArgumentException.class);
  }
}
