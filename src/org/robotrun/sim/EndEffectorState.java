package org.robotrun.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.world.EndEffectorGeometry;

/**
 * One robot's end effector as it is now: switched on or off, how far its fingers (or vacuum)
 * have got, the part it holds and, for a process tool, the trace it has left. {@link CellState}
 * changes it; the draw list and the collision check read it. Mutable, owned by the simulation.
 */
final class EndEffectorState {
  /** Time for fingers to close or open, or for the vacuum to build or drop (s). */
  static final double ACTUATION_SEC = 0.1;
  /** Finger clearance left on each side of a held part (mm), so the released part does not touch them. */
  static final double FINGER_CLEARANCE_MM = 0.5;
  /** A process tool adds a trace point when its TCP has moved this far (mm). */
  static final double TRACE_STEP_MM = 2;
  /** Trace segments kept; the oldest are dropped beyond this. */
  static final int MAX_TRACE_SEGMENTS = 2000;

  /** A part held: its name and its pose in the flange frame, fixed at the grip ({@code X_FP}). */
  record Held(String part, Transform X_FP, double widthMm) {}

  /** One straight piece of a process trace, in the cell frame (mm). */
  record TraceSegment(Vec3 from, Vec3 to) {}

  final String robot;
  final EndEffectorGeometry geometry;
  final org.robotrun.world.ToolIo io;
  private boolean on;
  /** 0 = open (or no vacuum) … 1 = closed (vacuum on); moves at 1 / {@link #ACTUATION_SEC}. */
  private double closedFraction;
  private Optional<Held> held = Optional.empty();
  /** Where the fingers stop closing (mm): on the part gripped last, until they are open again. */
  private double stopGapMm;
  private final java.util.ArrayDeque<TraceSegment> trace = new java.util.ArrayDeque<>();
  private Vec3 lastTracePoint;

  EndEffectorState(String robot, EndEffectorGeometry geometry) {
    this(robot, MountedTool.of(geometry));
  }

  EndEffectorState(String robot, MountedTool tool) {
    this.robot = robot;
    this.geometry = tool.geometry();
    this.io = tool.io();
  }

  boolean on() {
    return on;
  }

  void setOn(boolean on) {
    this.on = on;
    lastTracePoint = null;
  }

  /** Advances the fingers or vacuum towards the commanded state; returns whether they moved. */
  boolean actuate(double dtSec) {
    double target = on ? 1 : 0;
    if (closedFraction == target) {
      return false;
    }
    double step = dtSec / ACTUATION_SEC;
    // A small epsilon so 25 ticks of 4 ms complete 0.1 s despite rounding.
    closedFraction = on ? Math.min(1, closedFraction + step + 1e-9) : Math.max(0, closedFraction - step - 1e-9);
    if (closedFraction == 0 && held.isEmpty()) {
      stopGapMm = 0;
    }
    return true;
  }

  /** Whether the fingers or vacuum have reached the commanded state. */
  boolean settled() {
    return closedFraction == (on ? 1 : 0);
  }

  double closedFraction() {
    return closedFraction;
  }

  /** The gap between the fingers' inner faces now (mm): they stop on a held part. */
  double fingerGapMm() {
    double open = EndEffectorGeometry.FINGER_OPEN_GAP_MM;
    return open - closedFraction * (open - stopGapMm);
  }

  Optional<Held> held() {
    return held;
  }

  void hold(Held h) {
    held = Optional.of(h);
    stopGapMm = Math.min(EndEffectorGeometry.FINGER_OPEN_GAP_MM, h.widthMm() + 2 * FINGER_CLEARANCE_MM);
  }

  void release() {
    held = Optional.empty();
  }

  /** Adds the TCP position {@code p_CT} to the trace while the tool is on. */
  void extendTrace(Vec3 p_CT) {
    if (lastTracePoint == null) {
      lastTracePoint = p_CT;
      return;
    }
    if (lastTracePoint.distanceTo(p_CT) >= TRACE_STEP_MM) {
      trace.addLast(new TraceSegment(lastTracePoint, p_CT));
      if (trace.size() > MAX_TRACE_SEGMENTS) {
        trace.removeFirst();
      }
      lastTracePoint = p_CT;
    }
  }

  List<TraceSegment> trace() {
    return new ArrayList<>(trace);
  }

  /** Back to the start: open, nothing held, no trace (the output is read again next tick). */
  void reset() {
    held = Optional.empty();
    stopGapMm = 0;
    trace.clear();
    lastTracePoint = null;
  }
}
