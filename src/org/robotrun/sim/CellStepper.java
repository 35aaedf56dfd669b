package org.robotrun.sim;

import java.util.Objects;
import java.util.function.Consumer;

/**
 * The one way simulated time advances a cell, for the window and the headless commands alike:
 * whole fixed ticks of the {@link Simulation}, a remainder under one tick carried to the next
 * call, so over many calls simulated time tracks the time asked for exactly. The window passes the
 * wall time since its last frame ({@link #advanceRealTime}: a stalled frame never makes the cell
 * jump more than {@link #MAX_FRAME_SEC}, it slows down instead); key scripts and tests pass
 * simulated seconds ({@link #advance}); headless runs step one tick at a time ({@link #tick}). The simulation itself never reads a clock.
 */
public final class CellStepper {
  /** The most simulated time one window frame may advance (s). */
  public static final double MAX_FRAME_SEC = 0.1;

  private final Simulation simulation;
  private double pendingSec;
  private Consumer<Simulation> afterTick = s -> { };

  /** Steps {@code simulation}. */
  public CellStepper(Simulation simulation) {
    this.simulation = Objects.requireNonNull(simulation, "simulation");
  }

  /** The simulation this steps. */
  public Simulation simulation() {
    return simulation;
  }

  /** Called after every tick this runs (a CSV trace). */
  public void setAfterTick(Consumer<Simulation> listener) {
    afterTick = Objects.requireNonNull(listener, "listener");
  }

  /**
   * Advances {@code dtSec} of simulated time in whole ticks; a remainder under one tick carries
   * over to the next call. Answers the number of ticks run.
   */
  public int advance(double dtSec) {
    if (!(dtSec >= 0) || Double.isInfinite(dtSec)) {
      throw new IllegalArgumentException("dtSec must be finite and >= 0, got " + dtSec);
    }
    pendingSec += dtSec;
    double tick = simulation.tickSec();
    int ticks = 0;
    while (pendingSec >= tick - 1e-12) {
      tick();
      pendingSec -= tick;
      ticks++;
    }
    return ticks;
  }

  /** Runs one tick (a headless run that looks at the cell after each). */
  public void tick() {
    simulation.step();
    afterTick.accept(simulation);
  }

  /**
   * The window: {@code wallDeltaSec} of wall time passed since the last frame (negative counts as
   * 0); at most {@link #MAX_FRAME_SEC} of it is simulated.
   */
  public int advanceRealTime(double wallDeltaSec) {
    return advance(Math.min(MAX_FRAME_SEC, Math.max(0, wallDeltaSec)));
  }
}
