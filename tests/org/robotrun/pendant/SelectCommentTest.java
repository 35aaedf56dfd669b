package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.pendant.PendantKeys.run;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.robotrun.program.Program;

/**
 * Issue 29: SELECT cut a long program comment at the LCD's edge ("PLC job 1: to the press and
 * ba"). The comment now wraps under the comment column, whole, and the window keeps the cursor's
 * program whole in view.
 */
class SelectCommentTest {
  private final org.robotrun.control.RobotControl control = RealController.control();
  private final Pendant p = new Pendant(control);

  private void program(String name, String comment) {
    control.saveProgram(new Program(name, Map.of(), comment, List.of(), Map.of()));
  }

  /** The comment column's text of the LCD's body rows, joined by spaces (what a student reads). */
  private String commentText() {
    StringBuilder sb = new StringBuilder();
    for (String row : p.lcd().body()) {
      assertThat(row).hasSize(Lcd.WIDTH);
      if (row.length() > SelectScreen.COMMENT_COLUMN) {
        sb.append(row.substring(SelectScreen.COMMENT_COLUMN).strip()).append(' ');
      }
    }
    return sb.toString().replaceAll("\\s+", " ").strip();
  }

  @Test
  void aLongCommentShowsWholeOnRowsUnderTheCommentColumn() {
    String longComment = "PLC job 1: to the press and back, then wait for the next part at the nest";
    program("PNS0001", longComment);
    program("SHORT", "pick");
    run(p, "SELECT");

    assertThat(commentText()).isEqualTo(longComment + " pick");
    List<String> body = p.lcd().body();
    assertThat(body.get(0)).startsWith(">  1 PNS0001").contains("PLC job 1:");
    assertThat(body.get(1).substring(0, SelectScreen.COMMENT_COLUMN)).isBlank();
    assertThat(p.lcd().row(2)).contains("SELECT   2 programs");
    assertThat(body.get(0)).contains("   0 lines  PLC job 1:");
    // the next program starts its own row after the wrapped comment
    assertThat(body).filteredOn(r -> r.contains("SHORT")).singleElement().asString().startsWith("   2 SHORT");
  }

  @Test
  void theCursorsProgramStaysWholeInViewWhenTheListScrolls() {
    String comment = "a comment long enough to wrap onto a second and a third row of the LCD body";
    for (int i = 1; i <= 8; i++) {
      program("P" + i, comment + " " + i);
    }
    run(p, "SELECT\nDOWN *7");
    List<String> body = p.lcd().body();
    int cursorRow = -1;
    for (int i = 0; i < body.size(); i++) {
      if (body.get(i).startsWith(">")) {
        cursorRow = i;
      }
    }
    assertThat(body.get(cursorRow)).contains("P8");
    // every row after the cursor's is its comment's tail, ending with the program's own number
    String tail = String.join(" ", body.subList(cursorRow, body.size())).replaceAll("\\s+", " ").strip();
    assertThat(tail).endsWith(" 8");
    // the window starts on a program's first row, not on a comment's tail
    assertThat(body.get(0)).matches("^[ >] *\\d+ P\\d.*");
  }
}
