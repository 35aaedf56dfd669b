package org.robotrun.app;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.SavedState;
import org.robotrun.io.ScenarioWriter;
import org.robotrun.io.WorkspaceCapture;
import org.robotrun.io.WorkspaceSnapshot;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.world.CameraView;
import org.robotrun.world.CellEditor;
import org.robotrun.world.Scenario;

/**
 * Switching the active scenario of a workspace from the cell editor: the scenario the window
 * runs is kept as it stands now (robots' joints, parts, taught frames, camera) under its name
 * in {@code scenarios/}, the chosen one becomes {@code cell.json}, and the workspace is opened
 * again, so everything the chosen scenario defines (robots, end effectors, frames, registers,
 * camera, mode, task text, parts) replaces the running cell. The student's programs and the
 * controller's state (registers, comments, override) stay. Window thread only.
 */
final class ScenarioSwitch {
  private ScenarioSwitch() {}

  /** Whether the editor's active scenario is another one than the running cell's, or a robot of it another model. */
  static boolean wanted(WorkspaceSession s, CellEditor editor) {
    return !editor.active().name().equals(s.workspace.scenario().name())
        || !models(editor.active()).equals(models(s.workspace.scenario()));
  }

  private static List<String> models(Scenario sc) {
    return sc.robots().stream().map(r -> r.modelId()).toList();
  }

  /**
   * Pins what the workspace holds after the switch (every later save writes it); the caller then
   * opens the workspace again.
   *
   * @return "" when pinned, else why the chosen scenario cannot run (nothing changed then)
   */
  static String prepare(WorkspaceSession s, CellEditor editor, Optional<CameraView> camera) {
    Scenario running = s.workspace.scenario();
    Scenario target = editor.active();
    try {
      ScenarioCell.build(target, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
    } catch (IllegalArgumentException | org.robotrun.io.FileFormatException e) {
      return "scenario '" + target.name() + "' cannot be opened: " + e.getMessage();
    }
    String created = s.workspace.state().map(SavedState::created).orElse("");
    WorkspaceSnapshot now = WorkspaceCapture.capture(running, s.sim, camera, created, s.workspace.folder());
    Scenario leaving = WorkspaceCapture.cellNow(running, s.sim, camera, running.mainProgram());
    List<Scenario> others = new ArrayList<>();
    for (Scenario sc : editor.scenarios()) {
      if (sc != target) {
        // the running one as it stands; one deleted in the editor is simply not in the list
        others.add(sc.name().equals(running.name()) ? leaving : sc);
      }
    }
    try {
      String json = ScenarioWriter.toJson(target,
          Optional.of(SavedState.captureCell(s.sim.controllers(), created)), s.workspace.folder());
      s.pinned = new WorkspaceSnapshot(json, now.programs(), Optional.of(others));
    } catch (IOException e) {
      throw new UncheckedIOException(e);  // a StringWriter does not fail
    }
    return "";
  }
}
