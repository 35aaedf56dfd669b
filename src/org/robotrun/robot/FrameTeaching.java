package org.robotrun.robot;

import java.util.List;
import org.apache.commons.math3.linear.Array2DRowRealMatrix;
import org.apache.commons.math3.linear.ArrayRealVector;
import org.apache.commons.math3.linear.RealVector;
import org.apache.commons.math3.linear.SingularValueDecomposition;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;

/**
 * Teaching tool frames (UT) and user frames (UF) from recorded robot positions, the FANUC
 * methods: tool three-point and six-point (XZ and XY), user three-point and four-point, and
 * direct entry. Inputs are flange poses {@code X_WF} (tool methods) or TCP positions
 * {@code p_W} (user methods) in one fixed frame W (WORLD, or the base: only consistency
 * matters), mm. Tool frames come back as {@code X_FT} (tool in flange), user frames as
 * {@code X_WU}.
 *
 * <p>Degenerate input throws {@link FrameTeachingException} naming the point to re-teach.
 * Thresholds: points at least {@value #MIN_DISTANCE_MM} mm apart, directions at least
 * {@value #MIN_ANGLE_DEG}° from parallel, approach orientations at least
 * {@value #MIN_APPROACH_SPREAD_DEG}° apart pairwise and not all turned about one axis, and the
 * approaches agreeing on one touched point within {@value #MAX_APPROACH_RESIDUAL_MM} mm.
 */
public final class FrameTeaching {
  public static final double MIN_DISTANCE_MM = 1.0;
  public static final double MIN_ANGLE_DEG = 5.0;
  public static final double MIN_APPROACH_SPREAD_DEG = 15.0;
  public static final double MAX_APPROACH_RESIDUAL_MM = 2.0;
  /** Smallest singular value of the stacked [R_i, −I] system below which the TCP is ill-defined. */
  private static final double MIN_APPROACH_SIGMA = 0.1;

  /** Which axis the six-point method's third position teaches besides +X. */
  public enum SixPointVariant {
    /** Orient origin, +X direction, +Z direction (FANUC "six point (XZ)"). */
    XZ,
    /** Orient origin, +X direction, +Y direction (FANUC "six point (XY)"). */
    XY
  }

  private FrameTeaching() {}

  /**
   * Tool three-point: the TCP from three (or more) flange poses whose tool tip touches one
   * fixed point from different orientations, by least squares on {@code R_i·p_FT + t_i = p_W}
   * (six unknowns: the TCP in the flange and the touched point). The tool frame keeps the
   * flange's orientation (three points teach no orientation).
   */
  public static Transform toolThreePoint(List<Transform> X_WF_approaches) {
    Vec3 p_FT = tcp(X_WF_approaches);
    return Transform.translation(p_FT.x(), p_FT.y(), p_FT.z());
  }

  /**
   * Tool six-point: TCP from the three approach poses (as {@link #toolThreePoint}), orientation
   * from three more poses with the same flange orientation: the orient origin, then the robot
   * moved so the TCP goes along the wanted tool +X, then along +Z (XZ) or +Y (XY). The second
   * direction is orthogonalised against X.
   */
  public static Transform toolSixPoint(
      List<Transform> X_WF_approaches, Transform X_WF_orientOrigin, Transform X_WF_xDirection,
      Transform X_WF_secondDirection, SixPointVariant variant) {
    Vec3 p_FT = tcp(X_WF_approaches);
    Vec3 o = X_WF_orientOrigin.apply(p_FT);
    Vec3 px = X_WF_xDirection.apply(p_FT);
    Vec3 ps = X_WF_secondDirection.apply(p_FT);
    String second = variant == SixPointVariant.XZ ? "Z direction point" : "Y direction point";
    // Directions in the flange frame at the orient origin pose.
    Transform R_FW = X_WF_orientOrigin.inverse();
    Vec3 dx = R_FW.rotate(px.minus(o));
    Vec3 ds = R_FW.rotate(ps.minus(o));
    Axes axes = axes(dx, ds, "X direction point", second, "orient origin point");
    Vec3 x = axes.first, s = axes.second;
    return switch (variant) {
      case XZ -> frame(x, s.cross(x), s, p_FT);
      case XY -> frame(x, s, x.cross(s), p_FT);
    };
  }

  /**
   * User three-point: origin, a point on +X, a point in the XY plane on the +Y side. X points
   * from the origin to the X point; Y is the Y point's direction made orthogonal to X; Z = X × Y.
   */
  public static Transform userThreePoint(Vec3 p_WOrigin, Vec3 p_WX, Vec3 p_WY) {
    Axes axes = axes(p_WX.minus(p_WOrigin), p_WY.minus(p_WOrigin),
        "X direction point", "Y direction point", "origin point");
    return frame(axes.first, axes.second, axes.first.cross(axes.second), p_WOrigin);
  }

  /**
   * User four-point: the first three (orient origin, +X point, +Y point) give the orientation
   * as in {@link #userThreePoint}; the fourth is the frame's origin.
   */
  public static Transform userFourPoint(Vec3 p_WOrientOrigin, Vec3 p_WX, Vec3 p_WY, Vec3 p_WOrigin) {
    Axes axes = axes(p_WX.minus(p_WOrientOrigin), p_WY.minus(p_WOrientOrigin),
        "X direction point", "Y direction point", "orient origin point");
    return frame(axes.first, axes.second, axes.first.cross(axes.second), p_WOrigin);
  }

