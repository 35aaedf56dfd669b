package org.robotrun.robot;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Numeric position IK for any 6-axis arm: damped least squares (Levenberg–Marquardt) on the
 * analytic Jacobian, joints kept inside their limits by an active set, restarts from a fixed,
 * deterministic list of seeds, and hard caps on iterations and time. Never returns null,
 * never hangs.
 *
 * <p>Method. The error is {@code e = [(p_d − p)/L; log(R_d·Rᵀ)]} (position scaled by a
 * characteristic length L so millimetres and radians weigh alike). Each step solves
 * {@code (Jsᵀ·Js + λI)·Δq = Jsᵀ·e} with {@code λ = μ·½|e|² + λ0}: the damping follows the
 * error, after Sugihara, "Solvability-unconcerned inverse kinematics by the Levenberg–Marquardt
 * method" (IEEE T-RO 2011), so far from the target the step is short and steady and near it the
 * solve becomes Gauss–Newton with quadratic convergence. A joint at a limit that the step would
 * push further out is taken out of the step (its column dropped) so the others make up for it.
 * An attempt is abandoned when the error stops falling (local minimum, often pinned at a limit)
 * or after a per-attempt iteration budget; the next seed then starts: the caller's start, then
 * 64 seeds spread over the joint ranges (a Halton sequence), two of every three with J1 turned
 * toward or away from the target's wrist point, with twins across J1's limit gap; then 32 seeds in the outer
 * tenth of each range (postures folded to their limits); 16 seeds with the arm folded hard (J2
 * at the top, J3 at the bottom of its range); and at last a patient polish of the best posture
 * found, which may be creeping along a limit. A joint whose step would cross a limit is held at
 * the limit and the rest of the step solved again (an active set), and λ0 shrinks with the
 * error so the last steps near a singular wrist are Gauss–Newton.
 *
 * <p>Unreachable targets are recognised before iterating where possible: with OPW parameters
 * the closed form's reachability answer (beyond reach, or no solution inside the limits) is
 * used, without using its solutions; otherwise a reach check around the circle J2 sweeps about
 * the J1 axis.
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
   * @param timeCapNanos cap on the thread CPU time of one solve (ns), counted from the end of
   *     the first attempt
   * @param lengthScaleMm L, the length that weighs as one radian
   * @param dampingGain μ in λ = μ·½|e|² + λ0
   * @param stallRatio an attempt stalls when the error falls by less than this factor per step
   */
  public record Settings(
      double positionToleranceMm, double orientationToleranceRad, int iterationsPerAttempt,
      int maxIterations, long timeCapNanos, double lengthScaleMm, double dampingGain, double stallRatio) {

    public Settings {
      if (!(positionToleranceMm > 0 && orientationToleranceRad > 0 && iterationsPerAttempt > 0
          && maxIterations > 0 && timeCapNanos > 0 && lengthScaleMm > 0 && dampingGain >= 0
          && stallRatio > 0 && stallRatio <= 1)) {
        throw new IllegalArgumentException("numeric IK settings out of range: " + this);
      }
    }

    /**
     * 1e-6 mm, 1e-9 rad; 20 iterations per attempt, 2000 in all (about 1 ms once compiled);
     * 20 ms of CPU time as a safety net only (code the JIT has not compiled yet runs ~50 times
     * slower, and the iteration cap keeps results independent of machine speed); L = 300 mm,
     * μ = 0.1, stalled after three steps gaining less than 5 % each. Tuned on the LR Mate
     * reference targets: all three starts solve every row; from a random start the median is
     * 15 iterations, p99 about 110, worst about 220.
     */
    public static Settings defaults() {
      return new Settings(1e-6, 1e-9, 20, 2000, 20_000_000, 300, 0.1, 0.95);
    }
  }

  private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();
  private static final boolean CPU_TIME = CPU.isCurrentThreadCpuTimeSupported();
  /** Seeds in the middle 80 % of each range (most solutions are found from these). */
  private static final int MIDDLE_SEEDS = 64;
  /**
   * Seeds in the outer tenth at either end of each range: a posture folded to its limits (J2
   * near +139°, J3 near −68°, the wrist over the base) is a basin the middle seeds never start in.
   */
  private static final int EDGE_SEEDS = 32;
  /**
   * Seeds with the arm folded hard: J2 at the top of its range and J3 at the bottom (the corner
   * where the forearm lies back over the upper arm), the wrist spread by the Halton sequence.
   * Targets with J2 and J3 pinned there and J1 or J6 at a limit too sit in basins so narrow that
   * no edge seed started in them.
   */
  private static final int FOLDED_SEEDS = 16;
  private static final int SEEDS = MIDDLE_SEEDS + EDGE_SEEDS + FOLDED_SEEDS;
  /** Middle seeds stay off the limits: the middle 80 % of each range. */
  private static final double SEED_MARGIN = 0.1;
  /** Iterations of the final polish from the best posture (a slow crawl along a limit). */
  private static final int POLISH_ITERATIONS = 800;
  /** Polished only when the best posture's scaled error is below this many millimetres. */
  private static final double POLISH_BELOW_MM = 0.5;
  /** Below this manipulability (|det| of the scaled Jacobian) a failed solve is SINGULAR. */
  private static final double SINGULAR_MANIPULABILITY = 1e-4;
  /** λ0: keeps the normal equations positive definite at singularities. */
  private static final double BASE_DAMPING = 1e-9;
  /** The least λ0 when the error is tiny: still well above rounding in the normal equations. */
  private static final double MIN_DAMPING = 1e-16;

  private final KinematicChain chain;
  private final Settings settings;
  private final Optional<ClosedFormIk> reachCheck;
  private final double reachRadiusMm;
  /** The J1 axis line in the base frame: a point on it and its unit direction. */
  private final double[] j1Origin = new double[3];
  private final double[] j1Axis = new double[3];
  /** J2's origin at q = 0 along the J1 axis (from {@link #j1Origin}) and off it: its circle. */
  private final double shoulderAlong;
  private final double shoulderOff;
  /**
   * The wrist point (J5's origin) in the flange frame when it lies on J6's axis, so that it
   * does not move with J6 (a spherical or offset wrist); else the flange origin (all zero).
   */
  private final double[] wristInFlange = new double[3];
  private final double[] lower;
  private final double[] upper;
  private final double[] seeds = new double[SEEDS * 6];

  private final double[] target = new double[12];
  private final double[] pose = new double[12];
  private final double[] jac = new double[36];
  private final double[] scratch = new double[Jacobian.SCRATCH];
  private final double[] err = new double[6];
  private final double[] a = new double[36];
  private final double[] jt = new double[36];
  private final double[] invDiag = new double[6];
  private final double[] g = new double[6];
  private final double[] rhs = new double[6];
  private final double[] fixedStep = new double[6];
  private final double[] q = new double[6];
  private final double[] bestQ = new double[6];
  private final int[] perm = new int[6];
  private final double[] j1Seeds = new double[8];
  private int j1SeedCount;
  /** Lowest ½|e|² seen in this solve, at {@link #bestQ}. */
  private double bestE;
  /** Iterations so far in this solve. */
  private int total;

  public NumericIk(RobotModel model) {
    this(model, Settings.defaults());
  }

  public NumericIk(RobotModel model, Settings settings) {
    this.chain = new KinematicChain(model);
    this.settings = settings;
    this.reachCheck = model.opw().map(p -> new ClosedFormIk(model));
    this.lower = model.lowerLimits();
    this.upper = model.upperLimits();
    // Reach: no point is farther from the circle J2's origin sweeps about the J1 axis than the
    // sum of the offsets from J2 on, flange included (a loose but safe bound for any arm). The
    // circle is taken about the J1 axis line itself, wherever the base frame puts it.
    Transform x1 = model.joint(0).X_PJ();
    Vec3 a1 = x1.rotate(model.joint(0).axis()).normalized();
    j1Origin[0] = x1.x();
    j1Origin[1] = x1.y();
    j1Origin[2] = x1.z();
    j1Axis[0] = a1.x();
    j1Axis[1] = a1.y();
    j1Axis[2] = a1.z();
    Vec3 s2 = x1.compose(model.joint(1).X_PJ()).translationVector().minus(x1.translationVector());
    shoulderAlong = s2.dot(a1);
    shoulderOff = s2.minus(a1.times(shoulderAlong)).norm();
    double r = 0;
    for (int i = 2; i < RobotModel.DOF; i++) {
      r += model.joint(i).X_PJ().translationVector().norm();
    }
    reachRadiusMm = r + model.X_6F().translationVector().norm();
    JointSpec j6 = model.joint(RobotModel.DOF - 1);
    Vec3 j5InJ6 = j6.X_PJ().inverse().translationVector();
    if (j5InJ6.cross(j6.axis()).norm() <= 1e-9 * (1 + j5InJ6.norm())) {
      Vec3 w = model.X_6F().inverse().apply(j5InJ6);
      wristInFlange[0] = w.x();
      wristInFlange[1] = w.y();
      wristInFlange[2] = w.z();
    }
    fillSeeds();
  }

  /**
   * Solves for a flange pose in the base frame, starting from {@code qStart} (rad). For a tool
   * target {@code X_BT} ask for {@link ClosedFormIk#flangeTarget(Transform, Transform)}.
   */
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
    if (qStart.length != RobotModel.DOF) {
      throw new IllegalArgumentException("expected 6 start joint values, got " + qStart.length);
    }
    long t0 = -1;
    double invL = 1 / settings.lengthScaleMm();
    double tolP = settings.positionToleranceMm() * invL;
    double tolR = settings.orientationToleranceRad();
    bestE = Double.POSITIVE_INFINITY;
    total = 0;
    for (int attempt = 0; attempt <= SEEDS; attempt++) {
      if (attempt == 1) {
        // The start did not lead there: before restarting, reject what cannot be reached.
        Optional<IkResult.Unreachable> early = precheck();
        if (early.isPresent()) {
          return early.get();
        }
        // J1 turns toward the wrist point, not the flange: for a target near the J1 axis (the
        // wrist folded back over the base) the flange's azimuth says nothing about J1.
        double wx = target[0] * wristInFlange[0] + target[1] * wristInFlange[1] + target[2] * wristInFlange[2] + target[9];
        double wy = target[3] * wristInFlange[0] + target[4] * wristInFlange[1] + target[5] * wristInFlange[2] + target[10];
        fillJ1Seeds(Math.atan2(wy, wx));
      }
      startFrom(attempt, qStart);
      if (attemptConverges(invL, tolP, tolR, settings.iterationsPerAttempt(), 3)) {
        return solved(total);
      }
      if (total >= settings.maxIterations()) {
        return giveUp(total, "iteration cap");
      }
      // Checked between attempts only (most solves finish in the first): CPU time of this
      // thread, so a busy machine that deschedules us does not turn a solve into a failure.
      long now = CPU_TIME ? CPU.getCurrentThreadCpuTime() : System.nanoTime();
      if (t0 < 0) {
        t0 = now;
      } else if (now - t0 > settings.timeCapNanos()) {
        return giveUp(total, "time cap");
      }
    }
    // Every seed stalled: the best one, when already within a millimetre or so, may be creeping
    // along a limit toward the target, which the stall rule cuts short. Polish it, patiently.
    if (bestE < POLISH_BELOW_MM * POLISH_BELOW_MM * invL * invL) {
      System.arraycopy(bestQ, 0, q, 0, 6);
      if (attemptConverges(invL, tolP, tolR, POLISH_ITERATIONS, POLISH_ITERATIONS)) {
        return solved(total);
      }
    }
    return giveUp(total, "all seeds tried");
  }

  /**
   * Iterates from {@link #q} for at most {@code iterations}, giving up after {@code maxStalls}
   * steps in a row that gain too little; true when converged (q then holds the solution).
   */
  private boolean attemptConverges(double invL, double tolP, double tolR, int iterations, int maxStalls) {
    double prevE = Double.POSITIVE_INFINITY;
    int stalls = 0;
    for (int it = 0; it < iterations && total < settings.maxIterations(); it++) {
      total++;
      Jacobian.tcpJacobianInBase(chain, q, null, jac, pose, scratch);
      double e = error(invL);
      if (e < bestE) {
        bestE = e;
        System.arraycopy(q, 0, bestQ, 0, 6);
      }
      double ep2 = err[0] * err[0] + err[1] * err[1] + err[2] * err[2];
      double er2 = err[3] * err[3] + err[4] * err[4] + err[5] * err[5];
      if (ep2 < tolP * tolP && er2 < tolR * tolR) {
        return true;
      }
      // Stalled: the error no longer falls by the stall ratio per step (a local minimum or a limit).
      stalls = e > settings.stallRatio() * prevE ? stalls + 1 : 0;
      if (stalls >= maxStalls) {
        return false;
      }
      prevE = e;
      step(invL, e);
    }
    return false;
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
    if (cs > 0 && sn < 0.1) {
      // θ/sin θ = asin(s)/s as a series (to 1e-14 for s < 0.1): most iterations end up here,
      // and atan2 (not a JIT intrinsic) would be a tenth of an iteration's cost.
      double s2 = sn * sn;
      double f = 1 + s2 * (1.0 / 6 + s2 * (3.0 / 40 + s2 * (5.0 / 112 + s2 * (35.0 / 1152 + s2 * (63.0 / 2816)))));
      err[3] = f * sx;
      err[4] = f * sy;
      err[5] = f * sz;
    } else if (sn > 1e-7) {
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

  /**
   * One damped step {@code (Jsᵀ·Js + λI)·Δq = Jsᵀ·e}, then clamp to the limits. A joint already
   * at a limit that the step would push further out is locked (its column removed) and the step
   * solved again, so the other joints take up its share instead of the step being cut short.
   */
  private void step(double invL, double e) {
    for (int c = 0; c < 18; c++) {
      jac[c] *= invL;
    }
    // λ0 shrinks with the error (down to a floor): near a singular wrist (J5 within ~1e-4 rad
    // of 0) the smallest singular value σ of Js is about |J5|, and a fixed λ0 ≫ σ² would let
    // each step gain only σ²/(σ² + λ0) of the error along that direction (a crawl that ended
    // a hair short of the tolerance).
    double lambda = settings.dampingGain() * e + Math.max(MIN_DAMPING, Math.min(BASE_DAMPING, e));
    // Active set: a joint whose step would leave its range is held at the limit (Δq = the
    // distance to it, its column taken out) and the rest of the step solved again for what is
    // left of the error, so the other joints make up for it instead of the step being cut short.
    int locked = 0;
    System.arraycopy(err, 0, rhs, 0, 6);
    for (int pass = 0; pass < 6; pass++) {
      solveNormalEquations(lambda, locked);
      if (!finite(g)) {
        // Cholesky lost positive definiteness to rounding on an exactly singular posture.
        lambda += BASE_DAMPING;
        solveNormalEquations(lambda, locked);
      }
      int more = locked;
      for (int r = 0; r < 6; r++) {
        if ((locked & (1 << r)) != 0) {
          continue;
        }
        double v = q[r] + g[r];
        double d = v < lower[r] ? lower[r] - q[r] : (v > upper[r] ? upper[r] - q[r] : Double.NaN);
        if (!Double.isNaN(d)) {
          more |= 1 << r;
          fixedStep[r] = d;
          for (int k = 0; k < 6; k++) {
            rhs[k] -= jac[k * 6 + r] * d;
          }
        }
      }
      if (more == locked) {
        break;
      }
      locked = more;
    }
    for (int r = 0; r < 6; r++) {
      double v = q[r] + ((locked & (1 << r)) != 0 ? fixedStep[r] : g[r]);
      q[r] = v < lower[r] ? lower[r] : (v > upper[r] ? upper[r] : v);
    }
  }

  private static boolean finite(double[] v) {
    double s = 0;
    for (double x : v) {
      s += x;
    }
    return Double.isFinite(s);
  }

  /** g = Δq from the normal equations with the locked joints' columns left out (Δq = 0 there). */
  private void solveNormalEquations(double lambda, int locked) {
    // jt = Jsᵀ (rows contiguous), a locked joint's row zeroed: its Δq comes out 0.
    for (int r = 0; r < 6; r++) {
      boolean l = (locked & (1 << r)) != 0;
      int ro = r * 6;
      for (int k = 0; k < 6; k++) {
        jt[ro + k] = l ? 0 : jac[k * 6 + r];
      }
    }
    for (int r = 0; r < 6; r++) {
      int ro = r * 6;
      double t0 = jt[ro], t1 = jt[ro + 1], t2 = jt[ro + 2], t3 = jt[ro + 3], t4 = jt[ro + 4], t5 = jt[ro + 5];
      g[r] = t0 * rhs[0] + t1 * rhs[1] + t2 * rhs[2] + t3 * rhs[3] + t4 * rhs[4] + t5 * rhs[5];
      for (int c = 0; c <= r; c++) {
        int co = c * 6;
        a[ro + c] = t0 * jt[co] + t1 * jt[co + 1] + t2 * jt[co + 2] + t3 * jt[co + 3]
            + t4 * jt[co + 4] + t5 * jt[co + 5];
      }
      a[ro + r] += lambda;
    }
    Dense6.choleskySolve(a, g, invDiag);
  }

  /** Attempt 0 starts from the caller's joints; later ones from the seed list. */
  private void startFrom(int attempt, double[] qStart) {
    if (attempt == 0) {
      for (int i = 0; i < 6; i++) {
        q[i] = Math.max(lower[i], Math.min(upper[i], qStart[i]));
      }
      return;
    }
    System.arraycopy(seeds, (attempt - 1) * 6, q, 0, 6);
    // Two of every three restarts turn J1 toward (or away from) the target; the third keeps the
    // seed's own J1, for postures folded around the base where neither is close. Folded seeds
    // keep their J1, near a limit.
    int slot = (attempt - 1) % 3;
    if (slot < 2 && attempt <= MIDDLE_SEEDS + EDGE_SEEDS) {
      q[0] = j1Seeds[((attempt - 1) / 3 * 2 + slot) % j1SeedCount];
    }
  }

  /**
   * J1 seeds for a target at azimuth {@code az}: facing it and turned away from it (reaching
   * over the top), each moved into the J1 range by ±2π where it can be, else clamped. The
   * solver cannot cross the gap beyond the J1 limits, and the solution's J1 may differ from
   * the azimuth by tens of degrees (folded or offset wrists), so a seed within 90° of the gap
   * gets a twin just across it.
   */
  private void fillJ1Seeds(double az) {
    j1SeedCount = 0;
    addJ1Seeds(az);
    addJ1Seeds(az + Math.PI);
  }

  private void addJ1Seeds(double angle) {
    double lo = lower[0], hi = upper[0];
    double margin = 0.02 * (hi - lo);
    double a = ClosedFormIk.wrap(angle);
    double v = Double.NaN;
    for (int turn = -1; turn <= 1; turn++) {
      double w = a + turn * 2 * Math.PI;
      if (w >= lo && w <= hi) {
        v = w;
      }
    }
    if (Double.isNaN(v)) {
      // In the gap: both ends of the range.
      j1Seeds[j1SeedCount++] = hi - margin;
      j1Seeds[j1SeedCount++] = lo + margin;
      return;
    }
    j1Seeds[j1SeedCount++] = v;
    boolean hasGap = hi - lo < 2 * Math.PI;
    if (hasGap && hi - v < Math.PI / 2) {
      j1Seeds[j1SeedCount++] = lo + margin;
    } else if (hasGap && v - lo < Math.PI / 2) {
      j1Seeds[j1SeedCount++] = hi - margin;
    }
  }

  /** Why the target cannot be reached, if that is known without iterating. */
  private Optional<IkResult.Unreachable> precheck() {
    if (reachCheck.isPresent()) {
      // Only the verdict is used: the numeric solve below never sees the closed-form joints.
      return reachCheck.get().reachability(target);
    }
    // The target's distance from the circle J2's origin sweeps about the J1 axis.
    double vx = target[9] - j1Origin[0], vy = target[10] - j1Origin[1], vz = target[11] - j1Origin[2];
    double along = vx * j1Axis[0] + vy * j1Axis[1] + vz * j1Axis[2];
    double ox = vx - along * j1Axis[0], oy = vy - along * j1Axis[1], oz = vz - along * j1Axis[2];
    double d = Math.hypot(Math.sqrt(ox * ox + oy * oy + oz * oz) - shoulderOff, along - shoulderAlong);
    if (d > reachRadiusMm) {
      return Optional.of(new IkResult.Unreachable(IkResult.Reason.OUT_OF_REACH, String.format(
          "position (%.1f, %.1f, %.1f) mm is %.0f mm from the shoulder, beyond the %.0f mm reach",
          target[9], target[10], target[11], d, reachRadiusMm)));
    }
    return Optional.empty();
  }

  private IkResult solved(int iterations) {
    double dx = pose[9] - target[9], dy = pose[10] - target[10], dz = pose[11] - target[11];
    return new IkResult.Solved(q.clone(), Math.sqrt(dx * dx + dy * dy + dz * dz),
        ClosedFormIk.rotationAngle(pose, target), iterations);
  }

  /** No convergence: say whether the best attempt was pinned at a limit or near a singularity. */
  private IkResult giveUp(int iterations, String why) {
    Jacobian.tcpJacobianInBase(chain, bestQ, null, jac, pose, scratch);
    double dx = pose[9] - target[9], dy = pose[10] - target[10], dz = pose[11] - target[11];
    double posErr = Math.sqrt(dx * dx + dy * dy + dz * dz);
    double rotErr = ClosedFormIk.rotationAngle(pose, target);
    int atLimit = -1;
    for (int i = 0; i < 6 && atLimit < 0; i++) {
      if (bestQ[i] <= lower[i] + 1e-9 || bestQ[i] >= upper[i] - 1e-9) {
        atLimit = i;
      }
    }
    String detail = String.format(java.util.Locale.ROOT, "best error %.3g mm, %.3g rad after %d iterations (%s)",
        posErr, rotErr, iterations, why);
    if (atLimit >= 0) {
      return new IkResult.Unreachable(IkResult.Reason.JOINT_LIMIT,
          "no solution found inside the joint limits; J" + (atLimit + 1) + " stopped at its limit; " + detail);
    }
    // Manipulability |det Js| of the best posture (scaled as in the iterations).
    double invL = 1 / settings.lengthScaleMm();
    for (int c = 0; c < 18; c++) {
      jac[c] *= invL;
    }
    double w = Math.abs(Dense6.luDecompose(jac, perm));
    if (w < SINGULAR_MANIPULABILITY) {
      return new IkResult.Unreachable(IkResult.Reason.SINGULAR,
          "no solution found: the closest posture is singular (arm stretched, folded or wrist "
              + "axes in line), typically just beyond reach; " + detail);
    }
    return new IkResult.Unreachable(IkResult.Reason.NO_CONVERGENCE, "no solution found: " + detail);
  }

  /** Halton points (bases 2, 3, 5, 7, 11, 13) over the joint ranges: fixed, well spread. */
  private void fillSeeds() {
    int[] bases = {2, 3, 5, 7, 11, 13};
    for (int s = 0; s < MIDDLE_SEEDS; s++) {
      for (int i = 0; i < 6; i++) {
        double h = halton(s + 1, bases[i]);
        seeds[s * 6 + i] = lower[i] + (SEED_MARGIN + (1 - 2 * SEED_MARGIN) * h) * (upper[i] - lower[i]);
      }
    }
    // Edge seeds: the same sequence folded into the outer bands [0, 10 %] and [90 %, 100 %].
    for (int s = MIDDLE_SEEDS; s < MIDDLE_SEEDS + EDGE_SEEDS; s++) {
      for (int i = 0; i < 6; i++) {
        double h = halton(s + 1, bases[i]);
        double t = h < 0.5 ? 2 * h * SEED_MARGIN : 1 - 2 * (h - 0.5) * SEED_MARGIN;
        seeds[s * 6 + i] = lower[i] + t * (upper[i] - lower[i]);
      }
    }
    for (int s = MIDDLE_SEEDS + EDGE_SEEDS; s < SEEDS; s++) {
      for (int i = 0; i < 6; i++) {
        double h = halton(s + 1, bases[i]);
        double t = switch (i) {
          case 0 -> h < 0.5 ? 2 * h * SEED_MARGIN : 1 - 2 * (h - 0.5) * SEED_MARGIN; // J1 near a limit
          case 1 -> 1 - 0.03 * h;
          case 2 -> 0.03 * h;
          default -> h;
        };
        seeds[s * 6 + i] = lower[i] + t * (upper[i] - lower[i]);
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
