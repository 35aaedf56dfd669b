package org.robotrun.motion;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.NumericSolver;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.KinematicChain;
import org.robotrun.robot.RobotModel;

/**
 * Executes moves on one arm, one fixed tick at a time: the motion queue of a controller.
 *
 * <p>Each move is planned when it starts, from where the previous one ends, as a trapezoidal
 * {@link UnitProfile} under the speed, joint speed and acceleration limits. A CNT move lets the
 * next queued move start during its deceleration (see {@link Termination.Cnt}); the two
 * superimpose. Joint moves interpolate joints; linear and circular moves compute the desired
 * TCP pose every tick and reach it with the resolved-rate {@link PoseTracker}; if that would
 * need a joint faster than its limit (near a singularity) the path slows down for that tick,
 * and if it cannot be followed at all the move fails with a {@link MotionFault} and the robot
 * stops where it is. Two Cartesian moves blend in Cartesian space (the rounded corner stays in
 * the corner's plane); a joint and a Cartesian move blend in joint space (see
 * {@link #blends}); Cartesian moves with different tools do not blend.
 *
 * <p>The lead space is the first active move's: joint lead sums joint displacements on
 * {@code qBase}; Cartesian lead tracks the superimposed TCP pose into {@code qCart} and adds the
 * joint displacements of joint moves blending in behind. Every step is checked against the joint
 * speed limits and shrunk (the arm slows) if needed.
 *
 * <p>Time: the runner keeps its own simulated clock, advanced only by {@link #tick}. Override
 * and HOLD scale the rate at which path time runs (ramped, so the arm never jumps).
 * Deterministic: no wall clock, no randomness. Not thread-safe.
 */
public final class MotionRunner {
  /**
   * Time for the path rate to go from 0 to 100% (override changes, HOLD, resume), s: the joint
   * acceleration time, so a HOLD from a joint cruising at its top speed brakes at that joint's
   * acceleration limit.
   */
  static final double RATE_RAMP_SEC = MotionLimits.JOINT_ACCEL_TIME_SEC;
  /** Path tolerance per tick: the tracker must land within this of the desired pose. */
  static final double TRACK_TOL_MM = 0.01;
  static final double TRACK_TOL_RAD = 1e-4;
  /** Slowed below this fraction of the planned speed for {@link #STALL_SEC}: give up. */
  static final double STALL_SCALE = 0.05;
  static final double STALL_SEC = 0.5;
  /** Halvings of a tick's path step before a point counts as impossible to reach. */
  static final int MAX_RETRIES = 10;
  /**
   * A Cartesian move that brings J5 closer to 0 than this (the wrist singularity, J4 and J6 in
   * line) stops with an alarm, as a controller without singularity avoidance does.
   */
  static final double WRIST_SINGULAR_RAD = Math.toRadians(1);

  private final RobotModel model;
  private final MotionLimits limits;
  private final PoseTracker tracker;
  /** The arm's own solver for the ends of Cartesian moves; empty for a numeric-only arm (tracked instead). */
  private final Optional<IkSolver> allSolutions;
  private final MotionListener listener;

  private final double[] q;
  private final double[] qTry = new double[RobotModel.DOF];
  private final double[] qBase = new double[RobotModel.DOF];
  /** Cartesian lead: the joints that put the TCP on the superimposed Cartesian pose. */
  private final double[] qCart = new double[RobotModel.DOF];
  private final double[] qCartTry = new double[RobotModel.DOF];
  private final double[] qsTry = new double[RobotModel.DOF];
  private final ArrayDeque<MoveRequest> pending = new ArrayDeque<>();
  private final List<Segment> active = new ArrayList<>();
  private Transform X_WBase = Transform.IDENTITY;
  private double timeSec;
  private double rate;
  private double overrideFraction = 1;
  private boolean held;
  private double pathScale = 1;
  private double stallSec;
  /** T1 speed limit of the TCP and the flange (mm/s); infinite when off. */
  private double cartesianCapMmPerSec = Double.POSITIVE_INFINITY;
  /** The tool whose TCP the cap watches (the flange is always watched). */
  private Transform X_FTCap = Transform.IDENTITY;
  /** How far the cap slows the path now (1 = not at all); kept apart from {@link #pathScale} so T1 is no stall. */
  private double capScale = 1;

