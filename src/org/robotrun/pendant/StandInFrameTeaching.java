package org.robotrun.pendant;

import java.util.List;
import java.util.Locale;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.pendant.RobotControl.TeachMethod;
import org.robotrun.pendant.RobotControl.TeachResult;
import org.robotrun.program.Config;
import org.robotrun.program.Position;

/**
 * Frame teaching for the stand-in controller. The project's frame teaching belongs to
 * {@code robot.FrameTeaching} (kinematics issue), which the pendant may not import; the adapter
 * onto {@code sim.Controller} uses that one. This is the same geometry in its plainest form:
 * user frames from an origin, an X-direction and a Y-direction point (plus a system origin for
 * four points); tool centre points by the pivot method (the same point touched in three
 * orientations: least squares on {@code (R_i - R_j) t = p_j - p_i}, the standard TCP
 * calibration), with orientation from the six-point methods' direction points.
 */
final class StandInFrameTeaching {
  private StandInFrameTeaching() {}

  /** Minimum distance between teaching points (mm) before the frame counts as undefined. */
  private static final double MIN_SPREAD_MM = 1.0;

  /**
   * @param flanges X_WF at each recorded point
   * @param tcps the TCP of the active tool in world at each point (user-frame methods)
   */
  static TeachResult teach(TeachMethod method, List<Transform> flanges, List<Vec3> tcps) {
    return switch (method) {
      case USER_THREE_POINT -> userFrame(tcps.get(0), tcps.get(1), tcps.get(2), tcps.get(0));
      case USER_FOUR_POINT -> userFrame(tcps.get(0), tcps.get(1), tcps.get(2), tcps.get(3));
      case TOOL_THREE_POINT -> tcp(flanges) instanceof Pivot.Ok ok
          ? taught(Transform.translation(ok.t.x(), ok.t.y(), ok.t.z()), ok.detail())
          : new TeachResult.Failed(((Pivot.Bad) tcp(flanges)).reason);
      case TOOL_SIX_POINT_XZ, TOOL_SIX_POINT_XY -> sixPoint(flanges, method == TeachMethod.TOOL_SIX_POINT_XZ);
      case DIRECT_ENTRY_TOOL, DIRECT_ENTRY_USER -> new TeachResult.Failed("direct entry has no points to compute from");
    };
  }

  private static TeachResult userFrame(Vec3 origin, Vec3 xPoint, Vec3 yPoint, Vec3 frameOrigin) {
    Transform axes;
    try {
      axes = axes(origin, xPoint, yPoint, true);
    } catch (IllegalArgumentException e) {
      return new TeachResult.Failed(e.getMessage());
    }
    return taught(axes.withTranslation(frameOrigin.x(), frameOrigin.y(), frameOrigin.z()), "");
  }

  /** Rotation with X toward {@code xPoint} and the second axis (Y, or Z when !xy) toward {@code other}. */
  private static Transform axes(Vec3 origin, Vec3 xPoint, Vec3 other, boolean xy) {
    Vec3 dx = xPoint.minus(origin);
    Vec3 d2 = other.minus(origin);
    if (dx.norm() < MIN_SPREAD_MM || d2.norm() < MIN_SPREAD_MM) {
      throw new IllegalArgumentException("points too close together (under " + MIN_SPREAD_MM + " mm)");
    }
    Vec3 x = dx.normalized();
    Vec3 n = x.cross(d2);
    if (n.norm() < 1e-3 * d2.norm()) {
      throw new IllegalArgumentException("the three points are on one line");
    }
    Vec3 y;
    Vec3 z;
    if (xy) {
      z = n.normalized();
      y = z.cross(x);
    } else {
      // X-Z plane: the Z point fixes Z after removing its X part; Y completes a right-handed frame.
      y = d2.cross(x).normalized();
      z = x.cross(y);
    }
    return Transform.of(new double[] {x.x(), y.x(), z.x(), x.y(), y.y(), z.y(), x.z(), y.z(), z.z()}, 0, 0, 0);
  }

  private sealed interface Pivot {
    record Ok(Vec3 t, double spreadMm) implements Pivot {
      String detail() {
        return String.format(Locale.ROOT, "(pivot spread %.2f mm)", spreadMm);
      }
    }

    record Bad(String reason) implements Pivot {}
  }

  /** The TCP in the flange from three flange poses touching one point (least squares). */
  private static Pivot tcp(List<Transform> f) {
    double[][] ata = new double[3][3];
    double[] atb = new double[3];
    int[][] pairs = {{0, 1}, {0, 2}, {1, 2}};
    for (int[] pr : pairs) {
      Transform a = f.get(pr[0]);
      Transform b = f.get(pr[1]);
      double[] ra = a.rotationRowMajor();
      double[] rb = b.rotationRowMajor();
      double[] d = {b.x() - a.x(), b.y() - a.y(), b.z() - a.z()};
      for (int row = 0; row < 3; row++) {
        double[] arow = {ra[3 * row] - rb[3 * row], ra[3 * row + 1] - rb[3 * row + 1], ra[3 * row + 2] - rb[3 * row + 2]};
        for (int i = 0; i < 3; i++) {
          for (int j = 0; j < 3; j++) {
            ata[i][j] += arow[i] * arow[j];
          }
          atb[i] += arow[i] * d[row];
        }
      }
    }
    double det = det(ata);
    if (Math.abs(det) < 1e-6) {
      return new Pivot.Bad("approach orientations too similar: tilt the tool differently at each point");
    }
    double[] t = new double[3];
    for (int c = 0; c < 3; c++) {
      double[][] m = new double[3][];
      for (int r = 0; r < 3; r++) {
        m[r] = ata[r].clone();
        m[r][c] = atb[r];
      }
      t[c] = det(m) / det;
    }
    Vec3 tv = new Vec3(t[0], t[1], t[2]);
    double spread = 0;
    for (int i = 0; i < 3; i++) {
      for (int j = i + 1; j < 3; j++) {
        spread = Math.max(spread, f.get(i).apply(tv).distanceTo(f.get(j).apply(tv)));
      }
    }
    return new Pivot.Ok(tv, spread);
  }

  private static TeachResult sixPoint(List<Transform> f, boolean xz) {
    Pivot p = tcp(f.subList(0, 3));
    if (p instanceof Pivot.Bad bad) {
      return new TeachResult.Failed(bad.reason());
    }
    Vec3 t = ((Pivot.Ok) p).t();
    Transform origin = f.get(3);
    Vec3 o = origin.apply(t);
    Vec3 xp = f.get(4).apply(t);
    Vec3 other = f.get(5).apply(t);
    Transform R_WT;
    try {
      R_WT = axes(o, xp, other, !xz);
    } catch (IllegalArgumentException e) {
      return new TeachResult.Failed(e.getMessage());
    }
    Transform R_WF = origin.withTranslation(0, 0, 0);
    Transform R_FT = R_WF.inverse().compose(R_WT);
    return taught(R_FT.withTranslation(t.x(), t.y(), t.z()), ((Pivot.Ok) p).detail());
  }

  private static double det(double[][] m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }

  private static TeachResult taught(Transform frame, String detail) {
    return new TeachResult.Taught(Position.Cartesian.of(Xyzwpr.fromTransform(frame), Config.DEFAULT), detail);
  }
}
