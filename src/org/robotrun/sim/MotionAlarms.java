package org.robotrun.sim;

import org.robotrun.motion.MotionFault;
import org.robotrun.program.AlarmCode;

/**
 * Alarm codes the controller raises for motion; each is a row of the alarm table
 * ({@link AlarmCode}, docs/alarms.md), where RobotRun's own codes ({@code SIMU-nnn}) are kept
 * apart from the controller's.
 */
public final class MotionAlarms {
  private MotionAlarms() {}

  public static final String JOINT_LIMIT = AlarmCode.MOTN_017.code();
  public static final String UNREACHABLE = AlarmCode.MOTN_018.code();
  public static final String SINGULARITY = AlarmCode.MOTN_023.code();
  public static final String BAD_PATH = AlarmCode.SIMU_006.code();
  public static final String FRAME_MISMATCH = AlarmCode.SIMU_007.code();
  public static final String BAD_SPEED = AlarmCode.SIMU_008.code();
  public static final String BAD_OFFSET = AlarmCode.SIMU_009.code();
  public static final String QUEUE_BUSY = AlarmCode.SIMU_010.code();

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
