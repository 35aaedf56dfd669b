package org.robotrun.robot;

import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * One revolute joint of a serial chain, in the kinematic (URDF, uncoupled J3) convention.
 *
 * @param name joint name, e.g. "J1"
 * @param X_PJ the joint frame in its parent link's frame at q = 0 (mm)
 * @param axis unit rotation axis in the joint frame
 * @param lowerRad lower limit (rad)
 * @param upperRad upper limit (rad)
 * @param maxSpeedRadPerSec maximum joint speed (rad/s)
 */
public record JointSpec(
    String name, Transform X_PJ, Vec3 axis, double lowerRad, double upperRad, double maxSpeedRadPerSec) {

  public JointSpec {
    if (!(lowerRad < upperRad)) {
      throw new IllegalArgumentException(name + ": lower limit must be below the upper limit");
    }
    if (!(maxSpeedRadPerSec > 0)) {
      throw new IllegalArgumentException(name + ": max speed must be positive");
    }
    axis = axis.normalized();
  }

  public boolean withinLimits(double qRad) {
    return qRad >= lowerRad && qRad <= upperRad;
  }
}
