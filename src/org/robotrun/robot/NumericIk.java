package org.robotrun.robot;

import java.util.Optional;
import org.robotrun.math.Transform;

/**
 * Numeric position IK for any 6-axis arm: damped least squares (Levenberg–Marquardt) on the
 * analytic Jacobian, joints clamped to their limits after every step, restarts from a fixed,
 * deterministic list of seeds, and hard caps on iterations and time. Never returns null,
 * never hangs.
 *
 * <p>Method. The error is {@code e = [(p_d − p)/L; log(R_d·Rᵀ)]} (position scaled by a
 * characteristic length L so millimetres and radians weigh alike). Each step solves
 * {@code (Jsᵀ·Js + λI)·Δq = Jsᵀ·e} with {@code λ = ½|e|² + λ0}: the damping follows the error,
 * after Sugihara, "Solvability-unconcerned inverse kinematics by the Levenberg–Marquardt
 * method" (IEEE T-RO 2011), so far from the target the step is short and steady and near it the
 * solve becomes Gauss–Newton with quadratic convergence. An attempt is abandoned when the error
 * stops falling (local minimum, often pinned at a limit) or after a per-attempt iteration
 * budget; the next seed then starts: the caller's start, then seeds spread over the joint
 * ranges (a Halton sequence) with J1 turned toward the target, front side first.
 *
 * <p>Unreachable targets are recognised before iterating where possible: with OPW parameters
 * the closed form's reachability answer (beyond reach, or no solution inside the limits) is
 * used, without using its solutions; otherwise a reach-sphere check around J2.
 *
 * <p>Not thread-safe (scratch arrays). The inner loop allocates nothing.
 */
public final class NumericIk {

  /**
   * Tuning and caps.
   *
   * @param positionToleranceMm converged when the position error is below this (mm)
   * @param orientationToleranceRad and the orientation error below this (rad)
   * @param iterationsPerAttempt iterations before moving on to the next seed
   * @param maxIterations total iterations over all attempts
   * @param timeCapNanos wall-time cap for one solve (ns)
   * @param lengthScaleMm L, the length that weighs as one radian
   */
  public record Settings(
      double positionToleranceMm, double orientationToleranceRad, int iterationsPerAttempt,
      int maxIterations, long timeCapNanos, double lengthScaleMm) {

    /** 1e-6 mm, 1e-9 rad, 40 iterations per attempt, 3000 in all, 1 ms, L = 300 mm. */
    public static Settings defaults() {
      return new Settings(1e-6, 1e-9, 40, 3000, 1_000_000, 300);
    }
  }

  private static final int SEEDS = 64;
  /** λ0: keeps the normal equations positive definite at singularities. */
  private static final double BASE_DAMPING = 1e-9;

  private final KinematicChain chain;
  private final Settings settings;
  private final Optional<ClosedFormIk> reachCheck;
  private final double reachRadiusMm;
  private final double[] shoulder = new double[3];
  private final double[] lower;
  private final double[] upper;
  private final double[] seeds = new double[SEEDS * 6];

  private final double[] target = new double[12];
  private final double[] pose = new double[12];
  private final double[] jac = new double[36];
  private final double[] scratch = new double[Jacobian.SCRATCH];
  private final double[] err = new double[6];
  private final double[] a = new double[36];
  private final double[] g = new double[6];
  private final double[] q = new double[6];
  private final double[] bestQ = new double[6];

  public NumericIk(RobotModel model) {
    this(model, Settings.defaults());
  }

