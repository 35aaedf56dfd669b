package org.robotrun.world;

import java.util.LinkedHashMap;
import java.util.Map;
import org.robotrun.collision.Body;
import org.robotrun.collision.CollisionWorld;

/**
 * Puts the objects of a {@link World} into a {@link CollisionWorld} (one box each, owner = the
 * object's name, body kind from its {@link ObjectKind}) and keeps their boxes where the objects
 * are. Robot and tool boxes are added by the simulation, which knows the robot's links.
 */
public final class WorldBodies {
  private final Map<String, Integer> handleByName = new LinkedHashMap<>();

  /** Adds every object of {@code world} to {@code collision}. */
  public WorldBodies(World world, CollisionWorld collision) {
    for (WorldObject o : world.objects()) {
      Body body = switch (o.kind()) {
        case FIXTURE -> Body.fixture(o.name(), o.name());
        case PART -> Body.part(o.name(), o.name());
      };
      handleByName.put(o.name(), collision.add(body, world.collisionBox(o.name())));
    }
  }

  /** The collision handle of an object. */
  public int handle(String objectName) {
    Integer h = handleByName.get(objectName);
    if (h == null) {
      throw new IllegalArgumentException("no object named '" + objectName + "'");
    }
    return h;
  }

  /** Moves every object's box to where {@code world} has it now (same objects as at construction). */
  public void sync(World world, CollisionWorld collision) {
    for (Map.Entry<String, Integer> e : handleByName.entrySet()) {
      collision.setBox(e.getValue(), world.collisionBox(e.getKey()));
    }
  }
}
