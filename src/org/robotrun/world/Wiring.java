package org.robotrun.world;

/** Signals wired between robots and the cell (issue 15): which output drives which input. */
public record Wiring() {
  /** None: the scenario does not use this. */
  public static final Wiring NONE = new Wiring();
}
