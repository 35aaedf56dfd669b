package org.robotrun.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;
import org.robotrun.sim.HeadlessRun;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.world.Scenario;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun bench cell}: per-tick cost of a scenario's whole cell, and its program's cycle time. */
@Command(
    name = "cell",
    mixinStandardHelpOptions = true,
    description = {
      "Run a scenario's main program headless, --repeats times after one warm-up run, with collision checking on "
          + "and off, timing the CPU of the running thread.",
      "Prints the cycle time (simulated), ticks, CPU microseconds per tick with and without collisions (best and "
          + "median), and their difference: the whole-scene collision cost per tick (robot links, end effector, "
          + "fixtures, parts, held parts; grips and set-downs are in both).",
      "Output: scenario=F program=P cycle_s=C ticks=N objects=B tick_us_on=X median_on=X' tick_us_off=Y median_off=Y' "
          + "collision_us_per_tick=D"
    })
public final class BenchCellCommand implements Callable<Integer> {
  @picocli.CommandLine.Spec picocli.CommandLine.Model.CommandSpec spec;

  @Option(names = "--scenario", required = true, paramLabel = "FILE.json", description = "The scenario; it must name a mainProgram (a cell of several robots: each robot's runs at once) "
      + "or start from its PLC (production runStartsFromPlc, as run does).")
  Path scenario;

  @Option(names = "--repeats", defaultValue = "5", description = "Measured runs with and without collisions (default: ${DEFAULT-VALUE}).")
  int repeats;

  @Override
  public Integer call() throws IOException {
    if (repeats < 1 || repeats > 1000) {
      throw new UserError("--repeats: expected 1..1000, got " + repeats);
    }
    Scenario sc = ScenarioFiles.load(scenario);
    // Every robot with a main program runs it (the first robot: its own, else the scenario's), as run does.
    List<String> mains = new java.util.ArrayList<>();
    List<List<Program>> own = new java.util.ArrayList<>();
    for (int i = 0; i < sc.robots().size(); i++) {
      var r = sc.robots().get(i);
      mains.add(sc.preload(i).mainProgram().orElse(null));
      own.add(RunCommand.loadPrograms(r.programs()));
    }
    // A cell whose PLC starts the first robot's program runs as run does it (ProductionRun), not by mainProgram.
    boolean fromPlc = sc.production().of(sc.robots().get(0).name())
        .filter(org.robotrun.world.ProductionSetup.Robot::startFromPlc).isPresent();
    if (!fromPlc && mains.stream().allMatch(java.util.Objects::isNull)) {
      throw new UserError("--scenario: " + scenario + " names no mainProgram");
    }
    String program = fromPlc ? "PLC" : String.join("+", mains.stream().filter(java.util.Objects::nonNull).toList());
    List<Program> programs = RunCommand.loadPrograms(sc.programs());
    double cycle = 0;
    long ticks = 0;
    int bodies = 0;
    double[][] usPerTick = new double[2][repeats];
    for (int k = -1; k < repeats; k++) {
      for (int on = 0; on < 2; on++) {
        Simulation sim;
        try {
          sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
        } catch (FileFormatException | IllegalArgumentException e) {
          throw new UserError(scenario + ": " + e.getMessage());
        }
        sim.setCollisionChecking(on == 0);
        programs.forEach(sim.controllers().get(0)::saveProgram);
        java.util.Map<Controller, String> toRun = new java.util.LinkedHashMap<>();
        for (int i = 0; i < sim.controllers().size(); i++) {
          Controller c = sim.controllers().get(i);
          own.get(i).forEach(c::saveProgram);
          if (mains.get(i) != null) {
            toRun.put(c, mains.get(i));
          }
        }
        long t0 = BenchClock.CPU.nanos();
        HeadlessRun.CellResult r = fromPlc
            ? org.robotrun.sim.ProductionRun.run(sim, sim.controllers().get(0), 600, s -> {}, () -> false, "")
            : HeadlessRun.runCell(sim, toRun, 600, s -> {}, () -> false, "");
        long ns = BenchClock.CPU.nanos() - t0;
        if (r.status() != HeadlessRun.Status.FINISHED) {
          throw new UserError(program + " did not finish: " + r.alarm().map(a -> a.display()).orElse("?"), Main.EXIT_FAILED);
        }
        if (k >= 0) {
          usPerTick[on][k] = ns / 1e3 / r.ticks();
        }
        cycle = r.cycleTimeSec();
        ticks = r.ticks();
        bodies = sc.world().objects().size();
      }
    }
    for (double[] a : usPerTick) {
      Arrays.sort(a);
    }
    double medOn = usPerTick[0][repeats / 2];
    double medOff = usPerTick[1][repeats / 2];
    java.io.PrintWriter out = spec.commandLine().getOut();
    out.printf(Locale.ROOT,
        "scenario=%s program=%s cycle_s=%.3f ticks=%d objects=%d tick_us_on=%.2f median_on=%.2f tick_us_off=%.2f "
            + "median_off=%.2f collision_us_per_tick=%.2f repeats=%d%n",
        scenario.getFileName(), program, cycle, ticks, bodies, usPerTick[0][0], medOn, usPerTick[1][0], medOff,
        medOn - medOff, repeats);
    out.flush();
    return Main.EXIT_OK;
  }
}