  /**
   * @param q0 starting joints (rad, kinematic convention)
   * @param listener told when moves start, finish or fail
   */
  public MotionRunner(RobotModel model, MotionLimits limits, double[] q0, MotionListener listener) {
    this.model = model;
    this.limits = limits;
    this.tracker = new PoseTracker(model);
    IkSolver solver = IkSolver.forModel(model);
    this.allSolutions = solver instanceof NumericSolver ? Optional.empty() : Optional.of(solver);
    this.listener = listener;
    this.q = q0.clone();
  }

  // ---- state -------------------------------------------------------------------------------

  /** Current joints (rad, kinematic), a copy. */
  public double[] joints() {
    return q.clone();
  }

  /** Sets the joints directly (jogging, teleport); only while no move runs. */
  public void setJoints(double[] qNew) {
    if (!idle()) {
      throw new IllegalStateException("cannot set joints while moves run");
    }
    System.arraycopy(qNew, 0, q, 0, RobotModel.DOF);
  }

  /** The TCP pose in WORLD for the tool {@code X_FT}. */
  public Transform tcpInWorld(Transform X_FT) {
    return ForwardKinematics.flangePoseInWorld(model, q).compose(X_FT);
  }

  /** Simulated time of this runner's clock (s). */
  public double timeSec() {
    return timeSec;
  }

  /** Whether nothing runs and nothing waits. */
  public boolean idle() {
    return active.isEmpty() && pending.isEmpty();
  }

  /** Whether another move may be queued now: at most one waits behind the running ones. */
  public boolean acceptsMove() {
    return pending.isEmpty();
  }

  /** Tags of the moves being executed, oldest first. */
  public List<Long> activeTags() {
    List<Long> out = new ArrayList<>(active.size());
    for (Segment s : active) {
      out.add(s.tag);
    }
    return out;
  }

  /**
   * Whether the running move {@code tag} has reached the point where a following move would
   * start blending (CNT), or has finished. False for a queued move or one not known.
   */
  public boolean passedBlendPoint(long tag) {
    for (Segment s : active) {
      if (s.tag == tag) {
        return s.tSec >= s.blendStartSec || s.finished();
      }
    }
    return false;
  }

  /**
   * Simulated seconds until the running move {@code tag} reaches its end point at the current
   * override (path time left divided by the override); infinite for a queued or unknown move.
   */
  public double timeLeftSec(long tag) {
    for (Segment s : active) {
      if (s.tag == tag) {
        double left = Math.max(0, s.profile.durationSec() - s.tSec);
        return left / Math.max(override(), 1e-6);
      }
    }
    return Double.POSITIVE_INFINITY;
  }

  /** Whether a move with this tag is queued or running. */
  public boolean contains(long tag) {
    for (Segment s : active) {
      if (s.tag == tag) {
        return true;
      }
    }
    for (MoveRequest r : pending) {
      if (r.tag() == tag) {
        return true;
      }
    }
    return false;
  }

  /** Override as a fraction (0.01 .. 1). */
  public void setOverride(double fraction) {
    if (!(fraction > 0 && fraction <= 1)) {
      throw new IllegalArgumentException("override must be in (0, 1], got " + fraction);
    }
    overrideFraction = fraction;
  }

  public double override() {
    return overrideFraction;
  }

  /**
   * Caps the Cartesian speed of the flange and of the TCP of tool {@code X_FT} at
   * {@code mmPerSec} (T1 mode: 250 mm/s); every program move is slowed along its path as far as
   * needed, joint moves included. {@link Double#POSITIVE_INFINITY} turns the cap off.
   */
  public void setCartesianSpeedCap(double mmPerSec, Transform X_FT) {
    if (!(mmPerSec > 0)) {
      throw new IllegalArgumentException("speed cap must be > 0 mm/s, got " + mmPerSec);
    }
    cartesianCapMmPerSec = mmPerSec;
    X_FTCap = java.util.Objects.requireNonNull(X_FT, "X_FT");
  }

  /** The Cartesian speed cap (mm/s), infinite when off. */
  public double cartesianSpeedCap() {
    return cartesianCapMmPerSec;
  }

