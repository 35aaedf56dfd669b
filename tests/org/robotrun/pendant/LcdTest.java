package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class LcdTest {

  @Test
  void everyRowIsExactlyTheWidthAndLongRowsAreCut() {
    Lcd lcd = Lcd.of("S".repeat(100), "", "T", List.of("a", "b"), "p", List.of("F1", "F2"));
    assertThat(lcd.rows()).hasSize(Lcd.HEIGHT).allMatch(r -> r.length() == Lcd.WIDTH);
    assertThat(lcd.statusLine()).isEqualTo("S".repeat(Lcd.WIDTH));
    assertThat(lcd.functionKeys()).startsWith("    F1     |    F2     |");
  }

  @Test
  void negativeZeroLosesItsSignAndPaddedColumnsStayAligned() {
    assertThat(Lcd.fit("X    -0.000 mm  P -0.0 R -0.05 J -10.000").strip())
        .isEqualTo("X     0.000 mm  P 0.0 R -0.05 J -10.000");
  }

  @Test
  void wrapBreaksAtSpacesAndCutsLongWords() {
    assertThat(Lcd.wrap("re-teach the approach point 2", 12)).containsExactly("re-teach the", "approach", "point 2");
    assertThat(Lcd.wrap("ABCDEFGHIJ", 4)).containsExactly("ABCD", "EFGH", "IJ");
  }
}
