package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code robotrun pendant} in a cell of two robots: a pendant per robot, ROBOT switches, both run at once. */
class CellPendantTest {
  private static final String CELL = "scenarios/two-robot-handshake.json";

  @Test
  void eachRobotsSelectScreenListsItsOwnProgramsAndTheStatusLineNamesIt(@TempDir Path dir) throws Exception {
    Path keys = Files.writeString(dir.resolve("select.keys"), """
        SELECT
        SHOW
        ROBOT 2
        SELECT
        SHOW
        ROBOT robot1
        SHOW
        """);
    PendantCommandTest.Run r = PendantCommandTest.run("pendant", "--scenario", CELL, "--keys", keys.toString());
    assertThat(r.exitCode()).as(r.err()).isZero();
    String[] shows = r.out().split("-- SHOW ");
    assertThat(shows).hasSize(4);
    assertThat(shows[1]).contains("robot1) --").contains("|robot1 ").contains("LOADER").doesNotContain("UNLOADER");
    assertThat(shows[2]).contains("robot2) --").contains("|robot2 ").contains("UNLOADER");
    // Back on robot1: its pendant kept its own screen.
    assertThat(shows[3]).contains("|robot1 ").contains("SELECT").contains("LOADER").doesNotContain("UNLOADER");
  }

  @Test
  void bothRobotsStartedFromTheirOwnOperatorPanelsRunAtOnce(@TempDir Path dir) throws Exception {
    Path keys = Files.writeString(dir.resolve("start.keys"), """
        SELECT
        ENTER
        TP OFF
        MODE AUTO
        ROBOT 2
        SELECT
        ENTER
        TP OFF
        MODE AUTO
        CYCLE START
        ROBOT 1
        CYCLE START
        WAIT 3
        SHOW
        ROBOT 2
        SHOW
        WAIT 15
        SHOW
        """);
    PendantCommandTest.Run r = PendantCommandTest.run("pendant", "--scenario", CELL, "--override", "100",
        "--keys", keys.toString());
    assertThat(r.exitCode()).as(r.err()).isZero();
    String[] shows = r.out().split("-- SHOW ");
    assertThat(shows[1]).contains("|robot1 LOADER").contains("AUTO RUNNING");
    assertThat(shows[2]).contains("|robot2 UNLOADER").contains("AUTO RUNNING");
    // robot2 ends after the last part: its program ran to its last line with no alarm.
    assertThat(shows[3]).contains("|robot2 UNLOADER     LINE 30").contains("ABORTED");
  }

  @Test
  void aRobotTheCellDoesNotHaveStopsTheScriptBeforeAnyKey(@TempDir Path dir) throws Exception {
    Path keys = Files.writeString(dir.resolve("bad.keys"), "SELECT\nROBOT 3\nSHOW\n");
    PendantCommandTest.Run r = PendantCommandTest.run("pendant", "--scenario", CELL, "--keys", keys.toString());
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.err()).contains("bad.keys:2: no robot 3 in this cell (robots: 1..2: robot1, robot2)");
    assertThat(r.out()).isEmpty();
    Path noName = Files.writeString(dir.resolve("empty.keys"), "ROBOT\n");
    assertThat(PendantCommandTest.run("pendant", "--keys", noName.toString()).err()).contains("empty.keys:1: ROBOT needs");
  }
}
