package org.robotrun.robot;

import java.util.Optional;
import java.util.Random;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Detects whether a chain is ortho-parallel with a spherical wrist (the OPW family of
 * Brandstötter, Angerer and Hofbaur 2014: most FANUC arms) and derives its closed-form
 * parameters from the chain itself, so that any arm (a library file or an imported URDF) gets
 * the closed form when its geometry allows it. Nothing is read from a hand-written block.
 *
 * <p>Method, from the joint axis lines at q = 0 in OPW's base frame O (B itself, or B turned and
 * moved so that its z lies along J1): J2 horizontal (perpendicular to J1), J3 parallel to J2;
 * J4 perpendicular to J3, J5 to J4, J6 to J5; J4, J5 and J6 through one point C (the wrist
 * centre). The OPW frame's x is the horizontal direction perpendicular to J2 that
 * points toward C, which gives the J1 offset; a1, c1 are J2's position in that frame, b is C's
 * lateral offset, c2 the J2–J3 distance, c3 and a2 the J3→C vector along and across the J4
 * axis, c4 the distance from C along J6 to the flange's foot on the J6 axis. Offsets are the OPW angles at q = 0 (negated) and the sign
 * corrections compare each joint axis with OPW's positive axis, choosing J5's and J6's signs so
 * that their offsets are 0 where possible (FANUC's own choice). A base whose z is not along J1
 * (or whose origin is off the J1 axis) and a flange whose z is not along J6 (or whose origin is
 * off it) are carried as constant corrections ({@link OpwParameters#base()},
 * {@link OpwParameters#flange()}). The result is then checked: an
 * OPW forward kinematics of the parameters must reproduce the chain's flange pose on 64 joint
 * vectors within the limits (1e-6 mm, 1e-9 rad), else the chain is not treated as OPW.
 */
public final class OpwDerivation {
  /** Angular tolerance (rad, as |sin| or |cos|) of the perpendicular/parallel tests. */
  private static final double ANGLE_TOL = 1e-9;
  /** Length tolerance (mm) of the intersection tests. */
  private static final double LENGTH_TOL = 1e-6;
  private static final int VERIFY_SAMPLES = 64;
  /** Tolerances for a chain that is OPW only to within its file's rounding (rad, mm). */
  static final double LOOSE_ANGLE_TOL = 1e-4;
  static final double LOOSE_LENGTH_TOL = 0.05;
  /** How far the approximate OPW FK may then be from the chain's (mm, rad). */
  private static final double LOOSE_FIT_MM = 1.0;
  private static final double LOOSE_FIT_RAD = 2e-3;

  private OpwDerivation() {}

  /** The OPW parameters of a chain, or empty when it is not an OPW arm (its own opw is ignored). */
  public static Optional<OpwParameters> derive(RobotModel m) {
    Optional<OpwParameters> p = geometry(m, ANGLE_TOL, LENGTH_TOL).filter(o -> verify(m, o, 1e-6, 1e-9));
    if (p.isPresent()) {
      return p;
    }
    // OPW only to within the rounding of the file's numbers: the closed form gives a start that
    // Newton steps on the chain finish (OpwParameters.approximate).
    return geometry(m, LOOSE_ANGLE_TOL, LOOSE_LENGTH_TOL).filter(o -> verify(m, o, LOOSE_FIT_MM, LOOSE_FIT_RAD))
        .map(OpwParameters::asApproximate);
  }

  private static Optional<OpwParameters> geometry(RobotModel m, double at, double lt) {
    Transform[] L = ForwardKinematics.linkPosesInBase(m, new double[6]);
    Vec3[] p = new Vec3[6];
    Vec3[] d = new Vec3[6];
    for (int i = 0; i < 6; i++) {
      p[i] = L[i + 1].translationVector();
      d[i] = L[i + 1].rotate(m.joint(i).axis()).normalized();
    }
    Transform F0 = L[6].compose(m.X_6F());
    Vec3 z = Vec3.Z;
    // OPW's base frame O: B itself when J1 lies along ±z through B's origin (every library
    // arm), else z along J1, origin at the foot of B's origin on the J1 axis (a turned or moved
    // URDF base: wall, ceiling, offset mount). Everything below is measured in O.
    Transform X_BO = Transform.IDENTITY;
    if (Math.abs(d[0].x()) > ANGLE_TOL || Math.abs(d[0].y()) > ANGLE_TOL
        || Math.abs(p[0].x()) > LENGTH_TOL || Math.abs(p[0].y()) > LENGTH_TOL) {
      X_BO = frameOnAxis(p[0], d[0]);
      Transform X_OB = X_BO.inverse();
      for (int i = 0; i < 6; i++) {
        p[i] = X_OB.apply(p[i]);
        d[i] = X_OB.rotate(d[i]);
      }
      F0 = X_OB.compose(F0);
    }
    int s1 = d[0].z() > 0 ? 1 : -1;
    if (Math.abs(d[1].dot(z)) > at || d[1].cross(d[2]).norm() > at
        || Math.abs(d[3].dot(d[2])) > at || Math.abs(d[4].dot(d[3])) > at
        || Math.abs(d[5].dot(d[4])) > at) {
      return Optional.empty();
    }
    Optional<Vec3> c45 = intersection(p[3], d[3], p[4], d[4], lt);
    if (c45.isEmpty() || lineDistance(c45.get(), p[5], d[5]) > lt) {
      return Optional.empty();
    }
    Vec3 c = c45.get();
    // The OPW frame: x horizontal, perpendicular to J2, toward the wrist centre (else toward +x).
    Vec3 xO = d[1].cross(z).normalized();
    double toward = c.minus(p[1]).dot(xO);
    if (toward < -lt || (Math.abs(toward) <= lt && xO.x() < 0)) {
      xO = xO.times(-1);
    }
    Vec3 yO = z.cross(xO);
    double phi = Math.atan2(xO.y(), xO.x());
    int s2 = d[1].dot(yO) > 0 ? 1 : -1;
    int s3 = d[2].dot(yO) > 0 ? 1 : -1;
    double a1 = p[1].dot(xO), c1 = p[1].z(), b = c.dot(yO);
    // J3 in the arm plane (x, z).
    double x3 = p[2].dot(xO) - a1, z3 = p[2].z() - c1;
    double c2 = Math.hypot(x3, z3);
    double th2 = Math.atan2(x3, z3);
    // Forearm direction f along the J4 axis, pointing from J3 toward C.
    if (Math.abs(d[3].dot(yO)) > at) {
      return Optional.empty();
    }
    double fx = d[3].dot(xO), fz = d[3].z();
    double cx = c.dot(xO) - p[2].dot(xO), cz = c.z() - p[2].z();
    int s4 = 1;
    if (cx * fx + cz * fz < 0) {
      fx = -fx;
      fz = -fz;
      s4 = -1;
    }
    double s0 = Math.atan2(fx, fz);
    double th3 = s0 - th2;
    double a2 = cx * Math.cos(s0) - cz * Math.sin(s0);
    double c3 = cx * fx + cz * fz;
    // Forearm rotation Rz(φ)·Ry(s0); the wrist axes in it.
    Transform Ra = Transform.rotation(0, 0, 1, phi).compose(Transform.rotation(0, 1, 0, s0));
    Transform RaT = Ra.inverse();
    Vec3 v5 = RaT.rotate(d[4]);
    int s5 = Math.abs(v5.y()) > 1e-12 ? (v5.y() > 0 ? 1 : -1) : (v5.x() < 0 ? 1 : -1);
    double th4 = Math.atan2(-s5 * v5.x(), s5 * v5.y());
    Vec3 w = Transform.rotation(0, 0, 1, -th4).rotate(RaT.rotate(d[5]));
    int s6 = Math.abs(w.z()) > 1e-12 ? (w.z() > 0 ? 1 : -1) : (w.x() > 0 ? 1 : -1);
    double th5 = Math.atan2(s6 * w.x(), s6 * w.z());
    Transform Rw = Ra.compose(Transform.rotation(0, 0, 1, th4)).compose(Transform.rotation(0, 1, 0, th5));
    Transform M = Rw.inverse().compose(F0.withTranslation(0, 0, 0));
    // The canonical flange F' sits on the J6 axis (z along it) at the foot of the flange's
    // origin; where the file's flange is F' turned about z (every library arm), that turn is
    // J6's offset, else J6's offset is 0 and the rest is the constant correction X_F'F.
    // Tilt of the flange's z from J6 by its sine, not 1 - cos: a tilt of 3e-8 rad (a file's
    // rpy="3.14159265 -1.5707963 0") moves r22 by 5e-16 only, and read as "along" it was lost,
    // leaving the exact form off by that tilt and the arm on the approximate path.
    boolean zAlong = M.r22() > 0 && Math.hypot(M.r02(), M.r12()) <= ANGLE_TOL;
    double th6 = zAlong ? Math.atan2(M.r10(), M.r00()) : 0;
    Vec3 ez = Rw.axis(2);
    Vec3 cf = F0.translationVector().minus(c);
    double c4 = cf.dot(ez);
    double[] offsets = {
      ClosedFormIk.wrap(-phi), ClosedFormIk.wrap(-th2), ClosedFormIk.wrap(-th3),
      ClosedFormIk.wrap(-th4), ClosedFormIk.wrap(-th5), ClosedFormIk.wrap(-th6)
    };
    for (int i = 0; i < 6; i++) {
      offsets[i] = tidy(offsets[i]);
    }
    int[] signs = {s1, s2, s3, s4, s5, s6};
    OpwParameters plain = new OpwParameters(tidy(a1), tidy(a2), tidy(b), tidy(c1), tidy(c2), tidy(c3), tidy(c4),
        offsets, signs);
    Transform X_FpF = Transform.IDENTITY;
    if (!zAlong || cf.minus(ez.times(c4)).norm() > LENGTH_TOL) {
      X_FpF = orIdentity(forwardOpw(plain, new double[6]).inverse().compose(F0));
    }
    if (X_BO == Transform.IDENTITY && X_FpF == Transform.IDENTITY) {
      return Optional.of(plain);
    }
    return Optional.of(new OpwParameters(plain.a1(), plain.a2(), plain.b(), plain.c1(), plain.c2(), plain.c3(),
        plain.c4(), offsets, signs, X_BO, X_FpF));
  }

  /** A frame with its z along the unit direction d, its origin the foot of B's origin on the line (p, d). */
  private static Transform frameOnAxis(Vec3 p, Vec3 d) {
    Vec3 zo = d.normalized();
    Vec3 o = p.minus(zo.times(p.dot(zo)));
    Vec3 xo = Vec3.X.minus(zo.times(zo.x()));
    if (xo.norm() < 0.5) {
      xo = Vec3.Y.minus(zo.times(zo.y()));
    }
    xo = xo.normalized();
    Vec3 yo = zo.cross(xo);
    return Transform.of(new double[] {xo.x(), yo.x(), zo.x(), xo.y(), yo.y(), zo.y(), xo.z(), yo.z(), zo.z()},
        o.x(), o.y(), o.z());
  }

  /** The identity itself when {@code t} differs from it only by round-off, else {@code t}. */
  private static Transform orIdentity(Transform t) {
    return t.distanceTo(Transform.IDENTITY) < 1e-9 && t.rotationAngleTo(Transform.IDENTITY) < 1e-12
        ? Transform.IDENTITY : t;
  }

  /** Rounds away the last bits of round-off (e.g. -90.00000000000001° or 1e-14 mm). */
  private static double tidy(double v) {
    double r = Math.rint(v * 1e9) / 1e9;
    return Math.abs(v - r) < 1e-12 * Math.max(1, Math.abs(v)) ? r : v;
  }

  /**
   * OPW forward kinematics (flange pose in B) of the parameters, corrections included
   * ({@code X_BO · OPW(q) · X_F'F}): the check against the chain.
   */
  public static Transform forward(OpwParameters o, double[] q) {
    Transform f = forwardOpw(o, q);
    return o.corrected() ? o.base().compose(f).compose(o.flange()) : f;
  }

  /** The canonical OPW flange F' in OPW's base frame O (no corrections). */
  static Transform forwardOpw(OpwParameters o, double[] q) {
    double[] t = new double[6];
    for (int i = 0; i < 6; i++) {
      t[i] = o.sign(i) * q[i] - o.offsetRad(i);
    }
    double t23 = t[1] + t[2];
    double s2 = Math.sin(t[1]), c2 = Math.cos(t[1]), s23 = Math.sin(t23), c23 = Math.cos(t23);
    double x = o.a1() + o.c2() * s2 + o.c3() * s23 + o.a2() * c23;
    double zc = o.c1() + o.c2() * c2 + o.c3() * c23 - o.a2() * s23;
    Transform R1 = Transform.rotation(0, 0, 1, t[0]);
    Vec3 cw = R1.rotate(new Vec3(x, o.b(), zc));
    Transform R = R1.compose(Transform.rotation(0, 1, 0, t23)).compose(Transform.rotation(0, 0, 1, t[3]))
        .compose(Transform.rotation(0, 1, 0, t[4])).compose(Transform.rotation(0, 0, 1, t[5]));
    Vec3 f = cw.plus(R.axis(2).times(o.c4()));
    return R.withTranslation(f.x(), f.y(), f.z());
  }

  private static boolean verify(RobotModel m, OpwParameters o, double mm, double rad) {
    Random rnd = new Random(20251126L);
    double[] q = new double[6];
    for (int k = 0; k < VERIFY_SAMPLES; k++) {
      for (int i = 0; i < 6; i++) {
        q[i] = k == 0 ? 0 : m.joint(i).lowerRad() + rnd.nextDouble() * (m.joint(i).upperRad() - m.joint(i).lowerRad());
      }
      Transform a = forward(o, q);
      Transform b = ForwardKinematics.flangePoseInBase(m, q);
      if (a.distanceTo(b) > mm || a.rotationAngleTo(b) > rad) {
        return false;
      }
    }
    return true;
  }

  /** The common point of two lines (closest points within {@link #LENGTH_TOL}), if not parallel. */
  static Optional<Vec3> intersection(Vec3 p, Vec3 d, Vec3 q, Vec3 e) {
    return intersection(p, d, q, e, LENGTH_TOL);
  }

  /** As {@link #intersection(Vec3, Vec3, Vec3, Vec3)} with closest points within {@code tol} (mm). */
  static Optional<Vec3> intersection(Vec3 p, Vec3 d, Vec3 q, Vec3 e, double tol) {
    Vec3 n = d.cross(e);
    double nn = n.dot(n);
    if (nn < ANGLE_TOL * ANGLE_TOL) {
      return Optional.empty();
    }
    Vec3 r = q.minus(p);
    double s = r.cross(e).dot(n) / nn;
    double t = r.cross(d).dot(n) / nn;
    Vec3 a = p.plus(d.times(s));
    Vec3 b = q.plus(e.times(t));
    return a.distanceTo(b) <= tol ? Optional.of(a.plus(b).times(0.5)) : Optional.empty();
  }

  /** Distance of a point from a line. */
  static double lineDistance(Vec3 x, Vec3 p, Vec3 d) {
    return x.minus(p).cross(d).norm() / d.norm();
  }
}
