package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.Workspace;
import org.robotrun.program.Instruction;
import org.robotrun.program.Program;
import org.robotrun.world.CellEditor;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;

/** Switching the active scenario from the cell editor: what the workspace holds afterwards. */
class ScenarioSwitchTest {
  private static final CellEditor.MeshLoader NO_MESHES = (f, s) -> {
    throw new IllegalArgumentException("no meshes here");
  };

  private static WorkspaceSession openCopyOfPickAndPlace(Path tmp) {
    Path ws = WorkspaceFiles.createFromScenario(Path.of("scenarios/pick-and-place.json"), tmp.resolve("ws"));
    return WorkspaceSession.open(ws, false, Optional::empty, m -> {});
  }

  @Test
  void anotherRobotModelChosenInTheEditorReopensTheCellWithIt(@TempDir Path tmp) throws Exception {
    Path dir;
    try (WorkspaceSession s = openCopyOfPickAndPlace(tmp)) {
      dir = s.workspace.folder();
      CellEditor ed = new CellEditor(List.of(s.workspace.scenario()), 0, NO_MESHES);
      s.otherScenarios = () -> List.of();
      assertThat(ScenarioSwitch.wanted(s, ed)).isFalse();
      List<Double> home = List.of(0.0, 0.0, 0.0, 0.0, -Math.PI / 2, 0.0);
      assertThat(ed.setRobotModel(0, "crx10ia", home)).isInstanceOf(CellEditor.Result.Done.class);
      assertThat(ed.setRobotModel(1, "crx10ia", home)).isInstanceOf(CellEditor.Result.Refused.class);
      assertThat(ScenarioSwitch.wanted(s, ed)).isTrue();
      assertThat(ScenarioSwitch.prepare(s, ed, Optional.empty())).isEmpty();
    }
    try (Workspace ws = Workspace.open(dir, WorkspaceSession.newCell())) {
      assertThat(ws.problems()).isEmpty();
      assertThat(ws.scenario().name()).isEqualTo("Pick and place");
      assertThat(ws.scenario().robots().get(0).modelId()).isEqualTo("crx10ia");
      assertThat(ws.programs()).extracting(Program::name).contains("PICKPLACE");
    }
  }

  @Test
  void theChosenScenarioBecomesTheCellAndTheOneLeftIsKeptAsItStands(@TempDir Path tmp) throws Exception {
    Path dir;
    try (WorkspaceSession s = openCopyOfPickAndPlace(tmp)) {
      dir = s.workspace.folder();
      CellEditor ed = new CellEditor(List.of(s.workspace.scenario()), 0, NO_MESHES);
      s.otherScenarios = () -> List.of();
      // the student's work: a program, and a user frame taught in this cell
      s.sim.controllers().get(0).saveProgram(Program.of("MINE", List.of(new Instruction.Comment("mine"))));
      s.sim.controllers().get(0).setFrame(Instruction.FrameKind.USER, 3,
          new org.robotrun.program.Position.Cartesian(100, 200, 0, 0, 0, 0, org.robotrun.program.Config.DEFAULT));
      // "New": a copy under another name, made active; then delete its parts
      ed.addScenario("Empty lab");
      for (String part : List.of("part1", "part2", "part3")) {
        ed.delete(part);
      }
      assertThat(ScenarioSwitch.wanted(s, ed)).isTrue();
      assertThat(ScenarioSwitch.prepare(s, ed, Optional.empty())).isEmpty();
    }
    try (Workspace ws = Workspace.open(dir, WorkspaceSession.newCell())) {
      assertThat(ws.problems()).isEmpty();
      assertThat(ws.scenario().name()).isEqualTo("Empty lab");
      assertThat(ws.scenario().world().find("part1")).isEmpty();
      assertThat(ws.programs()).extracting(Program::name).contains("MINE", "PICKPLACE");
      assertThat(ws.otherScenarios()).extracting(Scenario::name).containsExactly("Pick and place");
      Scenario left = ws.otherScenarios().get(0);
      assertThat(left.world().find("part1")).isPresent();
      assertThat(left.userFrames()).containsKey(3);
      assertThat(left.userFrames().get(3).translationVector().y()).isCloseTo(200, org.assertj.core.api.Assertions.within(1e-6));
      assertThat(ws.scenario().userFrames()).doesNotContainKey(3);
    }
    assertThat(dir.resolve("scenarios/Pick_and_place.json")).exists();
    assertThat(dir.resolve("scenarios/Empty_lab.json")).doesNotExist();
  }

  @Test
  void aScenarioThatCannotRunIsRefusedAndNothingChanges(@TempDir Path tmp) throws Exception {
    Path cell;
    try (WorkspaceSession s = openCopyOfPickAndPlace(tmp)) {
      Scenario sc = s.workspace.scenario();
      RobotSetup r = sc.robots().get(0);
      Scenario broken = new Scenario("Broken", "", List.of(new RobotSetup(r.name(), "no-such-robot", r.X_CB(), r.endEffector(),
          r.initialJointsRad())), sc.world(), List.of(), Optional.empty(), sc.registers(), sc.toolFrames(), sc.userFrames(),
          sc.camera());
      CellEditor ed = new CellEditor(List.of(sc, broken), 1, NO_MESHES);
      String why = ScenarioSwitch.prepare(s, ed, Optional.empty());
      assertThat(why).contains("Broken").contains("no-such-robot");
      assertThat(s.pinned).isNull();
      cell = s.workspace.folder().resolve("cell.json");
    }
    // closing saved the running cell, not the refused one
    assertThat(Files.readString(cell)).contains("\"Pick and place\"").doesNotContain("Broken");
    assertThat(cell.resolveSibling("scenarios")).doesNotExist();
  }
}
