package org.robotrun.sim;

import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.motion.ArcPoints;
import org.robotrun.motion.MoveRequest;
import org.robotrun.motion.Speed;
import org.robotrun.motion.Termination;
import org.robotrun.program.Config;
import org.robotrun.program.Motion;
import org.robotrun.program.MotionPort;
import org.robotrun.program.MotionRequest;
import org.robotrun.program.Position;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;

/**
 * Turns a program's {@link MotionRequest} (program units: mm, degrees, frame numbers) into a
 * {@link MoveRequest} for the motion runner (WORLD poses, radians): checks the taught UF/UT
 * against the active frames, applies INC, Offset and Tool_Offset, solves joint targets in the
 * taught CONFIG, converts speed units. Every refusal is a {@link MotionPort.Start.Rejected} with a
 * code from {@link MotionAlarms}.
 *
 * <p>Offsets follow the controller: {@code Offset,PR[i]} adds the PR's X, Y, Z, W, P, R to the
 * target's values in its user frame (joint PRs add joint by joint); {@code Tool_Offset,PR[i]}
 * moves the target by the PR as a transform in the target's tool frame.
 */
final class TargetResolver {
  private final RobotModel model;
  /** The arm's solver, chosen from its chain (CONFIG honoured except by the numeric last resort). */
  private final IkSolver ik;
  private final Transform X_BW;

  TargetResolver(RobotModel model) {
    this.model = model;
    this.ik = IkSolver.forModel(model);
    this.X_BW = model.X_WB().inverse();
  }

  /** Joints for a flange pose in B in {@code config} (nearest {@code q} where two share it; the numeric solver: from {@code q}). */
  private IkResult solve(Transform X_BF, Config config, double[] q) {
    return ik.solve(X_BF, robotConfig(config), q);
  }

  /** A resolved move or the reason it cannot run. */
  sealed interface Resolved {}

  record Move(MoveRequest move, Transform X_WTarget) implements Resolved {}

  record Refused(MotionPort.Start.Rejected why) implements Resolved {}

  /**
   * @param q current joints (kinematic rad)
   * @param arcHistory WORLD TCP positions of the current run of A moves, oldest first: the run's
   *     start point, then each A target so far (the last two are used). An A move continues the
   *     circle through the previous two points and its own target; the first A of a run, with
   *     only its start point known, moves straight to its target.
   */
  Resolved resolve(MotionRequest r, FrameTable frames, double[] q, java.util.List<Vec3> arcHistory, long tag) {
    int uf = frames.active(org.robotrun.program.Instruction.FrameKind.USER);
    int ut = frames.active(org.robotrun.program.Instruction.FrameKind.TOOL);
    Transform X_WU = frames.activeUser();
    Transform X_FT = frames.activeTool();
    MotionRequest.Waypoint wp = r.target();
    if (wp.position() instanceof Position.Cartesian && (wp.userFrame() != uf || wp.toolFrame() != ut)) {
      return refuse(MotionAlarms.FRAME_MISMATCH, String.format(java.util.Locale.ROOT, "%s was taught in UF %d, UT %d but UF %d, UT %d are active",
          wp.name(), wp.userFrame(), wp.toolFrame(), uf, ut));
    }
    Speed speed;
    try {
      speed = speedOf(r);
    } catch (IllegalArgumentException e) {
      return refuse(MotionAlarms.BAD_SPEED, e.getMessage());
    }
    if (r.accPercent() < 1 || r.accPercent() > 150) {
      return refuse(MotionAlarms.BAD_SPEED, "ACC must be 1..150, got " + r.accPercent());
    }
    Termination term = r.fine() ? Termination.fine() : Termination.cnt(Math.max(0, Math.min(100, r.cnt())));
    double acc = r.accPercent() / 100.0;

    Target target = targetOf(wp, r, X_WU, X_FT, q);
    if (target instanceof Target.Bad bad) {
      return refuse(bad.code(), bad.message());
    }
    switch (r.type()) {
      case J -> {
        double[] qTarget;
        if (target instanceof Target.Joints j) {
          qTarget = j.q();
        } else {
          Target.Pose p = (Target.Pose) target;
          IkResult res = solve(X_BW.compose(p.X_WT()).compose(X_FT.inverse()), p.config(), q);
          if (res instanceof IkResult.Unreachable u) {
            return refuse(u.reason() == IkResult.Reason.JOINT_LIMIT ? MotionAlarms.JOINT_LIMIT : MotionAlarms.UNREACHABLE,
                wp.name() + ": " + u.message());
          }
          qTarget = ((IkResult.Solved) res).q();
        }
        int bad = model.firstJointOutsideLimits(qTarget);
        if (bad >= 0) {
          String coupled = bad == 2 && model.coupledJ3() ? " (J2 + J3 as the pendant shows them)" : "";
          return refuse(MotionAlarms.JOINT_LIMIT, String.format(java.util.Locale.ROOT, "%s needs J%d = %.1f deg%s, outside %.1f..%.1f deg",
              wp.name(), bad + 1, Math.toDegrees(qTarget[bad]), coupled, Math.toDegrees(model.joint(bad).lowerRad()),
              Math.toDegrees(model.joint(bad).upperRad())));
        }
        return new Move(new MoveRequest.Joint(qTarget, speed, term, acc, tag), tcp(qTarget, X_FT));
      }
      case L -> {
        Transform X_WT = poseOf(target, X_FT);
        return new Move(new MoveRequest.Linear(X_WT, X_FT, speed, term, acc, tag), X_WT);
      }
      case C -> {
        Target via = r.viaOwnOffsets()
            ? targetOf(r.via().orElse(wp), r, r.viaOffset(), r.viaToolOffset(), X_WU, X_FT, q)
            : targetOf(r.via().orElse(wp), r, X_WU, X_FT, q);
        if (via instanceof Target.Bad bad) {
          return refuse(bad.code(), bad.message());
        }
        Transform X_WT = poseOf(target, X_FT);
        return new Move(new MoveRequest.Circular(poseOf(via, X_FT), X_WT, X_FT, speed, term, acc, tag), X_WT);
      }
      case A -> {
        Transform X_WT = poseOf(target, X_FT);
        Optional<Vec3> via = arcHistory.size() >= 2
            ? ArcPoints.continuationVia(arcHistory.get(arcHistory.size() - 2), arcHistory.get(arcHistory.size() - 1),
                X_WT.translationVector())
            : Optional.empty();
        if (via.isPresent()) {
          Vec3 v = via.get();
          return new Move(new MoveRequest.Circular(X_WT.withTranslation(v.x(), v.y(), v.z()), X_WT, X_FT, speed, term,
              acc, tag), X_WT);
        }
        // The first point of an arc run (or three points on a line): straight to it.
        return new Move(new MoveRequest.Linear(X_WT, X_FT, speed, term, acc, tag), X_WT);
      }
    }
    throw new AssertionError("unreachable");
  }

