package org.robotrun.program;

/**
 * How the interpreter reaches the robot (implemented by the controller in {@code sim}; a fake
 * serves the tests). The port owns the controller state a program shares with the pendant:
 * active frame numbers, frame data, speed override. Positions cross it in the program's units
 * (mm, degrees).
 */
public interface MotionPort {

  /**
   * Starts (queues) a motion. A port that cannot take it — frame mismatch, unreachable target,
   * bad speed — answers {@link Start.Rejected}; the interpreter raises it as an alarm.
   */
  Start startMotion(MotionRequest request);

  /**
   * How motion {@code handle} stands. {@link Status#DONE} means the program may go on: at the
   * end point for FINE, once blending begins for CNT.
   */
  Status poll(long handle);

  /**
   * Seconds until running motion {@code handle} reaches its end point (TIME BEFORE actions fire
   * by it); infinite when the port cannot tell, so such an action fires when the motion is done.
   */
  default double timeLeftSec(long handle) {
    return Double.POSITIVE_INFINITY;
  }

  /**
   * Straight-line distance in mm from the TCP to the end point of motion {@code handle}
   * (DISTANCE BEFORE actions fire by it); infinite when the port cannot tell.
   */
  default double distanceLeftMm(long handle) {
    return Double.POSITIVE_INFINITY;
  }

  /** The reason motion {@code handle} failed, valid after {@link #poll} answered FAILED. */
  Start.Rejected failure(long handle);

  /** HOLD: decelerates motion {@code handle} to a stop; it stays resumable. */
  void hold(long handle);

  /** Resumes a held motion. */
  void resume(long handle);

  /** Abandons motion {@code handle} (program aborted or alarmed). */
  void cancel(long handle);

  /** The current TCP position as LPOS: in the active user and tool frames. */
  Position.Cartesian currentLpos();

  /** The current joint position as JPOS. */
  Position.Joint currentJpos();

  /** The active user frame ({@code USER}) or tool frame ({@code TOOL}) number, 0..10. */
  int activeFrame(Instruction.FrameKind kind);

  /** Selects the active user or tool frame (UFRAME_NUM / UTOOL_NUM); 0..10. */
  void selectFrame(Instruction.FrameKind kind, int number);

  /** Frame data UFRAME[n] / UTOOL[n], n = 1..10. */
  Position.Cartesian frame(Instruction.FrameKind kind, int number);

  /** Sets UFRAME[n] / UTOOL[n], n = 1..10. */
  void setFrame(Instruction.FrameKind kind, int number, Position.Cartesian value);

  /** The speed override in percent, 1..100. */
  int overridePct();

  /** Sets the speed override (OVERRIDE=n%), 1..100. */
  void setOverridePct(int percent);

  /** Outcome of {@link #startMotion}. */
  sealed interface Start {
    /** The motion is under way; poll it with {@code handle}. */
    record Started(long handle) implements Start {}

    /** The port refused or failed the motion; {@code code} is FANUC-style (e.g. {@code MOTN-017}). */
    record Rejected(String code, String message) implements Start {}
  }

  /** State of a started motion. */
  enum Status {
    RUNNING, DONE, FAILED
  }
}