  public NumericIk(RobotModel model, Settings settings) {
    this.chain = new KinematicChain(model);
    this.settings = settings;
    this.reachCheck = model.opw().map(p -> new ClosedFormIk(model));
    this.lower = model.lowerLimits();
    this.upper = model.upperLimits();
    // Reach sphere: J2's origin (at q1 = 0) plus every later offset, flange included.
    Transform j2 = model.joint(0).X_PJ().compose(model.joint(1).X_PJ());
    shoulder[0] = j2.x();
    shoulder[1] = j2.y();
    shoulder[2] = j2.z();
    double r = Math.hypot(j2.x(), j2.y());
    for (int i = 2; i < RobotModel.DOF; i++) {
      r += model.joint(i).X_PJ().translationVector().norm();
    }
    reachRadiusMm = r + model.X_6F().translationVector().norm();
    fillSeeds();
  }

  /** Solves for a flange pose in the base frame, starting from {@code qStart} (rad). */
  public IkResult solve(Transform X_BF, double[] qStart) {
    KinematicChain.pack(X_BF, target, 0);
    return solvePacked(qStart);
  }

  /** As {@link #solve(Transform, double[])} for a packed pose (12 doubles, see KinematicChain). */
  public IkResult solve(double[] X_BF, double[] qStart) {
    System.arraycopy(X_BF, 0, target, 0, 12);
    return solvePacked(qStart);
  }

  private IkResult solvePacked(double[] qStart) {
    long t0 = System.nanoTime();
    IkResult.Unreachable early = precheck();
    if (early != null) {
      return early;
    }
    double invL = 1 / settings.lengthScaleMm();
    double tolP = settings.positionToleranceMm() * invL;
    double tolR = settings.orientationToleranceRad();
    double bestE = Double.POSITIVE_INFINITY;
    int total = 0;
    double azimuth = Math.atan2(target[10], target[9]);
    for (int attempt = 0; attempt <= SEEDS; attempt++) {
      startFrom(attempt, qStart, azimuth);
      double prevE = Double.POSITIVE_INFINITY;
      int stalls = 0;
      for (int it = 0; it < settings.iterationsPerAttempt(); it++) {
        total++;
        Jacobian.tcpJacobianInBase(chain, q, null, jac, pose, scratch);
        double e = error(invL);
        if (e < bestE) {
          bestE = e;
          System.arraycopy(q, 0, bestQ, 0, 6);
        }
        double ep = Math.sqrt(err[0] * err[0] + err[1] * err[1] + err[2] * err[2]);
        double er = Math.sqrt(err[3] * err[3] + err[4] * err[4] + err[5] * err[5]);
        if (ep < tolP && er < tolR) {
          return solved(total);
        }
        // Stalled: the error no longer falls by 1% per step (a local minimum or a limit).
        stalls = e > 0.99 * prevE ? stalls + 1 : 0;
        if (stalls >= 3) {
          break;
        }
        prevE = e;
        step(invL, e);
        if (total >= settings.maxIterations()) {
          return giveUp(total, "iteration cap");
        }
      }
      if ((attempt & 3) == 3 && System.nanoTime() - t0 > settings.timeCapNanos()) {
        return giveUp(total, "time cap");
      }
    }
    return giveUp(total, "all seeds tried");
  }