  /** A target before the motion type is applied. */
  private sealed interface Target {
    record Joints(double[] q) implements Target {}

    record Pose(Transform X_WT, Config config) implements Target {}

    record Bad(String code, String message) implements Target {}
  }

  private Target targetOf(MotionRequest.Waypoint wp, MotionRequest r, Transform X_WU, Transform X_FT, double[] q) {
    return targetOf(wp, r, r.offset(), r.toolOffset(), X_WU, X_FT, q);
  }

  /** {@code wp} with the offsets {@code offset} / {@code toolOffset} (a via point may carry its own). */
  private Target targetOf(MotionRequest.Waypoint wp, MotionRequest r, java.util.Optional<Position> offset,
      java.util.Optional<Position> toolOffset, Transform X_WU, Transform X_FT, double[] q) {
    Position pos = wp.position();
    if (r.incremental()) {
      pos = switch (pos) {
        case Position.Joint j -> currentJoints(q).plus(j);
        case Position.Cartesian c -> lpos(q, X_WU, X_FT).plus(c);
      };
    }
    if (offset.isPresent()) {
      Position off = offset.get();
      if (pos instanceof Position.Joint j && off instanceof Position.Joint oj) {
        pos = j.plus(oj);
      } else if (off instanceof Position.Cartesian oc) {
        Position.Cartesian base = pos instanceof Position.Cartesian c ? c : cartesianOf((Position.Joint) pos, X_WU, X_FT);
        pos = base.plus(oc);
      } else {
        return new Target.Bad(MotionAlarms.BAD_OFFSET, "Offset: a joint PR cannot offset the Cartesian " + wp.name());
      }
    }
    if (toolOffset.isPresent()) {
      if (!(toolOffset.get() instanceof Position.Cartesian off)) {
        return new Target.Bad(MotionAlarms.BAD_OFFSET, "Tool_Offset needs a Cartesian PR");
      }
      Position.Cartesian base = pos instanceof Position.Cartesian c ? c : cartesianOf((Position.Joint) pos, X_WU, X_FT);
      Transform X_UT = base.toXyzwpr().toTransform().compose(off.toXyzwpr().toTransform());
      return new Target.Pose(X_WU.compose(X_UT), base.config());
    }
    return switch (pos) {
      case Position.Joint j -> new Target.Joints(JointConvention.pendantToKinematic(model,
          new double[] {Math.toRadians(j.j1Deg()), Math.toRadians(j.j2Deg()), Math.toRadians(j.j3Deg()),
              Math.toRadians(j.j4Deg()), Math.toRadians(j.j5Deg()), Math.toRadians(j.j6Deg())}));
      case Position.Cartesian c -> new Target.Pose(X_WU.compose(c.toXyzwpr().toTransform()), c.config());
    };
  }

