package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The vision lab for seeds 51..1050 (a few minutes; -Pfuzz, docs/fuzzing.md). */
class VisionPickFuzzCampaign {
  @Test
  void exampleProgramPlacesEveryBlockForAThousandMoreSeeds() {
    assertThat(VisionPickTest.failures(51, 1050)).isEmpty();
  }
}
