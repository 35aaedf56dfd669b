package org.robotrun.math;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The number formatters files, reports and messages share. */
class DecimalTextFormatTest {
  @Test
  void plainDropsDecimalsOfIntegralValuesOnly() {
    assertThat(DecimalText.plain(400)).isEqualTo("400");
    assertThat(DecimalText.plain(-3)).isEqualTo("-3");
    assertThat(DecimalText.plain(0.5)).isEqualTo("0.5");
    assertThat(DecimalText.plain(1e15)).isEqualTo("1.0E15");
  }

  @Test
  void tidyWritesFifteenSignificantDigitsWithoutExponentOrTrailingZeros() {
    assertThat(DecimalText.tidy(9.999999999999998)).isEqualTo("10");
    assertThat(DecimalText.tidy(Math.toDegrees(Math.toRadians(30)))).isEqualTo("30");
    assertThat(DecimalText.tidy(1e-13)).isEqualTo("0");
    assertThat(DecimalText.tidy(12.5)).isEqualTo("12.5");
    assertThat(DecimalText.tidy(1e20)).isEqualTo("100000000000000000000");
    assertThat(DecimalText.tidyReal(3)).isEqualTo("3.0");
    assertThat(DecimalText.tidyReal(0)).isEqualTo("0.0");
    assertThat(DecimalText.tidyReal(-2.25)).isEqualTo("-2.25");
  }
}
