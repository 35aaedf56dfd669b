package org.robotrun.collision.bench;

import java.util.Map;
import java.util.Random;
import org.robotrun.collision.Body;
import org.robotrun.collision.CollisionWorld;
import org.robotrun.collision.Obb;
import org.robotrun.collision.StandardPairFilter;
import org.robotrun.math.Transform;

/**
 * A synthetic cell for timing the broad phase: two robots of eight boxes each, swinging
 * through the cell, and 200 objects — 20 tables (fixtures) carrying 180 parts — spread over
 * 3 m × 3 m. The robots are stand-ins (a chain of boxes driven by sines), so the benchmark
 * needs no kinematics; what it measures is the cost of one {@link CollisionWorld#update()}.
 * {@code part0} counts as held by robot1, so the held-part rules are exercised too; it still
 * lies on its table, which is the one contact reported every tick.
 */
public final class CellScene {
  /** Boxes per robot. */
  public static final int ROBOT_BOXES = 8;

  private final CollisionWorld world;
  private final Transform[] robotBases = {Transform.translation(0, 0, 0), Transform.translation(1200, 0, 0)};
  private final Transform[] linkBoxes = new Transform[ROBOT_BOXES];

  /** Builds the cell; {@code seed} places the tables and parts. */
  public CellScene(long seed) {
    Random random = new Random(seed);
    world = new CollisionWorld(new StandardPairFilter(Map.of("part0", "robot1")));
    for (int k = 0; k < ROBOT_BOXES; k++) {
      // Box k of a robot sits half-way along its 90 mm segment of the chain.
      linkBoxes[k] = Transform.translation(0, 0, 45);
    }
    for (int r = 0; r < 2; r++) {
      for (int k = 0; k < ROBOT_BOXES; k++) {
        world.add(Body.robotLink("robot" + (r + 1), k, "robot" + (r + 1) + "/box" + k),
            Obb.axisAligned(0, 0, 0, 45, 40, 45));
      }
    }
    for (int t = 0; t < 20; t++) {
      double tx = -1500 + (t % 5) * 750, ty = -1500 + (t / 5) * 750;
      world.add(Body.fixture("table" + t, "table" + t), Obb.axisAligned(tx, ty, -400, 300, 300, 20));
      for (int p = 0; p < 9; p++) {
        String name = "part" + (t * 9 + p);
        double h = 10 + 30 * random.nextDouble();
        Obb part = Obb.of(Transform.rotation(0, 0, 1, random.nextDouble() * Math.PI)
                .withTranslation(tx + (p % 3 - 1) * 180, ty + (p / 3 - 1) * 180, -380 + h),
            10 + 40 * random.nextDouble(), 10 + 40 * random.nextDouble(), h);
        world.add(Body.part(name, name), part);
      }
    }
  }

  /** Number of bodies (216). */
  public int bodies() {
    return world.size();
  }

  /** Moves both robots to their pose at {@code tick} and runs the check; returns touching pairs. */
  public int tick(int tick) {
    for (int r = 0; r < 2; r++) {
      Transform X_WL = robotBases[r];
      double phase = tick * 0.004 + r;
      for (int k = 0; k < ROBOT_BOXES; k++) {
        double angle = 0.6 * Math.sin(phase * (1 + 0.3 * k));
        X_WL = X_WL.compose(Transform.rotation(k % 2 == 0 ? 0 : 1, 0, k % 2 == 0 ? 1 : 0, angle));
        world.setPose(r * ROBOT_BOXES + k, X_WL, linkBoxes[k]);
        X_WL = X_WL.compose(Transform.translation(0, 0, 90));
      }
    }
    return world.update();
  }

  /** The world, for inspection. */
  public CollisionWorld world() {
    return world;
  }
}
