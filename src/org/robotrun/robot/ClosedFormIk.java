package org.robotrun.robot;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robotrun.math.Transform;

/**
 * Closed-form inverse kinematics for ortho-parallel arms with a spherical wrist, after
 * Brandstötter, Angerer and Hofbaur, "An analytical solution of the inverse kinematics problem
 * of industrial serial manipulators with an ortho-parallel basis and a spherical wrist" (2014):
 * the wrist centre gives two J1 values, each with two (J2, J3) elbows; each of those four
 * arms has two wrists, so up to eight solutions, each labelled with a FANUC {@link Config}.
 * Targets are flange poses in the robot base frame B (mm); joint values in the kinematic
 * convention (rad), {@code q = sign·(θ_opw + offset)} as in {@link OpwParameters}. An arm whose
 * base or flange frame is not where OPW puts it is solved for {@code X_BO⁻¹ · X_BF · X_F'F⁻¹}
 * (the parameters' constant corrections); the result is still checked against the chain's FK.
 *
 * <h2>CONFIG flags for this family of arms</h2>
 * Let θ be the OPW angles of a joint vector ({@code θ = sign·q − offset}).
 * <ul>
 *   <li><b>F/N</b> (wrist): F when J5 &gt; 0, N when J5 ≤ 0. The two wrist solutions of one arm
 *       have opposite J5 ({@code θ5' = −θ5}), so each arm has one F and one N solution.
 *       (J5 = −90° with J4 = 0 is the tool-down posture FANUC teaches as 'N U T'; the same sign
 *       rule as ROS-Industrial tesseract's {@code getRobotConfig} for FANUC arms.)
 *   <li><b>U/D</b> (elbow): U when {@code sin(θ3 + atan2(a2, c3)) > 0}, i.e. the wrist centre is
 *       on the forward side of the upper arm (for the LR Mate: kinematic J3 &lt; 84.0°, where
 *       the forearm and upper arm line up, the elbow singularity). The OPW elbow pairs are
 *       {@code θ3 = ±acos(…) − atan2(a2, c3)}, so of each J1 pair one is U and one D.
 *   <li><b>T/B</b> (arm): T when the wrist centre lies in front of the J1 axis, measured along
 *       link 1's forward axis: {@code a1 + c2·sin θ2 + c3·sin(θ2+θ3) + a2·cos(θ2+θ3) > 0}.
 *       The two J1 solutions differ by 180° (b = 0), so one is T and one B.
 * </ul>
 * So the eight solutions map one to one onto the eight flag triples (a test checks this on
 * every reference pose, and another checks each flag against its geometric meaning from the
 * link frames: the wrist centre in link 1's and link 2's frames). Turn numbers are {@link Config#turnOf} of J1, J4, J6;
 * {@link #allSolutions} lists every whole-turn variant inside the limits, of every joint.
 *
 * <p>Not thread-safe (scratch arrays); allocation-free apart from the result object.
 */
public final class ClosedFormIk implements IkSolver {
  /** {@link IkSolver#kind()} of this solver. */
  public static final String KIND = "closed-form";
  /** Base solutions before turn variants: four arms times two wrists. */
  public static final int BASE_SOLUTIONS = 8;

  private static final double TWO_PI = 2 * Math.PI;
  /** Below this sin θ5 the wrist is treated as singular (θ4 and θ6 only defined as a sum). */
  private static final double WRIST_SINGULAR = 1e-9;
  /** Slack on the cosine-law arguments so exactly stretched poses still solve. */
  private static final double ACOS_SLACK = 1e-10;
  /** {@link #reachability}'s "maybe inside the limits" slack (rad): well above its rounding. */
  private static final double VERDICT_SLACK = 1e-6;
  /** A wrist centre this close to the J1 axis (mm) leaves J1 undetermined for {@link #reachability}. */
  private static final double SHOULDER_FREE_MM = 1e-5;

  private final RobotModel model;
  private final KinematicChain chain;
  private final double a1, a2, b, c1, c2, c3, c4, kappa, psi;
  private final double[] offset = new double[6];
  private final double[] sign = new double[6];
  private final JointRange range;

