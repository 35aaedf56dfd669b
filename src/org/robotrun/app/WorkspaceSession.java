package org.robotrun.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.TreeMap;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.robotrun.io.Autosave;
import org.robotrun.io.HandIn;
import org.robotrun.io.HandInException;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.UserDirs;
import org.robotrun.io.Workspace;
import org.robotrun.io.WorkspaceCapture;
import org.robotrun.io.WorkspaceException;
import org.robotrun.math.Transform;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.world.CameraView;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.World;

/**
 * An open workspace with its running cell: the {@link Workspace}, the {@link Simulation} built
 * from its {@code cell.json} with the saved state and programs put back, and the
 * {@link Autosave} that keeps the folder up to date. Shared by the window, {@code pendant} and
 * {@code run}.
 */
final class WorkspaceSession implements AutoCloseable {
  final Workspace workspace;
  final Simulation sim;
  final Autosave autosave;
  private final Path unpackedZip;
  /** The folder or zip the user gave: named in messages instead of a temporary copy. */
  private Path given;
  /** The other named scenarios to save (the window's cell editor); null: {@code scenarios/} is left as it is. */
  volatile Supplier<List<Scenario>> otherScenarios;
  /** When set, what every later save writes instead of the running cell (a scenario switch in progress). */
  volatile org.robotrun.io.WorkspaceSnapshot pinned;

  private WorkspaceSession(Workspace workspace, Simulation sim, Autosave autosave, Path unpackedZip) {
    this.workspace = workspace;
    this.sim = sim;
    this.autosave = autosave;
    this.unpackedZip = unpackedZip;
  }

  /**
   * Opens (or creates) the workspace in {@code dir}; a {@code .zip} hand-in is unpacked into a
   * temporary folder and opened read-only.
   *
   * @param camera the view to save with the cell (the window's), called on the polling thread
   * @param report receives autosave problems and recoveries
   * @throws UserError (exit 2) when the workspace cannot be opened at all
   */
  static WorkspaceSession open(Path dir, boolean readOnly, Supplier<Optional<CameraView>> camera, Consumer<String> report) {
    Path unpacked = null;
    Path folder = dir;
    if (dir.getFileName() != null && dir.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".zip")) {
      if (!Files.isRegularFile(dir)) {
        throw new UserError("--workspace: no such file " + dir);
      }
      try {
        unpacked = Files.createTempDirectory("robotrun-handin");
        HandIn.unpack(dir, unpacked);
      } catch (IOException e) {
        deleteTree(unpacked);
        throw new UserError("--workspace: cannot make a temporary folder (" + e.getMessage() + ")", Main.EXIT_FAILED);
      } catch (HandInException | RuntimeException e) {
        deleteTree(unpacked);
        throw e instanceof HandInException h ? new UserError(h.getMessage()) : (RuntimeException) e;
      }
      folder = unpacked;
      readOnly = true;
    }
    // An unpacked hand-in (a folder with the manifest.json File > Hand in writes, as Gradescope
    // unpacks it) is the student's handed-in work: looked at, never changed (its manifest would no
    // longer match), as a zip is. Issue 26.
    boolean unpackedHandIn = unpacked == null
        && Files.isRegularFile(dir.resolve(HandIn.MANIFEST), java.nio.file.LinkOption.NOFOLLOW_LINKS);
    Workspace ws;
    try {
      ws = unpacked != null || unpackedHandIn ? Workspace.openHandIn(folder, newCell())
          : Workspace.open(folder, newCell(), readOnly);
    } catch (WorkspaceException e) {
      deleteTree(unpacked);
      throw new UserError(e.getMessage());
    }
    Simulation sim;
    try {
      sim = ScenarioCell.build(ws.scenario(), RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
      WorkspaceCapture.restore(ws, sim);
    } catch (IllegalArgumentException e) {
      ws.close();
      deleteTree(unpacked);
      throw new UserError((unpacked != null ? dir.resolve(Workspace.CELL) : ws.folder().resolve(Workspace.CELL)) + ": "
          + e.getMessage());
    } catch (RuntimeException | Error e) {
      ws.close();
      deleteTree(unpacked);
      throw e;
    }
    String created = ws.state().map(s -> s.created()).orElse("");
    WorkspaceSession[] self = {null};
    Autosave autosave = new Autosave(ws, () -> {
      WorkspaceSession s = self[0];
      if (s.pinned != null) {
        return s.pinned;
      }
      var snap = WorkspaceCapture.capture(ws.scenario(), sim, camera.get(), created, ws.folder());
      Supplier<List<Scenario>> others = s.otherScenarios;
      return others == null ? snap : snap.withOtherScenarios(others.get());
    }, report);
    self[0] = new WorkspaceSession(ws, sim, autosave, unpacked);
    self[0].given = dir;
    return self[0];
  }

  /**
   * The cell of a new workspace: the default robot at HOME with the cell frame at its WORLD,
   * UTOOL[1] a 100 mm pointer and UFRAME[1] = WORLD, both active (as the default cell).
   */
  static Scenario newCell() {
    RobotModel model = RobotDefinitions.defaultRobot();
    List<Double> home = new ArrayList<>();
    for (int k = 1; k <= 6; k++) {
      home.add(Math.toRadians(DefaultCell.HOME.element(k)));
    }
    RobotSetup robot = new RobotSetup("robot1", RobotDefinitions.DEFAULT_ROBOT, model.X_WB(), EndEffectorType.POINTER, home);
    TreeMap<Integer, Transform> tools = new TreeMap<>();
    tools.put(1, Transform.translation(0, 0, DefaultCell.POINTER_MM));
    TreeMap<Integer, Transform> users = new TreeMap<>();
    users.put(1, Transform.IDENTITY);
    return new Scenario("", "", List.of(robot), World.empty(), List.of(), Optional.empty(), new TreeMap<>(), tools, users,
        Optional.empty());
  }

  /** The workspace {@code robotrun} opens with no argument: the last one, else the default one. */
  static Path lastOrDefault(UserDirs dirs) {
    return dirs.lastWorkspace().orElse(dirs.defaultWorkspace());
  }

  /** The opening problems as one text (empty when none). */
  String problems() {
    List<String> all = new ArrayList<>();
    if (workspace.readOnly() && unpackedZip == null) {
      all.add(workspace.folder() + ": " + workspace.readOnlyReason());
    }
    all.addAll(workspace.problems());
    String text = String.join("\n", all);
    // a hand-in is read from a temporary copy: name what the user gave, not the copy
    return unpackedZip == null ? text : text.replace(unpackedZip.toAbsolutePath().normalize().toString(), given + "!");
  }

  private final java.util.concurrent.atomic.AtomicBoolean closed = new java.util.concurrent.atomic.AtomicBoolean();

  /** Saves what is left and closes; the second call does nothing. */
  @Override
  public void close() {
    if (closed.getAndSet(true)) {
      return;
    }
    autosave.close();
    workspace.close();
    deleteTree(unpackedZip);
  }

  private static void deleteTree(Path dir) {
    if (dir == null) {
      return;
    }
    try (var s = Files.walk(dir)) {
      s.sorted(java.util.Comparator.reverseOrder()).forEach(p -> {
        try {
          Files.deleteIfExists(p);
        } catch (IOException e) {
          // a temporary folder; the OS cleans it eventually
        }
      });
    } catch (IOException e) {
      // as above
    }
  }
}
