package org.robotrun.program;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A motion port for tests: every motion takes {@code motionTimeSec} of simulated time (advanced
 * by {@link #advance(double)}), requests are recorded, and a local position taught in other
 * frames than the active ones is rejected as a frame mismatch, as the controller's port does.
 */
public final class FakeMotionPort implements MotionPort {
  /** Code the fake uses for a frame mismatch. */
  public static final String FRAME_MISMATCH = "MOTN-FRAME";

  private final double motionTimeSec;
  private final List<MotionRequest> requests = new ArrayList<>();
  private final Map<Long, Double> remaining = new HashMap<>();
  private final Map<Long, Boolean> held = new HashMap<>();
  private final Map<Long, MotionRequest> byHandle = new HashMap<>();
  private final EnumMap<Instruction.FrameKind, Integer> active = new EnumMap<>(Instruction.FrameKind.class);
  private final Map<String, Position.Cartesian> frames = new HashMap<>();
  private long nextHandle = 1;
  private int overridePct = 100;
  private Position lastPosition = Position.Joint.ZERO;
  private final List<Long> cancelled = new ArrayList<>();
  /** When set, the next motion fails while running with this reason. */
  private Start.Rejected failNext;

  public FakeMotionPort(double motionTimeSec) {
    this.motionTimeSec = motionTimeSec;
    active.put(Instruction.FrameKind.USER, 0);
    active.put(Instruction.FrameKind.TOOL, 0);
  }

  /** Advances simulated time for motions that are not held. */
  public void advance(double dtSec) {
    for (Map.Entry<Long, Double> e : remaining.entrySet()) {
      if (!held.getOrDefault(e.getKey(), false) && e.getValue() > 0) {
        double left = e.getValue() - dtSec;
        e.setValue(left);
        if (left <= 1e-9) {
          lastPosition = byHandle.get(e.getKey()).target().position();
        }
      }
    }
  }

  public List<MotionRequest> requests() {
    return requests;
  }

  public List<Long> cancelled() {
    return cancelled;
  }

  public void failNextMotion(String code, String message) {
    failNext = new Start.Rejected(code, message);
  }

  @Override
  public Start startMotion(MotionRequest request) {
    requests.add(request);
    MotionRequest.Waypoint t = request.target();
    int uf = active.get(Instruction.FrameKind.USER);
    int ut = active.get(Instruction.FrameKind.TOOL);
    if (t.position() instanceof Position.Cartesian && (t.userFrame() != uf || t.toolFrame() != ut)) {
      return new Start.Rejected(FRAME_MISMATCH, t.name() + " is taught in UF " + t.userFrame() + ", UT "
          + t.toolFrame() + " but UF " + uf + ", UT " + ut + " are active");
    }
    long h = nextHandle++;
    remaining.put(h, motionTimeSec);
    byHandle.put(h, request);
    if (motionTimeSec <= 0) {
      lastPosition = t.position();
    }
    return new Start.Started(h);
  }

  private final Map<Long, Start.Rejected> failures = new HashMap<>();

  @Override
  public Status poll(long handle) {
    if (failNext != null) {
      failures.put(handle, failNext);
      failNext = null;
      remaining.remove(handle);
      return Status.FAILED;
    }
    if (failures.containsKey(handle)) {
      return Status.FAILED;
    }
    Double left = remaining.get(handle);
    if (left == null) {
      throw new IllegalStateException("unknown or cancelled handle " + handle);
    }
    return left <= 1e-9 ? Status.DONE : Status.RUNNING;
  }

  /** The motion's time left (for TIME BEFORE): what the fake still has to run, 0 once done or cancelled. */
  @Override
  public double timeLeftSec(long handle) {
    Double left = remaining.get(handle);
    return left == null ? 0 : Math.max(0, left);
  }

  @Override
  public Start.Rejected failure(long handle) {
    return failures.get(handle);
  }

  @Override
  public void hold(long handle) {
    held.put(handle, true);
  }

  @Override
  public void resume(long handle) {
    held.put(handle, false);
  }

  public boolean isHeld(long handle) {
    return held.getOrDefault(handle, false);
  }

  @Override
  public void cancel(long handle) {
    remaining.remove(handle);
    cancelled.add(handle);
  }

  @Override
  public Position.Cartesian currentLpos() {
    return lastPosition instanceof Position.Cartesian c ? c : new Position.Cartesian(1, 2, 3, 4, 5, 6, Config.DEFAULT);
  }

  @Override
  public Position.Joint currentJpos() {
    return lastPosition instanceof Position.Joint j ? j : new Position.Joint(10, 20, 30, 40, 50, 60);
  }

  @Override
  public int activeFrame(Instruction.FrameKind kind) {
    return active.get(kind);
  }

  @Override
  public void selectFrame(Instruction.FrameKind kind, int number) {
    active.put(kind, number);
  }

  @Override
  public Position.Cartesian frame(Instruction.FrameKind kind, int number) {
    return frames.getOrDefault(kind + ":" + number, Position.Cartesian.ZERO);
  }

  @Override
  public void setFrame(Instruction.FrameKind kind, int number, Position.Cartesian value) {
    frames.put(kind + ":" + number, value);
  }

  @Override
  public int overridePct() {
    return overridePct;
  }

  @Override
  public void setOverridePct(int percent) {
    overridePct = percent;
  }
}
