package org.robotrun.world;

/** Production start from a PLC (issue 15): UOP signals, PNS/RSR program selection, background logic. */
public record ProductionSetup() {
  /** None: the scenario does not use this. */
  public static final ProductionSetup NONE = new ProductionSetup();
}
