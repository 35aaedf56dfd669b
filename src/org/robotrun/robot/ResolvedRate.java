package org.robotrun.robot;

/**
 * One resolved-rate step: the joint rates that give a desired TCP twist, by a damped
 * pseudoinverse of the analytic Jacobian whose damping rises smoothly near singularities.
 * This is what jogging in WORLD/TOOL/USER and linear/circular moves use.
 *
 * <p>Method. Linear rows of the Jacobian are divided by a characteristic length L (mm) so the
 * six rows are comparable (dimensionless {@code Js = S·J}, {@code S = diag(1/L, 1/L, 1/L, 1, 1, 1)}).
 * Manipulability is Yoshikawa's {@code w = sqrt(det(Js·Jsᵀ)) = |det Js|}. Damping follows
 * Nakamura and Hanafusa (1986): {@code λ² = λmax²·(1 − w/w0)²} for {@code w < w0}, else 0, which
 * is continuous with a continuous slope at w0. Then
 * {@code q̇ = Jsᵀ (Js·Jsᵀ + λ²I)⁻¹ S·v}. Away from singularities (λ = 0) that is exactly
 * {@code Js⁻¹·S·v}, solved by the same LU that gave det; near them the 6x6 normal equations
 * are solved by Cholesky. A hand 6x6 path is used instead of a general SVD because it is an
 * order of magnitude faster; the tests compare it with the SVD form
 * {@code Σ σᵢ/(σᵢ²+λ²)·vᵢuᵢᵀ} from Commons Math.
 *
 * <p>Not thread-safe: holds scratch arrays; use one per controller. Allocation-free.
 */
public final class ResolvedRate {
  /** Tuning: characteristic length (mm), manipulability threshold, maximum damping. */
  public record Settings(double lengthScaleMm, double manipulabilityThreshold, double maxDamping) {
    public Settings {
      if (!(lengthScaleMm > 0 && manipulabilityThreshold > 0 && maxDamping >= 0)) {
        throw new IllegalArgumentException("resolved-rate settings must be positive");
      }
    }

    /**
     * Defaults for a desktop-size arm: L = 500 mm; w0 = 0.01 (about 1/20 of the median w on
     * the LR Mate's reference targets, so damping only acts close to a singularity);
     * λmax = 0.05.
     */
    public static Settings defaults() {
      return new Settings(500, 0.01, 0.05);
    }
  }

  private final KinematicChain chain;
  private final Settings settings;
  private final double invL;
  private final double[] j = new double[36];
  private final double[] lu = new double[36];
  private final double[] a = new double[36];
  private final double[] pose = new double[12];
  private final double[] scratch = new double[Jacobian.SCRATCH];
  private final double[] rhs = new double[6];
  private final int[] perm = new int[6];
  private final double[] invDiag = new double[6];
  private double lastDamping;
  private double lastManipulability;

  public ResolvedRate(RobotModel model) {
    this(new KinematicChain(model), Settings.defaults());
  }

  public ResolvedRate(KinematicChain chain, Settings settings) {
    this.chain = chain;
    this.settings = settings;
    this.invL = 1 / settings.lengthScaleMm();
  }

  /**
   * Joint rates for a TCP twist.
   *
   * @param q current joints (rad)
   * @param twist_B desired TCP twist in the base frame: vx, vy, vz (mm/s), ωx, ωy, ωz (rad/s)
   * @param X_FT tool frame in the flange (packed 12, see {@link KinematicChain}), or null
   * @param qDot output joint rates (rad/s), 6
   * @return the manipulability w (dimensionless, see the class comment)
   */
  public double step(double[] q, double[] twist_B, double[] X_FT, double[] qDot) {
    Jacobian.tcpJacobianInBase(chain, q, X_FT, j, pose, scratch);
    for (int c = 0; c < 18; c++) {
      j[c] *= invL;
    }
    for (int r = 0; r < 6; r++) {
      rhs[r] = r < 3 ? twist_B[r] * invL : twist_B[r];
    }
    System.arraycopy(j, 0, lu, 0, 36);
    double det = Dense6.luDecompose(lu, perm);
    double w = Math.abs(det);
    double w0 = settings.manipulabilityThreshold();
    double lambda2 = 0;
    if (w < w0) {
      double f = 1 - w / w0;
      lambda2 = settings.maxDamping() * settings.maxDamping() * f * f;
    }
    lastManipulability = w;
    lastDamping = Math.sqrt(lambda2);
    if (lambda2 == 0) {
      Dense6.luSolve(lu, perm, rhs, qDot);
      return w;
    }
    // A = Js·Jsᵀ + λ²I (symmetric positive definite for λ > 0): solve A·y = rhs, q̇ = Jsᵀ·y.
    for (int r = 0; r < 6; r++) {
      int ro = r * 6;
      double j0 = j[ro], j1 = j[ro + 1], j2 = j[ro + 2], j3 = j[ro + 3], j4 = j[ro + 4], j5 = j[ro + 5];
      for (int c = 0; c <= r; c++) {
        int co = c * 6;
        a[ro + c] = j0 * j[co] + j1 * j[co + 1] + j2 * j[co + 2] + j3 * j[co + 3] + j4 * j[co + 4] + j5 * j[co + 5];
      }
      a[ro + r] += lambda2;
    }
    Dense6.choleskySolve(a, rhs, invDiag);
    for (int c = 0; c < 6; c++) {
      double sum = 0;
      for (int r = 0; r < 6; r++) {
        sum += j[r * 6 + c] * rhs[r];
      }
      qDot[c] = sum;
    }
    return w;
  }

  /** Damping λ used by the last {@link #step} (0 away from singularities). */
  public double lastDamping() {
    return lastDamping;
  }

  /** Manipulability of the last {@link #step}. */
  public double lastManipulability() {
    return lastManipulability;
  }

  public Settings settings() {
    return settings;
  }
}