  /** Fills {@link #err} with the scaled error; returns ½|e|². */
  private double error(double invL) {
    err[0] = (target[9] - pose[9]) * invL;
    err[1] = (target[10] - pose[10]) * invL;
    err[2] = (target[11] - pose[11]) * invL;
    // R_err = R_d·Rᵀ; its rotation vector (log map) in the base frame.
    double m00 = target[0] * pose[0] + target[1] * pose[1] + target[2] * pose[2];
    double m01 = target[0] * pose[3] + target[1] * pose[4] + target[2] * pose[5];
    double m02 = target[0] * pose[6] + target[1] * pose[7] + target[2] * pose[8];
    double m10 = target[3] * pose[0] + target[4] * pose[1] + target[5] * pose[2];
    double m11 = target[3] * pose[3] + target[4] * pose[4] + target[5] * pose[5];
    double m12 = target[3] * pose[6] + target[4] * pose[7] + target[5] * pose[8];
    double m20 = target[6] * pose[0] + target[7] * pose[1] + target[8] * pose[2];
    double m21 = target[6] * pose[3] + target[7] * pose[4] + target[8] * pose[5];
    double m22 = target[6] * pose[6] + target[7] * pose[7] + target[8] * pose[8];
    double sx = 0.5 * (m21 - m12), sy = 0.5 * (m02 - m20), sz = 0.5 * (m10 - m01);
    double sn = Math.sqrt(sx * sx + sy * sy + sz * sz);
    double cs = 0.5 * (m00 + m11 + m22 - 1);
    if (sn > 1e-7) {
      double f = Math.atan2(sn, cs) / sn;
      err[3] = f * sx;
      err[4] = f * sy;
      err[5] = f * sz;
    } else if (cs > 0) {
      err[3] = sx;
      err[4] = sy;
      err[5] = sz;
    } else {
      // A half turn: the axis from the symmetric part, R = 2aaᵀ − I.
      double ax = Math.sqrt(Math.max(0, (m00 + 1) / 2));
      double ay = Math.sqrt(Math.max(0, (m11 + 1) / 2));
      double az = Math.sqrt(Math.max(0, (m22 + 1) / 2));
      if (ax >= ay && ax >= az) {
        ay = Math.copySign(ay, m01);
        az = Math.copySign(az, m02);
      } else if (ay >= az) {
        ax = Math.copySign(ax, m01);
        az = Math.copySign(az, m12);
      } else {
        ax = Math.copySign(ax, m02);
        ay = Math.copySign(ay, m12);
      }
      err[3] = Math.PI * ax;
      err[4] = Math.PI * ay;
      err[5] = Math.PI * az;
    }
    double e = 0;
    for (int i = 0; i < 6; i++) {
      e += err[i] * err[i];
    }
    return 0.5 * e;
  }

  /** One damped step (Jsᵀ·Js + λI)·Δq = Jsᵀ·e, then clamp to the limits. */
  private void step(double invL, double e) {
    for (int c = 0; c < 18; c++) {
      jac[c] *= invL;
    }
    double lambda = e + BASE_DAMPING;
    for (int r = 0; r < 6; r++) {
      double gr = 0;
      for (int k = 0; k < 6; k++) {
        gr += jac[k * 6 + r] * err[k];
      }
      g[r] = gr;
      for (int c = 0; c <= r; c++) {
        double sum = 0;
        for (int k = 0; k < 6; k++) {
          sum += jac[k * 6 + r] * jac[k * 6 + c];
        }
        a[r * 6 + c] = r == c ? sum + lambda : sum;
      }
    }
    // Cholesky (lower, in place) and two triangular solves.
    for (int r = 0; r < 6; r++) {
      for (int c = 0; c <= r; c++) {
        double sum = a[r * 6 + c];
        for (int k = 0; k < c; k++) {
          sum -= a[r * 6 + k] * a[c * 6 + k];
        }
        a[r * 6 + c] = r == c ? Math.sqrt(sum) : sum / a[c * 6 + c];
      }
    }
    for (int r = 0; r < 6; r++) {
      double sum = g[r];
      for (int k = 0; k < r; k++) {
        sum -= a[r * 6 + k] * g[k];
      }
      g[r] = sum / a[r * 6 + r];
    }
    for (int r = 5; r >= 0; r--) {
      double sum = g[r];
      for (int k = r + 1; k < 6; k++) {
        sum -= a[k * 6 + r] * g[k];
      }
      g[r] = sum / a[r * 6 + r];
      double v = q[r] + g[r];
      q[r] = v < lower[r] ? lower[r] : (v > upper[r] ? upper[r] : v);
    }
  }

