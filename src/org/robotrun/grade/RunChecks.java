package org.robotrun.grade;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.program.IoKind;
import org.robotrun.program.Registers;
import org.robotrun.sim.CollisionEvent;
import org.robotrun.sim.ControllerAlarm;
import org.robotrun.sim.MotionAlarms;
import org.robotrun.sim.Simulation;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.WorldObject;

/** The checks that look at one run's end state; each says what it measured. */
final class RunChecks {
  private static final Set<String> MOTION_STOPS =
      Set.of(MotionAlarms.JOINT_LIMIT, MotionAlarms.UNREACHABLE, MotionAlarms.SINGULARITY);

  private RunChecks() {}

  /** A check's verdict on one run. */
  record Eval(boolean pass, String measured, Optional<Vec3> focus_C) {
    static Eval of(boolean pass, String measured) {
      return new Eval(pass, measured, Optional.empty());
    }
  }

  static Eval evaluate(Check c, RunOutcome run) {
    return switch (c) {
      case Check.RunsToEnd r -> runsToEnd(r, run);
      case Check.PartAt p -> partAt(p, run);
      case Check.NothingHeld n -> nothingHeld(run);
      case Check.NoneDropped n -> noneDropped(run);
      case Check.NoCollision n -> noCollision(n, run);
      case Check.NoMotionStop n -> run.robot(n.meta().robot()).alarm().filter(a -> MOTION_STOPS.contains(a.code()))
          .map(a -> Eval.of(false, "the motion stopped: " + alarm(a)))
          .orElseGet(() -> Eval.of(true, "no joint-limit, reach or singularity stop"));
      case Check.CycleTime t -> cycleTime(t, run);
      case Check.EndState s -> endState(s, run);
      case Check.TcpVisits t -> tcpVisits(t, run);
      case Check.HandIn h -> throw new IllegalArgumentException("not a run check");
      case Check.ProgramsCheck h -> throw new IllegalArgumentException("not a run check");
      case Check.ProgramUse h -> throw new IllegalArgumentException("not a run check");
      case Check.Frame h -> throw new IllegalArgumentException("not a run check");
      case Check.PositionRegister h -> throw new IllegalArgumentException("not a run check");
    };
  }

  /**
   * Why a robot of a cell of several has no result of its own: it had nothing to run, or it was
   * stopped by another robot's alarm; empty when it ran to its end or stopped with its own alarm.
   */
  private static Optional<String> notItsOwn(RunOutcome.RobotOutcome robot, RunOutcome run) {
    if (robot.status().isEmpty()) {
      return Optional.of(robot.robot() + " had no program to run");
    }
    if (robot.status().get() == org.robotrun.sim.HeadlessRun.RobotStatus.STOPPED) {
      return Optional.of("the program was stopped when the cell stopped" + run.robots().stream()
          .filter(o -> o.alarm().isPresent()).findFirst().map(o -> " on " + o.robot() + "'s " + alarm(o.alarm().get()))
          .orElse(""));
    }
    return Optional.empty();
  }

  private static Eval tcpVisits(Check.TcpVisits t, RunOutcome run) {
    List<String> missed = new ArrayList<>();
    double worst = 0;
    for (int i = 0; i < t.points_W().size(); i++) {
      Vec3 p = t.points_W().get(i);
      double best = Double.POSITIVE_INFINITY;
      for (Vec3 q : run.tcpPath()) {
        best = Math.min(best, q.distanceTo(p));
      }
      worst = Math.max(worst, best);
      if (best > t.toleranceMm()) {
        missed.add(String.format(Locale.ROOT, "point %d (X %.1f Y %.1f Z %.1f): closest %s", i + 1, p.x(), p.y(), p.z(),
            Double.isInfinite(best) ? "never (the arm did not move)" : String.format(Locale.ROOT, "%.1f mm", best)));
      }
    }
    String allowed = " (allowed " + Grader.fmt(t.toleranceMm()) + " mm)";
    return missed.isEmpty()
        ? Eval.of(true, String.format(Locale.ROOT, "the TCP passed within %.2f mm of every point", worst) + allowed)
        : Eval.of(false, "the TCP never came near " + String.join("; ", missed) + allowed);
  }