  private final double[] target = new double[12];
  private final double[] base = new double[BASE_SOLUTIONS * 6];
  private final boolean[] singularWrist = new boolean[BASE_SOLUTIONS];
  private final double[] fk = new double[12];
  private final double[] cand = new double[6];
  private final double[] best = new double[6];
  // Base and flange corrections (OpwParameters): X_OB and X_FF', and the target they give.
  private final boolean corrected;
  private final double[] xob = new double[12];
  private final double[] xffp = new double[12];
  private final double[] scratch = new double[12];
  private final double[] opwTarget = new double[12];
  /** Newton steps that finish each answer when the chain is OPW only to within rounding; else null. */
  private final NewtonPolish polish;

  /** @throws IllegalArgumentException if the model has no OPW parameters */
  public ClosedFormIk(RobotModel model) {
    OpwParameters p = model.opw().orElseThrow(() -> new IllegalArgumentException(
        model.id() + ": no OPW parameters, the closed-form solver does not apply"));
    this.model = model;
    this.chain = new KinematicChain(model);
    a1 = p.a1();
    a2 = p.a2();
    b = p.b();
    c1 = p.c1();
    c2 = p.c2();
    c3 = p.c3();
    c4 = p.c4();
    corrected = p.corrected();
    polish = p.approximate() ? new NewtonPolish(chain) : null;
    KinematicChain.pack(p.base().inverse(), xob, 0);
    KinematicChain.pack(p.flange().inverse(), xffp, 0);
    kappa = Math.sqrt(a2 * a2 + c3 * c3);
    psi = Math.atan2(a2, c3);
    for (int i = 0; i < 6; i++) {
      offset[i] = p.offsetRad(i);
      sign[i] = p.sign(i);
    }
    // Round-off can put a solution at a limit 1e-15 outside it: accept that and clamp.
    range = new JointRange(model);
  }

  @Override
  public RobotModel model() {
    return model;
  }

  @Override
  public String kind() {
    return KIND;
  }

  /** OPW branches are told apart by their CONFIG alone, so {@code qNear} is not needed. */
  @Override
  public IkResult solve(Transform X_BF, Config config, double[] qNear) {
    return solve(X_BF, config);
  }

  /**
   * The flange pose to ask for so that the tool frame T reaches {@code X_BT}:
   * {@code X_BF = X_BT · X_FT⁻¹}.
   */
  public static Transform flangeTarget(Transform X_BT, Transform X_FT) {
    return X_BT.compose(X_FT.inverse());
  }

  /** The CONFIG of a joint vector (see the class comment for the definitions). */
  @Override
  public Config configOf(double[] q) {
    return new Config(flipMargin(q) > 0, upMargin(q) > 0, topMargin(q) > 0,
        Config.turnOf(q[0]), Config.turnOf(q[3]), Config.turnOf(q[5]));
  }

  /**
   * Solves for the given CONFIG (taught positions): the branch whose F/N, U/D, T/B flags match,
   * with J1, J4, J6 moved to the asked turn numbers.
   */
  public IkResult solve(Transform X_BF, Config config) {
    KinematicChain.pack(X_BF, target, 0);
    return solve(target, config);
  }

  /** As {@link #solve(Transform, Config)} for a packed pose (12 doubles, see KinematicChain). */
  public IkResult solve(double[] X_BF, Config config) {
    if (X_BF != target) {
      System.arraycopy(X_BF, 0, target, 0, 12);
    }
    // The arm is known from the flags alone: T is the front J1 solution, U the +acos elbow
    // (see the class comment), so only that arm's wrist is computed.
    int arm = (config.top() ? 0 : 2) + (config.up() ? 0 : 1);
    double[] o6 = toOpw(target);
    int valid = solveBase(o6, 0, 1 << arm);
    if (valid == 0) {
      return solveBase(o6, 0) == 0 ? outOfReach() : new IkResult.Unreachable(
          IkResult.Reason.OUT_OF_REACH,
          "the pose is out of reach in CONFIG '" + config + "' (only the other arm side reaches it)");
    }
    // F/N: the wrist whose J5 has the asked sign (either one at the wrist singularity).
    int found = 2 * arm;
    if (!singularWrist[found] && (base[found * 6 + 4] > 0) != config.flip()) {
      found++;
    }
    int o = found * 6;
    for (int i = 0; i < 6; i++) {
      cand[i] = base[o + i];
    }
    cand[0] += TWO_PI * config.turn1();
    cand[3] += TWO_PI * config.turn4();
    cand[5] += TWO_PI * config.turn6();
    // J2, J3, J5 carry no turn number: take their variant inside the limits (J3 spans > 180°).
    cand[1] = range.intoLimits(cand[1], 1);
    cand[2] = range.intoLimits(cand[2], 2);
    cand[4] = range.intoLimits(cand[4], 4);
    for (int i = 0; i < 6; i++) {
      if (!range.ok(cand[i], i)) {
        return new IkResult.Unreachable(IkResult.Reason.JOINT_LIMIT, range.outside(config, i, cand[i]));
      }
      cand[i] = range.clamp(cand[i], i);
    }
    return solved(cand);
  }

