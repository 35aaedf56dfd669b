package org.robotrun.world;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.robotrun.collision.Obb;
import org.robotrun.math.Transform;

/**
 * The objects of a cell, by name, as an immutable value. Poses may be relative to a parent
 * fixture; {@link #poseInCell} follows the chain. Construction checks that names are unique
 * and that every parent exists, is a fixture and that no chain loops.
 */
public final class World {
  private final Map<String, WorldObject> byName;

  public World(List<WorldObject> objects) {
    Map<String, WorldObject> m = new LinkedHashMap<>();
    for (WorldObject o : objects) {
      if (m.put(o.name(), o) != null) {
        throw new IllegalArgumentException("two objects are named '" + o.name() + "'");
      }
    }
    for (WorldObject o : objects) {
      checkParents(m, o);
    }
    this.byName = java.util.Collections.unmodifiableMap(m);
  }

  /** A world with no objects. */
  public static World empty() {
    return new World(List.of());
  }

  private static void checkParents(Map<String, WorldObject> m, WorldObject o) {
    Set<String> seen = new HashSet<>();
    seen.add(o.name());
    for (Optional<String> p = o.parent(); p.isPresent(); ) {
      WorldObject parent = m.get(p.get());
      if (parent == null) {
        throw new IllegalArgumentException(o.name() + ": parent '" + p.get() + "' does not exist");
      }
      if (parent.kind() != ObjectKind.FIXTURE) {
        throw new IllegalArgumentException(o.name() + ": parent '" + p.get() + "' is not a fixture");
      }
      if (!seen.add(parent.name())) {
        throw new IllegalArgumentException(o.name() + ": parents form a loop through '" + parent.name() + "'");
      }
      p = parent.parent();
    }
  }

  /** The objects in the order they were given. */
  public List<WorldObject> objects() {
    return List.copyOf(byName.values());
  }

  public Optional<WorldObject> find(String name) {
    return Optional.ofNullable(byName.get(name));
  }

  /** The object's pose in the cell {@code X_CO} (mm), following parent fixtures. */
  public Transform poseInCell(String name) {
    WorldObject o = byName.get(name);
    if (o == null) {
      throw new IllegalArgumentException("no object named '" + name + "'");
    }
    Transform X_CO = o.pose();
    for (Optional<String> p = o.parent(); p.isPresent(); p = byName.get(p.get()).parent()) {
      X_CO = byName.get(p.get()).pose().compose(X_CO);
    }
    return X_CO;
  }

  /** The object's collision box in the cell. */
  public Obb collisionBox(String name) {
    return byName.get(name).shape().collisionBox(poseInCell(name));
  }

  /** This world with one object replaced by {@code moved} (same name). */
  public World with(WorldObject moved) {
    if (!byName.containsKey(moved.name())) {
      throw new IllegalArgumentException("no object named '" + moved.name() + "'");
    }
    List<WorldObject> out = new ArrayList<>(byName.values());
    out.replaceAll(o -> o.name().equals(moved.name()) ? moved : o);
    return new World(out);
  }

  /** Every object back at its start pose and parent ("reset scene"). */
  public World reset() {
    return new World(byName.values().stream().map(WorldObject::atStart).toList());
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof World w && objects().equals(w.objects());
  }

  @Override
  public int hashCode() {
    return objects().hashCode();
  }

  @Override
  public String toString() {
    return "World" + objects();
  }
}