  /**
   * The largest Cartesian displacement (mm) of the flange and of the TCP of {@code X_FT} between
   * joints {@code qa} and {@code qb} (radians, kinematic convention).
   */
  public static double cartesianStepMm(RobotModel model, double[] qa, double[] qb, Transform X_FT) {
    Transform fa = ForwardKinematics.flangePoseInWorld(model, qa);
    Transform fb = ForwardKinematics.flangePoseInWorld(model, qb);
    double flange = fa.translationVector().distanceTo(fb.translationVector());
    double tcp = fa.compose(X_FT).translationVector().distanceTo(fb.compose(X_FT).translationVector());
    return Math.max(flange, tcp);
  }

  /** HOLD: decelerate along the path to a stop and wait for {@link #resume}. */
  public void hold() {
    held = true;
  }

  /** Continue after {@link #hold}. */
  public void resume() {
    held = false;
  }

  public boolean held() {
    return held;
  }

  /** Whether the arm is at rest (idle, or held and fully decelerated). */
  public boolean atRest() {
    return idle() || rate == 0;
  }

  /** Drops every move at once; the arm stays where it is (abort, alarm). */
  public void stopNow() {
    active.clear();
    pending.clear();
    rate = 0;
    pathScale = 1;
    stallSec = 0;
    held = false;
  }

  /** Queues a move; check {@link #acceptsMove} first. */
  public void enqueue(MoveRequest move) {
    if (!acceptsMove()) {
      throw new IllegalStateException("a move is already waiting");
    }
    pending.add(move);
  }

  // ---- tick --------------------------------------------------------------------------------

  /** Advances by {@code dtSec} of simulated time. */
  public void tick(double dtSec) {
    timeSec += dtSec;
    double target = held ? 0 : overrideFraction;
    if (active.isEmpty()) {
      rate = target;
      startFromRest();
      if (active.isEmpty()) {
        return;
      }
    }
    double step = dtSec / RATE_RAMP_SEC;
    rate = rate < target ? Math.min(target, rate + step) : Math.max(target, rate - step);
    startBlends();
    if (active.isEmpty()) {
      return;
    }
    if (!advance(dtSec * rate, dtSec)) {
      return;
    }
    retireFinished();
    if (active.isEmpty()) {
      startFromRest();
    }
  }

  private void startFromRest() {
    while (active.isEmpty() && !pending.isEmpty()) {
      MoveRequest m = pending.poll();
      Segment s = plan(m, null);
      if (s == null) {
        return;
      }
      System.arraycopy(q, 0, qBase, 0, RobotModel.DOF);
      System.arraycopy(q, 0, qCart, 0, RobotModel.DOF);
      if (s instanceof Segment.CartesianSegment c) {
        X_WBase = c.X_WStart;
      }
      pathScale = 1;
      stallSec = 0;
      active.add(s);
      listener.moveStarted(m.tag(), timeSec);
      if (s.finished()) {
        retireFinished();
      }
    }
  }

  private void startBlends() {
    while (!pending.isEmpty() && !active.isEmpty()) {
      Segment last = active.get(active.size() - 1);
      MoveRequest next = pending.peek();
      if (last.tSec < last.blendStartSec || !blends(last, next)) {
        return;
      }
      pending.poll();
      Segment s = plan(next, last);
      if (s == null) {
        return;
      }
      if (s instanceof Segment.CartesianSegment c && last instanceof Segment.JointSegment j) {
        c.shadow = true;
        c.qs0 = j.q1.clone();
        c.qs = j.q1.clone();
      }
      active.add(s);
      listener.moveStarted(next.tag(), timeSec);
    }
  }

  /** Whether the first active move is a joint move (joints are the lead space). */
  private boolean jointLead() {
    return active.get(0) instanceof Segment.JointSegment;
  }

  /**
   * Which moves may start blending behind {@code last}. Joint moves blend with joint moves;
   * Cartesian moves with Cartesian moves of the same tool (the path stays in the corner's plane).
   * Mixed corners blend in joint space: a joint move behind Cartesian moves adds its joint
   * displacement; a Cartesian move behind joint moves runs as a shadow (see
   * {@link Segment.CartesianSegment#shadow}) and takes no follower until the joint moves end.
   * That holds at an L → J → L corner too: the second L starts at the J move's blend point even
   * while the first L is still decelerating (the shadow rides on the Cartesian lead), so a short
   * J between two CNT moves does not stop the arm.
   */
  private boolean blends(Segment last, MoveRequest next) {
    return switch (last) {
      case Segment.JointSegment j -> true;
      case Segment.CartesianSegment c -> {
        if (c.shadow) {
          yield false;
        }
        if (next instanceof MoveRequest.Joint) {
          yield true;
        }
        Transform tool = next instanceof MoveRequest.Linear l ? l.X_FT() : ((MoveRequest.Circular) next).X_FT();
        yield c.X_FT.equals(tool);
      }
    };
  }