  /**
   * The solution nearest to {@code qCurrent} (jogging): over every branch and every turn
   * variant inside the limits, the least sum of squared joint differences.
   */
  @Override
  public IkResult solveNearest(Transform X_BF, double[] qCurrent) {
    KinematicChain.pack(X_BF, target, 0);
    return solveNearest(target, qCurrent);
  }

  /** As {@link #solveNearest(Transform, double[])} for a packed pose. */
  public IkResult solveNearest(double[] X_BF, double[] qCurrent) {
    if (qCurrent.length != RobotModel.DOF) {
      throw new IllegalArgumentException("expected 6 current joint values, got " + qCurrent.length);
    }
    if (X_BF != target) {
      System.arraycopy(X_BF, 0, target, 0, 12);
    }
    int valid = solveBase(toOpw(target), sign[3] * qCurrent[3] - offset[3]);
    if (valid == 0) {
      return outOfReach();
    }
    if (!nearest(valid, qCurrent)) {
      return JointRange.everySolutionOutside();
    }
    return solved(best);
  }

  /**
   * Whether a packed flange pose may have a solution inside the limits, without building it:
   * empty if so, else why not. Cheaper than a solve (no result, no FK check); for other solvers'
   * quick rejection of unreachable targets, so it errs on the side of "maybe": a solution within
   * {@link #VERDICT_SLACK} of the limits counts. With the elbow stretched the closed form's acos
   * near ±1 loses half the digits (about 1e-8 rad), which would otherwise put a joint that sits
   * exactly at its limit just outside and turn a reachable target away.
   */
  public Optional<IkResult.Unreachable> reachability(double[] X_BF) {
    System.arraycopy(X_BF, 0, target, 0, 12);
    double[] o6 = toOpw(target);
    int valid = solveBase(o6, 0);
    if (valid == 0) {
      return Optional.of(outOfReach());
    }
    // The wrist centre on the J1 axis (a shoulder singularity): J1 is free there, but the base
    // solutions take it from the centre's meaningless azimuth, so the limits say nothing.
    double cx = o6[9] - c4 * o6[2], cy = o6[10] - c4 * o6[5];
    if (cx * cx + cy * cy - b * b < SHOULDER_FREE_MM * SHOULDER_FREE_MM) {
      return Optional.empty();
    }
    for (int k = 0; k < BASE_SOLUTIONS; k++) {
      if ((valid & (1 << k)) != 0 && withinLimitsLoosely(k)) {
        return Optional.empty();
      }
    }
    return Optional.of(JointRange.everySolutionOutside());
  }

  /** Base solution k has a turn of every joint within {@link #VERDICT_SLACK} of the limits. */
  private boolean withinLimitsLoosely(int k) {
    for (int i = 0; i < 6; i++) {
      double q = base[k * 6 + i];
      boolean any = false;
      for (int t = -2; t <= 2 && !any; t++) {
        double v = q + TWO_PI * t;
        any = v >= range.lower(i) - VERDICT_SLACK && v <= range.upper(i) + VERDICT_SLACK;
      }
      if (!any) {
        return false;
      }
    }
    return true;
  }

