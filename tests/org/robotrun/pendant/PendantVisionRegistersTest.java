package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.pendant.PendantKeys.body;
import static org.robotrun.pendant.PendantKeys.run;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.Config;
import org.robotrun.program.Position;
import org.robotrun.program.VisionResult;

/** DATA → [TYPE] → Vision Reg: the list of VR[1..10] and the DETAIL page of one. */
class PendantVisionRegistersTest {
  private final RobotControl control = RealController.control();
  private final Pendant p = new Pendant(control);

  @Test
  void listShowsEmptyAndFilledRegistersAndDetailShowsTheFields() {
    Position.Cartesian found = new Position.Cartesian(130, 175, 0, 0, 0, 12, Config.DEFAULT);
    Position.Cartesian offset = new Position.Cartesian(10, 5, 0, 0, 0, 12, Config.DEFAULT);
    control.registers().vision().set(2, new VisionResult("FIND_BLOCKS", 3, found, offset, 1, 94.5));
    run(p, """
        DATA
        F1
        4
        """);
    assertThat(p.lcd().row(2)).contains("DATA Vision Reg");
    assertThat(body(p)).contains(">VR[ 1] (empty)")
        .contains(" VR[ 2] MODELID 3  X10.0 Y5.0 Z0.0 W0.0 P0.0 R12.0");
    assertThat(body(p)).contains(" VR[10] (empty)").doesNotContain("VR[11]");
    run(p, """
        DOWN
        F4
        """);
    assertThat(body(p)).contains("VR[2]").contains("MODELID:     3").contains("OFFSET:      X10.0 Y5.0")
        .contains("FOUND_POS[1] X130.0 Y175.0").contains("MES[1]:      94.5").contains("UF: 1")
        .contains("PROCESS:     FIND_BLOCKS");
    run(p, "F2");
    assertThat(body(p)).contains("VR[1]").contains("(empty");
    run(p, "F4");
    assertThat(body(p)).contains(">VR[ 1] (empty)");
  }
}