  /**
   * Advances every active move by up to {@code dTau} of path time. The joints for the step are
   * computed; if they would need a joint faster than its limit, or the pose cannot be reached,
   * the step shrinks (the arm slows) and is tried again.
   */
  private boolean advance(double dTau, double dtSec) {
    double want = dTau * pathScale;
    double frac = 1;
    boolean accepted = false;
    double step = 0;
    for (int attempt = 0; attempt <= MAX_RETRIES && !accepted; attempt++) {
      step = want * frac;
      if (!candidate(step) || !finite(qTry)) {
        frac *= 0.5;
        continue;
      }
      double ratio = 0;
      for (int i = 0; i < RobotModel.DOF; i++) {
        ratio = Math.max(ratio, Math.abs(qTry[i] - q[i]) / (limits.jointSpeed(i) * dtSec));
      }
      // 1e-9: a planned joint move runs exactly at its limit; rounding must not slow it.
      if (ratio <= 1 + 1e-9) {
        accepted = true;
      } else {
        frac *= 0.9 / ratio;
      }
    }
    if (!accepted) {
      return fail(lastTag(), cannotFollow());
    }
    if (!capStep(step, dtSec)) {
      return fail(lastTag(), cannotFollow());
    }
    int bad = firstOutside(qTry);
    if (bad >= 0) {
      return fail(lastTag(), new MotionFault(MotionFault.Kind.JOINT_LIMIT, limitMessage(bad, qTry[bad])));
    }
    boolean cartesian = !jointLead() || active.size() > 1 && active.get(active.size() - 1) instanceof Segment.CartesianSegment;
    if (cartesian && entersWristSingularity(q, qTry)) {
      return fail(lastTag(), singularity());
    }
    if (!Double.isNaN(shortenedStep)) {
      step = shortenedStep;
      shortenedStep = Double.NaN;
    }
    for (Segment s : active) {
      s.tSec += step;
      if (s instanceof Segment.CartesianSegment c && c.shadow) {
        System.arraycopy(qsTry, 0, c.qs, 0, RobotModel.DOF);
      }
    }
    System.arraycopy(qTry, 0, q, 0, RobotModel.DOF);
    if (!jointLead()) {
      System.arraycopy(qCartTry, 0, qCart, 0, RobotModel.DOF);
    }
    // Slow down as far as this tick needed, then recover gently (about 0.3 s back to full speed).
    pathScale = frac < 1 ? Math.max(1e-4, pathScale * frac) : Math.min(1, pathScale * 1.05 + 1e-3);
    stallSec = pathScale < STALL_SCALE && want > 0 ? stallSec + dtSec : 0;
    if (stallSec > STALL_SEC) {
      return fail(lastTag(), cannotFollow());
    }
    return true;
  }

  /**
   * T1: shortens the accepted {@code step} until neither the flange nor the TCP moves faster than
   * the cap this tick (the check is on the candidate, so no tick ever exceeds it), then lets the
   * path speed recover slowly. Leaves {@link #qTry} on the step taken; false if a shorter step
   * cannot be reached.
   */
  private boolean capStep(double step, double dtSec) {
    if (Double.isInfinite(cartesianCapMmPerSec)) {
      return true;
    }
    double limitMm = cartesianCapMmPerSec * dtSec;
    double scale = Math.min(1, capScale * 1.02 + 1e-4);
    for (int attempt = 0; attempt < 20; attempt++) {
      if (scale < 1 && (!candidate(step * scale) || !finite(qTry))) {
        return false;
      }
      double moved = cartesianStepMm(model, q, qTry, X_FTCap);
      if (moved <= limitMm) {
        capScale = scale;
        if (scale < 1) {
          // the segments advance by the shortened step
          shortenedStep = step * scale;
        }
        return true;
      }
      scale *= 0.98 * limitMm / moved;
    }
    return false;
  }

