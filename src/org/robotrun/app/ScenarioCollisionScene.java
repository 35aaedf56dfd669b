package org.robotrun.app;

import java.util.ArrayList;
import java.util.List;
import org.robotrun.collision.CollisionWorld;
import org.robotrun.collision.StandardPairFilter;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.LinkSpec;
import org.robotrun.robot.RobotModel;
import org.robotrun.world.LocalBox;
import org.robotrun.world.RobotBodies;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.WorldBodies;

/**
 * A scenario's collision world for {@code bench broadphase --scenario}: its objects, and each
 * robot's link boxes (one per link shape) swinging about its initial joints. The link poses
 * of {@link #FRAMES} ticks are computed up front so the timing measures collision only.
 */
final class ScenarioCollisionScene {
  static final int FRAMES = 1000;

  private final CollisionWorld world = new CollisionWorld(StandardPairFilter.nothingHeld());
  private final List<RobotBodies> robots = new ArrayList<>();
  /** [robot][frame][link] link poses in the cell. */
  private final Transform[][][] X_CL;

  ScenarioCollisionScene(Scenario scenario) {
    new WorldBodies(scenario.world(), world);
    X_CL = new Transform[scenario.robots().size()][FRAMES][];
    for (int r = 0; r < scenario.robots().size(); r++) {
      RobotSetup setup = scenario.robots().get(r);
      RobotModel model = RobotDefinitions.load(setup.modelId());
      List<List<LocalBox>> boxes = new ArrayList<>();
      for (LinkSpec link : model.links()) {
        boxes.add(link.shapes().stream().map(ScenarioCollisionScene::box).toList());
      }
      robots.add(new RobotBodies(setup.name(), boxes, world));
      double[] q0 = JointConvention.pendantToKinematic(model, setup.initialJoints());
      for (int f = 0; f < FRAMES; f++) {
        double[] q = q0.clone();
        for (int j = 0; j < q.length; j++) {
          q[j] += 0.4 * Math.sin(2 * Math.PI * f / FRAMES * (1 + j));
        }
        Transform[] X_BL = ForwardKinematics.linkPosesInBase(model, q);
        for (int i = 0; i < X_BL.length; i++) {
          X_BL[i] = setup.X_CB().compose(X_BL[i]);
        }
        X_CL[r][f] = X_BL;
      }
    }
    // Frame 0 is the start pose: what touches there within one robot touches by construction.
    tick(0);
    world.setFilter(StandardPairFilter.nothingHeld()
        .withAllowedContacts(StandardPairFilter.robotSelfContacts(world.contacts())));
  }

  private static LocalBox box(LinkShape shape) {
    return switch (shape) {
      case LinkShape.Box b -> LocalBox.ofBox(b.X_LS(), b.size());
      case LinkShape.Cylinder c -> LocalBox.ofCylinder(c.X_LS(), c.radius(), c.length());
    };
  }

  int bodies() {
    return world.size();
  }

  /** Moves the robots to frame {@code tick % FRAMES} and runs the check; returns touching pairs. */
  int tick(int tick) {
    for (int r = 0; r < robots.size(); r++) {
      robots.get(r).moveTo(X_CL[r][tick % FRAMES], world);
    }
    return world.update();
  }

  CollisionWorld world() {
    return world;
  }
}
