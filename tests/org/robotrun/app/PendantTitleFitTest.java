package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Lcd;
import org.robotrun.pendant.Pendant;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * The title row never loses its end at the LCD's edge (issue 29): EDIT's "LINE n/m", and a choice
 * list's name after it ("- CNT50" read "- CN" with lab 11's UNLOADER, whose comment is long). The
 * program's comment gives way. Read from the LCD text model on the real controller.
 */
class PendantTitleFitTest {
  private final Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
  private final ControllerPort control = new ControllerPort(sim.controllers().get(0));
  private final org.robotrun.sim.CellStepper stepper = new org.robotrun.sim.CellStepper(sim);
  private final Pendant p = new Pendant(control, new LsLineParser());

  private void keys(String script) {
    KeyScript s = switch (KeyScript.parse("test.keys", script.lines().toList())) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new AssertionError(bad.error().display());
    };
    s.run(p, stepper::advance, text -> { });
  }

  private void store(String comment) {
    String ls = """
        /PROG  UNLOADER
        /ATTR
        COMMENT\t\t= "%s";
        /MN
           1:  J P[1] 100%% CNT50 ;
           2:  L P[1] 500mm/sec FINE ;
        /POS
        P[1]{
           GP1:
        \tUF : 0, UT : 0,\t\tCONFIG : 'N U T, 0, 0, 0',
        \tX =   400.000  mm,\tY =     0.000  mm,\tZ =   300.000  mm,
        \tW =   180.000 deg,\tP =     0.000 deg,\tR =     0.000 deg
        };
        /END
        """.formatted(comment);
    LsReadResult r = LsReader.parse("UNLOADER.LS", ls);
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    control.saveProgram(r.program());
  }

  private String title() {
    return p.lcd().title().stripTrailing();
  }

  @Test
  void aChoiceListsNameStaysWholeAtTheEndOfTheTitleRow() {
    store("parts from the nest to the tray");
    keys("SELECT\nENTER");
    assertThat(title()).isEqualTo("EDIT UNLOADER  parts from the nest to the tray   LINE 1/2");
    // the termination field of line 1: its list opens with its name after the title
    keys("RIGHT *5");
    assertThat(String.join("\n", p.lcd().body())).contains("{CNT50}");
    keys("ENTER");
    assertThat(title()).endsWith(" - CNT50").hasSizeLessThanOrEqualTo(Lcd.WIDTH).startsWith("EDIT UNLOADER  parts");
    assertThat(title()).contains("..");
    keys("PREV");
    assertThat(title()).isEqualTo("EDIT UNLOADER  parts from the nest to the tray   LINE 1/2");
  }

  @Test
  void aCommentTooLongForTheRowGivesWayToTheLineNumber() {
    String longComment = "a comment far longer than the sixteen characters a controller allows";
    store(longComment);
    keys("SELECT\nENTER");
    assertThat(title()).startsWith("EDIT UNLOADER  a comment far").endsWith("..   LINE 1/2").hasSize(Lcd.WIDTH);
    keys("RIGHT *5\nENTER");
    assertThat(title()).startsWith("EDIT UNLOADER").endsWith(" - CNT50");
  }
}
