package org.robotrun.program;

import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * Vision registers VR[1..10] and, per vision process, the results of its last RUN_FIND that
 * GET_OFFSET has not fetched yet (iRVision keeps them in the process; each GET_OFFSET takes the
 * next one).
 */
public final class VisionRegisters {
  /** VR[1..COUNT], iRVision's default number of vision registers. */
  public static final int COUNT = 10;

  private final VisionResult[] vr = new VisionResult[COUNT + 1];
  private final Map<String, ArrayDeque<VisionResult>> pending = new HashMap<>();
  private final Map<String, Integer> found = new HashMap<>();

  /** VR[i], empty until a GET_OFFSET filled it. */
  public Optional<VisionResult> get(int i) {
    check(i);
    return Optional.ofNullable(vr[i]);
  }

  /** Sets VR[i] (GET_OFFSET; tests). */
  public void set(int i, VisionResult r) {
    check(i);
    vr[i] = r;
  }

  /** Clears VR[i]. */
  public void clear(int i) {
    check(i);
    vr[i] = null;
  }

  /** Records a RUN_FIND's results, replacing what the process had. */
  void stored(String process, List<VisionResult> results) {
    String key = process.toUpperCase(Locale.ROOT);
    pending.put(key, new ArrayDeque<>(results));
    found.put(key, results.size());
  }

  /** How many parts the process's last RUN_FIND found; empty when it has not run. */
  public Optional<Integer> found(String process) {
    return Optional.ofNullable(found.get(process.toUpperCase(Locale.ROOT)));
  }

  /** The next result GET_OFFSET takes (removed); empty when none is left; null when the process has not run. */
  Optional<VisionResult> next(String process) {
    ArrayDeque<VisionResult> q = pending.get(process.toUpperCase(Locale.ROOT));
    return q == null ? null : Optional.ofNullable(q.poll());
  }

  /** Every register and result cleared (a new scene). */
  public void clearAll() {
    java.util.Arrays.fill(vr, null);
    pending.clear();
    found.clear();
  }

  private static void check(int i) {
    if (i < 1 || i > COUNT) {
      throw new IllegalArgumentException("VR[" + i + "]: expected 1.." + COUNT);
    }
  }
}
