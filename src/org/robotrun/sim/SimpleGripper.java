package org.robotrun.sim;

import org.robotrun.program.IoKind;
import org.robotrun.program.Registers;

/**
 * The default end effector's I/O until a scenario defines one: RO[1] commands the gripper
 * (ON = close), RI[1] reports it closed {@link #ACTUATION_SEC} after the command, and open again
 * as long after RO[1] goes OFF (TP-LANGUAGE.md: "RO[1] drives the end effector, RI[1] reports it
 * closed"). It holds no parts: that is the world's job.
 */
final class SimpleGripper {
  /** Time for the jaws to close or open (s). */
  static final double ACTUATION_SEC = 0.1;

  private double sinceChangeSec;
  private boolean commanded;

  void tick(Registers io, double dtSec) {
    boolean cmd = io.bit(IoKind.RO, 1);
    if (cmd != commanded) {
      commanded = cmd;
      sinceChangeSec = 0;
    }
    sinceChangeSec += dtSec;
    if (sinceChangeSec >= ACTUATION_SEC - 1e-9 && io.bit(IoKind.RI, 1) != cmd) {
      io.setBit(IoKind.RI, 1, cmd);
    }
  }
}
