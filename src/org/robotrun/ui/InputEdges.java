package org.robotrun.ui;

import java.util.ArrayDeque;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Press and release edges of buttons and keys, queued as they arrive and handed to the UI one
 * edge per button per frame. A panel that samples "is it down now?" once a frame then sees every
 * press, even one released within the same frame (a tap on a touch screen, a click over a remote
 * desktop), as one frame down and the next frame up. Only the last edge is dropped if a button
 * flips more than {@link #MAX_QUEUED} times before the UI draws.
 */
public final class InputEdges {
  static final int MAX_QUEUED = 16;

  private final Map<Integer, ArrayDeque<Boolean>> queued = new LinkedHashMap<>();
  private final Map<Integer, Boolean> last = new LinkedHashMap<>();

  /** Callback: one state to apply for {@code id} this frame. */
  @FunctionalInterface
  public interface Sink {
    void set(int id, boolean down);
  }

  /** An edge arrived (from an input callback). Repeats of the same state are ignored. */
  public void record(int id, boolean down) {
    ArrayDeque<Boolean> q = queued.computeIfAbsent(id, k -> new ArrayDeque<>());
    Boolean tail = q.isEmpty() ? last.get(id) : q.peekLast();
    if (tail != null && tail == down) {
      return;
    }
    if (q.size() < MAX_QUEUED) {
      q.addLast(down);
    }
  }

  /**
   * Once per frame, before the UI reads its input: gives each button with queued edges its
   * next state. Returns whether edges are still waiting (the window should draw another frame
   * soon rather than sleep).
   */
  public boolean apply(Sink sink) {
    boolean more = false;
    for (var e : queued.entrySet()) {
      ArrayDeque<Boolean> q = e.getValue();
      if (!q.isEmpty()) {
        boolean down = q.pollFirst();
        last.put(e.getKey(), down);
        sink.set(e.getKey(), down);
        more |= !q.isEmpty();
      }
    }
    return more;
  }

  /** Whether no edge is waiting. */
  public boolean isEmpty() {
    return queued.values().stream().allMatch(ArrayDeque::isEmpty);
  }
}