  /** Puts into {@link #best} the in-limit variant nearest to {@code qCurrent}; false if none. */
  private boolean nearest(int valid, double[] qCurrent) {
    double bestD = Double.POSITIVE_INFINITY;
    for (int k = 0; k < BASE_SOLUTIONS; k++) {
      if ((valid & (1 << k)) == 0) {
        continue;
      }
      int o = k * 6;
      double q1 = range.nearestTurn(base[o], qCurrent[0], 0);
      double q2 = range.nearestTurn(base[o + 1], qCurrent[1], 1);
      double q3 = range.nearestTurn(base[o + 2], qCurrent[2], 2);
      double q4 = range.nearestTurn(base[o + 3], qCurrent[3], 3);
      double q5 = range.nearestTurn(base[o + 4], qCurrent[4], 4);
      double q6 = range.nearestTurn(base[o + 5], qCurrent[5], 5);
      // NaN (no variant inside the limits) makes d NaN, which never compares smaller.
      double d = sq(q1 - qCurrent[0]) + sq(q2 - qCurrent[1]) + sq(q3 - qCurrent[2])
          + sq(q4 - qCurrent[3]) + sq(q5 - qCurrent[4]) + sq(q6 - qCurrent[5]);
      if (d < bestD) {
        bestD = d;
        best[0] = q1;
        best[1] = q2;
        best[2] = q3;
        best[3] = q4;
        best[4] = q5;
        best[5] = q6;
      }
    }
    return bestD != Double.POSITIVE_INFINITY;
  }

  /**
   * Every solution inside the joint limits, each turn variant separately, labelled with its
   * CONFIG. Empty when out of reach or only outside the limits. Allocates (not for hot loops).
   */
  @Override
  public List<Solution> allSolutions(Transform X_BF) {
    KinematicChain.pack(X_BF, target, 0);
    int valid = solveBase(toOpw(target), 0);
    List<Solution> out = new ArrayList<>();
    for (int k = 0; k < BASE_SOLUTIONS; k++) {
      if ((valid & (1 << k)) == 0) {
        continue;
      }
      double[] q0 = new double[6];
      System.arraycopy(base, k * 6, q0, 0, 6);
      for (double[] q : range.turnVariants(q0)) {
        if (polish != null) {
          polish.polish(q, target);
        }
        out.add(new Solution(q, configOf(q)));
      }
    }
    return out;
  }

  /**
   * The (up to) eight base solutions, each joint wrapped to (-π, π], not limit-checked.
   *
   * @param out 48 doubles: solution k at [6k..6k+5]
   * @return bit k set when solution k exists (0: out of reach)
   */
  public int solveAllBase(Transform X_BF, double[] out) {
    KinematicChain.pack(X_BF, target, 0);
    int valid = solveBase(toOpw(target), 0);
    System.arraycopy(base, 0, out, 0, base.length);
    return valid;
  }

  // ---------------------------------------------------------------------------------------

  /** The packed target in OPW's frames ({@code X_OB · X · X_FF'}); {@code X} itself without corrections. */
  private double[] toOpw(double[] X) {
    if (!corrected) {
      return X;
    }
    KinematicChain.compose(xob, X, scratch);
    KinematicChain.compose(scratch, xffp, opwTarget);
    return opwTarget;
  }

  /** Fills {@link #base}; returns the validity mask. Brandstötter et al. 2014, eqs. for θ1..θ6. */
  private int solveBase(double[] X, double theta4Singular) {
    return solveBase(X, theta4Singular, 0b1111);
  }

