package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.ScenarioLoad;
import org.robotrun.io.ScenarioReader;
import org.robotrun.program.IoKind;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ExecutionStatus;
import org.robotrun.sim.HeadlessRun;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.world.Scenario;

/** {@code robotrun run} on a cell of two robots: both programs at once, wired handshakes, one report entry per robot. */
class CellRunTest {
  static final Path HANDSHAKE = Path.of("scenarios/two-robot-handshake.json");

  @Test
  void theHandshakeExampleFinishesWithBothRobotsOverlappingAndIsByteIdenticalEveryRun(@TempDir Path dir) throws Exception {
    Path r1 = dir.resolve("r1.json");
    Path t1 = dir.resolve("t1.csv");
    Path r2 = dir.resolve("r2.json");
    Path t2 = dir.resolve("t2.csv");
    assertThat(Main.execute("run", "--scenario", HANDSHAKE.toString(), "--report", r1.toString(), "--trace", t1.toString()))
        .isZero();
    assertThat(Main.execute("run", "--scenario", HANDSHAKE.toString(), "--report", r2.toString(), "--trace", t2.toString()))
        .isZero();
    assertThat(Files.readAllBytes(r2)).isEqualTo(Files.readAllBytes(r1));
    assertThat(Files.readAllBytes(t2)).isEqualTo(Files.readAllBytes(t1));

    JsonNode r = new ObjectMapper().readTree(r1.toFile());
    assertThat(r.get("status").asText()).isEqualTo("finished");
    JsonNode robots = r.get("robots");
    assertThat(robots).hasSize(2);
    assertThat(robots.get(0).get("program").asText()).isEqualTo("LOADER");
    assertThat(robots.get(1).get("program").asText()).isEqualTo("UNLOADER");
    double busy = 0;
    for (JsonNode robot : robots) {
      assertThat(robot.get("status").asText()).isEqualTo("finished");
      assertThat(robot.get("alarm").isNull()).isTrue();
      assertThat(robot.get("motions").size()).isGreaterThan(10);
      busy += robot.get("busyTimeSec").asDouble();
    }
    double cycle = r.get("cycleTimeSec").asDouble();
    // The cell ends with its last robot, and the robots really moved at the same time.
    assertThat(cycle).isEqualTo(Math.max(robots.get(0).get("cycleTimeSec").asDouble(), robots.get(1).get("cycleTimeSec").asDouble()));
    assertThat(cycle).isLessThan(busy);
    // Every part went supply -> nest -> tray.
    for (JsonNode part : r.get("parts")) {
      assertThat(part.get("parent").asText()).as(part.get("name").asText()).isEqualTo("tray");
    }
    assertThat(r.get("collisions")).isEmpty();
    // The trace has both robots' joints.
    String header = Files.readAllLines(t1).getFirst();
    assertThat(header).contains("robot1").contains("robot2");
  }

  @Test
  void eachRobotWaitsForTheOtherAndTheyNeverShareTheNest() {
    Scenario sc = ((ScenarioLoad.Loaded) ScenarioReader.read(HANDSHAKE)).scenario();
    Simulation sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
    Controller loader = sim.controllers().get(0);
    Controller unloader = sim.controllers().get(1);
    try {
      RunCommand.loadPrograms(sc.robots().get(0).programs()).forEach(loader::saveProgram);
      RunCommand.loadPrograms(sc.robots().get(1).programs()).forEach(unloader::saveProgram);
    } catch (java.io.IOException e) {
      throw new AssertionError(e);
    }
    assertThat(loader.programNames()).containsExactly("LOADER");
    assertThat(unloader.programNames()).containsExactly("UNLOADER");
    int[] waits = new int[4];
    int[] sharedTicks = new int[1];
    Map<Controller, String> programs = new LinkedHashMap<>();
    programs.put(loader, "LOADER");
    programs.put(unloader, "UNLOADER");
    HeadlessRun.CellResult result = HeadlessRun.runCell(sim, programs, 120, s -> {
      int l = line(loader);
      int u = line(unloader);
      // LOADER 20: WAIT DI[1:NEST FREE]=ON; 28: WAIT DI[1:NEST FREE]=OFF. UNLOADER 14: WAIT DI[1:PART READY]=ON; 22: ...=OFF.
      waits[0] += l == 20 ? 1 : 0;
      waits[1] += l == 28 ? 1 : 0;
      waits[2] += u == 14 ? 1 : 0;
      waits[3] += u == 22 ? 1 : 0;
      // LOADER 21..25 and UNLOADER 16..20 are inside the nest.
      if (l >= 21 && l <= 25 && u >= 16 && u <= 20) {
        sharedTicks[0]++;
      }
      // Between ticks a wired input shows its output.
      assertThat(unloader.registers().bit(IoKind.DI, 1)).isEqualTo(loader.registers().bit(IoKind.DO, 1));
    }, () -> false, "");
    assertThat(result.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(sharedTicks[0]).isZero();
    // robot1 waits for a free nest and for robot2's acknowledgement, robot2 for each part; robot2's
    // own wait for PART READY OFF (UNLOADER 22) finds it off already, as it should in this cycle.
    assertThat(new int[] {waits[0], waits[1], waits[2]}).as("ticks at LOADER 20, 28, UNLOADER 14").doesNotContain(0);
  }

  @Test
  void withoutTheUnloadersWaitTheArmsCollideAndBothStop(@TempDir Path dir) throws Exception {
    // The user guide's lab, step 4: UNLOADER line 14 (WAIT DI[1:PART READY]=ON) made a comment.
    Files.createDirectories(dir.resolve("programs"));
    Files.copy(HANDSHAKE, dir.resolve("cell.json"));
    Files.copy(Path.of("scenarios/programs/LOADER.LS"), dir.resolve("programs/LOADER.LS"));
    String unloader = Files.readString(Path.of("scenarios/programs/UNLOADER.LS"));
    assertThat(unloader).contains("  14:  WAIT DI[1:PART READY]=ON ;");
    Files.writeString(dir.resolve("programs/UNLOADER.LS"),
        unloader.replace("  14:  WAIT DI[1:PART READY]=ON ;", "  14:  ! no wait ;"));
    Path report = dir.resolve("r.json");
    assertThat(Main.execute("run", "--scenario", dir.resolve("cell.json").toString(), "--report", report.toString()))
        .isEqualTo(1);
    JsonNode r = new ObjectMapper().readTree(report.toFile());
    assertThat(r.get("status").asText()).isEqualTo("alarm");
    for (JsonNode robot : r.get("robots")) {
      assertThat(robot.get("status").asText()).isEqualTo("alarm");
      assertThat(robot.get("alarm").get("code").asText()).isEqualTo("SRVO-050");
      assertThat(robot.get("alarm").get("message").asText()).containsPattern("robot1 J\\d ").containsPattern("robot2 J\\d ")
          .doesNotContain("/");
    }
  }

  private static int line(Controller c) {
    ExecutionStatus s = c.status();
    return s.state() == ExecutionStatus.State.IDLE ? 0 : s.line();
  }
}
