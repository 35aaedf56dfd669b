package org.robotrun.grade;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.SplittableRandom;
import java.util.TreeMap;
import java.util.function.Function;
import org.robotrun.math.Transform;
import org.robotrun.program.Config;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ControllerAlarm;
import org.robotrun.sim.HeadlessRun;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Scenario;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/**
 * Builds a fresh cell for each run (its own simulation, controllers and solvers: nothing is
 * shared between runs or threads but the immutable scenario and robot models) and runs the
 * submission's program on it.
 */
final class CellRunner {
  /** Thrown from the tick callback when the submission's wall-clock time is up. */
  static final class WallClockExceeded extends RuntimeException {
    WallClockExceeded() {
      super(null, null, false, false);
    }
  }

  private CellRunner() {}

  /**
   * One variation of the scenario: the parts moved by the seeded draw, and the override.
   *
   * @param index 0 for the nominal run, 1..count for the variations
   */
  record Variant(int index, Scenario scenario, int overridePct, Map<Integer, Position.Cartesian> offsetRegisters,
      boolean visionSeedVaried) {
    Variant(int index, Scenario scenario, int overridePct, Map<Integer, Position.Cartesian> offsetRegisters) {
      this(index, scenario, overridePct, offsetRegisters, false);
    }

    String label() {
      return index == 0 ? "nominal run" : "variation " + index + " (override " + overridePct + "%"
          + (visionSeedVaried ? ", vision seed " + scenario.vision().seed() : "") + ")";
    }
  }

  /** The nominal run: the scenario as it is, override 100%, zero offsets. */
  static Variant nominal(Scenario base, Task.Variations v) {
    Map<Integer, Position.Cartesian> regs = new TreeMap<>();
    for (Task.PartJitter j : v.parts()) {
      j.offsetRegister().ifPresent(n -> regs.put(n, Position.Cartesian.ZERO));
    }
    return new Variant(0, base, 100, regs);
  }

  /**
   * Variation {@code i} (1-based) drawn with seed {@code seed + i}: the same every time. The
   * offset registers are written into every robot's controller.
   */
  static Variant variation(Scenario base, Task.Variations v, int i) {
    SplittableRandom rng = new SplittableRandom(v.seed() + i);
    World world = base.world();
    Map<Integer, Position.Cartesian> regs = new TreeMap<>();
    for (Task.PartJitter j : v.parts()) {
      double dx = draw(rng, j.xMm());
      double dy = draw(rng, j.yMm());
      double drDeg = draw(rng, j.rDeg());
      WorldObject o = world.find(j.part()).orElseThrow();
      // Moved in its parent's frame, turned about its own vertical axis.
      Transform moved = Transform.translation(dx, dy, 0).compose(o.startPose())
          .compose(Transform.rotation(0, 0, 1, Math.toRadians(drDeg)));
      world = world.with(WorldObject.of(o.name(), o.kind(), o.shape(), o.colour(), moved, o.startParent()).withTouchable(o.touchable()));
      j.offsetRegister().ifPresent(n -> regs.put(n, new Position.Cartesian(dx, dy, 0, 0, 0, drDeg, Config.DEFAULT)));
    }
    int override = v.overrideMinPct() == v.overrideMaxPct() ? v.overrideMinPct()
        : rng.nextInt(v.overrideMinPct(), v.overrideMaxPct() + 1);
    Scenario out = base.withWorld(world);
    if (v.varyVisionSeed() && !base.vision().placements().isEmpty()) {
      // the seed `robotrun run --seed N` takes, so a student can replay the variation that failed
      long s = base.vision().seed();
      long next = org.robotrun.io.VisionJson.isValidSeed((double) s + i) ? s + i : s - i;
      out = out.withVision(base.vision().withSeed(next));
    }
    return new Variant(i, out, override, regs, v.varyVisionSeed() && !base.vision().placements().isEmpty());
  }

  private static double draw(SplittableRandom rng, double range) {
    // Rounded to 0.1 so the offsets a student sees in PR[] read as a vision system reports them.
    return range == 0 ? 0 : Math.round(rng.nextDouble(-range, range) * 10) / 10.0;
  }

  /**
   * What a robot after the first starts with: its program to run, its programs and the R[] and
   * PR[] of its saved state.
   */
  record RobotStart(String program, List<Program> programs, Map<Integer, Double> registers,
      Map<Integer, Position> positionRegisters) {}

