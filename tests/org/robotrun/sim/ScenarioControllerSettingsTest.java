package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.robotrun.program.IoKind;
import org.robotrun.program.Program;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;

/** A scenario's per-robot controller setup (I/O sizes, UALM texts) reaches the robot's controller. */
class ScenarioControllerSettingsTest {

  @Test
  void ioSizesAndUserAlarmTextsComeFromTheScenario() {
    Scenario base = CellRig.scenario("empty-cell.json");
    RobotSetup r = base.robots().getFirst();
    RobotSetup configured = new RobotSetup(r.name(), r.modelId(), r.X_CB(), r.endEffector(), r.initialJointsRad(),
        r.toolIo(), new TreeMap<>(Map.of("DO", 1024)), new TreeMap<>(Map.of(3, "Clamp not closed")));
    Scenario s = new Scenario(base.name(), base.description(), List.of(configured), base.world(), List.of(),
        base.mainProgram(), base.registers(), base.toolFrames(), base.userFrames(), base.camera(), base.onCollision());
    Simulation sim = CellRig.cell(s);
    Controller c = sim.controllers().getFirst();
    assertThat(c.registers().ioSize(IoKind.DO)).isEqualTo(1024);
    assertThat(c.registers().ioSize(IoKind.DI)).isEqualTo(512);
    Program p = CellRig.program(new String[] {"DO[1000]=ON", "UALM[3]"});
    c.saveProgram(p);
    c.run(p.name(), 1, true);
    for (int i = 0; i < 50; i++) {
      sim.step();
    }
    assertThat(c.registers().bit(IoKind.DO, 1000)).isTrue();
    assertThat(c.activeAlarms()).anySatisfy(a -> assertThat(a.message()).contains("Clamp not closed"));
  }
}
