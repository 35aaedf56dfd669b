package org.robotrun.collision;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.robotrun.math.Transform;

/**
 * The collision boxes of a cell and the query "which pairs touch now".
 *
 * <p>Bodies are added once (robot link boxes, end-effector boxes, fixtures, parts) and get an
 * integer handle; each tick the owner moves them with {@link #setPose} and calls
 * {@link #update()}. The broad phase is sort-and-sweep on world-axis-aligned bounds along x:
 * the order from the last tick is repaired by insertion sort, which is linear when little
 * moved. Pairs whose bounds overlap in x, y and z and that the {@link PairFilter} allows go to
 * the {@link SeparatingAxisTest}. The filter's answers are cached for the pairs the sweep meets
 * (a hash table of candidate pairs, not an n×n table: memory grows with the bodies, and is
 * capped at {@link #MAX_CACHED_PER_BODY} pairs per body, beyond which the filter is simply
 * asked again) until {@link #setFilter} is called again. The first update after bodies were
 * added sorts them in full (n log n); later ones repair the order by insertion sort, and fall
 * back to a full sort when that would cost more. Once every pair has been asked and the buffers
 * have grown to their working size, {@code setPose} and {@code update} allocate nothing.
 *
 * <p>Not thread-safe: one simulation owns one world.
 */
public final class CollisionWorld {
  private static final double BOUNDS_MARGIN_MM = 1000 * SeparatingAxisTest.CONTACT_TOLERANCE_MM;

  private final List<Body> bodies = new ArrayList<>();
  private double[] boxes = new double[16 * Obb.STRIDE];
  /** Axis-aligned bounds per body: minX, maxX, minY, maxY, minZ, maxZ. */
  private double[] bounds = new double[16 * 6];
  /** {@link #bounds} copied into {@link #order}'s order at each update. */
  private double[] sortedBounds = new double[16 * 6];
  /** Body handles sorted by minX (kept between updates). */
  private int[] order = new int[16];
  private boolean[] touching = new boolean[16];
  private int[] contactPairs = new int[64];
  private int contactCount;
  private PairFilter filter;
  /**
   * The filter's answer per candidate pair, {@link #CHECK} or {@link #SKIP}, kept until
   * {@link #setFilter}: parts lying on tables are near each other every tick, and asking again
   * would cost more than the whole sweep. Open addressing on the key {@code lo << 32 | hi};
   * {@link #EMPTY} marks a free slot.
   */
  private long[] ruleKeys = emptyKeys(1 << 10);
  private byte[] ruleValues = new byte[1 << 10];
  private int ruleCount;
  private static final long EMPTY = -1;
  private static final byte CHECK = 1;
  private static final byte SKIP = 2;

  /** Cached filter answers allowed per body (plus a fixed floor), so memory stays linear in bodies. */
  public static final int MAX_CACHED_PER_BODY = 16;
  private static final int MIN_CACHED = 1 << 16;

  /** Whether bodies were added since the last full sort of {@link #order}. */
  private boolean needsFullSort;

  /** An empty world checking pairs with {@code filter}. */
  public CollisionWorld(PairFilter filter) {
    this.filter = filter;
  }

  /** Adds a body with its box in WORLD and returns its handle (0, 1, 2, … in order of adding). */
  public int add(Body body, Obb box_W) {
    int h = bodies.size();
    if (h == order.length) {
      int n = 2 * h;
      boxes = Arrays.copyOf(boxes, n * Obb.STRIDE);
      bounds = Arrays.copyOf(bounds, n * 6);
      order = Arrays.copyOf(order, n);
      touching = Arrays.copyOf(touching, n);
    }
    needsFullSort = true;
    bodies.add(body);
    box_W.writeTo(boxes, h);
    order[h] = h;
    return h;
  }

  /** Replaces the pair filter, e.g. when a part is gripped or released. */
  public void setFilter(PairFilter filter) {
    this.filter = filter;
    Arrays.fill(ruleKeys, EMPTY);
    ruleCount = 0;
  }

  /** Bytes held by the pair-rule cache (for the broad-phase memory figure in docs). */
  public long cacheBytes() {
    return (long) ruleKeys.length * (Long.BYTES + 1);
  }

  public int size() {
    return bodies.size();
  }

  public Body body(int handle) {
    return bodies.get(handle);
  }

  /** The body's current box in WORLD. */
  public Obb box(int handle) {
    check(handle);
    return Obb.readFrom(boxes, handle);
  }

  /** Moves a body: its new box in WORLD (the half extents are taken from {@code box_W}). */
  public void setBox(int handle, Obb box_W) {
    check(handle);
    box_W.writeTo(boxes, handle);
  }

