package org.robotrun.robot;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Inverse kinematics for the CRX layout (an offset wrist): every solution of a flange pose,
 * each with its CONFIG, by a one-dimensional search over one angle, after the geometric
 * reduction of Abbes and Poisson, "Geometric Approach for Inverse Kinematics of the FANUC CRX
 * Collaborative Robot", Robotics 13(6) 91 (2024) (up to 16 solutions).
 *
 * <h2>The layout</h2>
 * Detected from the chain at q = 0 ({@link #applies}): J2 meets the J1 axis at P0 and is
 * perpendicular to it; J3 is parallel to J2; the J4 axis meets J3's at the elbow O3, in the
 * plane through P0 perpendicular to J2; the J5 axis meets J4's at O5; the J6 axis meets J5's at
 * O6, a distance y1 &gt; 0 from O5 (a spherical wrist would have y1 = 0 and is OPW). Upper arm
 * L2 = |O3 − P0|, forearm L3 = |O5 − O3|. The flange may sit anywhere on link 6.
 *
 * <h2>The search</h2>
 * The target fixes link 6, hence the J6 axis u6 and O6. O5 lies on the circle of radius y1
 * about O6 perpendicular to u6: {@code O5(t) = O6 + y1·(cos t·e1 + sin t·e2)}, and the J5 axis
 * is along {@code v(t) = cos t·e1 + sin t·e2}. For each t the elbow O3 (relative to P0) must
 * satisfy three linear equations: {@code O3·O5 = (|O5|² + L2² − L3²)/2} (the difference of
 * the two sphere equations |O3| = L2, |O3 − O5| = L3), {@code O3·v = O5·v} (J4 ⟂ J5) and
 * {@code O3·(z1 × O5) = 0} (the arm plane contains the J1 axis); Cramer's rule gives
 * {@code det·O3 = X(t)}, and the remaining equation |O3| = L2 becomes
 * {@code g(t) = |X(t)|² − L2²·det(t)² = 0}, a smooth scalar function with no branches: a
 * trigonometric polynomial of degree 4 (as mattj23/crx-kinematics also reports for its form of
 * the constraint), so at most 8 roots per turn. Its 9 Fourier coefficients come exactly from 16
 * samples; the Fourier form is scanned on a 128-point grid, and an interval is halved (up to 14
 * times) while a bound on g'' says it may hide more roots than its end values show; each root
 * is refined by the Illinois method, and a minimum of |g| that nearly touches zero is a
 * candidate. Every root (for J4 near 0° or 180°, or O5 on the J1 axis, where the three equations
 * become dependent, also the elbow from the two spheres and J4 ⟂ J5 alone) gives one O3
 * and two postures (J1 and J1 + 180° with the shoulder mirrored); each posture's joints follow
 * joint by joint (a rotation of a known vector onto a known vector per joint), are polished by a
 * few Newton steps on the pose, and are kept only when the chain's FK reproduces the target
 * (1e-6 mm, 1e-9 rad).
 *
 * <h2>CONFIG and branch choice</h2>
 * The flags are {@link ChainConfig}'s (F: J5 &gt; 0; U: the wrist point O5 on the forward side
 * of the upper arm; T: O5 in front of the J1 axis). With up to 16 solutions and 8 flag triples,
 * two solutions may share a CONFIG: a taught position then takes the one nearest the current
 * joints, and jogs and linear moves always take the solution nearest the current joints, so the
 * arm never changes branch by itself.
 *
 * <p>Not thread-safe (scratch arrays).
 */
public final class OffsetWristIk implements IkSolver {
  /** {@link IkSolver#kind()} of this solver. */
  public static final String KIND = "offset-wrist";
  /** g is a trigonometric polynomial of this degree (so at most 8 roots per turn). */
  static final int DEGREE = 4;
  /** Samples that fix g's Fourier coefficients exactly (more than 2·DEGREE + 1, no aliasing). */
  static final int FIT = 16;
  /** Grid on which the Fourier form is scanned for sign changes and possible root clusters. */
  static final int SAMPLES = 128;
  /** Roots and touching-root candidates (g has at most 8 roots; candidates near clusters add some). */
  private static final int MAX_ROOTS = 64;
  private static final int MAX_SOLUTIONS = 2 * MAX_ROOTS;
  private static final double TWO_PI = 2 * Math.PI;
  private static final double ANGLE_TOL = 1e-9;
  private static final double LENGTH_TOL = 1e-6;
  /** A grid interval that may hold more roots than it shows is halved up to this many times. */
  private static final int SPLIT_LEVELS = 14;
  /** Below this |det| (units of L2³) the elbow is also solved in the plane perpendicular to the J5 axis. */
  private static final double DEGENERATE = 1e-4;
  /** Golden-section steps when looking for a touching root in one grid interval. */
  private static final int GOLDEN_STEPS = 34;
  /** A minimum of |g| below this fraction of the curvature bound is a touching-root candidate. */
  private static final double TOUCH = 1e-5;
  /** Touching-root candidates closer than this (rad) to a root or candidate are left out. */
  private static final double CANDIDATE_SPACING = 1e-4;
  /** |J5| below this (rad) counts as the straight wrist, where F and N meet (solve by CONFIG). */
  private static final double STRAIGHT_WRIST_RAD = 1e-6;
  /** cos(k·t), sin(k·t) for k = 0..DEGREE on the fit and scan grids. */
  private static final double[][] FIT_COS = new double[DEGREE + 1][FIT];
  private static final double[][] FIT_SIN = new double[DEGREE + 1][FIT];
  private static final double[][] GRID_COS = new double[DEGREE + 1][SAMPLES];
  private static final double[][] GRID_SIN = new double[DEGREE + 1][SAMPLES];

  static {
    for (int k = 0; k <= DEGREE; k++) {
      for (int j = 0; j < FIT; j++) {
        FIT_COS[k][j] = Math.cos(k * j * TWO_PI / FIT);
        FIT_SIN[k][j] = Math.sin(k * j * TWO_PI / FIT);
      }
      for (int j = 0; j < SAMPLES; j++) {
        GRID_COS[k][j] = Math.cos(k * j * TWO_PI / SAMPLES);
        GRID_SIN[k][j] = Math.sin(k * j * TWO_PI / SAMPLES);
      }
    }
  }

  private final RobotModel model;
  private final KinematicChain chain;
  private final ChainConfig configs;
  private final Layout lay;
  private final JointRange range;
  // Per joint: X_PJ rotation (row-major), translation, axis in the joint frame.
  private final double[] rpj = new double[54];
  private final double[] tpj = new double[18];
  private final double[] ax = new double[18];
  private final double[] x6fInv = new double[12];

  // Scratch.
  private final double[] target = new double[12];
  private final double[] x6 = new double[12];
  private final double[] fk = new double[12];
  private final double[] g = new double[SAMPLES];
  private final double[] fit = new double[FIT];
  /** g(t) = ca[0] + Σ ca[k]·cos kt + sb[k]·sin kt. */
  private final double[] ca = new double[DEGREE + 1];
  private final double[] sb = new double[DEGREE + 1];
  /** Σ k²·|c_k| ≥ max |g''|. */
  private double curvatureBound;
  /**
   * Newton steps on the flange pose (at most 4) until the chain's FK is within 1e-9 mm and
   * 1e-12 rad of the target: a root of a cluster is only known to about 1e-8 rad. A candidate
   * farther than 1 mm or 0.01 rad is not this root's and is dropped, not pulled onto another.
   */
  private final NewtonPolish polish;
  private final double[] roots = new double[MAX_ROOTS];
  private int rootCount;
  private final double[] sol = new double[MAX_SOLUTIONS * 6];
  private int solCount;
  private final double[] cand = new double[6];
  private final double[] best = new double[6];
  private final double[] fr = new double[9];
  private final double[] fp = new double[3];
  private final double[] ra = new double[9];
  private final double[] oa = new double[3];
  // Per target: the search's fixed vectors (in units of L2, relative to P0).
  private double cx, cy, cz, e1x, e1y, e1z, e2x, e2y, e2z, u6x, u6y, u6z, o6x, o6y, o6z;
  private double ex3, ey3, ez3, ox3, oy3, oz3, ox5, oy5, oz5;

  /** The CRX layout's fixed geometry (mm, in the frames named). */
  record Layout(Vec3 p0, Vec3 z1, double l2, double l3, double y1, Vec3 o3InL2, Vec3 o5InL3, Vec3 o56InL4,
      Vec3 a6InL5, Vec3 o6InL6, Vec3 e6InL6, Vec3 n2InL1) {}

  public OffsetWristIk(RobotModel model) {
    this.model = model;
    this.lay = layout(model).orElseThrow(() -> new IllegalArgumentException(
        model.id() + ": not the CRX layout (see OffsetWristIk), the offset-wrist solver does not apply"));
    this.chain = new KinematicChain(model);
    this.polish = new NewtonPolish(chain, 4, 1, 1e-2);
    this.configs = new ChainConfig(chain);
    range = new JointRange(model);
    for (int i = 0; i < 6; i++) {
      JointSpec j = model.joint(i);
      System.arraycopy(j.X_PJ().rotationRowMajor(), 0, rpj, 9 * i, 9);
      tpj[3 * i] = j.X_PJ().x();
      tpj[3 * i + 1] = j.X_PJ().y();
      tpj[3 * i + 2] = j.X_PJ().z();
      ax[3 * i] = j.axis().x();
      ax[3 * i + 1] = j.axis().y();
      ax[3 * i + 2] = j.axis().z();
    }
    KinematicChain.pack(model.X_6F().inverse(), x6fInv, 0);
  }

  /** Whether the model has the CRX layout (and is not OPW). */
  public static boolean applies(RobotModel model) {
    return model.opw().isEmpty() && layout(model).isPresent();
  }

  static Optional<Layout> layout(RobotModel m) {
    Transform[] L = ForwardKinematics.linkPosesInBase(m, new double[6]);
    Vec3[] p = new Vec3[6];
    Vec3[] d = new Vec3[6];
    for (int i = 0; i < 6; i++) {
      p[i] = L[i + 1].translationVector();
      d[i] = L[i + 1].rotate(m.joint(i).axis()).normalized();
    }
    if (Math.abs(d[0].dot(d[1])) > ANGLE_TOL || d[1].cross(d[2]).norm() > ANGLE_TOL
        || Math.abs(d[2].dot(d[3])) > ANGLE_TOL || Math.abs(d[3].dot(d[4])) > ANGLE_TOL
        || Math.abs(d[4].dot(d[5])) > ANGLE_TOL) {
      return Optional.empty();
    }
    Optional<Vec3> p0 = OpwDerivation.intersection(p[0], d[0], p[1], d[1]);
    Optional<Vec3> o3 = OpwDerivation.intersection(p[2], d[2], p[3], d[3]);
    Optional<Vec3> o5 = OpwDerivation.intersection(p[3], d[3], p[4], d[4]);
    Optional<Vec3> o6 = OpwDerivation.intersection(p[4], d[4], p[5], d[5]);
    if (p0.isEmpty() || o3.isEmpty() || o5.isEmpty() || o6.isEmpty()) {
      return Optional.empty();
    }
    if (Math.abs(o3.get().minus(p0.get()).dot(d[1])) > LENGTH_TOL) {
      return Optional.empty();
    }
    double l2 = o3.get().distanceTo(p0.get());
    double l3 = o5.get().distanceTo(o3.get());
    double y1 = o6.get().distanceTo(o5.get());
    if (l2 < LENGTH_TOL || l3 < LENGTH_TOL || y1 < LENGTH_TOL) {
      return Optional.empty();
    }
    Transform L6 = L[6];
    Vec3 a6 = m.joint(5).axis();
    Vec3 e6 = Math.abs(a6.x()) < 0.9 ? a6.cross(Vec3.X).normalized() : a6.cross(Vec3.Y).normalized();
    return Optional.of(new Layout(p0.get(), d[0], l2, l3, y1,
        L[2].inverse().apply(o3.get()), L[3].inverse().apply(o5.get()),
        L[4].inverse().rotate(o6.get().minus(o5.get())),
        m.joint(5).X_PJ().rotate(a6).normalized(), L6.inverse().apply(o6.get()), e6,
        m.joint(1).X_PJ().rotate(m.joint(1).axis()).normalized()));
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
    return configs.configOf(q);
  }

  // ---- solution choice -------------------------------------------------------------------

  @Override
  public IkResult solve(Transform X_BF, Config config, double[] qNear) {
    int n = solveAll(X_BF);
    if (n == 0) {
      return outOfReach();
    }
    double bestD = Double.POSITIVE_INFINITY;
    boolean branch = false;
    String limitWhy = null;
    for (int k = 0; k < n; k++) {
      System.arraycopy(sol, 6 * k, cand, 0, 6);
      Config c = configOf(cand);
      // J5 at 0 (the wrist straight) is F and N at once: a position taught there may carry either
      // flag, and the search's root may land a hair on the other side of 0.
      boolean straight = Math.abs(ClosedFormIk.wrap(cand[4])) < STRAIGHT_WRIST_RAD;
      if (!(c.sameBranch(config) || straight && c.up() == config.up() && c.top() == config.top())) {
        continue;
      }
      branch = true;
      cand[0] += TWO_PI * config.turn1();
      cand[3] += TWO_PI * config.turn4();
      cand[5] += TWO_PI * config.turn6();
      cand[1] = range.intoLimits(cand[1], 1);
      cand[2] = range.intoLimits(cand[2], 2);
      cand[4] = range.intoLimits(cand[4], 4);
      int bad = range.firstOutside(cand);
      if (bad >= 0) {
        limitWhy = range.outside(config, bad, cand[bad]);
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
    int n = solveAll(X_BF);
    if (n == 0) {
      return outOfReach();
    }
    double bestD = Double.POSITIVE_INFINITY;
    for (int k = 0; k < n; k++) {
      boolean ok = true;
      for (int i = 0; i < 6 && ok; i++) {
        cand[i] = range.nearestTurn(sol[6 * k + i], qCurrent[i], i);
        ok = !Double.isNaN(cand[i]);
      }
      if (!ok) {
        continue;
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
    return solved(best);
  }

  @Override
  public List<Solution> allSolutions(Transform X_BF) {
    int n = solveAll(X_BF);
    List<Solution> out = new ArrayList<>();
    for (int k = 0; k < n; k++) {
      double[] q0 = new double[6];
      System.arraycopy(sol, 6 * k, q0, 0, 6);
      for (double[] q : range.turnVariants(q0)) {
        out.add(new Solution(q, configOf(q)));
      }
    }
    return out;
  }

  /**
   * Every base solution of a flange pose (joints wrapped to (−π, π], not limit-checked), for
   * tests and benchmarks.
   */
  public List<double[]> baseSolutions(Transform X_BF) {
    int n = solveAll(X_BF);
    List<double[]> out = new ArrayList<>();
    for (int k = 0; k < n; k++) {
      double[] q = new double[6];
      System.arraycopy(sol, 6 * k, q, 0, 6);
      out.add(q);
    }
    return out;
  }

  // ---- the search ------------------------------------------------------------------------

  /** Fills {@link #sol} with every solution; returns their count. */
  private int solveAll(Transform X_BF) {
    KinematicChain.pack(X_BF, target, 0);
    KinematicChain.compose(target, x6fInv, x6);
    double inv = 1 / lay.l2();
    // J6 axis and O6 in B.
    Vec3 a6 = model.joint(5).axis();
    u6x = x6[0] * a6.x() + x6[1] * a6.y() + x6[2] * a6.z();
    u6y = x6[3] * a6.x() + x6[4] * a6.y() + x6[5] * a6.z();
    u6z = x6[6] * a6.x() + x6[7] * a6.y() + x6[8] * a6.z();
    Vec3 o = lay.o6InL6();
    o6x = x6[0] * o.x() + x6[1] * o.y() + x6[2] * o.z() + x6[9];
    o6y = x6[3] * o.x() + x6[4] * o.y() + x6[5] * o.z() + x6[10];
    o6z = x6[6] * o.x() + x6[7] * o.y() + x6[8] * o.z() + x6[11];
    Vec3 e = lay.e6InL6();
    e1x = x6[0] * e.x() + x6[1] * e.y() + x6[2] * e.z();
    e1y = x6[3] * e.x() + x6[4] * e.y() + x6[5] * e.z();
    e1z = x6[6] * e.x() + x6[7] * e.y() + x6[8] * e.z();
    e2x = u6y * e1z - u6z * e1y;
    e2y = u6z * e1x - u6x * e1z;
    e2z = u6x * e1y - u6y * e1x;
    Vec3 p0 = lay.p0();
    cx = (o6x - p0.x()) * inv;
    cy = (o6y - p0.y()) * inv;
    cz = (o6z - p0.z()) * inv;
    rootCount = 0;
    // The Fourier form of g from FIT samples (exact: g has degree DEGREE).
    for (int j = 0; j < FIT; j++) {
      fit[j] = g(FIT_COS[1][j], FIT_SIN[1][j]);
    }
    curvatureBound = 0;
    for (int k = 0; k <= DEGREE; k++) {
      double a = 0, b = 0;
      for (int j = 0; j < FIT; j++) {
        a += fit[j] * FIT_COS[k][j];
        b += fit[j] * FIT_SIN[k][j];
      }
      ca[k] = (k == 0 ? 1.0 : 2.0) * a / FIT;
      sb[k] = k == 0 ? 0 : 2.0 * b / FIT;
      curvatureBound += k * k * Math.hypot(ca[k], sb[k]);
    }
    for (int j = 0; j < SAMPLES; j++) {
      double v = ca[0];
      for (int k = 1; k <= DEGREE; k++) {
        v += ca[k] * GRID_COS[k][j] + sb[k] * GRID_SIN[k][j];
      }
      g[j] = v;
    }
    double step = TWO_PI / SAMPLES;
    for (int j = 0; j < SAMPLES; j++) {
      scan(j * step, (j + 1) * step, g[j], g[(j + 1) % SAMPLES], 0);
    }
    solCount = 0;
    for (int r = 0; r < rootCount; r++) {
      postures(roots[r]);
    }
    return solCount;
  }

  /** g(t) for cos t, sin t (units of L2). Also leaves O3·det in (ox3..), O5 in (ox5..) and det in {@link #lastDet}. */
  private double g(double c, double s) {
    double vx = c * e1x + s * e2x, vy = c * e1y + s * e2y, vz = c * e1z + s * e2z;
    double y = lay.y1() / lay.l2();
    double l3 = lay.l3() / lay.l2();
    double px = cx + y * vx, py = cy + y * vy, pz = cz + y * vz;
    Vec3 z = lay.z1();
    // n = z1 × O5
    double nx = z.y() * pz - z.z() * py, ny = z.z() * px - z.x() * pz, nz = z.x() * py - z.y() * px;
    double r0 = 0.5 * (px * px + py * py + pz * pz + 1 - l3 * l3);
    double r1 = px * vx + py * vy + pz * vz;
    // v × n, n × O5
    double a0 = vy * nz - vz * ny, a1 = vz * nx - vx * nz, a2 = vx * ny - vy * nx;
    double b0 = ny * pz - nz * py, b1 = nz * px - nx * pz, b2 = nx * py - ny * px;
    double det = px * a0 + py * a1 + pz * a2;
    ex3 = r0 * a0 + r1 * b0;
    ey3 = r0 * a1 + r1 * b1;
    ez3 = r0 * a2 + r1 * b2;
    ox5 = px;
    oy5 = py;
    oz5 = pz;
    lastDet = det;
    return ex3 * ex3 + ey3 * ey3 + ez3 * ez3 - det * det;
  }

  private double lastDet;

  /** g(t) from its Fourier form. */
  private double gAt(double t) {
    double c1 = Math.cos(t), s1 = Math.sin(t);
    double c = c1, sn = s1, v = ca[0] + ca[1] * c1 + sb[1] * s1;
    for (int k = 2; k <= DEGREE; k++) {
      double nc = c * c1 - sn * s1, ns = sn * c1 + c * s1;
      c = nc;
      sn = ns;
      v += ca[k] * c + sb[k] * sn;
    }
    return v;
  }

  /**
   * Roots of g in [a, b] (a grid interval, then its halves). With M2 = Σ k²·|c_k| ≥ |g''|:
   * without a sign change, g cannot reach zero when min(|g(a)|, |g(b)|) &gt; w²/8 · M2 (it lies
   * within that of the chord); with one, there is exactly one root when |g'(mid)| &gt; w/2 · M2
   * (g is monotone there). Otherwise the interval is halved, down to {@link #SPLIT_LEVELS}; a
   * last interval with a sign change is refined, one without is searched for the minimum of |g|
   * (golden section): a sign change there gives both roots, a near-zero minimum a touching-root
   * candidate that {@link #polish} confirms or drops (the roots of a cluster are only known to
   * about the square root of the rounding).
   */
  private void scan(double a, double b, double ga, double gb, int depth) {
    if (ga == 0) {
      addRoot(a);
      return;
    }
    double w = b - a;
    boolean change = ga * gb < 0;
    if (change) {
      if (depth >= SPLIT_LEVELS || Math.abs(gDerivativeAt(0.5 * (a + b))) > 0.5 * w * curvatureBound) {
        addRoot(illinois(a, b, ga, gb));
        return;
      }
    } else if (Math.min(Math.abs(ga), Math.abs(gb)) > 0.125 * w * w * curvatureBound) {
      return;
    }
    if (depth < SPLIT_LEVELS) {
      double m = 0.5 * (a + b);
      double gm = gAt(m);
      scan(a, m, ga, gm, depth + 1);
      scan(m, b, gm, gb, depth + 1);
      return;
    }
    double sign = Math.signum(ga);    final double r = 0.5 * (Math.sqrt(5) - 1);
    double lo = a, hi = b;
    double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
    double f1 = sign * gAt(x1), f2 = sign * gAt(x2);
    for (int it = 0; it < GOLDEN_STEPS && f1 > 0 && f2 > 0; it++) {
      if (f1 < f2) {
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - r * (hi - lo);
        f1 = sign * gAt(x1);
      } else {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + r * (hi - lo);
        f2 = sign * gAt(x2);
      }
    }
    double tm = f1 < f2 ? x1 : x2;
    double fm = Math.min(f1, f2);
    if (fm <= 0) {
      addRoot(illinois(a, tm, ga, sign * fm));
      addRoot(illinois(tm, b, sign * fm, gb));
    } else if (fm < TOUCH * curvatureBound && tm - a > 1e-3 * (b - a) && b - tm > 1e-3 * (b - a)
        && !nearRoot(tm, CANDIDATE_SPACING)) {
      // In a flat stretch rounding makes many tiny minima: one candidate per CANDIDATE_SPACING.
      addRoot(tm);
    }
  }

  /** g'(t) from the Fourier form. */
  private double gDerivativeAt(double t) {
    double c1 = Math.cos(t), s1 = Math.sin(t);
    double c = c1, sn = s1, v = -ca[1] * s1 + sb[1] * c1;
    for (int k = 2; k <= DEGREE; k++) {
      double nc = c * c1 - sn * s1, ns = sn * c1 + c * s1;
      c = nc;
      sn = ns;
      v += k * (-ca[k] * sn + sb[k] * c);
    }
    return v;
  }

  /** Illinois false position on a bracket of the Fourier form. */
  private double illinois(double a, double b, double fa, double fb) {
    int side = 0;
    for (int it = 0; it < 100; it++) {
      double c = (a * fb - b * fa) / (fb - fa);
      if (!(c > Math.min(a, b) && c < Math.max(a, b))) {
        c = 0.5 * (a + b);
      }
      double fc = gAt(c);
      if (fc == 0) {
        return c;
      }
      if (fc * fb < 0) {
        a = b;
        fa = fb;
        b = c;
        fb = fc;
        if (side == -1) {
          fa *= 0.5;
        }
        side = -1;
      } else {
        b = c;
        fb = fc;
        if (side == 1) {
          fa *= 0.5;
        }
        side = 1;
      }
      if (Math.abs(b - a) < 1e-14) {
        return b;
      }
    }
    return 0.5 * (a + b);
  }

  private boolean nearRoot(double t, double within) {
    for (int r = 0; r < rootCount; r++) {
      if (Math.abs(ClosedFormIk.wrap(roots[r] - t)) < within) {
        return true;
      }
    }
    return false;
  }

  private void addRoot(double t) {
    for (int r = 0; r < rootCount; r++) {
      if (Math.abs(ClosedFormIk.wrap(roots[r] - t)) < 1e-13) {
        return;
      }
    }
    if (rootCount < MAX_ROOTS) {
      roots[rootCount++] = t;
    }
  }

  /** Both postures of one root: O3 and O5 from g's last evaluation at t. */
  private void postures(double t) {
    double c = Math.cos(t), sn = Math.sin(t);
    g(c, sn);
    double l2 = lay.l2();
    Vec3 p0 = lay.p0();
    double px = ox5, py = oy5, pz = oz5;
    double det = lastDet;
    if (Math.abs(det) > 1e-12) {
      elbow(p0.x() + l2 * ex3 / det, p0.y() + l2 * ey3 / det, p0.z() + l2 * ez3 / det, px, py, pz);
    }
    if (Math.abs(det) < DEGENERATE) {
      // The three equations are dependent: the J5 axis (nearly) perpendicular to the arm plane
      // (J4 near 0 or 180°, a common taught posture), or O5 on the J1 axis (z1 × O5 = 0, the arm
      // plane not fixed by O5). Cramer's rule says nothing there, but the first two equations
      // still hold: O3·v = O5·v (a plane with normal v, through P0 when J4 is 0 or 180°) and the
      // two spheres. With O5 = d·u + dv·v (u across v): O3 = a·u + dv·v ± h·(v × u).
      double vx = c * e1x + sn * e2x, vy = c * e1y + sn * e2y, vz = c * e1z + sn * e2z;
      double dv = px * vx + py * vy + pz * vz;
      double dx = px - dv * vx, dy = py - dv * vy, dz = pz - dv * vz;
      double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
      double l3 = lay.l3() / l2;
      if (d > 1e-12) {
        double a = (1 - l3 * l3 - dv * dv + d * d) / (2 * d);
        double h2 = 1 - a * a - dv * dv;
        if (h2 > -1e-9) {
          double h = Math.sqrt(Math.max(0, h2));
          double ux = dx / d, uy = dy / d, uz = dz / d;
          double wx = vy * uz - vz * uy, wy = vz * ux - vx * uz, wz = vx * uy - vy * ux;
          for (int s = -1; s <= 1; s += 2) {
            elbow(p0.x() + l2 * (a * ux + dv * vx + s * h * wx), p0.y() + l2 * (a * uy + dv * vy + s * h * wy),
                p0.z() + l2 * (a * uz + dv * vz + s * h * wz), px, py, pz);
          }
        }
      }
    }
  }

  /** Both postures (J1 and J1 + 180°) of one elbow O3 (mm, B) with O5 = P0 + L2·(px, py, pz). */
  private void elbow(double e3x, double e3y, double e3z, double px, double py, double pz) {
    double l2 = lay.l2();
    Vec3 p0 = lay.p0();
    ox3 = e3x;
    oy3 = e3y;
    oz3 = e3z;
    ox5 = px;
    oy5 = py;
    oz5 = pz;
    double o5x = p0.x() + l2 * ox5, o5y = p0.y() + l2 * oy5, o5z = p0.z() + l2 * oz5;
    // Arm plane normal (units of L2): z1 × (O5 − P0), or z1 × (O3 − P0) where the elbow lies
    // farther from the J1 axis (O5 on or next to the axis, where its direction across the axis is
    // only the root's rounding, about 1e-8); both on the axis: J1 is free (0).
    Vec3 z = lay.z1();
    double nx = z.y() * oz5 - z.z() * oy5, ny = z.z() * ox5 - z.x() * oz5, nz = z.x() * oy5 - z.y() * ox5;
    double nn = Math.sqrt(nx * nx + ny * ny + nz * nz);
    double qx = (ox3 - p0.x()) / l2, qy = (oy3 - p0.y()) / l2, qz = (oz3 - p0.z()) / l2;
    double mx = z.y() * qz - z.z() * qy, my = z.z() * qx - z.x() * qz, mz = z.x() * qy - z.y() * qx;
    double mm = Math.sqrt(mx * mx + my * my + mz * mz);
    if (mm > nn) {
      nx = mx;
      ny = my;
      nz = mz;
      nn = mm;
    }
    for (int sgn = 1; sgn >= -1; sgn -= 2) {
      if (solCount >= MAX_SOLUTIONS) {
        return;
      }
      int o = 6 * solCount;
      // J1: the J2 axis onto ±n.
      identity();
      enter(0);
      double q1;
      if (nn < 1e-9) {
        q1 = sgn > 0 ? 0 : Math.PI;
      } else {
        Vec3 u = lay.n2InL1();
        q1 = angle(0, u.x(), u.y(), u.z(), sgn * nx / nn, sgn * ny / nn, sgn * nz / nn, false);
      }
      turn(0, q1);
      enter(1);
      Vec3 u3 = lay.o3InL2();
      double q2 = angle(1, u3.x(), u3.y(), u3.z(), ox3 - oa[0], oy3 - oa[1], oz3 - oa[2], true);
      if (Double.isNaN(q2)) {
        continue;
      }
      turn(1, q2);
      enter(2);
      Vec3 u5 = lay.o5InL3();
      double q3 = angle(2, u5.x(), u5.y(), u5.z(), o5x - oa[0], o5y - oa[1], o5z - oa[2], true);
      if (Double.isNaN(q3)) {
        continue;
      }
      turn(2, q3);
      enter(3);
      Vec3 u56 = lay.o56InL4();
      double q4 = angle(3, u56.x(), u56.y(), u56.z(), o6x - o5x, o6y - o5y, o6z - o5z, false);
      turn(3, q4);
      enter(4);
      Vec3 a6 = lay.a6InL5();
      double q5 = angle(4, a6.x(), a6.y(), a6.z(), u6x, u6y, u6z, false);
      turn(4, q5);
      enter(5);
      Vec3 e = lay.e6InL6();
      double q6 = angle(5, e.x(), e.y(), e.z(), e1x, e1y, e1z, false);
      sol[o] = ClosedFormIk.wrap(q1);
      sol[o + 1] = ClosedFormIk.wrap(q2);
      sol[o + 2] = ClosedFormIk.wrap(q3);
      sol[o + 3] = ClosedFormIk.wrap(q4);
      sol[o + 4] = ClosedFormIk.wrap(q5);
      sol[o + 5] = ClosedFormIk.wrap(q6);
      System.arraycopy(sol, o, cand, 0, 6);
      if (!polish.polish(cand, target)) {
        continue;
      }
      for (int i = 0; i < 6; i++) {
        sol[o + i] = ClosedFormIk.wrap(cand[i]);
      }
      if (!duplicate(o)) {
        solCount++;
      }
    }
  }

  private boolean duplicate(int o) {
    for (int k = 0; k < o; k += 6) {
      double d = 0;
      for (int i = 0; i < 6; i++) {
        d = Math.max(d, Math.abs(ClosedFormIk.wrap(sol[k + i] - sol[o + i])));
      }
      if (d < 1e-7) {
        return true;
      }
    }
    return false;
  }

  // ---- joint by joint: the frame walker --------------------------------------------------

  private void identity() {
    fr[0] = 1; fr[1] = 0; fr[2] = 0;
    fr[3] = 0; fr[4] = 1; fr[5] = 0;
    fr[6] = 0; fr[7] = 0; fr[8] = 1;
    fp[0] = 0; fp[1] = 0; fp[2] = 0;
  }

  /** ra, oa := the frame of joint i at q_i = 0: (fr, fp) · X_PJ(i). */
  private void enter(int i) {
    int o9 = 9 * i, o3 = 3 * i;
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) {
        ra[3 * r + c] = fr[3 * r] * rpj[o9 + c] + fr[3 * r + 1] * rpj[o9 + 3 + c] + fr[3 * r + 2] * rpj[o9 + 6 + c];
      }
      oa[r] = fp[r] + fr[3 * r] * tpj[o3] + fr[3 * r + 1] * tpj[o3 + 1] + fr[3 * r + 2] * tpj[o3 + 2];
    }
  }

  /** (fr, fp) := (ra, oa) · Rot(axis_i, q). */
  private void turn(int i, double q) {
    double kx = ax[3 * i], ky = ax[3 * i + 1], kz = ax[3 * i + 2];
    double c = Math.cos(q), s = Math.sin(q), v = 1 - c;
    double m00 = c + kx * kx * v, m01 = kx * ky * v - kz * s, m02 = kx * kz * v + ky * s;
    double m10 = ky * kx * v + kz * s, m11 = c + ky * ky * v, m12 = ky * kz * v - kx * s;
    double m20 = kz * kx * v - ky * s, m21 = kz * ky * v + kx * s, m22 = c + kz * kz * v;
    for (int r = 0; r < 3; r++) {
      double a = ra[3 * r], b = ra[3 * r + 1], d = ra[3 * r + 2];
      fr[3 * r] = a * m00 + b * m10 + d * m20;
      fr[3 * r + 1] = a * m01 + b * m11 + d * m21;
      fr[3 * r + 2] = a * m02 + b * m12 + d * m22;
    }
    fp[0] = oa[0];
    fp[1] = oa[1];
    fp[2] = oa[2];
  }

  /**
   * The angle about joint i's axis that turns the link-frame vector u onto the base vector w
   * (seen from the joint frame {@link #ra}); with {@code check}, NaN when no angle does (the
   * lengths across the axis or along it differ by more than 1e-6 relative).
   */
  private double angle(int i, double ux, double uy, double uz, double wx, double wy, double wz, boolean check) {
    // w' = raᵀ w
    double vx = ra[0] * wx + ra[3] * wy + ra[6] * wz;
    double vy = ra[1] * wx + ra[4] * wy + ra[7] * wz;
    double vz = ra[2] * wx + ra[5] * wy + ra[8] * wz;
    double kx = ax[3 * i], ky = ax[3 * i + 1], kz = ax[3 * i + 2];
    double ku = kx * ux + ky * uy + kz * uz, kv = kx * vx + ky * vy + kz * vz;
    double cross = kx * (uy * vz - uz * vy) + ky * (uz * vx - ux * vz) + kz * (ux * vy - uy * vx);
    double dot = ux * vx + uy * vy + uz * vz - ku * kv;
    if (check) {
      double uu = ux * ux + uy * uy + uz * uz - ku * ku, vv = vx * vx + vy * vy + vz * vz - kv * kv;
      double scale = Math.max(1, Math.sqrt(ux * ux + uy * uy + uz * uz));
      if (Math.abs(Math.sqrt(Math.max(0, uu)) - Math.sqrt(Math.max(0, vv))) > 1e-3 * scale
          || Math.abs(ku - kv) > 1e-3 * scale) {
        return Double.NaN;
      }
    }
    return Math.atan2(cross, dot);
  }

  // ---- helpers ---------------------------------------------------------------------------

  private IkResult solved(double[] q) {
    chain.flangePose(q, fk, null);
    double dx = fk[9] - target[9], dy = fk[10] - target[10], dz = fk[11] - target[11];
    return new IkResult.Solved(q.clone(), Math.sqrt(dx * dx + dy * dy + dz * dz), ClosedFormIk.rotationAngle(fk, target), 0);
  }

  private IkResult.Unreachable outOfReach() {
    return new IkResult.Unreachable(IkResult.Reason.OUT_OF_REACH, String.format(java.util.Locale.ROOT,
        "position (%.1f, %.1f, %.1f) mm is out of reach: no arm posture places the wrist there",
        target[9], target[10], target[11]));
  }
}
