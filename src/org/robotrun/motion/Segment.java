package org.robotrun.motion;

import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * A planned move being executed: its profile and how far along it is ({@code tSec}, path time,
 * which runs slower than simulated time under override, HOLD or near singularities). Moves are
 * superimposed while blending: each contributes its displacement from its own start, so two
 * overlapping moves sum to a corner-cutting path that stays in the plane of the corner.
 */
abstract sealed class Segment permits Segment.JointSegment, Segment.CartesianSegment {
  final long tag;
  final UnitProfile profile;
  /** Path time from which the next move may start (infinite for FINE). */
  final double blendStartSec;
  double tSec;

  Segment(long tag, UnitProfile profile, Termination termination) {
    this.tag = tag;
    this.profile = profile;
    this.blendStartSec = switch (termination) {
      case Termination.Fine f -> Double.POSITIVE_INFINITY;
      case Termination.Cnt c -> profile.durationSec() - c.value() / 100.0 * profile.accelTimeSec();
    };
  }

  final boolean finished() {
    return tSec >= profile.durationSec();
  }

  /** A joint move: {@code q = q0 + u·(q1 − q0)}. */
  static final class JointSegment extends Segment {
    final double[] q0;
    final double[] q1;

    JointSegment(long tag, UnitProfile profile, Termination termination, double[] q0, double[] q1) {
      super(tag, profile, termination);
      this.q0 = q0.clone();
      this.q1 = q1.clone();
    }

    /** Adds this move's displacement at path time t to {@code q}. */
    void addDisplacement(double t, double[] q) {
      double u = profile.position(t);
      for (int i = 0; i < q.length; i++) {
        q[i] += (q1[i] - q0[i]) * u;
      }
    }
  }

  /**
   * A Cartesian move: the TCP position follows {@code path}, the orientation turns about the
   * fixed WORLD axis of {@code rotation_W} (the slerp from start to end orientation).
   */
  static final class CartesianSegment extends Segment {
    final PathShape path;
    final Vec3 rotation_W;
    final Transform X_FT;
    final Transform X_WStart;
    final Transform X_WEnd;
    /**
     * A Cartesian move blending out of a joint move runs as a shadow: it tracks its own path
     * from the joint move's end joints ({@code qs}, starting at {@code qs0}) and adds
     * {@code qs − qs0} to the joints. Once the joint move has ended it becomes an ordinary
     * Cartesian move (the runner promotes it).
     */
    boolean shadow;
    double[] qs;
    double[] qs0;

    CartesianSegment(long tag, UnitProfile profile, Termination termination, PathShape path, Transform X_FT,
        Transform X_WStart, Transform X_WEnd) {
      super(tag, profile, termination);
      this.path = path;
      this.X_FT = X_FT;
      this.X_WStart = X_WStart;
      this.X_WEnd = X_WEnd;
      this.rotation_W = Rotations.between(X_WEnd, X_WStart);
    }

    /** This move's own desired pose at path time t (ignoring other moves). */
    Transform ownPoseAt(double t) {
      double u = profile.position(t);
      Vec3 p = X_WStart.translationVector().plus(path.displacement(u));
      return Rotations.exp(rotation_W, u).compose(X_WStart.withTranslation(0, 0, 0)).withTranslation(p.x(), p.y(), p.z());
    }
  }
}
