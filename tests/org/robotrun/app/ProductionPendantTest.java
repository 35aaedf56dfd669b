package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The PLC cell from the pendant: the scenario's PLC starts job 1 once the mode is AUTO and the
 * TP is off; STATUS Program lists it, SETUP BG Logic lists the BG program and stops it; a key
 * script drives a UOP input.
 */
class ProductionPendantTest {

  @Test
  void statusProgramAndBgLogicScreensShowWhatRuns(@TempDir Path dir) throws Exception {
    Path keys = dir.resolve("plc.keys");
    Files.writeString(keys, """
        TP OFF
        MODE AUTO
        WAIT 1
        MENU
        DOWN *9
        ENTER
        SHOW
        MENU
        DOWN *8
        ENTER
        SHOW
        F3
        SHOW
        UI[2] OFF
        WAIT 0.1
        MENU
        DOWN *9
        ENTER
        SHOW
        """);
    PendantCommandTest.Run r = PendantCommandTest.run("pendant", "--scenario", "scenarios/plc-cell.json",
        "--keys", keys.toString());
    assertThat(r.exitCode()).as(r.err()).isZero();
    String[] shows = r.out().split("-- SHOW");
    assertThat(shows).hasSize(5);
    assertThat(shows[1]).contains("STATUS Program").containsPattern("PNS0001 +RUNNING +\\d+  \\(main\\)");
    assertThat(shows[2]).contains("SETUP BG Logic").containsPattern("BGLIGHT +Running");
    assertThat(shows[3]).containsPattern("BGLIGHT +Stop").contains("BGLIGHT stopped");
    // *HOLD off from the key script: the PLC's job is held
    assertThat(shows[4]).containsPattern("PNS0001 +PAUSED");
  }
}
