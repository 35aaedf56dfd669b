package org.robotrun.pendant;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;

/**
 * The default cell's arm worked out by hand, for the pendant tests' expected numbers: nothing here
 * calls the product's kinematics, jogger or controller. The chain (joint origins, axes, speeds,
 * the flange, the WORLD origin) is read with a plain JSON parser from
 * {@code resources/robots/lrmate200id.json}, whose numbers docs/robots.md traces to
 * FANUC-CORPORATION/ROS-Industrial's LR Mate 200iD description (shared/robots/chains); the poses are
 * composed here with plain 4×4 arithmetic. The rules used, each from the project's docs:
 *
 * <ul>
 *   <li>the default cell (docs/pendant.md): the arm at HOME, all joints 0 except J5 = −90°, UTOOL[1]
 *       a 100 mm pointer along the flange's z axis, UFRAME[1] = WORLD, both active; mode T1 and a
 *       new controller's override of 100 % (the tests check both before relying on them);
 *   <li>FANUC's coupled J3 (docs/robots.md): the pendant's J3 is the kinematic J3 minus J2;
 *   <li>poses in FANUC W, P, R (shared/DESIGN.md): R = Rz(r)·Ry(p)·Rx(w), fixed axes;
 *   <li>jogging (docs/motion.md, "Jog"): JOINT at 25 % of the joint's data-sheet speed, WORLD at
 *       250 mm/s, times the override; each axis ramps up and down linearly in 0.1 s; the clock
 *       ticks in 4 ms (shared/DESIGN.md, "Time"); letting SHIFT or the DEADMAN go stops at once
 *       (docs/pendant.md); in T1 a jog tick that would move the TCP or the flange faster than
 *       250 mm/s is shortened to that speed. docs/testing.md states that cap as "never above
 *       250 mm/s, at least 249 mm/s while capped", so travel under the cap is given as a range.
 * </ul>
 *
 * <p>At HOME, by hand: J2's axis is 50 mm in front of the J1 axis at WORLD's origin height; the
 * upper arm (330 mm) stands up, J4's axis 35 mm above the elbow runs forward 335 mm to the wrist
 * centre (385, 0, 365); J5 at −90° about −y turns the 80 mm wrist straight down: the flange at
 * (385, 0, 285) facing down (W 180, P 0, R 0), the pointer's tip at (385, 0, 185).
 */
final class ArmByHand {
  private ArmByHand() {}

  /** Clock tick (s): shared/DESIGN.md, "Time". */
  static final double DT = 0.004;
  /** Jog ramp (s): docs/motion.md, "Jog". */
  static final double RAMP = 0.1;
  /** WORLD/TOOL/USER jog speed at 100 % (mm/s): docs/motion.md. */
  static final double LINEAR_JOG_MM_S = 250;
  /** The T1 cap of the TCP and the flange (mm/s), and the least speed it may run at while capped (docs/testing.md). */
  static final double T1_MM_S = 250;
  static final double T1_LEAST_MM_S = 249;
  /** The default cell's pointer tool (mm along the flange's z). */
  static final double POINTER_MM = 100;
  /** HOME in pendant degrees. */
  static final double[] HOME = {0, 0, 0, 0, -90, 0};

  private static final JsonNode ROBOT = read();

