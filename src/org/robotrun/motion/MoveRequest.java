package org.robotrun.motion;

import org.robotrun.math.Transform;
import org.robotrun.robot.RobotModel;

/**
 * One motion for the {@link MotionRunner}: where to go, how fast, how to end. Targets are
 * already resolved by the caller (frames applied, offsets added, CONFIG solved for joint
 * moves). {@code tag} is the caller's handle (the controller numbers its moves), echoed in
 * every {@link MotionListener} event.
 */
public sealed interface MoveRequest {

  Speed speed();

  Termination termination();

  /** ACC as a fraction (1 = ACC100); scales the acceleration limits. */
  double accFraction();

  long tag();

  /**
   * A joint-interpolated move (J): all joints start and arrive together.
   *
   * @param qTarget joint values (rad, kinematic convention), inside the limits
   */
  record Joint(double[] qTarget, Speed speed, Termination termination, double accFraction, long tag)
      implements MoveRequest {
    public Joint {
      qTarget = qTarget.clone();
      if (qTarget.length != RobotModel.DOF) {
        throw new IllegalArgumentException("a joint target needs 6 values");
      }
      checkAcc(accFraction);
    }

    @Override
    public double[] qTarget() {
      return qTarget.clone();
    }
  }

  /**
   * A linear move (L): the TCP runs on the straight line, orientation slerped.
   *
   * @param X_WTarget target TCP pose in WORLD
   * @param X_FT the tool frame (TCP) in the flange frame
   */
  record Linear(Transform X_WTarget, Transform X_FT, Speed speed, Termination termination, double accFraction,
      long tag) implements MoveRequest {
    public Linear {
      checkAcc(accFraction);
    }
  }

  /**
   * A circular move (C, and each arc of A): the TCP runs on the circle through its start, the
   * via point and the target, from the start through the via point to the target.
   *
   * @param X_WVia a point on the arc in WORLD (only its position is used)
   * @param X_WTarget the end pose in WORLD
   */
  record Circular(Transform X_WVia, Transform X_WTarget, Transform X_FT, Speed speed, Termination termination,
      double accFraction, long tag) implements MoveRequest {
    public Circular {
      checkAcc(accFraction);
    }
  }

  private static void checkAcc(double accFraction) {
    if (!(accFraction > 0 && accFraction <= 1.5)) {
      throw new IllegalArgumentException("ACC must be 1..150, got " + accFraction * 100);
    }
  }
}
