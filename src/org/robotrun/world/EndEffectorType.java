package org.robotrun.world;

/** The tools a robot can carry on its flange; scenario files name them in lower case. */
public enum EndEffectorType {
  /** Bare flange. */
  FACEPLATE,
  /** Parallel two-finger gripper. */
  GRIPPER,
  /** Suction cup. */
  SUCTION,
  /** A pointed rod for teaching frames. */
  POINTER,
  /** A process tool that leaves a trace while on. */
  GLUEGUN;

  /** The name used in files. */
  public String fileName() {
    return name().toLowerCase(java.util.Locale.ROOT);
  }
}
