package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.pendant.PendantKeys.run;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.Program;

/**
 * Issue 26: a hand-in opened read-only in the window accepted edits (CREATE), and closing the
 * window discarded them without a word. A read-only pendant refuses every program change, saying
 * why on the prompt line, as a controller refuses to edit a write-protected program.
 */
class PendantReadOnlyTest {
  private static final String WHY = "READ-ONLY (a hand-in opens read-only): edits are refused";

  private static Pendant pendantWithOneProgram() {
    RobotControl control = RealController.control();
    Pendant p = new Pendant(control);
    run(p, """
        HOLD DEADMAN
        SELECT
        F1
        TYPE PICK1
        ENTER
        SHIFT+F1
        SHIFT+F1
        """);
    assertThat(control.program("PICK1")).get().extracting(Program::lineCount).isEqualTo(2);
    p.setReadOnly(WHY);
    return p;
  }

  @Test
  void selectRefusesCreateDeleteCopyCommentAndRenameAndNothingChanges() {
    Pendant p = pendantWithOneProgram();
    var before = p.control().programNames();
    for (String key : new String[] {"F1", "F2", "F3", "F4", "F5"}) {
      run(p, "SELECT\n" + key + "\n");
      assertThat(p.message()).as(key).isEqualTo(WHY);
      run(p, "ENTER\n");
      assertThat(p.control().programNames()).as(key).isEqualTo(before);
    }
  }

  @Test
  void lineEditsTouchupAndRecordingAreRefusedAndTheProgramStaysAsItWas() {
    Pendant p = pendantWithOneProgram();
    Program was = p.control().program("PICK1").orElseThrow();
    run(p, """
        SELECT
        ENTER
        SHIFT+F1
        """);
    assertThat(p.message()).isEqualTo(WHY);
    run(p, """
        UP
        SHIFT+F5
        """);
    assertThat(p.message()).isEqualTo(WHY);
    assertThat(p.control().program("PICK1")).contains(was);
  }
}
