package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;

import org.robotrun.control.RobotControl;
import static org.robotrun.pendant.PendantKeys.run;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Issue 29: a choice list opens on the field's current value, as a controller's does. */
class PendantChoiceTest {
  private final RobotControl control = RealController.control();
  private final Pendant p = new Pendant(control);

  private String cursorRow() {
    return p.lcd().cursorRow().orElseThrow().strip();
  }

  @Test
  void speedUnitAndTerminationListsOpenOnTheCurrentValue() {
    run(p, """
        SELECT
        F1
        TYPE N
        ENTER
        SHIFT+F1
        UP
        RIGHT
        ENTER
        """);
    assertThat(cursorRow()).endsWith("J");
    run(p, "2\n");  // L
    assertThat(String.join("\\n", p.lcd().body())).contains("{L} P[1] 100mm/sec");
    run(p, "RIGHT *3\nENTER\n");
    assertThat(cursorRow()).endsWith("mm/sec");
    // the second item of L's units is msec; the list then opens on it
    run(p, "2\n");
    assertThat(String.join("\n", p.lcd().body())).contains("100{msec}");
    run(p, "ENTER\n");
    assertThat(cursorRow()).endsWith("msec").doesNotEndWith("mm/sec");
    run(p, "PREV\nRIGHT\nENTER\n");
    assertThat(cursorRow()).endsWith("FINE");
  }

  @Test
  void theIoTypeAndDataTypeListsOpenOnTheShownType() {
    run(p, "I/O\nF1\n");
    assertThat(cursorRow()).endsWith("DO");
    run(p, "6\nF1\n");
    assertThat(cursorRow()).endsWith("GO");
    run(p, "PREV\nDATA\nF1\n2\nF1\n");
    assertThat(cursorRow()).startsWith(">").contains(" 2 ");
  }

  @Test
  void currentChoiceMatchesFieldTextToItsItem() {
    assertThat(Pendant.currentChoice(List.of("FINE", "CNT"), "CNT50")).isEqualTo(1);
    assertThat(Pendant.currentChoice(List.of("DO[...]", "RO[...]", "GO[...]"), "RO[3]")).isEqualTo(1);
    assertThat(Pendant.currentChoice(List.of("%", "sec", "msec"), "msec")).isEqualTo(2);
    assertThat(Pendant.currentChoice(List.of("a", "b"), "zzz")).isZero();
  }
}
