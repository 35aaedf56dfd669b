package org.robotrun.grade;

import java.util.ArrayList;
import java.util.HashMap;
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
  record Variant(int index, Scenario scenario, int overridePct, Map<Integer, Position.Cartesian> offsetRegisters) {
    String label() {
      return index == 0 ? "nominal run" : "variation " + index + " (override " + overridePct + "%)";
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

  /** Variation {@code i} (1-based) drawn with seed {@code seed + i}: the same every time. */
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
      world = world.with(WorldObject.of(o.name(), o.kind(), o.shape(), o.colour(), moved, o.startParent()));
      j.offsetRegister().ifPresent(n -> regs.put(n, new Position.Cartesian(dx, dy, 0, 0, 0, drDeg, Config.DEFAULT)));
    }
    int override = v.overrideMinPct() == v.overrideMaxPct() ? v.overrideMinPct()
        : rng.nextInt(v.overrideMinPct(), v.overrideMaxPct() + 1);
    Scenario s = new Scenario(base.name(), base.description(), base.robots(), world, base.programs(), base.mainProgram(),
        base.registers(), base.toolFrames(), base.userFrames(), base.camera(), base.onCollision()).withExtrasOf(base);
    return new Variant(i, s, override, regs);
  }

  private static double draw(SplittableRandom rng, double range) {
    // Rounded to 0.1 so the offsets a student sees in PR[] read as a vision system reports them.
    return range == 0 ? 0 : Math.round(rng.nextDouble(-range, range) * 10) / 10.0;
  }

  /**
   * Runs {@code program} on the variant's cell.
   *
   * @param positionRegisters the student's PR[] to start with (taught at the pendant)
   *
   * @param deadlineNanos {@link System#nanoTime()} after which the run is abandoned
   * @throws WallClockExceeded when the deadline passes
   * @throws IllegalArgumentException when the cell cannot be built or the program not started
   */
  static RunOutcome run(Variant v, Function<String, RobotModel> models, List<Program> programs,
      Map<Integer, Position> positionRegisters, String program, double maxSimSec, long deadlineNanos) {
    Simulation sim = ScenarioCell.build(v.scenario(), models, Simulation.DEFAULT_TICK_SEC);
    Controller c = sim.controllers().get(0);
    programs.forEach(c::saveProgram);
    c.setOverridePct(v.overridePct());
    // The student's own PRs first; the task's offset registers (where parts were found) win.
    positionRegisters.forEach((n, p) -> c.registers().setPosition(n, p));
    v.offsetRegisters().forEach((n, p) -> c.registers().setPosition(n, p));
    Map<String, Optional<String>> startParents = new HashMap<>();
    for (WorldObject o : sim.world().objects()) {
      if (o.kind() == ObjectKind.PART) {
        startParents.put(o.name(), o.parent());
      }
    }
    HeadlessRun.Result r = HeadlessRun.run(sim, c, program, maxSimSec, s -> {
      if ((s.ticks() & 63) == 0 && System.nanoTime() - deadlineNanos > 0) {
        throw new WallClockExceeded();
      }
    });
    return new RunOutcome(v.label(), r.status() == HeadlessRun.Status.FINISHED, r.alarm(), r.cycleTimeSec(),
        sim.world(), Map.copyOf(sim.heldParts()), new ArrayList<>(sim.collisionEvents()), c.registers(), c.frames(),
        sim.snapshot().scene(), startParents);
  }
}