  /**
   * Moves a body whose box sits at {@code X_LB} in a moving frame L (a link) that is now at
   * {@code X_WL}; keeps the half extents. Composes in place, without allocating.
   */
  public void setPose(int handle, Transform X_WL, Transform X_LB) {
    check(handle);
    Transform a = X_WL;
    Transform b = X_LB;
    int o = handle * Obb.STRIDE;
    double[] f = boxes;
    // X_WB = X_WL · X_LB: centre p_W = R_WL·p_LB + p_WL, axes R_WB = R_WL·R_LB.
    f[o] = a.r00() * b.x() + a.r01() * b.y() + a.r02() * b.z() + a.x();
    f[o + 1] = a.r10() * b.x() + a.r11() * b.y() + a.r12() * b.z() + a.y();
    f[o + 2] = a.r20() * b.x() + a.r21() * b.y() + a.r22() * b.z() + a.z();
    f[o + 6] = a.r00() * b.r00() + a.r01() * b.r10() + a.r02() * b.r20();
    f[o + 7] = a.r00() * b.r01() + a.r01() * b.r11() + a.r02() * b.r21();
    f[o + 8] = a.r00() * b.r02() + a.r01() * b.r12() + a.r02() * b.r22();
    f[o + 9] = a.r10() * b.r00() + a.r11() * b.r10() + a.r12() * b.r20();
    f[o + 10] = a.r10() * b.r01() + a.r11() * b.r11() + a.r12() * b.r21();
    f[o + 11] = a.r10() * b.r02() + a.r11() * b.r12() + a.r12() * b.r22();
    f[o + 12] = a.r20() * b.r00() + a.r21() * b.r10() + a.r22() * b.r20();
    f[o + 13] = a.r20() * b.r01() + a.r21() * b.r11() + a.r22() * b.r21();
    f[o + 14] = a.r20() * b.r02() + a.r21() * b.r12() + a.r22() * b.r22();
  }

  /** Runs the check for the current poses; returns the number of touching pairs. */
  public int update() {
    int n = bodies.size();
    computeBounds(n);
    sortByMinX(n);
    gatherSortedBounds(n);
    Arrays.fill(touching, 0, n, false);
    contactCount = 0;
    double[] sb = sortedBounds;
    for (int s = 0; s < n; s++) {
      int o = s * 6;
      double maxX = sb[o + 1], minY = sb[o + 2], maxY = sb[o + 3], minZ = sb[o + 4], maxZ = sb[o + 5];
      // Candidates follow in minX order; the first one starting beyond maxX ends the run.
      for (int u = s + 1; u < n; u++) {
        int q = u * 6;
        if (sb[q] > maxX) {
          break;
        }
        if (sb[q + 2] > maxY || minY > sb[q + 3] || sb[q + 4] > maxZ || minZ > sb[q + 5]) {
          continue;
        }
        int i = order[s];
        int j = order[u];
        int lo = Math.min(i, j);
        int hi = Math.max(i, j);
        if (mayCollide(lo, hi) && SeparatingAxisTest.overlap(boxes, i, boxes, j)) {
          addContact(lo, hi);
        }
      }
    }
    return contactCount;
  }

  // The bounds in sweep order, so the inner loop reads memory front to back.
  private void gatherSortedBounds(int n) {
    if (sortedBounds.length < n * 6) {
      sortedBounds = new double[order.length * 6];
    }
    for (int s = 0; s < n; s++) {
      System.arraycopy(bounds, order[s] * 6, sortedBounds, s * 6, 6);
    }
  }

  /**
   * The bodies whose boxes overlap or touch {@code probe_W} and that {@code accept} lets
   * through, by handle, at their current poses (no {@link #update()} needed). For one-off
   * questions such as "which part is inside the gripper's pickup zone"; allocates its result.
   */
  public List<Integer> overlapping(Obb probe_W, java.util.function.Predicate<Body> accept) {
    double[] probe = new double[Obb.STRIDE];
    probe_W.writeTo(probe, 0);
    List<Integer> out = new ArrayList<>();
    for (int h = 0; h < bodies.size(); h++) {
      if (accept.test(bodies.get(h)) && SeparatingAxisTest.overlap(probe, 0, boxes, h)) {
        out.add(h);
      }
    }
    return out;
  }

  /** Number of touching pairs found by the last {@link #update()}. */
  public int contactCount() {
    return contactCount;
  }

  /** Handle of the first body of contact {@code k} (the smaller handle). */
  public int contactA(int k) {
    return contactPairs[2 * k];
  }

  /** Handle of the second body of contact {@code k} (the larger handle). */
  public int contactB(int k) {
    return contactPairs[2 * k + 1];
  }

  /** Whether the body touched anything (that the filter allows) at the last update: red or green. */
  public boolean isTouching(int handle) {
    check(handle);
    return touching[handle];
  }

  /** The touching pairs of the last update, ordered by handles (allocates; for reports). */
  public List<Contact> contacts() {
    long[] keys = new long[contactCount];
    for (int k = 0; k < contactCount; k++) {
      keys[k] = ((long) contactA(k) << 32) | contactB(k);
    }
    Arrays.sort(keys);
    List<Contact> out = new ArrayList<>(contactCount);
    for (long key : keys) {
      out.add(new Contact(bodies.get((int) (key >>> 32)), bodies.get((int) key)));
    }
    return out;
  }

