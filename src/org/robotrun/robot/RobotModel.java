package org.robotrun.robot;

import java.util.List;
import java.util.Optional;
import org.robotrun.math.Transform;

/**
 * An immutable description of a serial 6-axis arm: the joint chain (kinematic convention,
 * uncoupled J3), limits, speeds, link bodies and, where the arm has one, its closed-form (OPW)
 * parameters. Algorithms read a model and a joint vector; nothing changes the model.
 *
 * <p>Frames: B is the robot base (on the floor, J1 axis), W is the controller's WORLD (on the
 * J1 axis at J2 height for a FANUC arm), F is the flange (z out of the faceplate). Links are
 * numbered 0 (base) to 6; link i moves with joint i.
 *
 * @param id short identifier used in files, e.g. "lrmate200id"
 * @param displayName human name
 * @param joints six joints, base to wrist
 * @param X_6F the flange frame in link 6's frame
 * @param X_WB the base frame in WORLD
 * @param links seven links: base and links 1..6
 * @param opw closed-form parameters, if the arm is ortho-parallel with a spherical wrist
 * @param coupledJ3 whether the pendant shows J3 coupled to J2 (FANUC convention)
 * @param maxLinearSpeedMmPerSec the fastest TCP speed a program may ask for ($MRR_GRP.$SPEEDLIM, mm/s):
 *     {@link #DEFAULT_MAX_LINEAR_SPEED_MM_PER_SEC} unless the robot's file says otherwise
 */
public record RobotModel(
    String id,
    String displayName,
    List<JointSpec> joints,
    Transform X_6F,
    Transform X_WB,
    List<LinkSpec> links,
    Optional<OpwParameters> opw,
    boolean coupledJ3,
    double maxLinearSpeedMmPerSec) {

  public static final int DOF = 6;
  /** The controller's default $SPEEDLIM (mm/s): the top of the mm/sec range on an R-30iB. */
  public static final double DEFAULT_MAX_LINEAR_SPEED_MM_PER_SEC = 2000;

  /** A model with the controller's default maximum TCP speed. */
  public RobotModel(String id, String displayName, List<JointSpec> joints, Transform X_6F, Transform X_WB,
      List<LinkSpec> links, Optional<OpwParameters> opw, boolean coupledJ3) {
    this(id, displayName, joints, X_6F, X_WB, links, opw, coupledJ3, DEFAULT_MAX_LINEAR_SPEED_MM_PER_SEC);
  }

  public RobotModel {
    joints = List.copyOf(joints);
    links = List.copyOf(links);
    if (joints.size() != DOF) {
      throw new IllegalArgumentException("a robot needs exactly 6 joints, got " + joints.size());
    }
    if (links.size() != DOF + 1) {
      throw new IllegalArgumentException("a robot needs 7 links (base and 6), got " + links.size());
    }
    if (!(maxLinearSpeedMmPerSec >= 1 && maxLinearSpeedMmPerSec <= MAX_LINEAR_SPEED_LIMIT_MM_PER_SEC)) {
      throw new IllegalArgumentException("maxLinearSpeed: expected 1 to " + (int) MAX_LINEAR_SPEED_LIMIT_MM_PER_SEC
          + " mm/s, got " + maxLinearSpeedMmPerSec);
    }
  }

  /** The largest maximum TCP speed a robot file may give (mm/s). */
  public static final double MAX_LINEAR_SPEED_LIMIT_MM_PER_SEC = 10_000;

  /** This model with another maximum TCP speed (mm/s). */
  public RobotModel withMaxLinearSpeed(double mmPerSec) {
    return new RobotModel(id, displayName, joints, X_6F, X_WB, links, opw, coupledJ3, mmPerSec);
  }

  /**
   * A model from its chain alone: the closed-form parameters are derived from the joints and
   * checked against the chain's FK ({@link OpwDerivation}), empty when the arm is not OPW. Every
   * loader (library file, imported URDF) builds its model here.
   */
  public static RobotModel fromChain(String id, String displayName, List<JointSpec> joints, Transform X_6F,
      Transform X_WB, List<LinkSpec> links, boolean coupledJ3) {
    RobotModel bare = new RobotModel(id, displayName, joints, X_6F, X_WB, links, Optional.empty(), coupledJ3);
    Optional<OpwParameters> opw = OpwDerivation.derive(bare);
    return opw.isEmpty() ? bare : new RobotModel(id, displayName, joints, X_6F, X_WB, links, opw, coupledJ3);
  }

  /**
   * "spherical" (the OPW closed form applies), "offset" (the CRX layout), "parallel" (three
   * parallel axes and an offset wrist, the UR layout) or "other".
   */
  public String wristKind() {
    return opw.isPresent() ? "spherical" : OffsetWristIk.applies(this) ? "offset"
        : UrTypeIk.applies(this) ? "parallel" : "other";
  }

  public JointSpec joint(int i) {
    return joints.get(i);
  }

  /** Lower limits (rad, kinematic convention). */
  public double[] lowerLimits() {
    double[] out = new double[DOF];
    for (int i = 0; i < DOF; i++) {
      out[i] = joints.get(i).lowerRad();
    }
    return out;
  }

  /** Upper limits (rad, kinematic convention). */
  public double[] upperLimits() {
    double[] out = new double[DOF];
    for (int i = 0; i < DOF; i++) {
      out[i] = joints.get(i).upperRad();
    }
    return out;
  }

  /** Index of the first joint outside its limits, or -1 when all are inside. */
  public int firstJointOutsideLimits(double[] q) {
    for (int i = 0; i < DOF; i++) {
      if (!joints.get(i).withinLimits(q[i])) {
        return i;
      }
    }
    return -1;
  }
}