  /** Attempt 0 starts from the caller's joints; later ones from the seed list, J1 toward the target. */
  private void startFrom(int attempt, double[] qStart, double azimuth) {
    if (attempt == 0) {
      for (int i = 0; i < 6; i++) {
        q[i] = Math.max(lower[i], Math.min(upper[i], qStart[i]));
      }
      return;
    }
    System.arraycopy(seeds, (attempt - 1) * 6, q, 0, 6);
    // Odd attempts face the target, even ones turn their back to it (reaching over the top).
    double q1 = (attempt & 1) == 1 ? azimuth : ClosedFormIk.wrap(azimuth + Math.PI);
    q[0] = Math.max(lower[0], Math.min(upper[0], q1));
  }

  private IkResult.Unreachable precheck() {
    if (reachCheck.isPresent()) {
      // Only the verdict is used: the numeric solve below never sees the closed-form joints.
      IkResult r = reachCheck.get().solveNearest(target, zeros());
      return switch (r) {
        case IkResult.Solved s -> null;
        case IkResult.Unreachable u -> u;
      };
    }
    double dx = target[9] - shoulder[0] * 0, dy = target[10], dz = target[11] - shoulder[2];
    double horizontal = Math.sqrt(dx * dx + dy * dy);
    double d = Math.hypot(horizontal - Math.hypot(shoulder[0], shoulder[1]), dz);
    if (d > reachRadiusMm) {
      return new IkResult.Unreachable(IkResult.Reason.OUT_OF_REACH, String.format(
          "position (%.1f, %.1f, %.1f) mm is %.0f mm from the shoulder, beyond the %.0f mm reach",
          target[9], target[10], target[11], d, reachRadiusMm));
    }
    return null;
  }

  private final double[] zeros = new double[6];

  private double[] zeros() {
    return zeros;
  }

  private IkResult solved(int iterations) {
    double dx = pose[9] - target[9], dy = pose[10] - target[10], dz = pose[11] - target[11];
    return new IkResult.Solved(q.clone(), Math.sqrt(dx * dx + dy * dy + dz * dz),
        ClosedFormIk.rotationAngle(pose, target), iterations);
  }

  /** No convergence: say whether the best attempt was pinned at a limit or near a singularity. */
  private IkResult giveUp(int iterations, String why) {
    chain.flangePose(bestQ, pose, null);
    double dx = pose[9] - target[9], dy = pose[10] - target[10], dz = pose[11] - target[11];
    double posErr = Math.sqrt(dx * dx + dy * dy + dz * dz);
    double rotErr = ClosedFormIk.rotationAngle(pose, target);
    int atLimit = -1;
    for (int i = 0; i < 6 && atLimit < 0; i++) {
      if (bestQ[i] <= lower[i] + 1e-9 || bestQ[i] >= upper[i] - 1e-9) {
        atLimit = i;
      }
    }
    String detail = String.format("best error %.3f mm, %.4f rad after %d iterations (%s)",
        posErr, rotErr, iterations, why);
    if (atLimit >= 0) {
      return new IkResult.Unreachable(IkResult.Reason.JOINT_LIMIT,
          "no solution found inside the joint limits; J" + (atLimit + 1) + " stopped at its limit; " + detail);
    }
    return new IkResult.Unreachable(IkResult.Reason.NO_CONVERGENCE, "no solution found: " + detail);
  }

  /** Halton points (bases 2, 3, 5, 7, 11, 13) over the joint ranges: fixed, well spread. */
  private void fillSeeds() {
    int[] bases = {2, 3, 5, 7, 11, 13};
    for (int s = 0; s < SEEDS; s++) {
      for (int i = 0; i < 6; i++) {
        double h = halton(s + 1, bases[i]);
        // Stay off the limits themselves: the middle 80 % of each range.
        seeds[s * 6 + i] = lower[i] + (0.1 + 0.8 * h) * (upper[i] - lower[i]);
      }
    }
  }

  private static double halton(int index, int base) {
    double f = 1, r = 0;
    for (int i = index; i > 0; i /= base) {
      f /= base;
      r += f * (i % base);
    }
    return r;
  }
}
