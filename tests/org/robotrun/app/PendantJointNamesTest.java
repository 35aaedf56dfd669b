package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.TestArms;
import org.robotrun.io.UrdfImporter;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * The pendant labels joints as the robot file names them, through the control port: J1..J6 on
 * a library arm (the controller's own screen), an imported URDF's joint names on that arm; and
 * J3 is shown coupled to J2 only where the model says so.
 */
class PendantJointNamesTest {
  @TempDir
  Path tmp;

  private static String posn(RobotModel model) {
    Simulation sim = DefaultCell.simulation(model);
    ControllerPort control = new ControllerPort(sim.controllers().get(0));
    Pendant p = new Pendant(control, new LsLineParser());
    KeyScript s = switch (KeyScript.parse("t.keys", java.util.List.of("POSN"))) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new AssertionError(bad.error().display());
    };
    s.run(p, dt -> { }, text -> { });
    return String.join("\n", p.lcd().body());
  }

  @Test
  void aLibraryArmShowsJ1ToJ6AsTheController() {
    String body = posn(RobotDefinitions.defaultRobot());
    assertThat(body).containsPattern("(?m)^  J1 +-?\\d+\\.\\d{3}  J2 +-?\\d+\\.\\d{3}  J3 +-?\\d+\\.\\d{3} *$")
        .containsPattern("(?m)^  J4 +-?\\d+\\.\\d{3}  J5 +-?\\d+\\.\\d{3}  J6 +-?\\d+\\.\\d{3} *$");
  }

  @Test
  void anImportedArmShowsItsOwnJointNamesAndItsOwnJ3() throws Exception {
    RobotModel ur = UrdfImporter.importRobot(TestArms.offsetPackage(tmp), Map.of()).model();
    String body = posn(ur);
    assertThat(body).contains("shoulder_pan_joint").contains("shoulder_lift_joint").contains("elbow_joint")
        .contains("wrist_1_joint").contains("wrist_2_joint").contains("wrist_3_joint").doesNotContain("  J1 ");
    for (String row : body.split("\n")) {
      assertThat(row.length()).isLessThanOrEqualTo(org.robotrun.pendant.Lcd.WIDTH);
    }
    Simulation sim = DefaultCell.simulation(ur);
    ControllerPort control = new ControllerPort(sim.controllers().get(0));
    assertThat(control.coupledJ3()).isFalse();
    assertThat(new ControllerPort(DefaultCell.simulation(RobotDefinitions.defaultRobot()).controllers().get(0)).coupledJ3()).isTrue();
    assertThat(control.jointNames()).containsExactly("shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
        "wrist_1_joint", "wrist_2_joint", "wrist_3_joint");
  }
}
