package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/**
 * BG Logic's line when it offers no program (issue 29): it sends the student to "Not offered"
 * only when that list is there, and with no program at all says what a background program is
 * (in free play it pointed to a list that did not show).
 */
class BgLogicHintTest {
  @Test
  void theHintPointsToNotOfferedOnlyWhenThatListShows() {
    assertThat(PlcPanel.noOfferHint(false, 2)).isEqualTo("No program can run as BG Logic: \"Not offered\" says why");
    assertThat(PlcPanel.noOfferHint(true, 1)).isEqualTo("No other program can run as BG Logic: \"Not offered\" says why");
    assertThat(PlcPanel.noOfferHint(true, 0)).isEqualTo("No other program can run as BG Logic");
    assertThat(PlcPanel.noOfferHint(false, 0)).doesNotContain("Not offered").contains("No programs yet")
        .contains("DEFAULT_GROUP = *,*,*,*,*");
  }
}