  private static JsonNode read() {
    try {
      return new ObjectMapper().readTree(Path.of("resources/robots/lrmate200id.json").toFile());
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  private static double[] vec(JsonNode n) {
    return new double[] {n.get(0).asDouble(), n.get(1).asDouble(), n.get(2).asDouble()};
  }

  /** Data-sheet maximum speed of joint j = 1..6 (deg/s). */
  static double maxSpeedDegS(int j) {
    return ROBOT.get("joints").get(j - 1).get("maxSpeed").asDouble();
  }

  /** JOINT jog speed of joint j at 100 % override (deg/s): a quarter of the data sheet's. */
  static double jointJogDegS(int j) {
    return 0.25 * maxSpeedDegS(j);
  }

  /** The flange in WORLD for pendant joints (deg), 4×4 row-major. */
  static double[] flange(double... pendantDeg) {
    double[] q = pendantDeg.clone();
    if (ROBOT.get("coupledJ3").asBoolean()) {
      q[2] = pendantDeg[2] + pendantDeg[1];
    }
    JsonNode w = ROBOT.get("worldInBase");
    // X_WB: WORLD's origin sits at worldInBase in the base frame (no rotation).
    double[] m = translation(-w.get("x").asDouble(), -w.get("y").asDouble(), -w.get("z").asDouble());
    for (int i = 0; i < 6; i++) {
      JsonNode joint = ROBOT.get("joints").get(i);
      double[] xyz = vec(joint.get("xyz"));
      double[] rpy = vec(joint.get("rpy"));
      m = mul(m, mul(translation(xyz[0], xyz[1], xyz[2]), rpyDeg(rpy)));
      m = mul(m, axisAngle(vec(joint.get("axis")), Math.toRadians(q[i])));
    }
    JsonNode f = ROBOT.get("flange");
    double[] fx = vec(f.get("xyz"));
    return mul(m, mul(translation(fx[0], fx[1], fx[2]), rpyDeg(vec(f.get("rpy")))));
  }

  /** The default pointer's tip (UTOOL[1]) in WORLD for pendant joints (deg). */
  static double[] tcp(double... pendantDeg) {
    return mul(flange(pendantDeg), translation(0, 0, POINTER_MM));
  }

  /** X, Y, Z (mm), W, P, R (deg) of a pose, FANUC's convention. */
  static double[] xyzwpr(double[] m) {
    double p = Math.asin(-m[8]);
    double w = Math.atan2(m[9], m[10]);
    double r = Math.atan2(m[4], m[0]);
    return new double[] {m[3], m[7], m[11], Math.toDegrees(w), Math.toDegrees(p), Math.toDegrees(r)};
  }

  /** Distance of a pose's origin from the J1 axis (WORLD z through WORLD's origin). */
  static double radiusFromJ1(double[] m) {
    return Math.hypot(m[3], m[7]);
  }

  /** Length of the upper arm, J2 axis to J3 axis (mm): the J3 joint's origin offset. */
  static double upperArmMm() {
    double[] xyz = vec(ROBOT.get("joints").get(2).get("xyz"));
    return Math.sqrt(xyz[0] * xyz[0] + xyz[1] * xyz[1] + xyz[2] * xyz[2]);
  }

  /**
   * Travel of one jog axis held for {@code heldSec} from rest and stopped at once (SHIFT or the
   * DEADMAN let go, no ramp down): each 4 ms tick adds the ramped speed, shortened to
   * {@code capPerSec} (same unit as {@code fullPerSec}; infinity when nothing caps it).
   */
  static double heldThenStopped(double fullPerSec, double capPerSec, double heldSec) {
    long ticks = Math.round(heldSec / DT);
    double travel = 0;
    for (long k = 1; k <= ticks; k++) {
      double v = Math.min(fullPerSec, fullPerSec * k * DT / RAMP);
      travel += Math.min(v, capPerSec) * DT;
    }
    return travel;
  }

  /**
   * Travel of one jog axis held for {@code heldSec} from rest, then let go and left to ramp down
   * (at the ramp's rate, from the speed it had: the capped one when the cap held it).
   */
  static double heldThenReleased(double fullPerSec, double capPerSec, double heldSec) {
    double travel = heldThenStopped(fullPerSec, capPerSec, heldSec);
    double v = Math.min(capPerSec, Math.min(fullPerSec, fullPerSec * Math.round(heldSec / DT) * DT / RAMP));
    double dv = fullPerSec * DT / RAMP;
    while ((v -= dv) > 1e-12) {
      travel += v * DT;
    }
    return travel;
  }

  /** {lowest, highest} of a WORLD jog of one axis at 100 % in T1, held {@code heldSec}, stopped at once or ramped down. */
  static double[] worldJogRange(double heldSec, boolean rampedDown) {
    return rampedDown
        ? new double[] {heldThenReleased(LINEAR_JOG_MM_S, T1_LEAST_MM_S, heldSec), heldThenReleased(LINEAR_JOG_MM_S, T1_MM_S, heldSec)}
        : new double[] {heldThenStopped(LINEAR_JOG_MM_S, T1_LEAST_MM_S, heldSec), heldThenStopped(LINEAR_JOG_MM_S, T1_MM_S, heldSec)};
  }

  /**
   * The range {lowest, highest} a joint jog of joint j (100 %, T1, HOME's other joints) covers in
   * {@code heldSec} and stopped at once, when the TCP and flange swing at {@code radiusMm} from the
   * joint's axis: the T1 cap turns 249..250 mm/s into degrees per second at that radius.
   */
  static double[] jointJogRange(int j, double radiusMm, double heldSec) {
    double full = jointJogDegS(j);
    double hi = heldThenStopped(full, Math.toDegrees(T1_MM_S / radiusMm), heldSec);
    double lo = heldThenStopped(full, Math.toDegrees(T1_LEAST_MM_S / radiusMm), heldSec);
    return new double[] {lo, hi};
  }

  /** Pure translation {@code (x, y, z)}. */
  static double[] translation(double x, double y, double z) {
    return new double[] {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z, 0, 0, 0, 1};
  }

  /** URDF rpy (deg, fixed axes X then Y then Z): Rz·Ry·Rx. */
  private static double[] rpyDeg(double[] rpy) {
    double[] rx = axisAngle(new double[] {1, 0, 0}, Math.toRadians(rpy[0]));
    double[] ry = axisAngle(new double[] {0, 1, 0}, Math.toRadians(rpy[1]));
    double[] rz = axisAngle(new double[] {0, 0, 1}, Math.toRadians(rpy[2]));
    return mul(rz, mul(ry, rx));
  }

  /** Rotation by {@code a} rad about the unit axis {@code u} (Rodrigues). */
  private static double[] axisAngle(double[] u, double a) {
    double c = Math.cos(a);
    double s = Math.sin(a);
    double t = 1 - c;
    double x = u[0];
    double y = u[1];
    double z = u[2];
    return new double[] {
        t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0,
        t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0,
        t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0,
        0, 0, 0, 1};
  }

  static double[] mul(double[] a, double[] b) {
    double[] c = new double[16];
    for (int i = 0; i < 4; i++) {
      for (int j = 0; j < 4; j++) {
        for (int k = 0; k < 4; k++) {
          c[4 * i + j] += a[4 * i + k] * b[4 * k + j];
        }
      }
    }
    return c;
  }
}