  private Transform poseOf(Target t, Transform X_FT) {
    return switch (t) {
      case Target.Joints j -> tcp(j.q(), X_FT);
      case Target.Pose p -> p.X_WT();
      case Target.Bad b -> throw new IllegalStateException(b.message());
    };
  }

  Transform tcp(double[] q, Transform X_FT) {
    return ForwardKinematics.flangePoseInWorld(model, q).compose(X_FT);
  }

  /** JPOS: pendant degrees. */
  Position.Joint currentJoints(double[] q) {
    double[] p = JointConvention.kinematicToPendant(model, q);
    return new Position.Joint(Math.toDegrees(p[0]), Math.toDegrees(p[1]), Math.toDegrees(p[2]),
        Math.toDegrees(p[3]), Math.toDegrees(p[4]), Math.toDegrees(p[5]));
  }

  /** Kinematic radians from pendant degrees. */
  double[] kinematicOf(Position.Joint j) {
    return JointConvention.pendantToKinematic(model, new double[] {Math.toRadians(j.j1Deg()), Math.toRadians(j.j2Deg()),
        Math.toRadians(j.j3Deg()), Math.toRadians(j.j4Deg()), Math.toRadians(j.j5Deg()), Math.toRadians(j.j6Deg())});
  }

  /** LPOS: the TCP of {@code X_FT} in the user frame {@code X_WU}, with the current CONFIG. */
  Position.Cartesian lpos(double[] q, Transform X_WU, Transform X_FT) {
    Transform X_UT = X_WU.inverse().compose(tcp(q, X_FT));
    Config config = programConfig(ik.configOf(q));
    return Position.Cartesian.of(Xyzwpr.fromTransform(X_UT), config);
  }

  Position.Cartesian cartesianOf(Position.Joint j, Transform X_WU, Transform X_FT) {
    return lpos(kinematicOf(j), X_WU, X_FT);
  }

  /** Joints for a Cartesian position in the given frames (its CONFIG; near {@code q} without a closed form), or why none. */
  IkResult jointsOf(Position.Cartesian c, Transform X_WU, Transform X_FT, double[] q) {
    Transform X_WT = X_WU.compose(c.toXyzwpr().toTransform());
    return solve(X_BW.compose(X_WT).compose(X_FT.inverse()), c.config(), q);
  }

  static org.robotrun.robot.Config robotConfig(Config c) {
    return new org.robotrun.robot.Config(c.flip(), c.up(), c.top(), c.turn1(), c.turn2(), c.turn3());
  }

  static Config programConfig(org.robotrun.robot.Config c) {
    return new Config(c.flip(), c.up(), c.top(), c.turn1(), c.turn4(), c.turn6());
  }

  private static Speed speedOf(MotionRequest r) {
    double v = r.speed();
    if (!(v > 0) || !Double.isFinite(v)) {
      throw new IllegalArgumentException("speed must be positive, got " + v);
    }
    return switch (r.speedUnit()) {
      case PERCENT -> {
        if (v > 100) {
          throw new IllegalArgumentException("joint speed must be at most 100%, got " + v + "%");
        }
        yield Speed.percent(v);
      }
      case SEC -> Speed.seconds(v);
      case MSEC -> Speed.milliseconds(v);
      case MM_PER_SEC -> Speed.mmPerSec(v);
      case CM_PER_MIN -> Speed.cmPerMin(v);
      case INCH_PER_MIN -> Speed.inchPerMin(v);
      case DEG_PER_SEC -> Speed.degPerSec(v);
    };
  }

  private static Refused refuse(String code, String message) {
    return new Refused(new MotionPort.Start.Rejected(code, message));
  }

  static boolean isArc(MotionRequest r) {
    return r.type() == Motion.Type.A;
  }
}
