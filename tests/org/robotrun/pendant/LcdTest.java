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

  /** The three texts a first-time student saw cut at the LCD's edge (issue 29). */
  private static final String CYCLE_START = "CYCLE START refused: the TP is enabled (turn it OFF to run in AUTO)";
  private static final String COLLISION =
      "SRVO-050 (PICK, 7) Collision Detect alarm: collision: robot2/link4 touches robot1/tool";
  private static final String UNREACHABLE =
      "MOTN-018 (MAIN, 3) Position not reachable: P[4]: position (2000.0, 0.0, 300.0) is beyond the arm's reach";

  @Test
  void aLongPromptWrapsAboveThePromptLineAndLosesNothing() {
    List<String> body = new java.util.ArrayList<>();
    for (int i = 1; i <= Lcd.BODY_ROWS; i++) {
      body.add((i == Lcd.BODY_ROWS ? ">" : " ") + " line " + i);
    }
    Lcd lcd = Lcd.of("S", "", "EDIT", body, CYCLE_START, List.of());
    assertThat(lcd.rows()).hasSize(Lcd.HEIGHT).allMatch(r -> r.length() == Lcd.WIDTH);
    assertThat(lcd.promptRows()).isEqualTo(2);
    assertThat(lcd.promptLine()).isEqualTo(CYCLE_START);
    assertThat(lcd.row(Lcd.HEIGHT - 2).strip()).isEqualTo("AUTO)");
    // the body gives up a row, and keeps its cursor line in view
    assertThat(lcd.body()).hasSize(Lcd.BODY_ROWS - 1);
    assertThat(lcd.cursorRow()).hasValueSatisfying(r -> assertThat(r).startsWith("> line " + Lcd.BODY_ROWS));
  }

  @Test
  void aLongAlarmWrapsUnderTheAlarmLineAndTheTitleFollows() {
    for (String alarm : List.of(COLLISION, UNREACHABLE)) {
      Lcd lcd = Lcd.of("S", alarm, "EDIT MAIN", List.of("> {1:} J P[1] 100% FINE"), "", List.of());
      assertThat(lcd.alarmRows()).as(alarm).isEqualTo(2);
      assertThat(lcd.alarmLine()).isEqualTo(alarm);
      assertThat(lcd.isAlarmRow(1)).isTrue();
      assertThat(lcd.isAlarmRow(2)).isTrue();
      assertThat(lcd.isAlarmRow(3)).isFalse();
      assertThat(lcd.title()).startsWith("EDIT MAIN");
      assertThat(lcd.row(3)).startsWith("EDIT MAIN");
      assertThat(lcd.cursorField()).hasValueSatisfying(f -> assertThat(f.row()).isEqualTo(4));
      assertThat(lcd.rows()).hasSize(Lcd.HEIGHT).allMatch(r -> r.length() == Lcd.WIDTH);
    }
    assertThat(Lcd.of("S", COLLISION, "T", List.of(), "", List.of()).toString()).contains("touches robot1/tool");
    assertThat(Lcd.of("S", UNREACHABLE, "T", List.of(), "", List.of()).toString()).contains("beyond the arm's reach");
  }

  @Test
  void aShortAlarmAndPromptTakeOneRowEach() {
    Lcd lcd = Lcd.of("S", "SRVO-003 Deadman switch released", "T", List.of("a"), "p", List.of());
    assertThat(lcd.alarmRows()).isEqualTo(1);
    assertThat(lcd.promptRows()).isEqualTo(1);
    assertThat(lcd.body()).hasSize(Lcd.BODY_ROWS);
    assertThat(lcd.row(2)).startsWith("T");
  }
}