  /** Set by {@link #capStep} when it shortened the step (NaN otherwise). */
  private double shortenedStep = Double.NaN;

  /**
   * Fills {@link #qTry} with the joints after advancing every active move by {@code step}:
   * joint lead: {@code qBase + Σ joint displacements (+ shadow's qs − qs0)}; Cartesian lead:
   * the tracked joints of the superimposed Cartesian pose plus the joint displacements of joint
   * moves blending in behind. False if a pose cannot be reached.
   */
  private boolean candidate(double step) {
    if (jointLead()) {
      System.arraycopy(qBase, 0, qTry, 0, RobotModel.DOF);
      for (Segment s : active) {
        switch (s) {
          case Segment.JointSegment j -> j.addDisplacement(j.tSec + step, qTry);
          case Segment.CartesianSegment c -> {
            if (!trackShadow(c, step)) {
              return false;
            }
          }
        }
      }
      return true;
    }
    Segment.CartesianSegment first = (Segment.CartesianSegment) active.get(0);
    System.arraycopy(qCart, 0, qCartTry, 0, RobotModel.DOF);
    if (!tracker.track(qCartTry, poseAt(step), first.X_FT, TRACK_TOL_MM, TRACK_TOL_RAD)) {
      return false;
    }
    System.arraycopy(qCartTry, 0, qTry, 0, RobotModel.DOF);
    for (Segment s : active) {
      switch (s) {
        case Segment.JointSegment j -> j.addDisplacement(j.tSec + step, qTry);
        case Segment.CartesianSegment c when c.shadow -> {
          // L -> J -> L: the second L blends in behind the J while the first L still leads.
          if (!trackShadow(c, step)) {
            return false;
          }
        }
        case Segment.CartesianSegment c -> { }
      }
    }
    return true;
  }

  /** Tracks the shadow's own path into {@link #qsTry} and adds its displacement {@code qs − qs0} to {@link #qTry}. */
  private boolean trackShadow(Segment.CartesianSegment c, double step) {
    System.arraycopy(c.qs, 0, qsTry, 0, RobotModel.DOF);
    if (!tracker.track(qsTry, c.ownPoseAt(c.tSec + step), c.X_FT, TRACK_TOL_MM, TRACK_TOL_RAD)) {
      return false;
    }
    for (int i = 0; i < RobotModel.DOF; i++) {
      qTry[i] += qsTry[i] - c.qs0[i];
    }
    return true;
  }

  /** The desired TCP pose if every active segment advanced by {@code step} of path time. */
  private Transform poseAt(double step) {
    Vec3 p = X_WBase.translationVector();
    Transform R = X_WBase.withTranslation(0, 0, 0);
    for (Segment s : active) {
      if (!(s instanceof Segment.CartesianSegment c) || c.shadow) {
        continue;
      }
      double u = c.profile.position(c.tSec + step);
      p = p.plus(c.path.displacement(u));
      R = Rotations.exp(c.rotation_W, u).compose(R);
    }
    return R.withTranslation(p.x(), p.y(), p.z());
  }

  private void retireFinished() {
    while (!active.isEmpty() && active.get(0).finished()) {
      Segment s = active.remove(0);
      switch (s) {
        case Segment.JointSegment j -> {
          for (int i = 0; i < RobotModel.DOF; i++) {
            qBase[i] += j.q1[i] - j.q0[i];
          }
        }
        case Segment.CartesianSegment c -> {
          Vec3 p = X_WBase.translationVector().plus(c.path.displacement(1));
          X_WBase = Rotations.exp(c.rotation_W, 1).compose(X_WBase.withTranslation(0, 0, 0))
              .withTranslation(p.x(), p.y(), p.z());
        }
      }
      listener.moveFinished(s.tag, timeSec);
      changeLead(s);
    }
    if (active.isEmpty()) {
      pathScale = 1;
    }
  }