  private static Eval runsToEnd(Check.RunsToEnd r, RunOutcome run) {
    RunOutcome.RobotOutcome robot = run.robot(r.meta().robot());
    Optional<String> not = notItsOwn(robot, run);
    if (not.isPresent()) {
      return Eval.of(false, not.get());
    }
    if (r.alarm().isPresent()) {
      String want = r.alarm().get();
      return robot.alarm().map(a -> Eval.of(a.code().equalsIgnoreCase(want), "the program stopped with " + alarm(a)
              + (a.code().equalsIgnoreCase(want) ? "" : " (expected " + want + ")")))
          .orElseGet(() -> Eval.of(false, "the program ran to its end; expected it to stop with alarm " + want));
    }
    return robot.alarm().map(a -> Eval.of(false, "the program stopped with " + alarm(a)))
        .orElseGet(() -> Eval.of(true, String.format(Locale.ROOT, "the program ran to its end in %.2f s", robot.cycleTimeSec())));
  }

  private static Eval partAt(Check.PartAt p, RunOutcome run) {
    Vec3 p_C = run.world().poseInCell(p.part()).translationVector();
    Optional<Vec3> focus = Optional.of(p_C);
    String holder = run.heldParts().get(p.part());
    if (holder != null) {
      return new Eval(false, p.part() + " is still held by " + holder + " at the end", focus);
    }
    Optional<String> parent = run.world().find(p.part()).flatMap(WorldObject::parent);
    if (parent.isEmpty()) {
      return new Eval(false, String.format(Locale.ROOT, "%s was let go in the air at (%.1f, %.1f, %.1f) mm, not on the %s",
          p.part(), p_C.x(), p_C.y(), p_C.z(), p.fixture()), focus);
    }
    if (!parent.get().equals(p.fixture())) {
      return new Eval(false, p.part() + " rests on the " + parent.get() + ", not on the " + p.fixture()
          + (parent.equals(run.startParents().get(p.part())) && moved(run, p.part()) == 0 ? " (it was not moved)" : ""),
          focus);
    }
    Transform X_CF = run.world().poseInCell(p.fixture());
    Transform X_FP = X_CF.inverse().compose(run.world().poseInCell(p.part()));
    Vec3 d = X_FP.translationVector().minus(p.p_FP());
    double dist = d.norm();
    String m = String.format(Locale.ROOT, "%s is %.1f mm from its place on the %s (allowed %s mm)", p.part(), dist,
        p.fixture(), Grader.fmt(p.toleranceMm()));
    boolean ok = dist <= p.toleranceMm();
    if (p.rDeg().isPresent()) {
      double[] r = X_FP.rotationRowMajor();
      double yaw = Math.toDegrees(Math.atan2(r[3], r[0]));
      double off = Math.abs(Math.IEEEremainder(yaw - p.rDeg().get(), 360));
      m += String.format(Locale.ROOT, " and turned %.1f deg from its place (allowed %s deg)", off,
          Grader.fmt(p.toleranceDeg()));
      ok &= off <= p.toleranceDeg();
    }
    return new Eval(ok, m, ok ? Optional.empty() : focus);
  }

  /** How far a part is from its start, in mm. */
  private static double moved(RunOutcome run, String part) {
    WorldObject o = run.world().find(part).orElseThrow();
    return o.pose().distanceTo(o.startPose());
  }

  private static Eval nothingHeld(RunOutcome run) {
    if (run.heldParts().isEmpty()) {
      return Eval.of(true, "no part is left in the gripper");
    }
    List<String> held = new ArrayList<>();
    run.heldParts().entrySet().stream().sorted(Map.Entry.comparingByKey())
        .forEach(e -> held.add(e.getKey() + " (held by " + e.getValue() + ")"));
    return Eval.of(false, "still in the gripper at the end: " + String.join(", ", held));
  }

