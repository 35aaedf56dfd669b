package org.robotrun.motion;

import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.KinematicChain;
import org.robotrun.robot.RobotModel;

/**
 * Turns the jog keys into arm motion, one tick at a time.
 *
 * <p>JOINT moves each joint at {@link #JOINT_JOG_FRACTION} of its maximum speed times the
 * override, slowing so it comes to rest exactly at its limit; with FANUC's coupled J3 the J2 keys
 * keep the pendant's J3 (the forearm's attitude), as on the real pendant. WORLD, TOOL and USER move a desired
 * TCP pose along / about the frame's axes through the TCP (linear {@link #LINEAR_JOG_MM_PER_SEC},
 * rotation {@link #ROTATION_JOG_RAD_PER_SEC}, times the override) and reach it with the
 * resolved-rate {@link PoseTracker}; because the desired pose is integrated, not the joint
 * rates, the TCP does not drift off the axis. Each axis ramps its speed up and down in
 * {@link #RAMP_SEC}. Near a singularity, where the joints would have to outrun their speed
 * limits, the jog slows down; a jog that would pass a joint limit, reach the wrist singularity or
 * slow below {@link #MIN_SLOWDOWN} stops with a message, and never jumps.
 *
 * <p>Not thread-safe; one per controller.
 */
public final class Jogger {
  /** JOINT jog speed at 100% override, as a fraction of each joint's maximum. */
  public static final double JOINT_JOG_FRACTION = 0.25;
  /** Cartesian jog speed at 100% override (mm/s): the teach-mode limit of real controllers. */
  public static final double LINEAR_JOG_MM_PER_SEC = 250;
  /** Cartesian rotation jog speed at 100% override (rad/s): 60°/s. */
  public static final double ROTATION_JOG_RAD_PER_SEC = Math.toRadians(60);
  /** Slowest a Cartesian jog may get near a singularity, as a fraction of its asked speed, before it stops. */
  public static final double MIN_SLOWDOWN = 0.05;
  /** Time to reach full jog speed from rest and back (s). */
  public static final double RAMP_SEC = 0.1;

  private static final JogResult IDLE = new JogResult.Idle();
  private static final JogResult MOVING = new JogResult.Moving();

  private final RobotModel model;
  private final MotionLimits limits;
  private final PoseTracker tracker;
  private final KinematicChain chain;
  private final double[] speed = new double[6];
  private final double[] qTry = new double[RobotModel.DOF];
  private Transform X_WTdesired;
  private JogFrame lastFrame;
  private Transform lastTool;
  private double cartesianCapMmPerSec = Double.POSITIVE_INFINITY;

  public Jogger(RobotModel model, MotionLimits limits) {
    this.model = model;
    this.limits = limits;
    this.tracker = new PoseTracker(model);
    this.chain = tracker.chain();
  }

  /** Full speed of axis i at 100% override in the frame (rad/s or mm/s). */
  double fullSpeed(JogFrame frame, int axis) {
    return switch (frame) {
      case JOINT -> JOINT_JOG_FRACTION * limits.jointSpeed(axis);
      case WORLD, TOOL, USER, JGFRM -> axis < 3 ? LINEAR_JOG_MM_PER_SEC : ROTATION_JOG_RAD_PER_SEC;
    };
  }

  /**
   * Caps the speed of the flange and of the TCP in a WORLD, TOOL, USER or JGFRM jog (mm/s; T1):
   * the desired pose advances only as far as the cap allows, along the jogged axes, so a jog of
   * several axes keeps its line and never runs ahead of the arm. {@link Double#POSITIVE_INFINITY}
   * turns it off. (A JOINT jog has no desired pose; the controller shortens its ticks.)
   */
  public void setCartesianSpeedCap(double mmPerSec) {
    if (!(mmPerSec > 0)) {
      throw new IllegalArgumentException("speed cap must be > 0 mm/s, got " + mmPerSec);
    }
    cartesianCapMmPerSec = mmPerSec;
  }

  /** Stops at once (HOLD, deadman, alarm): speeds to zero, keys off. */
  public void stop(JogState keys) {
    keys.stopAll();
    java.util.Arrays.fill(speed, 0);
    X_WTdesired = null;
  }