  /** After {@code retired} left the front, hands the lead to the new front move's space. */
  private void changeLead(Segment retired) {
    if (active.isEmpty()) {
      return;
    }
    Segment front = active.get(0);
    if (front instanceof Segment.CartesianSegment c && c.shadow) {
      // The joint moves have ended: the shadow becomes the Cartesian lead, from where it is.
      c.shadow = false;
      X_WBase = c.X_WStart;
      System.arraycopy(c.qs, 0, qCart, 0, RobotModel.DOF);
    } else if (front instanceof Segment.JointSegment && retired instanceof Segment.CartesianSegment) {
      // The Cartesian moves have ended: the joints they reached become the joint base.
      System.arraycopy(qCart, 0, qBase, 0, RobotModel.DOF);
    }
  }

  // ---- planning ----------------------------------------------------------------------------

  /** Plans a move from the end of {@code previous} (blending) or from the current state; null if it failed. */
  private Segment plan(MoveRequest m, Segment previous) {
    return switch (m) {
      case MoveRequest.Joint j -> {
        double[] q0 = switch (previous) {
          case null -> q;
          case Segment.JointSegment pj -> pj.q1;
          case Segment.CartesianSegment pc -> jointsAtEnd(pc, j.tag());
        };
        yield q0 == null ? null : planJoint(j, q0);
      }
      case MoveRequest.Linear l -> {
        Transform start = startPose(previous, l.X_FT());
        if (!reachable(l.X_WTarget(), l.X_FT(), l.tag(), "the target")) {
          yield null;
        }
        PathShape path = new PathShape.Line(l.X_WTarget().translationVector().minus(start.translationVector()));
        yield planCartesian(m, path, start, l.X_WTarget(), l.X_FT());
      }
      case MoveRequest.Circular c -> {
        Transform start = startPose(previous, c.X_FT());
        if (!reachable(c.X_WVia(), c.X_FT(), c.tag(), "the via point") || !reachable(c.X_WTarget(), c.X_FT(), c.tag(), "the target")) {
          yield null;
        }
        PathShape.Arc arc = PathShape.Arc.through(
            start.translationVector(), c.X_WVia().translationVector(), c.X_WTarget().translationVector());
        if (arc == null) {
          fail(c.tag(), new MotionFault(MotionFault.Kind.BAD_PATH,
              "circular move: start, via and end point lie on one line or coincide"));
          yield null;
        }
        yield planCartesian(m, arc, start, c.X_WTarget(), c.X_FT());
      }
    };
  }

  /** Where a Cartesian move starts: the current TCP, or the end of the move it blends out of. */
  private Transform startPose(Segment previous, Transform X_FT) {
    return switch (previous) {
      case null -> tcpInWorld(X_FT);
      case Segment.CartesianSegment pc -> pc.X_WEnd;
      case Segment.JointSegment pj -> ForwardKinematics.flangePoseInWorld(model, pj.q1).compose(X_FT);
    };
  }

  /** The joints at the end of a Cartesian move (the arm's solver, the branch nearest the current joints); null after a fault. */
  private double[] jointsAtEnd(Segment.CartesianSegment c, long tag) {
    if (allSolutions.isEmpty()) {
      double[] qq = qCart.clone();
      return tracker.track(qq, c.X_WEnd, c.X_FT, TRACK_TOL_MM, TRACK_TOL_RAD) ? qq : null;
    }
    Transform X_BF = model.X_WB().inverse().compose(c.X_WEnd).compose(c.X_FT.inverse());
    IkResult r = allSolutions.get().solveNearest(X_BF, qCart);
    if (r instanceof IkResult.Solved sol) {
      return sol.q();
    }
    fail(tag, new MotionFault(MotionFault.Kind.OUT_OF_REACH, "the end of the previous move has no joint solution"));
    return null;
  }

  private Segment planJoint(MoveRequest.Joint m, double[] q0) {
    double[] q1 = m.qTarget();
    int bad = firstOutside(q1);
    if (bad >= 0) {
      fail(m.tag(), new MotionFault(MotionFault.Kind.JOINT_LIMIT, "target " + limitMessage(bad, q1[bad])));
      return null;
    }
    double maxRate = Double.POSITIVE_INFINITY;
    double maxAccel = Double.POSITIVE_INFINITY;
    double fraction = switch (m.speed()) {
      case Speed.JointPercent p -> p.fraction();
      case Speed.Linear l -> Math.min(1, l.mmPerSec() / limits.linearMaxSpeedMmPerSec());
      case Speed.Angular a -> Math.min(1, a.radPerSec() / limits.rotationMaxSpeedRadPerSec());
      case Speed.Duration d -> 1;
    };
    for (int i = 0; i < RobotModel.DOF; i++) {
      double d = Math.abs(q1[i] - q0[i]);
      if (d > 1e-12) {
        maxRate = Math.min(maxRate, fraction * limits.jointSpeed(i) / d);
        maxAccel = Math.min(maxAccel, Math.min(1, m.accFraction()) * limits.jointAccel(i) / d);
      }
    }
    return new Segment.JointSegment(m.tag(), profile(m.speed(), maxRate, maxAccel), m.termination(), q0, q1);
  }

