package org.robotrun.world;

/** Vision (issue 16): cameras, vision processes and seeded random part placement. */
public record VisionSetup() {
  /** None: the scenario does not use this. */
  public static final VisionSetup NONE = new VisionSetup();
}