  /**
   * One tick.
   *
   * @param q joints (rad, kinematic), updated in place
   * @param overrideFraction 0.01..1
   * @param X_FT active tool (TCP in the flange)
   * @param X_WU active user frame in WORLD (used for USER)
   */
  public JogResult tick(double[] q, JogState keys, JogFrame frame, double overrideFraction, Transform X_FT,
      Transform X_WU, double dtSec) {
    if (frame != lastFrame || !X_FT.equals(lastTool)) {
      java.util.Arrays.fill(speed, 0);
      X_WTdesired = null;
      lastFrame = frame;
      lastTool = X_FT;
    }
    boolean any = false;
    for (int i = 0; i < 6; i++) {
      double full = fullSpeed(frame, i) * overrideFraction;
      double target = keys.direction(i) * full;
      double dv = full / RAMP_SEC * dtSec;
      speed[i] = speed[i] < target ? Math.min(target, speed[i] + dv) : Math.max(target, speed[i] - dv);
      any |= speed[i] != 0;
    }
    if (!any) {
      X_WTdesired = null;
      return IDLE;
    }
    return frame == JogFrame.JOINT ? jogJoints(q, keys, overrideFraction, dtSec) : jogCartesian(q, keys, frame, X_FT, X_WU, dtSec);
  }

  private JogResult jogJoints(double[] q, JogState keys, double overrideFraction, double dtSec) {
    for (int i = 0; i < 6; i++) {
      if (speed[i] == 0) {
        continue;
      }
      // With FANUC's coupled J3, the J2 keys turn kinematic J3 along so the forearm keeps its
      // attitude (the pendant's J3 value does not change).
      boolean dragsJ3 = i == 1 && model.coupledJ3();
      double a = fullSpeed(JogFrame.JOINT, i) * overrideFraction / RAMP_SEC;
      double room = room(q, i, speed[i]);
      int limiting = i;
      if (dragsJ3 && room(q, 2, speed[i]) < room) {
        room = room(q, 2, speed[i]);
        limiting = 2;
      }
      // Brake so the joint comes to rest at its limit: v ≤ sqrt(2·a·room).
      double vMax = Math.sqrt(2 * a * Math.max(0, room));
      double v = Math.signum(speed[i]) * Math.min(Math.abs(speed[i]), vMax);
      speed[i] = v;
      double step = v * dtSec;
      boolean atLimit = room <= 1e-9 || Math.abs(step) >= room;
      double applied = Math.signum(step) * Math.min(Math.abs(step), Math.max(0, room));
      q[i] = clamp(q[i] + applied, i);
      if (dragsJ3) {
        q[2] = clamp(q[2] + applied, 2);
      }
      if (atLimit) {
        String side = (v != 0 ? v > 0 : keys.direction(i) > 0) ? "upper" : "lower";
        stop(keys);
        return new JogResult.Stopped(limiting == i
            ? String.format(java.util.Locale.ROOT, "J%d at its %s limit (%.1f deg)", i + 1, side, Math.toDegrees(q[i]))
            : String.format(java.util.Locale.ROOT, "J%d stopped: J3 (coupled to J2) at its %s limit", i + 1, side));
      }
    }
    return MOVING;
  }

  /** How far joint j may still move in the direction of {@code sign} (rad). */
  private double room(double[] q, int j, double sign) {
    return sign > 0 ? chain.upper(j) - q[j] : q[j] - chain.lower(j);
  }

  private double clamp(double v, int j) {
    return Math.max(chain.lower(j), Math.min(chain.upper(j), v));
  }

  /**
   * Incremental jog: moves {@code q} (in place) by one step of axis {@code axis} (0..5) in
   * {@code sign} direction: {@code stepMm} along X/Y/Z, {@code stepRad} about them or of a joint.
   * Refused (joints unchanged) past a joint limit or out of reach.
   *
   * @param X_WAxes the frame whose axes USER/JGFRM jog along (WORLD: identity; TOOL uses the TCP)
   */
  public JogResult step(double[] q, JogFrame frame, int axis, int sign, double stepMm, double stepRad,
      Transform X_FT, Transform X_WAxes) {
    System.arraycopy(q, 0, qTry, 0, RobotModel.DOF);
    if (frame == JogFrame.JOINT) {
      qTry[axis] += sign * stepRad;
      if (axis == 1 && model.coupledJ3()) {
        qTry[2] += sign * stepRad;
      }
    } else {
      Transform X_WT = org.robotrun.robot.ForwardKinematics.flangePoseInWorld(model, q).compose(X_FT);
      Transform axes = switch (frame) {
        case WORLD, JOINT -> Transform.IDENTITY;
        case USER, JGFRM -> X_WAxes;
        case TOOL -> X_WT;
      };
      Vec3 unit = axes.rotate(new Vec3(axis % 3 == 0 ? 1 : 0, axis % 3 == 1 ? 1 : 0, axis % 3 == 2 ? 1 : 0));
      Transform want;
      if (axis < 3) {
        Vec3 p = X_WT.translationVector().plus(unit.times(sign * stepMm));
        want = X_WT.withTranslation(p.x(), p.y(), p.z());
      } else {
        Vec3 p = X_WT.translationVector();
        want = Rotations.exp(unit.times(sign), stepRad).compose(X_WT.withTranslation(0, 0, 0)).withTranslation(p.x(), p.y(), p.z());
      }
      if (!tracker.track(qTry, want, X_FT, 1e-5, 1e-8)) {
        return new JogResult.Stopped("step out of reach");
      }
    }
    for (int i = 0; i < 6; i++) {
      if (!(qTry[i] >= chain.lower(i) && qTry[i] <= chain.upper(i))) {
        return new JogResult.Stopped(String.format("J%d at its limit", i + 1));
      }
    }
    System.arraycopy(qTry, 0, q, 0, RobotModel.DOF);
    return MOVING;
  }

