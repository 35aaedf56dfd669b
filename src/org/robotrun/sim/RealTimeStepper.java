package org.robotrun.sim;

/**
 * Keeps a simulation in step with real time for the GUI without the simulation ever reading a
 * clock: the caller passes the wall time that elapsed since its last frame, and this says how
 * many fixed ticks to run now. The remainder carries over, so over many frames simulated time
 * tracks wall time exactly; after a stall (a slow frame, a debugger) at most
 * {@code maxTicksPerFrame} ticks run and the rest is dropped, so the simulation slows down
 * instead of spiralling.
 */
public final class RealTimeStepper {
  private final double tickSec;
  private final int maxTicksPerFrame;
  private double owedSec;

  public RealTimeStepper(double tickSec, int maxTicksPerFrame) {
    if (!(tickSec > 0) || maxTicksPerFrame < 1) {
      throw new IllegalArgumentException("tick must be positive and at least one tick per frame allowed");
    }
    this.tickSec = tickSec;
    this.maxTicksPerFrame = maxTicksPerFrame;
  }

  /** Ticks to run for {@code wallDeltaSec} of elapsed wall time (negative counts as 0). */
  public int ticksFor(double wallDeltaSec) {
    owedSec += Math.max(0, wallDeltaSec);
    int n = (int) Math.floor(owedSec / tickSec + 1e-9);
    if (n > maxTicksPerFrame) {
      owedSec = 0;
      return maxTicksPerFrame;
    }
    owedSec -= n * tickSec;
    return n;
  }
}