  /** Direct entry: the frame as typed on the pendant (X, Y, Z mm; W, P, R). */
  public static Transform directEntry(Xyzwpr frame) {
    return frame.toTransform();
  }

  // ---------------------------------------------------------------------------------------

  /** Least-squares TCP in the flange frame from approach poses touching one point. */
  static Vec3 tcp(List<Transform> X_WF) {
    int n = X_WF.size();
    if (n < 3) {
      throw new FrameTeachingException("approach point " + (n + 1),
          "three approach points are needed, " + n + " recorded");
    }
    // Each approach must differ in orientation from the earlier ones.
    for (int j = 1; j < n; j++) {
      for (int i = 0; i < j; i++) {
        double deg = Math.toDegrees(X_WF.get(i).rotationAngleTo(X_WF.get(j)));
        if (deg < MIN_APPROACH_SPREAD_DEG) {
          throw new FrameTeachingException("approach point " + (j + 1), String.format(
              "its orientation is only %.1f deg from approach point %d (at least %.0f deg needed)",
              deg, i + 1, MIN_APPROACH_SPREAD_DEG));
        }
      }
    }
    // [R_i  −I] · [p_FT; p_W] = −t_i, stacked.
    double[][] a = new double[3 * n][6];
    double[] b = new double[3 * n];
    for (int i = 0; i < n; i++) {
      Transform t = X_WF.get(i);
      double[] r = t.rotationRowMajor();
      for (int row = 0; row < 3; row++) {
        for (int c = 0; c < 3; c++) {
          a[3 * i + row][c] = r[row * 3 + c];
        }
        a[3 * i + row][3 + row] = -1;
      }
      b[3 * i] = -t.x();
      b[3 * i + 1] = -t.y();
      b[3 * i + 2] = -t.z();
    }
    Array2DRowRealMatrix m = new Array2DRowRealMatrix(a, false);
    SingularValueDecomposition svd = new SingularValueDecomposition(m);
    double[] sigma = svd.getSingularValues();
    if (sigma[sigma.length - 1] < MIN_APPROACH_SIGMA) {
      throw new FrameTeachingException("approach point " + n,
          "the approach orientations all turn about one axis, so the TCP along that axis is "
              + "undetermined; tilt the tool about a different axis");
    }
    RealVector x = svd.getSolver().solve(new ArrayRealVector(b, false));
    Vec3 p_FT = new Vec3(x.getEntry(0), x.getEntry(1), x.getEntry(2));
    Vec3 p_W = new Vec3(x.getEntry(3), x.getEntry(4), x.getEntry(5));
    // Each approach should put the TCP on the same point: blame the farthest one.
    int worst = -1;
    double worstMm = 0;
    for (int i = 0; i < n; i++) {
      double d = X_WF.get(i).apply(p_FT).distanceTo(p_W);
      if (d > worstMm) {
        worstMm = d;
        worst = i;
      }
    }
    if (worstMm > MAX_APPROACH_RESIDUAL_MM) {
      throw new FrameTeachingException("approach point " + (worst + 1), String.format(
          "its tool tip is %.2f mm from the point the others agree on (at most %.1f mm allowed)",
          worstMm, MAX_APPROACH_RESIDUAL_MM));
    }
    return p_FT;
  }

  private record Axes(Vec3 first, Vec3 second) {}

  /** Unit first axis and the second made orthogonal to it, with named-point checks. */
  private static Axes axes(Vec3 d1, Vec3 d2, String p1, String p2, String origin) {
    if (d1.norm() < MIN_DISTANCE_MM) {
      throw new FrameTeachingException(p1, String.format(
          "it is %.2f mm from the %s (at least %.1f mm needed)", d1.norm(), origin, MIN_DISTANCE_MM));
    }
    if (d2.norm() < MIN_DISTANCE_MM) {
      throw new FrameTeachingException(p2, String.format(
          "it is %.2f mm from the %s (at least %.1f mm needed)", d2.norm(), origin, MIN_DISTANCE_MM));
    }
    Vec3 x = d1.normalized();
    double sin = x.cross(d2).norm() / d2.norm();
    if (sin < Math.sin(Math.toRadians(MIN_ANGLE_DEG))) {
      throw new FrameTeachingException(p2, String.format(
          "it lies %.2f deg from the line through the %s and the %s (at least %.0f deg needed)",
          Math.toDegrees(Math.asin(Math.min(1, sin))), origin, p1, MIN_ANGLE_DEG));
    }
    Vec3 s = d2.minus(x.times(x.dot(d2))).normalized();
    return new Axes(x, s);
  }

  private static Transform frame(Vec3 x, Vec3 y, Vec3 z, Vec3 origin) {
    return new Transform(
        x.x(), y.x(), z.x(),
        x.y(), y.y(), z.y(),
        x.z(), y.z(), z.z(),
        origin.x(), origin.y(), origin.z());
  }
}
