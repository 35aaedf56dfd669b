package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.ScenarioLoad;
import org.robotrun.io.ScenarioReader;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;

/** Grading variations: every robot sees the offsets, and no field of the cell is dropped. */
class VariationsEveryRobotTest {
  private static Scenario handshake() {
    return switch (ScenarioReader.read(Path.of("scenarios/two-robot-handshake.json"))) {
      case ScenarioLoad.Loaded l -> l.scenario();
      case ScenarioLoad.Failed f -> throw new AssertionError(f.message());
    };
  }

  private static Program idle(String name) {
    return LsReader.parse(name + ".LS", "/PROG  " + name + "\n/ATTR\n/MN\n   1:  R[1]=1 ;\n/POS\n/END\n").program();
  }

  private static final Task.Variations JITTER = new Task.Variations(2, 42,
      List.of(new Task.PartJitter("part1", 15, 15, 10, Optional.of(11))), 100, 100);

  @Test
  void aVariationsOffsetRegisterIsWrittenIntoEveryRobot() {
    CellRunner.Variant v = CellRunner.variation(handshake(), JITTER, 1);
    Position.Cartesian offset = v.offsetRegisters().get(11);
    assertThat(offset.xMm() != 0 || offset.yMm() != 0 || offset.rDeg() != 0).as("a real draw").isTrue();
    RunOutcome out = CellRunner.run(v, RobotDefinitions::load, List.of(idle("MAIN")), Map.of(), "MAIN",
        Map.of("robot2", new CellRunner.RobotStart("OTHER", List.of(idle("OTHER")), Map.of(), Map.of())), 10,
        System.nanoTime() + 60_000_000_000L);
    assertThat(out.robot(Optional.of("robot1")).registers().position(11)).isEqualTo(offset);
    assertThat(out.robot(Optional.of("robot2")).registers().position(11)).isEqualTo(offset);
  }

  @Test
  void aVariationKeepsTheCellsModeAndEveryOtherField() {
    Scenario base = handshake().withMode(Optional.of("AUTO"));
    Scenario moved = CellRunner.variation(base, JITTER, 1).scenario();
    assertThat(moved.mode()).isEqualTo(Optional.of("AUTO"));
    assertThat(moved.world()).isNotEqualTo(base.world());
    assertThat(moved.withWorld(base.world())).isEqualTo(base);
  }
}