  private JogResult jogCartesian(double[] q, JogState keys, JogFrame frame, Transform X_FT, Transform X_WU,
      double dtSec) {
    Transform X_WT = org.robotrun.robot.ForwardKinematics.flangePoseInWorld(model, q).compose(X_FT);
    if (X_WTdesired == null) {
      X_WTdesired = X_WT;
    }
    Transform axes = switch (frame) {
      case WORLD, JOINT -> Transform.IDENTITY;
      case USER, JGFRM -> X_WU;
      case TOOL -> X_WTdesired;
    };
    // The speed cap (T1): the whole step is shortened, so every axis keeps its share.
    double capScale = 1;
    if (cartesianCapMmPerSec < Double.POSITIVE_INFINITY) {
      Transform full = advanced(axes, dtSec);
      Transform X_TF = X_FT.inverse();
      double step = Math.max(full.translationVector().distanceTo(X_WTdesired.translationVector()),
          full.compose(X_TF).translationVector().distanceTo(X_WTdesired.compose(X_TF).translationVector()));
      if (step > cartesianCapMmPerSec * dtSec * (1 + 1e-9)) {
        capScale = cartesianCapMmPerSec * dtSec / step;
      }
    }
    // Near a singularity the joints would have to outrun their limits: jog slower (down to 5% of
    // the asked speed) rather than whip the wrist; below that, stop with a message.
    double scale = 1;
    boolean ok = false;
    double ratio = Double.POSITIVE_INFINITY;
    Transform want = X_WTdesired;
    for (int attempt = 0; attempt < 4; attempt++) {
      want = advanced(axes, dtSec * capScale * scale);
      System.arraycopy(q, 0, qTry, 0, RobotModel.DOF);
      ok = tracker.track(qTry, want, X_FT, 1e-3, 1e-6);
      ratio = 0;
      for (int i = 0; i < 6 && ok; i++) {
        ok = Double.isFinite(qTry[i]);
        ratio = Math.max(ratio, Math.abs(qTry[i] - q[i]) / (limits.jointSpeed(i) * dtSec));
      }
      if (!ok || ratio <= 1) {
        break;
      }
      scale *= 0.9 / ratio;
    }
    if (!ok || ratio > 1 || scale < MIN_SLOWDOWN || MotionRunner.entersWristSingularity(q, qTry)) {
      stop(keys);
      return new JogResult.Stopped(Math.abs(Math.sin(q[4])) < Math.sin(Math.toRadians(10))
          ? String.format(java.util.Locale.ROOT, "stopped near the wrist singularity (J5 = %.1f deg): jog J5 in JOINT first", Math.toDegrees(q[4]))
          : "stopped: singularity or edge of reach");
    }
    if (scale * capScale < 1) {
      for (int i = 0; i < 6; i++) {
        speed[i] *= scale * capScale;
      }
    }
    for (int i = 0; i < 6; i++) {
      if (!(qTry[i] >= chain.lower(i) && qTry[i] <= chain.upper(i))) {
        stop(keys);
        return new JogResult.Stopped(String.format(java.util.Locale.ROOT, "J%d at its %s limit (%.1f deg)", i + 1,
            qTry[i] > chain.upper(i) ? "upper" : "lower", Math.toDegrees(q[i])));
      }
    }
    System.arraycopy(qTry, 0, q, 0, RobotModel.DOF);
    X_WTdesired = want;
    return MOVING;
  }

  /** The desired pose moved on by the current speeds for {@code h} seconds, along / about {@code axes}' axes. */
  private Transform advanced(Transform axes, double h) {
    Vec3 v_W = axes.rotate(new Vec3(speed[0], speed[1], speed[2]));
    Vec3 w_W = axes.rotate(new Vec3(speed[3], speed[4], speed[5]));
    Vec3 p = X_WTdesired.translationVector().plus(v_W.times(h));
    return Rotations.exp(w_W, h).compose(X_WTdesired.withTranslation(0, 0, 0)).withTranslation(p.x(), p.y(), p.z());
  }
}
