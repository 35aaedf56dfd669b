package org.robotrun.world;

/**
 * Which robot I/O ports an end effector uses: RO[{@code output}] switches it, RI[{@code
 * actuatedInput}] reports it closed (vacuum on, dispensing) once the actuation time has passed,
 * RI[{@code holdingInput}] reports a part held. Ports are 1..{@link #MAX_PORT}.
 */
public record ToolIo(int output, int actuatedInput, int holdingInput) {
  /** The controller's robot I/O has 64 ports of each kind. */
  public static final int MAX_PORT = 64;
  /** RO[1], RI[1], RI[2]. */
  public static final ToolIo DEFAULT = new ToolIo(1, 1, 2);

  public ToolIo {
    for (int p : new int[] {output, actuatedInput, holdingInput}) {
      if (p < 1 || p > MAX_PORT) {
        throw new IllegalArgumentException("robot I/O ports are 1.." + MAX_PORT + ", got " + p);
      }
    }
    if (actuatedInput == holdingInput) {
      throw new IllegalArgumentException("the actuated and holding inputs must differ, both are RI[" + holdingInput + "]");
    }
  }
}