  private Segment planCartesian(MoveRequest m, PathShape path, Transform start, Transform end, Transform X_FT) {
    double lengthMm = path.lengthMm();
    double angleRad = start.rotationAngleTo(end);
    double acc = m.accFraction();
    double linearSpeed = switch (m.speed()) {
      case Speed.Linear l -> Math.min(l.mmPerSec(), limits.linearMaxSpeedMmPerSec());
      case Speed.JointPercent p -> p.fraction() * limits.linearMaxSpeedMmPerSec();
      case Speed.Angular a -> limits.linearMaxSpeedMmPerSec();
      case Speed.Duration d -> limits.linearMaxSpeedMmPerSec();
    };
    double rotationSpeed = m.speed() instanceof Speed.Angular a
        ? Math.min(a.radPerSec(), limits.rotationMaxSpeedRadPerSec())
        : limits.rotationMaxSpeedRadPerSec();
    double maxRate = Double.POSITIVE_INFINITY;
    double maxAccel = Double.POSITIVE_INFINITY;
    if (lengthMm > 1e-9) {
      maxRate = linearSpeed / lengthMm;
      maxAccel = acc * linearSpeed / MotionLimits.LINEAR_ACCEL_TIME_SEC / lengthMm;
    }
    if (angleRad > 1e-12) {
      maxRate = Math.min(maxRate, rotationSpeed / angleRad);
      maxAccel = Math.min(maxAccel, acc * rotationSpeed / MotionLimits.LINEAR_ACCEL_TIME_SEC / angleRad);
    }
    Transform endPose = end;
    if (path instanceof PathShape.Arc arc) {
      Vec3 p = start.translationVector().plus(arc.displacement(1));
      endPose = end.withTranslation(p.x(), p.y(), p.z());
    }
    return new Segment.CartesianSegment(m.tag(), profile(m.speed(), maxRate, maxAccel), m.termination(), path, X_FT,
        start, endPose);
  }

  private static UnitProfile profile(Speed speed, double maxRate, double maxAccel) {
    if (maxAccel == Double.POSITIVE_INFINITY) {
      return speed instanceof Speed.Duration d
          ? UnitProfile.forDuration(d.seconds(), 1 / d.seconds() * 2, 4 / (d.seconds() * d.seconds()))
          : UnitProfile.EMPTY;
    }
    return speed instanceof Speed.Duration d
        ? UnitProfile.forDuration(d.seconds(), maxRate, maxAccel)
        : UnitProfile.fastest(maxRate, maxAccel);
  }

  private boolean reachable(Transform X_WT, Transform X_FT, long tag, String what) {
    if (allSolutions.isEmpty()) {
      return true;
    }
    Transform X_BF = model.X_WB().inverse().compose(X_WT).compose(X_FT.inverse());
    IkResult r = allSolutions.get().solveNearest(X_BF, q);
    if (r instanceof IkResult.Unreachable u) {
      MotionFault.Kind kind = u.reason() == IkResult.Reason.JOINT_LIMIT
          ? MotionFault.Kind.JOINT_LIMIT : MotionFault.Kind.OUT_OF_REACH;
      fail(tag, new MotionFault(kind, what + " is unreachable: " + u.message()));
      return false;
    }
    return true;
  }

  // ---- faults ------------------------------------------------------------------------------

  private boolean fail(long tag, MotionFault fault) {
    stopNow();
    listener.moveFailed(tag, fault);
    return false;
  }

  private long lastTag() {
    return active.isEmpty() ? -1 : active.get(active.size() - 1).tag;
  }

