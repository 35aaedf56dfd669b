package org.robotrun.robot;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Random;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Closed-form inverse kinematics for arms with three parallel axes and an offset wrist (the
 * Universal Robots layout, also Techman, Aubo, Elite, JAKA and similar): J2, J3 and J4
 * parallel, J1 not parallel to them, and the J5 and J6 axes meeting in one point W. Up to
 * eight solutions, each with its CONFIG. The steps are those of the known analytic UR solution
 * (Hawkins, "Analytic Inverse Kinematics for the Universal Robots UR-5/UR-10 Arms", 2013;
 * Andersen, "Kinematics of a UR5", Aalborg 2018), written here from the joint axis lines of the
 * chain instead of a DH table, so any URDF layout of the family works:
 * <ol>
 *   <li>W is fixed on link 6, so the target gives it. Rotations about J2, J3, J4 keep a point's
 *       coordinate along their common direction n, and W is fixed on link 4, so W's n
 *       coordinate in link 1 is a constant d: {@code A cos θ1 + B sin θ1 = d − C} gives two
 *       J1 values (T/B: W in front of or behind the J1 axis).
 *   <li>n is then known in the base; the angle between n and the J6 axis depends on J5 alone:
 *       two J5 values (F/N, either side of the wrist singularity where J6 lines up with n).
 *   <li>J6 turns n (seen from link 6) onto where J5 puts it (free at the wrist singularity:
 *       kept at the reference value).
 *   <li>Link 4's pose follows; J2, J3 are a planar two-link problem in the plane across n
 *       (U/D: the elbow's side), J4 the rest of the planar rotation.
 * </ol>
 * Every solution is checked against the chain's FK at use (the result carries the error), and
 * the derivation itself at load on 32 random joint vectors ({@link #applies}). A chain that fits
 * the family only to within the rounding of its file's numbers (axes up to 1e-4 rad off
 * parallel, J5 and J6 up to 0.05 mm apart, e.g. {@code rpy="1.5708 0 0"}) gets the same closed
 * form on its slightly-off geometry, each answer finished by a few Newton steps on the chain.
 *
 * <h2>CONFIG</h2>
 * The flags are the controller's, carried to this geometry (as {@link ChainConfig} does for the
 * CRX, with W the point where J5 and J6 meet): T when W lies in front of the J1 axis along
 * link 1's forward direction (J1 × J2, oriented so that W is in front at q = 0); U when
 * ((J3 − J2) × (J4 − J3)) · (J1 × forward) &gt; 0, the elbow on the upper side; F when J5 is on
 * the positive side of its singular value (J5 &gt; 0 for the usual layouts, where J5 = 0 lines
 * J6 up with J2..J4). Turn numbers of J1, J4, J6 as {@link Config#turnOf}; J2, J3 and J5 take the
 * variant inside the limits nearest the reference joints (UR joints turn ±360°). So the eight
 * solutions map one to one onto the eight flag triples; a taught CONFIG picks its branch, and
 * jogs and linear moves take the solution nearest the current joints, never another branch.
 *
 * <p>Not thread-safe (scratch arrays).
 */
public final class UrTypeIk implements IkSolver {
  /** {@link IkSolver#kind()} of this solver. */
  public static final String KIND = "ur-type";
  /** Base solutions: two J1 × two J5 × two elbows. */
  public static final int BASE_SOLUTIONS = 8;

  private static final double TWO_PI = 2 * Math.PI;
  private static final double ANGLE_TOL = 1e-9;
  private static final double LENGTH_TOL = 1e-6;
  /** Slack on the cosine arguments so that exactly stretched or singular poses still solve. */
  private static final double ACOS_SLACK = 1e-9;
  /**
   * |n × J6| below this leaves J6 free (the wrist singularity). It is a square root of rounding
   * (√(1 − ma²) with ma one ulp from 1 is 1.5e-8), so it must lie above √ε: at 1e-9 a pose with
   * J5 = 0 took J6 from rounding noise and solveNearest jumped 0.78 rad away from the arm's joints.
   */
  private static final double WRIST_SINGULAR = 1e-7;
  private static final int VERIFY_SAMPLES = 32;
  /** Looser tolerances for a chain of the family only to within its file's rounding (rad, mm). */
  private static final double LOOSE_ANGLE_TOL = 1e-4;
  private static final double LOOSE_LENGTH_TOL = 0.05;

  private final RobotModel model;
  private final KinematicChain chain;
  /** Newton steps that finish each answer when the geometry fits only to within rounding; else null. */
  private final NewtonPolish polish;
  private final JointRange range;
  // Joint frames: rotation (row-major), translation, axis (joint frame), for J1, J5, J6.
  private final double[] r1 = new double[9];
  private final double[] t1 = new double[3];
  private final double[] a1 = new double[3];
  private final double[] r5 = new double[9];
  private final double[] t5 = new double[3];
  private final double[] a5 = new double[3];
  private final double[] r6 = new double[9];
  private final double[] t6 = new double[3];
  private final double[] a6 = new double[3];
  private final double[] x6fInv = new double[12];
  /** W in the flange frame. */
  private final double[] wF = new double[3];
  /** J1 step: A = nA·p', B = nB·p', C = cC·(a1·p'); the n coordinate d. */
  private final double[] nA = new double[3];
  private final double[] nB = new double[3];
  private final double cC;
  private final double dLat;
  /** n in link 1 (= J2's axis there), the plane basis eu, ew (eu × ew = n). */
  private final double[] n1 = new double[3];
  private final double[] eu = new double[3];
  private final double[] ew = new double[3];
  /** J5 step: J6·n = A5 cos θ5 + B5 sin θ5 + C5. */
  private final double a5c;
  private final double b5c;
  private final double c5c;
  private final double r5c;
  private final double alpha5;
  private final double sigmaF;
  /** J6 step: n seen from the J6 joint frame is v0 + cos θ5·vc + sin θ5·vs. */
  private final double[] v0 = new double[3];
  private final double[] vc = new double[3];
  private final double[] vs = new double[3];
  /** −R_PJ5ᵀ·t_PJ5: link 4's origin seen from J5's joint frame. */
  private final double[] h5 = new double[3];
  /** eu seen from J5's joint frame (through link 4 at q = 0). */
  private final double[] eu5 = new double[3];
  /** Planar chain at q = 0: J2 → J3 and J3 → J4 in (eu, ew), their lengths and angle. */
  private final double p2u;
  private final double p2w;
  private final double v23u;
  private final double v23w;
  private final double v34u;
  private final double v34w;
  private final double l2;
  private final double l3;
  private final double beta;
  private final int s3;
  private final int s4;
  /** Orientation of link 1's forward direction (J1 × J2) so that W is in front at q = 0. */
  private final double sigmaT;

  // Scratch.
  private final double[] target = new double[12];
  private final double[] x6 = new double[12];
  private final double[] fk = new double[12];
  private final double[] axes = new double[36];
  private final double[] base = new double[BASE_SOLUTIONS * 6];
  private final boolean[] flagF = new boolean[BASE_SOLUTIONS];
  private final boolean[] flagU = new boolean[BASE_SOLUTIONS];
  private final boolean[] flagT = new boolean[BASE_SOLUTIONS];
  private final double[] cand = new double[6];
  private final double[] best = new double[6];
  private final double[] u = new double[3];
  private final double[] w = new double[3];
  private final double[] tmp = new double[3];

  /** @throws IllegalArgumentException if the chain is not of this family */
  public UrTypeIk(RobotModel model) {
    this.model = model;
    this.chain = new KinematicChain(model);
    range = new JointRange(model);
    Transform[] L = ForwardKinematics.linkPosesInBase(model, new double[6]);
    Vec3[] p = new Vec3[6];
    Vec3[] d = new Vec3[6];
    for (int i = 0; i < 6; i++) {
      p[i] = L[i + 1].translationVector();
      d[i] = L[i + 1].rotate(model.joint(i).axis()).normalized();
    }
    String why = structure(d, LOOSE_ANGLE_TOL);
    if (why != null) {
      throw new IllegalArgumentException(model.id() + ": not a three-parallel-axes arm (" + why + ")");
    }
    boolean exact = structure(d, ANGLE_TOL) == null && OpwDerivation.intersection(p[4], d[4], p[5], d[5]).isPresent();
    polish = exact ? null : new NewtonPolish(chain);
    Optional<Vec3> wB = OpwDerivation.intersection(p[4], d[4], p[5], d[5], exact ? LENGTH_TOL : LOOSE_LENGTH_TOL);
    if (wB.isEmpty()) {
      throw new IllegalArgumentException(model.id() + ": not a three-parallel-axes arm (the J5 and J6 axes do not meet)");
    }
    JointSpec j1 = model.joint(0);
    JointSpec j2 = model.joint(1);
    JointSpec j3 = model.joint(2);
    JointSpec j4 = model.joint(3);
    JointSpec j5 = model.joint(4);
    JointSpec j6 = model.joint(5);
    frame(j1, r1, t1, a1);
    frame(j5, r5, t5, a5);
    frame(j6, r6, t6, a6);
    KinematicChain.pack(model.X_6F().inverse(), x6fInv, 0);
    Transform X_BF0 = L[6].compose(model.X_6F());
    put(X_BF0.inverse().apply(wB.get()), wF);
    // n in link 1: J2's axis there; J3's and J4's must be ±n.
    Vec3 n = j2.X_PJ().rotate(j2.axis()).normalized();
    put(n, n1);
    Transform X14 = j2.X_PJ().compose(j3.X_PJ()).compose(j4.X_PJ());
    Vec3 n3 = j2.X_PJ().compose(j3.X_PJ()).rotate(j3.axis());
    Vec3 n4 = X14.rotate(j4.axis());
    s3 = n3.dot(n) > 0 ? 1 : -1;
    s4 = n4.dot(n) > 0 ? 1 : -1;
    Vec3 ax1 = j1.axis();
    cC = ax1.dot(n);
    put(n.minus(ax1.times(cC)), nA);
    put(ax1.cross(n), nB);
    Vec3 w4 = L[4].inverse().apply(wB.get());
    dLat = X14.apply(w4).dot(n);
    Vec3 e1 = Math.abs(n.x()) < 0.9 ? Vec3.X : Vec3.Y;
    Vec3 eU = e1.minus(n.times(e1.dot(n))).normalized();
    Vec3 eW = n.cross(eU);
    put(eU, eu);
    put(eW, ew);
    // J5: J6's axis against n, all in J5's joint frame.
    Vec3 nIn4 = X14.inverse().rotate(n);
    Vec3 m = j5.X_PJ().inverse().rotate(nIn4);
    Vec3 ax5 = j5.axis();
    Vec3 wv = j6.X_PJ().rotate(j6.axis());
    Vec3 wPerp = wv.minus(ax5.times(ax5.dot(wv)));
    a5c = wPerp.dot(m);
    b5c = ax5.cross(wv).dot(m);
    c5c = ax5.dot(wv) * ax5.dot(m);
    r5c = Math.hypot(a5c, b5c);
    if (r5c < 1e-6) {
      throw new IllegalArgumentException(model.id() + ": not a three-parallel-axes arm (J5 does not change J6's angle to J2)");
    }
    alpha5 = Math.atan2(b5c, a5c);
    sigmaF = Math.cos(alpha5) >= 0 ? 1 : -1;
    // n from J6's joint frame: R_PJ6ᵀ·Rot(a5, −θ5)·m.
    Transform r6t = j6.X_PJ().withTranslation(0, 0, 0).inverse();
    Vec3 mPar = ax5.times(ax5.dot(m));
    put(r6t.rotate(mPar), v0);
    put(r6t.rotate(m.minus(mPar)), vc);
    put(r6t.rotate(ax5.cross(m)).times(-1), vs);
    Transform j5inv = j5.X_PJ().inverse();
    put(j5inv.apply(Vec3.ZERO), h5);
    put(j5inv.rotate(X14.inverse().rotate(eU)), eu5);
    // The planar chain at q = 0 in link 1.
    Vec3 P2 = j2.X_PJ().translationVector();
    Vec3 P3 = j2.X_PJ().apply(j3.X_PJ().translationVector());
    Vec3 P4 = X14.translationVector();
    p2u = P2.dot(eU);
    p2w = P2.dot(eW);
    v23u = P3.minus(P2).dot(eU);
    v23w = P3.minus(P2).dot(eW);
    v34u = P4.minus(P3).dot(eU);
    v34w = P4.minus(P3).dot(eW);
    l2 = Math.hypot(v23u, v23w);
    l3 = Math.hypot(v34u, v34w);
    if (l2 < LENGTH_TOL || l3 < LENGTH_TOL) {
      throw new IllegalArgumentException(model.id() + ": not a three-parallel-axes arm (an arm link of zero length)");
    }
    beta = Math.atan2(v23u * v34w - v23w * v34u, v23u * v34u + v23w * v34w);
    // T/B orientation: W in front of the J1 axis along J1 × J2 at q = 0.
    Vec3 f = d[0].cross(d[1]);
    double front = f.dot(wB.get().minus(p[0]));
    sigmaT = front < -1e-9 ? -1 : 1;
    if (!verify()) {
      throw new IllegalArgumentException(model.id() + ": not a three-parallel-axes arm (the closed form does not reproduce the chain)");
    }
  }

  /** Whether the model is of this family (and neither OPW nor the CRX layout), checked against its FK. */
  public static boolean applies(RobotModel model) {
    if (model.opw().isPresent()) {
      return false;
    }
    Transform[] L = ForwardKinematics.linkPosesInBase(model, new double[6]);
    Vec3[] d = new Vec3[6];
    Vec3[] p = new Vec3[6];
    for (int i = 0; i < 6; i++) {
      p[i] = L[i + 1].translationVector();
      d[i] = L[i + 1].rotate(model.joint(i).axis()).normalized();
    }
    if (structure(d, LOOSE_ANGLE_TOL) != null || OpwDerivation.intersection(p[4], d[4], p[5], d[5], LOOSE_LENGTH_TOL).isEmpty()) {
      return false;
    }
    try {
      new UrTypeIk(model);
      return true;
    } catch (IllegalArgumentException e) {
      return false;
    }
  }

  /** Null when the axis directions at q = 0 fit the family, else what does not. */
  private static String structure(Vec3[] d, double tol) {
    if (d[1].cross(d[2]).norm() > tol || d[2].cross(d[3]).norm() > tol) {
      return "J2, J3 and J4 are not parallel";
    }
    if (d[0].cross(d[1]).norm() < 1e-3) {
      return "J1 is parallel to J2";
    }
    if (d[4].cross(d[5]).norm() < 1e-3) {
      return "J5 is parallel to J6";
    }
    return null;
  }

  private boolean verify() {
    Random rnd = new Random(20251126L);
    double[] q = new double[6];
    double[] x = new double[12];
    for (int k = 0; k < VERIFY_SAMPLES; k++) {
      for (int i = 0; i < 6; i++) {
        q[i] = k == 0 ? 0.3 : range.lower(i) + rnd.nextDouble() * (range.upper(i) - range.lower(i));
      }
      chain.flangePose(q, x, null);
      System.arraycopy(x, 0, target, 0, 12);
      int valid = solveBase(q[5]);
      boolean found = false;
      for (int s = 0; s < BASE_SOLUTIONS; s++) {
        if ((valid & (1 << s)) == 0) {
          continue;
        }
        double[] b = java.util.Arrays.copyOfRange(base, 6 * s, 6 * s + 6);
        if (polish != null) {
          polish.polish(b, target);
        }
        chain.flangePose(b, fk, null);
        if (poseError(fk, target) > 1e-6) {
          return false;
        }
        boolean same = true;
        for (int i = 0; i < 6; i++) {
          same &= Math.abs(ClosedFormIk.wrap(b[i] - q[i])) < 1e-6;
        }
        found |= same && configOf(q).sameBranch(flags(s));
      }
      if (!found) {
        return false;
      }
    }
    return true;
  }

  @Override
  public RobotModel model() {
    return model;
  }

  @Override
  public String kind() {
    return KIND;
  }

  @Override
  public Config configOf(double[] q) {
    chain.flangePose(q, fk, axes);
    // W = X_BF · wF.
    double wx = fk[0] * wF[0] + fk[1] * wF[1] + fk[2] * wF[2] + fk[9];
    double wy = fk[3] * wF[0] + fk[4] * wF[1] + fk[5] * wF[2] + fk[10];
    double wz = fk[6] * wF[0] + fk[7] * wF[1] + fk[8] * wF[2] + fk[11];
    // forward f = J1 × J2 (oriented by sigmaT)
    double fx = axes[4] * axes[11] - axes[5] * axes[10];
    double fy = axes[5] * axes[9] - axes[3] * axes[11];
    double fz = axes[3] * axes[10] - axes[4] * axes[9];
    double top = sigmaT * (fx * (wx - axes[0]) + fy * (wy - axes[1]) + fz * (wz - axes[2]));
    // ((J3 − J2) × (J4 − J3)) · n, with J1 × forward = −sigmaT·n⊥ (see the class comment).
    double ux = axes[12] - axes[6], uy = axes[13] - axes[7], uz = axes[14] - axes[8];
    double vx = axes[18] - axes[12], vy = axes[19] - axes[13], vz = axes[20] - axes[14];
    double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    double up = -sigmaT * (cx * axes[9] + cy * axes[10] + cz * axes[11]);
    boolean flip = sigmaF * Math.sin(q[4] - alpha5) > 0;
    return new Config(flip, up > 0, top > 0, Config.turnOf(q[0]), Config.turnOf(q[3]), Config.turnOf(q[5]));
  }

  private Config flags(int s) {
    return new Config(flagF[s], flagU[s], flagT[s], 0, 0, 0);
  }

  // ---- solution choice -------------------------------------------------------------------

  @Override
  public IkResult solve(Transform X_BF, Config config, double[] qNear) {
    KinematicChain.pack(X_BF, target, 0);
    int valid = solveBase(qNear[5]);
    if (valid == 0) {
      return outOfReach();
    }
    double bestD = Double.POSITIVE_INFINITY;
    boolean branch = false;
    String limitWhy = null;
    for (int s = 0; s < BASE_SOLUTIONS; s++) {
      if ((valid & (1 << s)) == 0 || flagF[s] != config.flip() || flagU[s] != config.up() || flagT[s] != config.top()) {
        continue;
      }
      branch = true;
      int o = 6 * s;
      cand[0] = base[o] + TWO_PI * config.turn1();
      cand[1] = range.nearestTurn(base[o + 1], qNear[1], 1);
      cand[2] = range.nearestTurn(base[o + 2], qNear[2], 2);
      cand[3] = base[o + 3] + TWO_PI * config.turn4();
      cand[4] = range.nearestTurn(base[o + 4], qNear[4], 4);
      cand[5] = base[o + 5] + TWO_PI * config.turn6();
      int bad = range.firstOutside(cand);
      if (bad >= 0) {
        double shown = Double.isNaN(cand[bad]) ? base[o + bad] : cand[bad];
        limitWhy = range.outside(config, bad, shown);
        continue;
      }
      double d = JointRange.distance(cand, qNear);
      if (d < bestD) {
        bestD = d;
        System.arraycopy(cand, 0, best, 0, 6);
      }
    }
    if (bestD < Double.POSITIVE_INFINITY) {
      range.clampAll(best);
      return solved(best);
    }
    if (!branch) {
      return JointRange.otherConfigsOnly(config);
    }
    return new IkResult.Unreachable(IkResult.Reason.JOINT_LIMIT, limitWhy);
  }

  @Override
  public IkResult solveNearest(Transform X_BF, double[] qCurrent) {
    KinematicChain.pack(X_BF, target, 0);
    int valid = solveBase(qCurrent[5]);
    if (valid == 0) {
      return outOfReach();
    }
    double bestD = Double.POSITIVE_INFINITY;
    for (int s = 0; s < BASE_SOLUTIONS; s++) {
      if ((valid & (1 << s)) == 0) {
        continue;
      }
      for (int i = 0; i < 6; i++) {
        cand[i] = range.nearestTurn(base[6 * s + i], qCurrent[i], i);
      }
      double d = JointRange.distance(cand, qCurrent);
      if (d < bestD) {
        bestD = d;
        System.arraycopy(cand, 0, best, 0, 6);
      }
    }
    if (bestD == Double.POSITIVE_INFINITY) {
      return JointRange.everySolutionOutside();
    }
    range.clampAll(best);
    return solved(best);
  }

  @Override
  public List<Solution> allSolutions(Transform X_BF) {
    KinematicChain.pack(X_BF, target, 0);
    int valid = solveBase(0);
    List<Solution> out = new ArrayList<>();
    for (int s = 0; s < BASE_SOLUTIONS; s++) {
      if ((valid & (1 << s)) == 0) {
        continue;
      }
      double[] q0 = new double[6];
      System.arraycopy(base, 6 * s, q0, 0, 6);
      for (double[] q : range.turnVariants(q0)) {
        if (polish != null) {
          polish.polish(q, target);
        }
        range.clampAll(q);
        out.add(new Solution(q, configOf(q)));
      }
    }
    return out;
  }

  /** Every base solution (joints wrapped to (−π, π], not limit-checked), for tests and benchmarks. */
  public List<double[]> baseSolutions(Transform X_BF) {
    KinematicChain.pack(X_BF, target, 0);
    int valid = solveBase(0);
    List<double[]> out = new ArrayList<>();
    for (int s = 0; s < BASE_SOLUTIONS; s++) {
      if ((valid & (1 << s)) != 0) {
        double[] q = java.util.Arrays.copyOfRange(base, 6 * s, 6 * s + 6);
        if (polish != null) {
          polish.polish(q, target);
        }
        out.add(q);
      }
    }
    return out;
  }

  // ---- the closed form ---------------------------------------------------------------------

  /**
   * Fills {@link #base} and the flags from {@link #target}; returns the validity mask (bit s:
   * solution s = 4·(J1 branch) + 2·(J5 branch) + elbow).
   */
  private int solveBase(double theta6Free) {
    KinematicChain.compose(target, x6fInv, x6);
    // W in B, then in J1's joint frame (p').
    double wx = target[0] * wF[0] + target[1] * wF[1] + target[2] * wF[2] + target[9] - t1[0];
    double wy = target[3] * wF[0] + target[4] * wF[1] + target[5] * wF[2] + target[10] - t1[1];
    double wz = target[6] * wF[0] + target[7] * wF[1] + target[8] * wF[2] + target[11] - t1[2];
    double px = r1[0] * wx + r1[3] * wy + r1[6] * wz;
    double py = r1[1] * wx + r1[4] * wy + r1[7] * wz;
    double pz = r1[2] * wx + r1[5] * wy + r1[8] * wz;
    double a = nA[0] * px + nA[1] * py + nA[2] * pz;
    double b = nB[0] * px + nB[1] * py + nB[2] * pz;
    double rhs = dLat - cC * (a1[0] * px + a1[1] * py + a1[2] * pz);
    double r = Math.hypot(a, b);
    if (!(r > 0) || Math.abs(rhs) > r * (1 + ACOS_SLACK)) {
      return 0;
    }
    double alpha = Math.atan2(b, a);
    double acos1 = Math.acos(clamp(rhs / r));
    // J6's axis in B (from the flange frame's rotation and J6's axis in link 6).
    double zx = x6[0] * a6[0] + x6[1] * a6[1] + x6[2] * a6[2];
    double zy = x6[3] * a6[0] + x6[4] * a6[1] + x6[5] * a6[2];
    double zz = x6[6] * a6[0] + x6[7] * a6[1] + x6[8] * a6[2];
    int valid = 0;
    for (int b1 = 0; b1 < 2; b1++) {
      double th1 = ClosedFormIk.wrap(alpha + (b1 == 0 ? acos1 : -acos1));
      double c1 = Math.cos(th1), s1 = Math.sin(th1);
      // n in B = R_PJ1 · Rot(a1, θ1) · n1.
      rot(a1, c1, s1, n1, u);
      double nx = r1[0] * u[0] + r1[1] * u[1] + r1[2] * u[2];
      double ny = r1[3] * u[0] + r1[4] * u[1] + r1[5] * u[2];
      double nz = r1[6] * u[0] + r1[7] * u[1] + r1[8] * u[2];
      double cos5 = (zx * nx + zy * ny + zz * nz - c5c) / r5c;
      if (Math.abs(cos5) > 1 + ACOS_SLACK) {
        continue;
      }
      double acos5 = Math.acos(clamp(cos5));
      // n seen from link 6.
      double m6x = x6[0] * nx + x6[3] * ny + x6[6] * nz;
      double m6y = x6[1] * nx + x6[4] * ny + x6[7] * nz;
      double m6z = x6[2] * nx + x6[5] * ny + x6[8] * nz;
      for (int b5 = 0; b5 < 2; b5++) {
        double th5 = ClosedFormIk.wrap(alpha5 + (b5 == 0 ? acos5 : -acos5));
        double c5 = Math.cos(th5), s5 = Math.sin(th5);
        double vx = v0[0] + c5 * vc[0] + s5 * vs[0];
        double vy = v0[1] + c5 * vc[1] + s5 * vs[1];
        double vz = v0[2] + c5 * vc[2] + s5 * vs[2];
        // θ6: Rot(a6, θ6)·m6 = v.
        double ma = m6x * a6[0] + m6y * a6[1] + m6z * a6[2];
        double va = vx * a6[0] + vy * a6[1] + vz * a6[2];
        double crx = m6y * vz - m6z * vy, cry = m6z * vx - m6x * vz, crz = m6x * vy - m6y * vx;
        double sn = crx * a6[0] + cry * a6[1] + crz * a6[2];
        double cs = m6x * vx + m6y * vy + m6z * vz - ma * va;
        double perp = Math.sqrt(Math.max(0, 1 - ma * ma));
        double th6 = perp < WRIST_SINGULAR ? ClosedFormIk.wrap(theta6Free) : Math.atan2(sn, cs);
        double c6 = Math.cos(th6), s6 = Math.sin(th6);
        // Link 4's origin and eu in B: X_B6 · (X_PJ6·Rot6)⁻¹ · (X_PJ5·Rot5)⁻¹.
        rot(a5, c5, -s5, h5, u);
        toLink6(u, c6, s6, true);
        double ox = w[0], oy = w[1], oz = w[2];
        rot(a5, c5, -s5, eu5, u);
        toLink6(u, c6, s6, false);
        double gx = w[0], gy = w[1], gz = w[2];
        // Into link 1: Rot(a1, −θ1) · R_PJ1ᵀ · (x − t1).
        ox -= t1[0];
        oy -= t1[1];
        oz -= t1[2];
        u[0] = r1[0] * ox + r1[3] * oy + r1[6] * oz;
        u[1] = r1[1] * ox + r1[4] * oy + r1[7] * oz;
        u[2] = r1[2] * ox + r1[5] * oy + r1[8] * oz;
        rot(a1, c1, -s1, u, w);
        double du = w[0] * eu[0] + w[1] * eu[1] + w[2] * eu[2] - p2u;
        double dw = w[0] * ew[0] + w[1] * ew[1] + w[2] * ew[2] - p2w;
        u[0] = r1[0] * gx + r1[3] * gy + r1[6] * gz;
        u[1] = r1[1] * gx + r1[4] * gy + r1[7] * gz;
        u[2] = r1[2] * gx + r1[5] * gy + r1[8] * gz;
        rot(a1, c1, -s1, u, w);
        double phi = Math.atan2(w[0] * ew[0] + w[1] * ew[1] + w[2] * ew[2], w[0] * eu[0] + w[1] * eu[1] + w[2] * eu[2]);
        double cosE = (du * du + dw * dw - l2 * l2 - l3 * l3) / (2 * l2 * l3);
        if (Math.abs(cosE) > 1 + ACOS_SLACK) {
          continue;
        }
        double acosE = Math.acos(clamp(cosE));
        for (int be = 0; be < 2; be++) {
          double psi3 = -beta + (be == 0 ? acosE : -acosE);
          double cp = Math.cos(psi3), sp = Math.sin(psi3);
          double uu = v23u + cp * v34u - sp * v34w;
          double uw = v23w + sp * v34u + cp * v34w;
          double th2 = Math.atan2(uu * dw - uw * du, uu * du + uw * dw);
          int s = 4 * b1 + 2 * b5 + be;
          int o = 6 * s;
          base[o] = th1;
          base[o + 1] = ClosedFormIk.wrap(th2);
          base[o + 2] = ClosedFormIk.wrap(s3 * psi3);
          base[o + 3] = ClosedFormIk.wrap(s4 * (phi - th2 - psi3));
          base[o + 4] = th5;
          base[o + 5] = ClosedFormIk.wrap(th6);
          // Flags from the branches (class comment): b1 = 0 puts W behind J1 × J2.
          flagT[s] = sigmaT * (b1 == 0 ? -1 : 1) > 0;
          flagU[s] = -sigmaT * (be == 0 ? 1 : -1) > 0;
          flagF[s] = sigmaF * (b5 == 0 ? 1 : -1) > 0;
          valid |= 1 << s;
        }
      }
    }
    return valid;
  }

  /**
   * {@link #w} = X_B6 · (X_PJ6 · Rot(a6, θ6))⁻¹ applied to {@code v}, a point (or a vector)
   * given in link 5's frame: the point (vector) in B.
   */
  private void toLink6(double[] v, double c6, double s6, boolean point) {
    // Link 5 → J6 joint frame: R_PJ6ᵀ·(v − t6), then Rot(a6, −θ6), then X_B6.
    double x = v[0] - (point ? t6[0] : 0), y = v[1] - (point ? t6[1] : 0), z = v[2] - (point ? t6[2] : 0);
    double jx = r6[0] * x + r6[3] * y + r6[6] * z;
    double jy = r6[1] * x + r6[4] * y + r6[7] * z;
    double jz = r6[2] * x + r6[5] * y + r6[8] * z;
    w[0] = jx;
    w[1] = jy;
    w[2] = jz;
    rot(a6, c6, -s6, w, tmp);
    w[0] = x6[0] * tmp[0] + x6[1] * tmp[1] + x6[2] * tmp[2] + (point ? x6[9] : 0);
    w[1] = x6[3] * tmp[0] + x6[4] * tmp[1] + x6[5] * tmp[2] + (point ? x6[10] : 0);
    w[2] = x6[6] * tmp[0] + x6[7] * tmp[1] + x6[8] * tmp[2] + (point ? x6[11] : 0);
  }

  /** out = Rot(axis, θ)·v with c = cos θ, s = sin θ (Rodrigues); out may not alias v. */
  private static void rot(double[] ax, double c, double s, double[] v, double[] out) {
    double d = ax[0] * v[0] + ax[1] * v[1] + ax[2] * v[2];
    double kx = ax[1] * v[2] - ax[2] * v[1], ky = ax[2] * v[0] - ax[0] * v[2], kz = ax[0] * v[1] - ax[1] * v[0];
    out[0] = c * v[0] + s * kx + (1 - c) * d * ax[0];
    out[1] = c * v[1] + s * ky + (1 - c) * d * ax[1];
    out[2] = c * v[2] + s * kz + (1 - c) * d * ax[2];
  }

  private static void frame(JointSpec j, double[] r, double[] t, double[] a) {
    System.arraycopy(j.X_PJ().rotationRowMajor(), 0, r, 0, 9);
    t[0] = j.X_PJ().x();
    t[1] = j.X_PJ().y();
    t[2] = j.X_PJ().z();
    a[0] = j.axis().x();
    a[1] = j.axis().y();
    a[2] = j.axis().z();
  }

  private static void put(Vec3 v, double[] out) {
    out[0] = v.x();
    out[1] = v.y();
    out[2] = v.z();
  }

  private static double clamp(double x) {
    return x > 1 ? 1 : (x < -1 ? -1 : x);
  }

  private static double poseError(double[] a, double[] b) {
    double dx = a[9] - b[9], dy = a[10] - b[10], dz = a[11] - b[11];
    return Math.max(Math.sqrt(dx * dx + dy * dy + dz * dz), 1e3 * ClosedFormIk.rotationAngle(a, b));
  }

  private IkResult solved(double[] q) {
    if (polish != null) {
      polish.polish(q, target);
    }
    chain.flangePose(q, fk, null);
    double dx = fk[9] - target[9], dy = fk[10] - target[10], dz = fk[11] - target[11];
    return new IkResult.Solved(q.clone(), Math.sqrt(dx * dx + dy * dy + dz * dz), ClosedFormIk.rotationAngle(fk, target), 0);
  }

  private IkResult.Unreachable outOfReach() {
    return new IkResult.Unreachable(IkResult.Reason.OUT_OF_REACH, String.format(Locale.ROOT,
        "position (%.1f, %.1f, %.1f) mm is out of reach: no arm posture places the wrist there",
        target[9], target[10], target[11]));
  }
}
