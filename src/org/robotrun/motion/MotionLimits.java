package org.robotrun.motion;

import org.robotrun.robot.RobotModel;

/**
 * Speed and acceleration limits the planner and the jog respect (rad, mm, s). Joint speeds come
 * from the robot model; accelerations follow the controller habit of an acceleration time: a
 * joint reaches its maximum speed in {@link #JOINT_ACCEL_TIME_SEC}, a linear move reaches its
 * commanded speed in {@link #LINEAR_ACCEL_TIME_SEC} (both scaled by ACC).
 *
 * @param jointMaxSpeedRadPerSec per joint, from the model
 * @param jointMaxAccelRadPerSec2 per joint
 * @param linearMaxSpeedMmPerSec TCP speed limit for linear and circular moves
 * @param rotationMaxSpeedRadPerSec TCP orientation speed limit (applies to every Cartesian move)
 * @param rotationMaxAccelRadPerSec2 TCP orientation acceleration limit
 */
public record MotionLimits(
    double[] jointMaxSpeedRadPerSec,
    double[] jointMaxAccelRadPerSec2,
    double linearMaxSpeedMmPerSec,
    double rotationMaxSpeedRadPerSec,
    double rotationMaxAccelRadPerSec2) {

  /** Time for a joint to reach its maximum speed at ACC100 (s). */
  public static final double JOINT_ACCEL_TIME_SEC = 0.25;
  /** Time for a linear move to reach its commanded speed at ACC100 (s). */
  public static final double LINEAR_ACCEL_TIME_SEC = 0.2;
  /** The fastest TCP speed a program may ask for (mm/s) unless the model gives its own. */
  public static final double LINEAR_MAX_SPEED_MM_PER_SEC = RobotModel.DEFAULT_MAX_LINEAR_SPEED_MM_PER_SEC;
  /** The fastest TCP orientation change (rad/s): 180°/s. */
  public static final double ROTATION_MAX_SPEED_RAD_PER_SEC = Math.PI;

  public MotionLimits {
    jointMaxSpeedRadPerSec = jointMaxSpeedRadPerSec.clone();
    jointMaxAccelRadPerSec2 = jointMaxAccelRadPerSec2.clone();
    if (jointMaxSpeedRadPerSec.length != RobotModel.DOF || jointMaxAccelRadPerSec2.length != RobotModel.DOF) {
      throw new IllegalArgumentException("limits need one value per joint");
    }
  }

  /** The default limits for a robot model. */
  public static MotionLimits forModel(RobotModel model) {
    double[] v = new double[RobotModel.DOF];
    double[] a = new double[RobotModel.DOF];
    for (int i = 0; i < RobotModel.DOF; i++) {
      v[i] = model.joint(i).maxSpeedRadPerSec();
      a[i] = v[i] / JOINT_ACCEL_TIME_SEC;
    }
    return new MotionLimits(v, a, model.maxLinearSpeedMmPerSec(), ROTATION_MAX_SPEED_RAD_PER_SEC,
        ROTATION_MAX_SPEED_RAD_PER_SEC / LINEAR_ACCEL_TIME_SEC);
  }

  @Override
  public double[] jointMaxSpeedRadPerSec() {
    return jointMaxSpeedRadPerSec.clone();
  }

  @Override
  public double[] jointMaxAccelRadPerSec2() {
    return jointMaxAccelRadPerSec2.clone();
  }

  /** Maximum speed of joint i (rad/s). */
  public double jointSpeed(int i) {
    return jointMaxSpeedRadPerSec[i];
  }

  /** Maximum acceleration of joint i (rad/s²). */
  public double jointAccel(int i) {
    return jointMaxAccelRadPerSec2[i];
  }
}
