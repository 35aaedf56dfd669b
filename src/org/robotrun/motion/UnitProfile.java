package org.robotrun.motion;

/**
 * A trapezoidal velocity profile over a unit path parameter {@code u} from 0 to 1: constant
 * acceleration, cruise at the peak rate, constant deceleration (triangular when the path is too
 * short to reach the peak). Every motion is one of these: a joint move maps {@code u} to
 * {@code q0 + u·(q1 − q0)}, a linear move to the point {@code u·L} along the line, so all joints
 * (or position and orientation) start and arrive together and each derivative is the profile's
 * rate times a constant.
 *
 * @param peakRate cruise rate of u (1/s)
 * @param accel acceleration and deceleration of u (1/s²)
 * @param accelTimeSec time spent accelerating (= time decelerating)
 * @param cruiseTimeSec time at the peak rate
 */
public record UnitProfile(double peakRate, double accel, double accelTimeSec, double cruiseTimeSec) {

  /** A profile that is already at its end: duration 0 (a move to where the robot is). */
  public static final UnitProfile EMPTY = new UnitProfile(0, 0, 0, 0);

  public UnitProfile {
    if (!(peakRate >= 0 && accel >= 0 && accelTimeSec >= 0 && cruiseTimeSec >= 0)) {
      throw new IllegalArgumentException("profile values must be finite and non-negative");
    }
  }

  /**
   * The fastest profile under a rate limit and an acceleration limit.
   *
   * @param maxRate peak rate limit (1/s), positive (infinite allowed: then triangular)
   * @param maxAccel acceleration limit (1/s²), positive and finite
   */
  public static UnitProfile fastest(double maxRate, double maxAccel) {
    if (!(maxRate > 0 && maxAccel > 0 && Double.isFinite(maxAccel))) {
      throw new IllegalArgumentException("rate and acceleration limits must be positive, got " + maxRate + ", " + maxAccel);
    }
    // Accelerating to v and back covers v²/a of the unit path: trapezoid if that fits.
    if (maxRate * maxRate / maxAccel <= 1) {
      double ta = maxRate / maxAccel;
      double cruise = (1 - maxRate * maxRate / maxAccel) / maxRate;
      return new UnitProfile(maxRate, maxAccel, ta, cruise);
    }
    double v = Math.sqrt(maxAccel);
    return new UnitProfile(v, maxAccel, v / maxAccel, 0);
  }

  /**
   * A profile that takes {@code durationSec} (a {@code sec}/{@code msec} speed) using the full
   * acceleration, or the fastest profile when the asked time is shorter than the limits allow.
   */
  public static UnitProfile forDuration(double durationSec, double maxRate, double maxAccel) {
    UnitProfile fastest = fastest(maxRate, maxAccel);
    if (!(durationSec > fastest.durationSec())) {
      return fastest;
    }
    // T = 1/v + v/a  =>  v² − a·T·v + a = 0; the smaller root keeps the cruise phase.
    double a = maxAccel;
    double disc = a * a * durationSec * durationSec - 4 * a;
    double v = (a * durationSec - Math.sqrt(Math.max(0, disc))) / 2;
    double ta = v / a;
    return new UnitProfile(v, a, ta, Math.max(0, durationSec - 2 * ta));
  }

  /** Total time (s). */
  public double durationSec() {
    return 2 * accelTimeSec + cruiseTimeSec;
  }

  /** Time at which deceleration starts (s). */
  public double decelStartSec() {
    return accelTimeSec + cruiseTimeSec;
  }

  /** The path parameter u at time t (clamped to [0, 1] outside the profile). */
  public double position(double t) {
    if (this == EMPTY || t >= durationSec()) {
      return 1;
    }
    if (t <= 0) {
      return 0;
    }
    if (t < accelTimeSec) {
      return 0.5 * accel * t * t;
    }
    double reachedAtCruise = 0.5 * accel * accelTimeSec * accelTimeSec;
    if (t < decelStartSec()) {
      return reachedAtCruise + peakRate * (t - accelTimeSec);
    }
    double left = durationSec() - t;
    return 1 - 0.5 * accel * left * left;
  }

  /** The rate du/dt at time t (1/s). */
  public double rate(double t) {
    if (t <= 0 || t >= durationSec()) {
      return 0;
    }
    if (t < accelTimeSec) {
      return accel * t;
    }
    if (t < decelStartSec()) {
      return peakRate;
    }
    return accel * (durationSec() - t);
  }
}