  /**
   * As {@link #solveBase(double[], double)} for the arms in {@code arms} only (bit i: arm i,
   * i.e. solutions 2i and 2i+1; arms 0, 1 front elbow up/down, arms 2, 3 back elbow up/down).
   */
  private int solveBase(double[] X, double theta4Singular, int arms) {
    double r00 = X[0], r01 = X[1], r02 = X[2];
    double r10 = X[3], r11 = X[4], r12 = X[5];
    double r20 = X[6], r21 = X[7], r22 = X[8];
    // Wrist centre: back from the flange along its approach (z) axis.
    double cx = X[9] - c4 * r02, cy = X[10] - c4 * r12, cz = X[11] - c4 * r22;
    double rxy2 = cx * cx + cy * cy - b * b;
    if (!(rxy2 >= 0)) {
      return 0;
    }
    double nx1 = Math.sqrt(rxy2) - a1;
    double phi = Math.atan2(cy, cx);
    double beta = Math.atan2(b, nx1 + a1);
    double th1Front = phi - beta;
    double th1Back = phi + beta - Math.PI;
    double dz = cz - c1;
    double s1sq = nx1 * nx1 + dz * dz;
    double nx2 = nx1 + 2 * a1;
    double s2sq = nx2 * nx2 + dz * dz;
    double c2sq = c2 * c2, k2 = kappa * kappa;
    int valid = 0;
    // Front arm (θ1 = φ − β), elbows i and ii.
    double s1 = Math.sqrt(s1sq);
    double cosA = (s1sq - c2sq - k2) / (2 * c2 * kappa);
    if ((arms & 0b0011) != 0 && s1 > 0 && Math.abs(cosA) <= 1 + ACOS_SLACK) {
      double g = Math.acos(clamp((s1sq + c2sq - k2) / (2 * s1 * c2)));
      double e = Math.atan2(nx1, dz);
      double a = Math.acos(clamp(cosA));
      if ((arms & 0b0001) != 0) {
        valid |= arm(0, th1Front, -g + e, a - psi, r00, r01, r02, r10, r11, r12, r20, r21, r22, theta4Singular);
      }
      if ((arms & 0b0010) != 0) {
        valid |= arm(2, th1Front, g + e, -a - psi, r00, r01, r02, r10, r11, r12, r20, r21, r22, theta4Singular);
      }
    }
    // Back arm (θ1 = φ + β − π), elbows iii and iv.
    double s2 = Math.sqrt(s2sq);
    double cosB = (s2sq - c2sq - k2) / (2 * c2 * kappa);
    if ((arms & 0b1100) != 0 && s2 > 0 && Math.abs(cosB) <= 1 + ACOS_SLACK) {
      double g = Math.acos(clamp((s2sq + c2sq - k2) / (2 * s2 * c2)));
      double e = Math.atan2(nx2, dz);
      double a = Math.acos(clamp(cosB));
      if ((arms & 0b0100) != 0) {
        valid |= arm(4, th1Back, -g - e, a - psi, r00, r01, r02, r10, r11, r12, r20, r21, r22, theta4Singular);
      }
      if ((arms & 0b1000) != 0) {
        valid |= arm(6, th1Back, g - e, -a - psi, r00, r01, r02, r10, r11, r12, r20, r21, r22, theta4Singular);
      }
    }
    return valid;
  }

  /** Wrist angles for one arm (θ1, θ2, θ3); writes solutions k and k+1; returns their bits. */
  private int arm(int k, double th1, double th2, double th3,
      double r00, double r01, double r02, double r10, double r11, double r12,
      double r20, double r21, double r22, double theta4Singular) {
    double cs1 = Math.cos(th1), sn1 = Math.sin(th1);
    double th23 = th2 + th3;
    double c23 = Math.cos(th23), s23 = Math.sin(th23);
    // Columns of R seen in the forearm frame 3 (R_03 = Rz(θ1)·Ry(θ2+θ3)); wrist is ZYZ there.
    double ah = cs1 * r02 + sn1 * r12;
    double ax3 = c23 * ah - s23 * r22;
    double ay3 = -sn1 * r02 + cs1 * r12;
    double az3 = s23 * ah + c23 * r22;
    double sinB = Math.sqrt(ax3 * ax3 + ay3 * ay3);
    double th4, th5, th6;
    boolean singular = sinB < WRIST_SINGULAR;
    if (!singular) {
      th4 = Math.atan2(ay3, ax3);
      th5 = Math.atan2(sinB, az3);
      double nz3 = s23 * (cs1 * r00 + sn1 * r10) + c23 * r20;
      double oz3 = s23 * (cs1 * r01 + sn1 * r11) + c23 * r21;
      th6 = Math.atan2(oz3, -nz3);
    } else {
      // Axes 4 and 6 line up: only θ4 + θ6 (θ5 = 0) or θ4 − θ6 (θ5 = π) is defined; keep θ4.
      double nh = cs1 * r00 + sn1 * r10;
      double nx3 = c23 * nh - s23 * r20;
      double ny3 = -sn1 * r00 + cs1 * r10;
      th4 = theta4Singular;
      if (az3 > 0) {
        th5 = 0;
        th6 = Math.atan2(ny3, nx3) - th4;
      } else {
        th5 = Math.PI;
        th6 = th4 - Math.atan2(-ny3, -nx3);
      }
    }
    write(k, th1, th2, th3, th4, th5, th6);
    write(k + 1, th1, th2, th3, th4 + Math.PI, -th5, th6 - Math.PI);
    singularWrist[k] = singular;
    singularWrist[k + 1] = singular;
    return 3 << k;
  }

