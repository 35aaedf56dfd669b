package org.robotrun.sim;

import org.robotrun.motion.MotionFault;

/**
 * Alarm codes the controller raises for motion. FANUC-style ({@code MOTN-nnn}, the family a
 * FANUC controller uses for motion faults); the numbers are RobotRun's own.
 *
 * <pre>
 * code      when
 * MOTN-017  a joint would pass its limit (target or on the way)
 * MOTN-018  the target or a point of the path is out of reach
 * MOTN-023  the path runs into a singularity (wrist: J5 near 0)
 * MOTN-030  bad circular geometry (points on one line)
 * MOTN-046  the position's UF/UT differ from the active frames
 * MOTN-047  bad speed or ACC value
 * MOTN-048  bad offset (joint PR for a Cartesian target, Tool_Offset with a joint PR)
 * MOTN-049  motion queue busy (a MOVE_TO while a motion waits)
 * </pre>
 */
public final class MotionAlarms {
  private MotionAlarms() {}

  public static final String JOINT_LIMIT = "MOTN-017";
  public static final String UNREACHABLE = "MOTN-018";
  public static final String SINGULARITY = "MOTN-023";
  public static final String BAD_PATH = "MOTN-030";
  public static final String FRAME_MISMATCH = "MOTN-046";
  public static final String BAD_SPEED = "MOTN-047";
  public static final String BAD_OFFSET = "MOTN-048";
  public static final String QUEUE_BUSY = "MOTN-049";

  /** The code for a fault reported by the motion runner. */
  public static String codeOf(MotionFault fault) {
    return switch (fault.kind()) {
      case JOINT_LIMIT -> JOINT_LIMIT;
      case OUT_OF_REACH -> UNREACHABLE;
      case SINGULARITY -> SINGULARITY;
      case BAD_PATH -> BAD_PATH;
    };
  }
}
