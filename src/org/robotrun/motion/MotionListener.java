package org.robotrun.motion;

/** What the {@link MotionRunner} reports while it runs moves (simulated time in seconds). */
public interface MotionListener {

  /** The move started (for a blended move: when its blend began). */
  void moveStarted(long tag, double simTimeSec);

  /** The move reached its end point. */
  void moveFinished(long tag, double simTimeSec);

  /**
   * The move cannot be followed (joint limit, unreachable point, singularity, bad geometry):
   * the robot has stopped where it was and every queued move is dropped.
   */
  void moveFailed(long tag, MotionFault fault);

  /** A listener that ignores everything (tests, jog-only use). */
  MotionListener NONE = new MotionListener() {
    @Override
    public void moveStarted(long tag, double simTimeSec) {}

    @Override
    public void moveFinished(long tag, double simTimeSec) {}

    @Override
    public void moveFailed(long tag, MotionFault fault) {}
  };
}
