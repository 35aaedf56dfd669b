package org.robotrun.world;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
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
  private final List<WorldObject> objects;
  /** Poses in the cell, filled on demand; a world is immutable, so they never go stale. */
  private final Map<String, Transform> poseCache = new java.util.concurrent.ConcurrentHashMap<>();

  public World(List<WorldObject> objects) {
    Map<String, WorldObject> m = new LinkedHashMap<>();
    for (WorldObject o : objects) {
      if (m.put(o.name(), o) != null) {
        throw new IllegalArgumentException("two objects are named '" + o.name() + "'");
      }
    }
    // Each chain is followed once: a walk stops at an object an earlier walk has cleared, so
    // checking 100 000 objects in one long chain is linear, not quadratic.
    Set<String> cleared = new HashSet<>();
    for (WorldObject o : objects) {
      checkParents(m, o, cleared);
    }
    this.byName = java.util.Collections.unmodifiableMap(m);
    this.objects = List.copyOf(m.values());
  }

  /** A world with no objects. */
  public static World empty() {
    return new World(List.of());
  }

  private static void checkParents(Map<String, WorldObject> m, WorldObject o, Set<String> cleared) {
    Set<String> seen = new LinkedHashSet<>();
    seen.add(o.name());
    for (Optional<String> p = o.parent(); p.isPresent(); ) {
      WorldObject parent = m.get(p.get());
      if (parent == null) {
        throw new IllegalArgumentException(o.name() + ": parent '" + p.get() + "' does not exist");
      }
      if (parent.kind() != ObjectKind.FIXTURE) {
        throw new IllegalArgumentException(o.name() + ": parent '" + p.get() + "' is not a fixture");
      }
      if (cleared.contains(parent.name())) {
        break;  // its chain above was checked already
      }
      if (!seen.add(parent.name())) {
        throw new IllegalArgumentException(o.name() + ": parents form a loop through '" + parent.name() + "'");
      }
      p = parent.parent();
    }
    cleared.addAll(seen);
  }

  /** The objects in the order they were given. */
  public List<WorldObject> objects() {
    return objects;
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
    Transform cached = poseCache.get(name);
    if (cached != null) {
      return cached;
    }
    // Walk up to the first object whose pose is known (or the cell), then come back down
    // composing, caching every pose on the way: linear over all objects, however deep the chains.
    List<WorldObject> chain = new ArrayList<>();
    Transform X_CP = null;  // null: the cell itself
    for (WorldObject at = o; ; ) {
      Transform known = poseCache.get(at.name());
      if (known != null) {
        X_CP = known;
        break;
      }
      chain.add(at);
      if (at.parent().isEmpty()) {
        break;
      }
      at = byName.get(at.parent().get());
    }
    for (int i = chain.size() - 1; i >= 0; i--) {
      WorldObject c = chain.get(i);
      X_CP = X_CP == null ? c.pose() : X_CP.compose(c.pose());
      poseCache.put(c.name(), X_CP);
    }
    return X_CP;
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
