package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class FanucFormatTest {

  @Test
  void positionValuesHaveThreeDecimalsInTenColumns() {
    assertThat(FanucFormat.positionValue(350)).isEqualTo("   350.000");
    assertThat(FanucFormat.positionValue(-90)).isEqualTo("   -90.000");
    assertThat(FanucFormat.positionValue(-0.0)).isEqualTo("     0.000");
    assertThat(FanucFormat.positionValue(1234.5)).isEqualTo("  1234.500");
  }

  @Test
  void positionValuesAreRoundedToThreeDecimalsAsAControllerWritesThem() {
    // Issue 14: a controller writes "Y = 0.000 mm", never -0.000000000000012246.
    assertThat(FanucFormat.positionValue(1234.5678)).isEqualTo("  1234.568");
    assertThat(FanucFormat.positionValue(424.654999)).isEqualTo("   424.655");
    assertThat(FanucFormat.positionValue(-1.2246467991473532e-14)).isEqualTo("     0.000");
    assertThat(FanucFormat.positionValue(-0.0004)).isEqualTo("     0.000");
  }

  @Test
  void otherValuesWithMoreDigitsThanTheFormatKeepThemAll() {
    assertThat(FanucFormat.waitSeconds(1.234)).isEqualTo(" 1.234");
    assertThat(FanucFormat.real(-0.0)).isEqualTo("-0.0");
  }

  @Test
  void waitTimesDropTheLeadingZero() {
    assertThat("WAIT " + FanucFormat.waitSeconds(0.2)).isEqualTo("WAIT    .20");
    assertThat("WAIT " + FanucFormat.waitSeconds(1.5)).isEqualTo("WAIT   1.50");
    assertThat("WAIT " + FanucFormat.waitSeconds(10)).isEqualTo("WAIT  10.00");
  }

  @Test
  void constantsReadBackExactly() {
    assertThat(FanucFormat.real(2.5)).isEqualTo("2.5");
    assertThat(FanucFormat.real(2)).isEqualTo("2.0");
    assertThat(FanucFormat.real(0.1)).isEqualTo("0.1");
    assertThat(Double.parseDouble(FanucFormat.real(1.0 / 3))).isEqualTo(1.0 / 3);
    assertThat(FanucFormat.plain(400)).isEqualTo("400");
    assertThat(FanucFormat.plain(0.5)).isEqualTo("0.5");
  }

  @Test
  void attrKeysAreTabbedToColumnSixteen() {
    assertThat(FanucFormat.attrKey("OWNER")).isEqualTo("OWNER\t\t");
    assertThat(FanucFormat.attrKey("PROG_SIZE")).isEqualTo("PROG_SIZE\t");
    assertThat(FanucFormat.attrKey("DEFAULT_GROUP")).isEqualTo("DEFAULT_GROUP\t");
    assertThat(FanucFormat.padWithTabs("      TASK_PRIORITY", 0)).isEqualTo("      TASK_PRIORITY\t");
  }
}
