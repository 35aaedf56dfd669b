package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Xyzwpr;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;

/**
 * Issue 26: grading variations could not change the vision seed, so a task could not grade a
 * vision program over several placements. {@code variations.varyVisionSeed} places the parts of
 * variation i with {@code vision.seed + i}.
 */
class VisionVariationsTest {
  private static final String SCENARIO = Path.of("scenarios/vision-pick.json").toAbsolutePath().toString()
      .replace("\\", "/");

  private static Path task(Path dir, String variations) throws Exception {
    Path t = dir.resolve("vision.task.json");
    Files.writeString(t, """
        {"format": 1, "title": "vision over placements", "scenario": "%s", "program": "VISPICK",
         "limits": {"simSeconds": 120, "wallSeconds": 120},
         "variations": %s,
         "checks": [
           {"name": "Runs to the end", "type": "runsToEnd", "points": 10, "runs": "all", "message": "end"},
           {"name": "Four blocks placed", "type": "endState", "points": 10, "runs": "all", "values": {"R[1]": 4},
            "message": "all four"}
         ]}
        """.formatted(SCENARIO, variations));
    return t;
  }

  @Test
  void eachVariationPlacesTheVisionPartsWithItsOwnSeedAndTheVisionProgramIsGradedOverAll(@TempDir Path dir)
      throws Exception {
    TaskLoad l = TaskReader.read(task(dir, "{\"count\": 3, \"seed\": 5, \"varyVisionSeed\": true}"));
    assertThat(l).isInstanceOf(TaskLoad.Loaded.class);
    Task t = ((TaskLoad.Loaded) l).task();
    var scenario = ((TaskLoad.Loaded) l).scenario();
    assertThat(t.variations().varyVisionSeed()).isTrue();
    // four different placements: the nominal run's and three more
    Set<String> placements = new HashSet<>();
    for (int i = 0; i <= 3; i++) {
      CellRunner.Variant v = i == 0 ? CellRunner.nominal(scenario, t.variations())
          : CellRunner.variation(scenario, t.variations(), i);
      assertThat(v.scenario().vision().seed()).isEqualTo(scenario.vision().seed() + i);
      Simulation sim = ScenarioCell.build(v.scenario(), RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
      placements.add(Xyzwpr.fromTransform(sim.world().poseInCell("block1")).toString());
      if (i > 0) {
        assertThat(v.label()).contains("vision seed " + (scenario.vision().seed() + i));
      }
    }
    assertThat(placements).hasSize(4);
    // the vision program finds and places every block in every placement
    Path sub = dir.resolve("student");
    Files.createDirectories(sub);
    Files.copy(Path.of("scenarios/programs/VISPICK.LS"), sub.resolve("VISPICK.LS"));
    GradeResult r = Grading.gradeOne(new Grader(t, scenario), new SubmissionLoader(), sub, true);
    assertThat(HandIns.failed(r)).isEmpty();
    assertThat(r.runs()).hasSize(4);
    assertThat(r.score()).isEqualTo(20);
  }

  @Test
  void withoutItTheVariationsKeepTheScenariosSeed(@TempDir Path dir) throws Exception {
    TaskLoad.Loaded l = (TaskLoad.Loaded) TaskReader.read(task(dir, "{\"count\": 2, \"seed\": 5}"));
    assertThat(CellRunner.variation(l.scenario(), l.task().variations(), 2).scenario().vision().seed())
        .isEqualTo(l.scenario().vision().seed());
  }

  @Test
  void aScenarioWithoutPlacementsOrAWrongTypeIsRefusedWithPathAndLine(@TempDir Path dir) throws Exception {
    Path t = task(dir, "{\"count\": 2, \"varyVisionSeed\": \"yes\"}");
    assertThat(TaskReader.read(t)).isInstanceOf(TaskLoad.Failed.class);
    assertThat(((TaskLoad.Failed) TaskReader.read(t)).errors().toString()).contains("variations.varyVisionSeed")
        .contains("expected true or false");
    Path pp = dir.resolve("pp.task.json");
    Files.writeString(pp, Files.readString(task(dir, "{\"count\": 2, \"varyVisionSeed\": true}"))
        .replace(SCENARIO, Path.of("scenarios/pick-and-place.json").toAbsolutePath().toString().replace("\\", "/"))
        .replace("VISPICK", "PICKPLACE"));
    TaskLoad f = TaskReader.read(pp);
    assertThat(f).isInstanceOf(TaskLoad.Failed.class);
    assertThat(((TaskLoad.Failed) f).errors().toString()).contains("variations.varyVisionSeed").contains("no vision placements");
  }
}
