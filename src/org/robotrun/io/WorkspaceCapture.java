package org.robotrun.io;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import org.robotrun.math.Transform;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;
import org.robotrun.sim.FrameTable;
import org.robotrun.sim.Simulation;
import org.robotrun.world.CameraView;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.World;

/**
 * Turns a running cell into what its workspace holds ({@link WorkspaceSnapshot}) and back. The
 * cell as a scenario is the one it was opened from with the robots' joints, the objects' poses,
 * the first robot's frames and the camera as they are now; the first controller's registers,
 * outputs, override, active frames and comments go in the {@code "state"} section, and every
 * other robot's (with its frames) under {@code "state"."robots"}; their programs are kept in
 * {@code programs/ROBOT/} ({@link Workspace#robotFolder}).
 *
 * <p>Capturing reads the simulation and must run on the thread that steps it; it does no I/O.
 */
public final class WorkspaceCapture {
  private WorkspaceCapture() {}

  /**
   * The workspace's content now.
   *
   * @param base the cell the simulation was built from (models, shapes, end effectors)
   * @param camera the window's view, if there is one
   * @param created the workspace's creation time, kept in {@code cell.json}
   */
  public static WorkspaceSnapshot capture(Scenario base, Simulation sim, Optional<CameraView> camera, String created,
      Path workspaceDir) {
    Controller first = sim.controllers().get(0);
    Map<String, Program> programs = new LinkedHashMap<>();
    for (String name : first.programNames()) {
      first.program(name).ifPresent(p -> programs.put(name, p));
    }
    // The other robots' programs, keyed "ROBOT/NAME" (programs/ROBOT/NAME.LS; Workspace.robotFolder).
    Map<String, Program> others = new LinkedHashMap<>();
    for (int i = 1; i < sim.controllers().size(); i++) {
      Controller c = sim.controllers().get(i);
      String folder = Workspace.robotFolder(c.name());
      for (String name : c.programNames()) {
        c.program(name).ifPresent(p -> others.put(folder + "/" + name, p));
      }
    }
    Scenario now = cellNow(base, sim, camera, mainProgram(base, first, programs));
    programs.putAll(others);
    try {
      String json = ScenarioWriter.toJson(now, Optional.of(SavedState.captureCell(sim.controllers(), created)), workspaceDir);
      return new WorkspaceSnapshot(json, programs);
    } catch (IOException e) {
      throw new UncheckedIOException(e);  // a StringWriter does not fail
    }
  }

  /** The scenario of the cell as it stands: joints, object poses, frames and camera now. */
  public static Scenario cellNow(Scenario base, Simulation sim, Optional<CameraView> camera, Optional<String> main) {
    List<RobotSetup> robots = new ArrayList<>();
    for (int i = 0; i < base.robots().size(); i++) {
      RobotSetup r = base.robots().get(i);
      Position.Joint q = sim.controllers().get(i).currentJoints();
      List<Double> rad = new ArrayList<>();
      for (int k = 1; k <= 6; k++) {
        rad.add(Math.toRadians(q.element(k)));
      }
      // the presets are now the controller's state (frames of the first robot: the top-level "frames")
      robots.add(r.withJoints(rad).withPresets(new TreeMap<>(), new TreeMap<>(), new TreeMap<>()));
    }
    World world = sim.world();
    FrameTable frames = sim.controllers().get(0).frames();
    TreeMap<Integer, Transform> tools = new TreeMap<>();
    TreeMap<Integer, Transform> users = new TreeMap<>();
    for (int n = 1; n <= FrameTable.COUNT; n++) {
      // Frame 1 always: a scenario without UT[1] gets the end effector's TCP there.
      if (n == 1 || !frames.transform(FrameKind.TOOL, n).equals(Transform.IDENTITY)) {
        tools.put(n, frames.transform(FrameKind.TOOL, n));
      }
      if (n == 1 || !frames.transform(FrameKind.USER, n).equals(Transform.IDENTITY)) {
        users.put(n, frames.transform(FrameKind.USER, n));
      }
    }
    // The vision setup as it is now: a Reset with a new seed changed the seed the parts were placed by.
    Scenario withVision = sim.vision().isPresent() ? base.withVision(sim.vision().get().setup()) : base;
    return withVision.withRobots(robots).withWorld(world).withPrograms(List.of(), main)
        .withPresets(new TreeMap<>(), tools, users).withCamera(camera.isPresent() ? camera : base.camera());
  }

  /** The program {@code run --workspace} runs: the cell's main program while it exists, else the only one, else the one last run. */
  private static Optional<String> mainProgram(Scenario base, Controller c, Map<String, Program> programs) {
    if (base.mainProgram().isPresent() && programs.containsKey(base.mainProgram().get())) {
      return base.mainProgram();
    }
    if (programs.size() == 1) {
      return Optional.of(programs.keySet().iterator().next());
    }
    String current = c.status().program();
    return current != null && programs.containsKey(current) ? Optional.of(current) : Optional.empty();
  }

  /** Puts a workspace's saved state and programs into a simulation built from its cell. */
  public static void restore(Workspace ws, Simulation sim) {
    Controller first = sim.controllers().get(0);
    ws.state().ifPresent(s -> s.applyToCell(sim.controllers()));
    ws.programs().forEach(first::saveProgram);
    for (int i = 1; i < sim.controllers().size(); i++) {
      Controller c = sim.controllers().get(i);
      ws.programs(c.name()).forEach(c::saveProgram);
    }
  }
}
