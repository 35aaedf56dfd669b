package org.robotrun.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.ScenarioLoad;
import org.robotrun.io.ScenarioReader;
import org.robotrun.render.OrbitCamera;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.SceneSnapshot;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.world.CameraView;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;

/** Loading a scenario for a command, with every problem as a {@link UserError}. */
final class ScenarioFiles {
  private ScenarioFiles() {}

  /** Reads the scenario or throws one error listing every problem found (file:line: path: what). */
  static Scenario load(Path file) {
    if (!Files.exists(file)) {
      throw new UserError(Files.isSymbolicLink(file)
          ? "--scenario: " + file + " is " + org.robotrun.io.BoundedFiles.missing(file)
          : "--scenario: no such file " + file);
    }
    return switch (ScenarioReader.read(file)) {
      case ScenarioLoad.Loaded l -> l.scenario();
      case ScenarioLoad.Failed f -> throw new UserError(f.errors().stream()
          .map(Object::toString).collect(Collectors.joining(System.lineSeparator())));
    };
  }

  /** The robot model a setup names. */
  static RobotModel model(RobotSetup setup) {
    try {
      return RobotDefinitions.load(setup.modelId());
    } catch (FileFormatException e) {
      throw new UserError("robot '" + setup.name() + "': " + e.getMessage());
    }
  }

  /**
   * The cell as the simulation starts it (robots with their end effectors, bodies in contact
   * red after one collision check), optionally with its collision boxes; {@code jointsOverride}
   * (pendant degrees, may be null) replaces the first robot's joints.
   */
  static SceneSnapshot simulatedScene(Scenario sc, String jointsOverride, boolean showBoxes) {
    Scenario s = sc;
    if (jointsOverride != null) {
      RobotSetup first = sc.robots().get(0);
      double[] q = JointConvention.kinematicToPendant(model(first), JointsOption.parseToKinematic(jointsOverride, model(first)));
      List<RobotSetup> robots = new ArrayList<>(sc.robots());
      robots.set(0, first.withJoints(java.util.Arrays.stream(q).boxed().toList()));
      s = sc.withRobots(robots);
    }
    Simulation sim;
    try {
      sim = ScenarioCell.build(s, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
    } catch (FileFormatException | IllegalArgumentException e) {
      throw new UserError("--scenario: " + e.getMessage());
    }
    sim.setShowCollisionBoxes(showBoxes);
    // One tick: the arms stand still, the collision check runs.
    sim.step();
    return sim.snapshot().scene();
  }

  static void applyCamera(CameraView v, OrbitCamera camera) {
    camera.set((float) v.targetMm().x(), (float) v.targetMm().y(), (float) v.targetMm().z(),
        (float) v.distanceMm(), (float) v.yawRad(), (float) v.pitchRad());
  }
}