  /**
   * Runs {@code program} on the variant's first robot and, in a cell of several robots, each
   * other robot's program at the same tick (as {@code robotrun run} does).
   *
   * @param positionRegisters the student's PR[] to start with (taught at the pendant)
   * @param others robot name to what it runs, for the robots after the first (a robot not listed stays idle)
   * @param deadlineNanos {@link System#nanoTime()} after which the run is abandoned
   * @throws WallClockExceeded when the deadline passes
   * @throws IllegalArgumentException when the cell cannot be built or a program not started
   */
  static RunOutcome run(Variant v, Function<String, RobotModel> models, List<Program> programs,
      Map<Integer, Position> positionRegisters, String program, Map<String, RobotStart> others, double maxSimSec,
      long deadlineNanos) {
    Simulation sim = ScenarioCell.build(v.scenario(), models, Simulation.DEFAULT_TICK_SEC);
    Controller c = sim.controllers().get(0);
    programs.forEach(c::saveProgram);
    c.setOverridePct(v.overridePct());
    // The student's own PRs first; the task's offset registers (where parts were found) win.
    positionRegisters.forEach((n, p) -> c.registers().setPosition(n, p));
    v.offsetRegisters().forEach((n, p) -> c.registers().setPosition(n, p));
    Map<Controller, String> mains = new LinkedHashMap<>();
    mains.put(c, program);
    for (Controller o : sim.controllers().subList(1, sim.controllers().size())) {
      RobotStart rs = others.get(o.name());
      if (rs == null) {
        continue;
      }
      rs.programs().forEach(o::saveProgram);
      o.setOverridePct(v.overridePct());
      rs.registers().forEach((n, x) -> {
        if (x == Math.rint(x) && Math.abs(x) <= Integer.MAX_VALUE) {
          o.registers().setInteger(n, (int) (double) x);
        } else {
          o.registers().setReal(n, x);
        }
      });
      rs.positionRegisters().forEach((n, p) -> o.registers().setPosition(n, p));
      mains.put(o, rs.program());
    }
    // Every robot of the cell sees where the parts were found (its own PRs first, as the first's).
    for (Controller o : sim.controllers().subList(1, sim.controllers().size())) {
      v.offsetRegisters().forEach((n, p) -> o.registers().setPosition(n, p));
    }
    Map<String, Optional<String>> startParents = new HashMap<>();
    for (WorldObject o : sim.world().objects()) {
      if (o.kind() == ObjectKind.PART) {
        startParents.put(o.name(), o.parent());
      }
    }
    List<org.robotrun.math.Vec3> path = new ArrayList<>();
    java.util.function.Consumer<Simulation> afterTick = s -> {
      org.robotrun.math.Xyzwpr t = c.tcpInWorld();
      path.add(new org.robotrun.math.Vec3(t.x(), t.y(), t.z()));
      if ((s.ticks() & 63) == 0 && System.nanoTime() - deadlineNanos > 0) {
        throw new WallClockExceeded();
      }
    };
    // A cell its PLC starts (production.ROBOT.runStartsFromPlc) is started as `robotrun run` starts
    // it: the PLC sequence selects and starts the program; a start of our own would clash with it
    // (PROG-007: the program is already running). Issue 26.
    Optional<org.robotrun.world.ProductionSetup.Robot> plc = v.scenario().production().of(c.name())
        .filter(org.robotrun.world.ProductionSetup.Robot::startFromPlc);
    HeadlessRun.CellResult r;
    if (plc.isPresent()) {
      List<String> bad = org.robotrun.sim.ProductionRun.check(c.name(), plc.get(), c);
      if (!bad.isEmpty()) {
        throw new IllegalArgumentException(String.join("; ", bad));
      }
      r = org.robotrun.sim.ProductionRun.run(sim, c, maxSimSec, afterTick, () -> false, "");
    } else {
      r = HeadlessRun.runCell(sim, mains, maxSimSec, afterTick, () -> false, "");
    }
    List<RunOutcome.RobotOutcome> robots = new ArrayList<>();
    for (Controller x : sim.controllers()) {
      HeadlessRun.RobotResult rr = r.robots().stream().filter(y -> y.robot().equals(x.name())).findFirst().orElse(null);
      robots.add(new RunOutcome.RobotOutcome(x.name(), rr == null ? "" : rr.program(),
          rr == null ? Optional.empty() : Optional.of(rr.status()), rr == null ? Optional.empty() : rr.alarm(),
          rr == null ? 0 : rr.cycleTimeSec(), x.registers(), x.frames()));
    }
    // One robot: as HeadlessRun.run reports it (the first robot's status and alarm, the cell's cycle time).
    HeadlessRun.RobotResult one = r.robots().get(0);
    boolean finished = sim.controllers().size() == 1 ? one.status() == HeadlessRun.RobotStatus.FINISHED
        : r.status() == HeadlessRun.Status.FINISHED;
    Optional<ControllerAlarm> alarm = sim.controllers().size() == 1 ? one.alarm() : r.alarm();
    return new RunOutcome(v.label(), finished, alarm, r.cycleTimeSec(),
        sim.world(), Map.copyOf(sim.heldParts()), new ArrayList<>(sim.collisionEvents()), c.registers(), c.frames(),
        sim.snapshot().scene(), startParents, List.copyOf(robots), List.copyOf(path),
        sim.controllers().stream().flatMap(x -> x.warnings().stream()).toList());
  }
}