  private void write(int k, double t1, double t2, double t3, double t4, double t5, double t6) {
    int o = k * 6;
    base[o] = wrap(sign[0] * (t1 + offset[0]));
    base[o + 1] = wrap(sign[1] * (t2 + offset[1]));
    base[o + 2] = wrap(sign[2] * (t3 + offset[2]));
    base[o + 3] = wrap(sign[3] * (t4 + offset[3]));
    base[o + 4] = wrap(sign[4] * (t5 + offset[4]));
    base[o + 5] = wrap(sign[5] * (t6 + offset[5]));
  }

  /** F/N margin: J5 itself (F when positive). */
  private double flipMargin(double[] q) {
    return wrap(q[4]);
  }

  /** U/D margin: sin(θ3 + atan2(a2, c3)), positive for U. */
  private double upMargin(double[] q) {
    double th3 = sign[2] * q[2] - offset[2];
    return Math.sin(th3 + psi);
  }

  /** T/B margin (mm): wrist centre's distance in front of the J1 axis along link 1's x. */
  private double topMargin(double[] q) {
    double th2 = sign[1] * q[1] - offset[1];
    double th23 = th2 + sign[2] * q[2] - offset[2];
    return a1 + c2 * Math.sin(th2) + c3 * Math.sin(th23) + a2 * Math.cos(th23);
  }

  private IkResult solved(double[] q) {
    if (polish != null) {
      polish.polish(q, target);
    }
    chain.flangePose(q, fk, null);
    double dx = fk[9] - target[9], dy = fk[10] - target[10], dz = fk[11] - target[11];
    double pos = Math.sqrt(dx * dx + dy * dy + dz * dz);
    return new IkResult.Solved(q.clone(), pos, rotationAngle(fk, target), 0);
  }

  private IkResult.Unreachable outOfReach() {
    return new IkResult.Unreachable(IkResult.Reason.OUT_OF_REACH, String.format(
        "position (%.1f, %.1f, %.1f) mm is out of reach: the wrist centre is beyond the arm's "
            + "reach or closer to the shoulder than the folded arm allows",
        target[9], target[10], target[11]));
  }

  /** Rotation angle (rad) between two packed orientations, accurate near 0. */
  static double rotationAngle(double[] a, double[] b) {
    double tr = a[0] * b[0] + a[3] * b[3] + a[6] * b[6]
        + a[1] * b[1] + a[4] * b[4] + a[7] * b[7]
        + a[2] * b[2] + a[5] * b[5] + a[8] * b[8];
    // Skew part of Raᵀ·Rb gives sin: keeps precision for small angles.
    double sx = (a[1] * b[2] + a[4] * b[5] + a[7] * b[8]) - (a[2] * b[1] + a[5] * b[4] + a[8] * b[7]);
    double sy = (a[2] * b[0] + a[5] * b[3] + a[8] * b[6]) - (a[0] * b[2] + a[3] * b[5] + a[6] * b[8]);
    double sz = (a[0] * b[1] + a[3] * b[4] + a[6] * b[7]) - (a[1] * b[0] + a[4] * b[3] + a[7] * b[6]);
    double s = 0.5 * Math.sqrt(sx * sx + sy * sy + sz * sz);
    double c = Math.max(-1, Math.min(1, (tr - 1) / 2));
    return Math.atan2(s, c);
  }

  private static double clamp(double x) {
    return x > 1 ? 1 : (x < -1 ? -1 : x);
  }

  private static double sq(double x) {
    return x * x;
  }

  /** Wraps into (-π, π] without the cost of IEEEremainder for values already near the range. */
  static double wrap(double a) {
    while (a > Math.PI) {
      a -= TWO_PI;
    }
    while (a <= -Math.PI) {
      a += TWO_PI;
    }
    return a;
  }
}