  private static Eval noneDropped(RunOutcome run) {
    List<String> dropped = new ArrayList<>();
    for (WorldObject o : run.world().objects()) {
      if (o.kind() == ObjectKind.PART && o.parent().isEmpty() && !run.heldParts().containsKey(o.name())
          && run.startParents().getOrDefault(o.name(), Optional.empty()).isPresent()) {
        dropped.add(o.name());
      }
    }
    return dropped.isEmpty() ? Eval.of(true, "no part was let go in the air")
        : Eval.of(false, "let go in the air, not on a fixture: " + String.join(", ", dropped));
  }

  private static Eval noCollision(Check.NoCollision n, RunOutcome run) {
    Optional<ControllerAlarm> a = run.alarm().filter(x -> x.code().equals(Simulation.COLLISION_ALARM));
    List<CollisionEvent> ev = run.collisions();
    String first = ev.isEmpty() ? "" : String.format(Locale.ROOT, " (first: %s touched %s at %.2f s)",
        ev.get(0).nameA(), ev.get(0).nameB(), ev.get(0).simTimeSec());
    if (a.isPresent()) {
      return Eval.of(false, "the robot collided: " + alarm(a.get()) + first);
    }
    if (ev.size() > n.maxWarnings()) {
      return Eval.of(false, ev.size() + " collision(s) (allowed " + n.maxWarnings() + ")" + first);
    }
    return Eval.of(true, ev.isEmpty() ? "no collision" : ev.size() + " collision warning(s) (allowed " + n.maxWarnings() + ")");
  }

  private static Eval cycleTime(Check.CycleTime t, RunOutcome run) {
    RunOutcome.RobotOutcome robot = run.robot(t.meta().robot());
    Optional<String> not = notItsOwn(robot, run);
    if (!robot.finished()) {
      return Eval.of(false, "the program did not reach its end, so it has no cycle time"
          + not.or(() -> robot.alarm().map(ControllerAlarm::display).map(a -> "alarm " + a)).map(a -> " (" + a + ")")
              .orElse(""));
    }
    return Eval.of(robot.cycleTimeSec() <= t.maxSec(), String.format(Locale.ROOT, "cycle time %.2f s (allowed %s s)",
        robot.cycleTimeSec(), Grader.fmt(t.maxSec())));
  }

  private static Eval endState(Check.EndState s, RunOutcome run) {
    List<String> wrong = new ArrayList<>();
    List<String> right = new ArrayList<>();
    for (Map.Entry<String, Double> e : s.expected().entrySet()) {
      String key = e.getKey();
      String table = key.substring(0, key.indexOf('['));
      int i = Integer.parseInt(key.substring(key.indexOf('[') + 1, key.length() - 1));
      Registers regs = run.robot(s.meta().robot()).registers();
      boolean bit = !table.equals("R") && !table.startsWith("G");
      double v;
      try {
        v = table.equals("R") ? regs.number(i)
            : bit ? (regs.bit(IoKind.valueOf(table), i) ? 1 : 0) : regs.value(IoKind.valueOf(table), i);
      } catch (RuntimeException ex) {
        wrong.add(key + " does not exist on the controller");
        continue;
      }
      String shown = bit ? (v != 0 ? "ON" : "OFF") : Grader.fmt(v);
      String want = bit ? (e.getValue() != 0 ? "ON" : "OFF") : Grader.fmt(e.getValue());
      if (Math.abs(v - e.getValue()) <= s.tolerance()) {
        right.add(key + " = " + shown);
      } else {
        wrong.add(key + " is " + shown + ", expected " + want);
      }
    }
    return wrong.isEmpty() ? Eval.of(true, String.join(", ", right)) : Eval.of(false, String.join("; ", wrong));
  }

  private static String alarm(ControllerAlarm a) {
    return "alarm " + a.display();
  }
}
