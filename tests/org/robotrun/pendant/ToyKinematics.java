package org.robotrun.pendant;

import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Position;

/**
 * The stand-in controller's arm: a Cartesian gantry with a three-axis wrist, so that joints and
 * flange pose convert both ways in closed form without the {@code robot} package (which the
 * pendant may not import). J1..J3 travel 10 mm per degree along world X, Y, Z from
 * (600, 0, 400) mm; J4..J6 add to W = 180°, P = 0°, R = 0° (flange pointing down at zero).
 * Every joint is limited to ±170°. It exists so pendant scripts and tests run before the real
 * controller is wired; the real arm lives behind {@code sim.Controller}.
 */
final class ToyKinematics {
  private ToyKinematics() {}

  static final double MM_PER_DEG = 10;
  static final double LIMIT_DEG = 170;
  private static final double X0_MM = 600;
  private static final double Z0_MM = 400;
  private static final double W0_DEG = 180;

  /** X_WF: the flange pose in world for joints (deg). */
  static Transform flangeInWorld(Position.Joint q) {
    return Xyzwpr.ofDegrees(X0_MM + MM_PER_DEG * q.j1Deg(), MM_PER_DEG * q.j2Deg(), Z0_MM + MM_PER_DEG * q.j3Deg(),
        W0_DEG + q.j4Deg(), q.j5Deg(), q.j6Deg()).toTransform();
  }

  /** Joints for a flange pose in world, or empty when a joint would pass its limit. */
  static Optional<Position.Joint> joints(Transform X_WF) {
    Xyzwpr f = Xyzwpr.fromTransform(X_WF);
    Position.Joint q = new Position.Joint((f.x() - X0_MM) / MM_PER_DEG, f.y() / MM_PER_DEG, (f.z() - Z0_MM) / MM_PER_DEG,
        wrap(f.wDeg() - W0_DEG), f.pDeg(), f.rDeg());
    return withinLimits(q) ? Optional.of(q) : Optional.empty();
  }

  static boolean withinLimits(Position.Joint q) {
    for (int j = 1; j <= 6; j++) {
      if (Math.abs(q.element(j)) > LIMIT_DEG + 1e-9) {
        return false;
      }
    }
    return true;
  }

  /** The first joint past its limit, for the alarm text (0 when none). */
  static int jointOverLimit(Position.Joint q) {
    for (int j = 1; j <= 6; j++) {
      if (Math.abs(q.element(j)) > LIMIT_DEG + 1e-9) {
        return j;
      }
    }
    return 0;
  }

  private static double wrap(double deg) {
    double d = deg % 360;
    if (d > 180) {
      d -= 360;
    } else if (d <= -180) {
      d += 360;
    }
    return d;
  }
}
