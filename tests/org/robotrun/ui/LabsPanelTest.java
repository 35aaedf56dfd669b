package org.robotrun.ui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.grade.Course;

/** The Labs menu's pieces that need no window: the course file, a guide's steps, a lab's state. */
class LabsPanelTest {
  @Test
  void theShippedCourseReadsAndEveryGuideHasNumberedSteps() throws Exception {
    Course c = Course.read(Path.of("scenarios/labs"));
    assertThat(c.labs()).hasSize(12);
    for (Course.Lab lab : c.labs()) {
      List<String> steps = LabsPanel.steps(lab.guide());
      assertThat(steps).as(lab.id()).hasSizeGreaterThanOrEqualTo(4);
      assertThat(steps.get(0)).as(lab.id()).startsWith("1. ");
      for (int i = 0; i < steps.size(); i++) {
        assertThat(steps.get(i)).as(lab.id()).startsWith((i + 1) + ". ").doesNotContain("**", "`");
      }
    }
    // A step's continuation lines are joined to it.
    assertThat(LabsPanel.steps(c.lab("05-first-program").orElseThrow().guide()).get(1))
        .contains("POINT records").contains("CNT50");
  }

  @Test
  void aLabsStateFollowsItsFolderItsHandInAndItsLastCheck(@TempDir Path home) throws Exception {
    Course c = Course.read(Path.of("scenarios/labs"));
    Course.Lab lab5 = c.lab("05-first-program").orElseThrow();
    LabsPanel p = new LabsPanel(c, home, Optional.of(lab5), l -> { });
    assertThat(p.stateOf(lab5)).isEqualTo("not started");
    Files.createDirectories(home.resolve("05-first-program"));
    assertThat(p.stateOf(lab5)).isEqualTo("in progress");
    p.checked(new org.robotrun.grade.GradeResult("w", "", List.of(), List.of(), 0));
    assertThat(p.stateOf(lab5)).isEqualTo("in progress, last check 0 of 0");
    Files.writeString(home.resolve("05-first-program-handin.zip"), "zip");
    assertThat(p.stateOf(lab5)).startsWith("handed in ").endsWith(", last check 0 of 0");
    // The score is kept for the next window.
    assertThat(new LabsPanel(c, home, Optional.empty(), l -> { }).stateOf(lab5)).endsWith("last check 0 of 0");
  }

  @Test
  void aBadCourseFileIsRefusedWithLineAndPath(@TempDir Path dir) throws Exception {
    Path f = dir.resolve("course.json");
    Files.writeString(f, "{\"format\": 1, \"title\": \"x\",\n \"labs\": [{\"id\": \"a b\", \"title\": \"A\", \"guide\": \"g.md\","
        + " \"cell\": \"c.json\", \"task\": \"t.json\", \"color\": 1}]}");
    assertThatThrownBy(() -> Course.read(f)).isInstanceOf(Course.CourseException.class)
        .hasMessageContaining("course.json:2: labs[0].color: unknown field")
        .hasMessageContaining("labs[0].id: expected letters")
        .hasMessageContaining("labs[0].guide: file not found");
  }
}