  /** Whether J5 heads into (or through) the wrist singularity between the two joint vectors. */
  static boolean entersWristSingularity(double[] qFrom, double[] qTo) {
    double from = Math.abs(Math.sin(qFrom[4]));
    double to = Math.abs(Math.sin(qTo[4]));
    boolean crosses = Math.signum(Math.sin(qFrom[4])) * Math.signum(Math.sin(qTo[4])) < 0;
    return crosses || (to < Math.sin(WRIST_SINGULAR_RAD) && to < from);
  }

  /**
   * Why the path cannot be followed from here (no step could be taken, or it crawled too long):
   * the wrist singularity when J5 is near 0; MOTN-018 when the path ahead leaves the arm's reach
   * (docs/alarms.md: "a point of the straight or circular path is out of the arm's reach"; at the
   * edge of reach the stretched arm crawls into that edge before the tracker fails); else a
   * singularity inside the reach.
   */
  private MotionFault cannotFollow() {
    if (Math.abs(Math.sin(q[4])) < Math.sin(Math.toRadians(10))) {
      return singularity();
    }
    Vec3 out = firstUnreachableAhead();
    if (out != null) {
      return new MotionFault(MotionFault.Kind.OUT_OF_REACH, String.format(java.util.Locale.ROOT,
          "the path leaves the arm's reach at (%.1f, %.1f, %.1f) mm", out.x(), out.y(), out.z()));
    }
    return new MotionFault(MotionFault.Kind.SINGULARITY,
        "the path passes too close to a singularity: joints would exceed their speed");
  }

  /** Points sampled on the rest of a path when it stops, to find where it leaves the reach. */
  static final int REACH_SAMPLES = 200;

  /**
   * The first sampled point of the rest of the Cartesian path (the lead's superimposed path, or
   * the shadow's own under a joint lead: the first Cartesian move is one or the other) that the arm's solver finds out of reach; null if none
   * is, or the arm has no closed-form solver to ask.
   */
  private Vec3 firstUnreachableAhead() {
    if (allSolutions.isEmpty()) {
      return null;
    }
    Segment.CartesianSegment follow = null;
    for (Segment s : active) {
      if (s instanceof Segment.CartesianSegment c) {
        follow = c;
        break;
      }
    }
    if (follow == null) {
      return null;
    }
    double left = 0;
    for (Segment s : active) {
      left = Math.max(left, s.profile.durationSec() - s.tSec);
    }
    Transform X_BW = model.X_WB().inverse();
    Transform X_TF = follow.X_FT.inverse();
    for (int k = 1; k <= REACH_SAMPLES; k++) {
      double ahead = left * k / REACH_SAMPLES;
      Transform X_WT = follow.shadow ? follow.ownPoseAt(follow.tSec + ahead) : poseAt(ahead);
      Transform X_BF = X_BW.compose(X_WT).compose(X_TF);
      if (allSolutions.get().solveNearest(X_BF, q) instanceof IkResult.Unreachable u
          && u.reason() == IkResult.Reason.OUT_OF_REACH) {
        return X_WT.translationVector();
      }
    }
    return null;
  }

  private MotionFault singularity() {
    return new MotionFault(MotionFault.Kind.SINGULARITY, String.format(
        "wrist singularity: J4 and J6 line up (J5 = %.1f deg); teach the path with the wrist bent or use a joint move",
        Math.toDegrees(q[4])));
  }

  private int firstOutside(double[] qq) {
    for (int i = 0; i < RobotModel.DOF; i++) {
      KinematicChain c = tracker.chain();
      if (!(qq[i] >= c.lower(i) && qq[i] <= c.upper(i))) {
        return i;
      }
    }
    return -1;
  }

  private String limitMessage(int joint, double value) {
    // Limits hold for the kinematic joints; with the pendant's coupled J3 that is J2 + J3.
    String coupled = joint == 2 && model.coupledJ3() ? " (J2 + J3 as the pendant shows them)" : "";
    return String.format(java.util.Locale.ROOT, "J%d would reach %.1f deg%s, outside its limits %.1f..%.1f deg", joint + 1,
        Math.toDegrees(value), coupled, Math.toDegrees(model.joint(joint).lowerRad()),
        Math.toDegrees(model.joint(joint).upperRad()));
  }

  private static boolean finite(double[] v) {
    for (double x : v) {
      if (!Double.isFinite(x)) {
        return false;
      }
    }
    return true;
  }
}