  private boolean mayCollide(int lo, int hi) {
    long key = ((long) lo << 32) | hi;
    int mask = ruleKeys.length - 1;
    int slot = mix(key) & mask;
    while (true) {
      long k = ruleKeys[slot];
      if (k == key) {
        return ruleValues[slot] == CHECK;
      }
      if (k == EMPTY) {
        break;
      }
      slot = (slot + 1) & mask;
    }
    boolean check = filter.mayCollide(bodies.get(lo), bodies.get(hi));
    long cap = Math.max(MIN_CACHED, (long) MAX_CACHED_PER_BODY * bodies.size());
    if (ruleCount < cap) {
      if (2 * (ruleCount + 1) > ruleKeys.length) {
        growRules();
        mask = ruleKeys.length - 1;
        slot = mix(key) & mask;
        while (ruleKeys[slot] != EMPTY) {
          slot = (slot + 1) & mask;
        }
      }
      ruleKeys[slot] = key;
      ruleValues[slot] = check ? CHECK : SKIP;
      ruleCount++;
    }
    return check;
  }

  private void growRules() {
    long[] oldKeys = ruleKeys;
    byte[] oldValues = ruleValues;
    ruleKeys = emptyKeys(2 * oldKeys.length);
    ruleValues = new byte[2 * oldKeys.length];
    int mask = ruleKeys.length - 1;
    for (int i = 0; i < oldKeys.length; i++) {
      if (oldKeys[i] != EMPTY) {
        int slot = mix(oldKeys[i]) & mask;
        while (ruleKeys[slot] != EMPTY) {
          slot = (slot + 1) & mask;
        }
        ruleKeys[slot] = oldKeys[i];
        ruleValues[slot] = oldValues[i];
      }
    }
  }

  private static long[] emptyKeys(int n) {
    long[] k = new long[n];
    Arrays.fill(k, EMPTY);
    return k;
  }

  /** A 64-bit finaliser (the MurmurHash3 fmix64 constants), so nearby handle pairs spread out. */
  private static int mix(long key) {
    long h = key;
    h ^= h >>> 33;
    h *= 0xff51afd7ed558ccdL;
    h ^= h >>> 33;
    h *= 0xc4ceb9fe1a85ec53L;
    h ^= h >>> 33;
    return (int) h;
  }

  private void addContact(int a, int b) {
    if (2 * contactCount + 2 > contactPairs.length) {
      contactPairs = Arrays.copyOf(contactPairs, 2 * contactPairs.length);
    }
    contactPairs[2 * contactCount] = a;
    contactPairs[2 * contactCount + 1] = b;
    contactCount++;
    touching[a] = true;
    touching[b] = true;
  }

  // World-axis bounds of each box: half width along world x is sum_k |R[0][k]|·h_k, etc.
  private void computeBounds(int n) {
    double[] f = boxes;
    for (int i = 0; i < n; i++) {
      int o = i * Obb.STRIDE;
      double hx = f[o + 3], hy = f[o + 4], hz = f[o + 5];
      double ex = Math.abs(f[o + 6]) * hx + Math.abs(f[o + 7]) * hy + Math.abs(f[o + 8]) * hz;
      double ey = Math.abs(f[o + 9]) * hx + Math.abs(f[o + 10]) * hy + Math.abs(f[o + 11]) * hz;
      double ez = Math.abs(f[o + 12]) * hx + Math.abs(f[o + 13]) * hy + Math.abs(f[o + 14]) * hz;
      // Widen far beyond the contact tolerance so that every pair the SAT calls touching stays
      // a candidate (the SAT's gap is measured along its own axes, not world x, y, z).
      double m = BOUNDS_MARGIN_MM;
      int b = i * 6;
      bounds[b] = f[o] - ex - m;
      bounds[b + 1] = f[o] + ex + m;
      bounds[b + 2] = f[o + 1] - ey - m;
      bounds[b + 3] = f[o + 1] + ey + m;
      bounds[b + 4] = f[o + 2] - ez - m;
      bounds[b + 5] = f[o + 2] + ez + m;
    }
  }

  // Insertion sort on minX: linear when the order barely changed since the last tick; a full
  // sort after bodies were added, or when the insertion sort has shifted more than a few passes.
  private void sortByMinX(int n) {
    if (needsFullSort) {
      fullSort(n);
      return;
    }
    long budget = 8L * n + 1024;
    for (int s = 1; s < n; s++) {
      int h = order[s];
      double key = bounds[h * 6];
      int u = s - 1;
      while (u >= 0 && bounds[order[u] * 6] > key) {
        order[u + 1] = order[u];
        u--;
        if (--budget < 0) {
          order[u + 1] = h;
          fullSort(n);
          return;
        }
      }
      order[u + 1] = h;
    }
  }

  private void fullSort(int n) {
    Integer[] handles = new Integer[n];
    for (int s = 0; s < n; s++) {
      handles[s] = order[s];
    }
    Arrays.sort(handles, (a, b) -> Double.compare(bounds[a * 6], bounds[b * 6]));
    for (int s = 0; s < n; s++) {
      order[s] = handles[s];
    }
    needsFullSort = false;
  }

  private void check(int handle) {
    if (handle < 0 || handle >= bodies.size()) {
      throw new IndexOutOfBoundsException("no collision body with handle " + handle);
    }
  }
}
