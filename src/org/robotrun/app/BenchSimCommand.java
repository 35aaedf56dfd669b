package org.robotrun.app;

import java.io.IOException;
import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.motion.MotionLimits;
import org.robotrun.motion.MotionListener;
import org.robotrun.motion.MotionRunner;
import org.robotrun.motion.MoveRequest;
import org.robotrun.motion.Speed;
import org.robotrun.motion.Termination;
import org.robotrun.program.Program;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.RobotModel;
import org.robotrun.sim.Controller;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.HeadlessRun;
import org.robotrun.sim.Simulation;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code robotrun bench sim}: headless simulation speed and the per-tick cost of a linear move. */
@Command(
    name = "sim",
    mixinStandardHelpOptions = true,
    description = {
      "Measure headless simulation speed on the default cell (4 ms ticks).",
      "1) A pick-and-place program of about 60 s of simulated time (the example PICKPLACE, called 9 times) is run "
          + "--repeats times after one warm-up run, with and without collision checking; prints simulated seconds per "
          + "wall second and per CPU second of the running thread (best and median; the CPU figure is the one that "
          + "holds on a busy machine).",
      "2) A 500 mm linear move at 100 mm/s (1 250 ticks of resolved-rate tracking) is run --repeats times; prints "
          + "the wall time per tick (best and median).",
      "--robots N runs workload 1 on a cell of N default robots 1.5 m apart, each running its own copy of it at "
          + "the same time (collisions between every pair checked); the speed is simulated seconds of the whole cell.",
      "Output: robots=N collisions=on|off sim_speed_x=B median_x=M cpu_speed_x=B cpu_median_x=M ... and linear_tick_us=B median_us=M ..."
    })
public final class BenchSimCommand implements Callable<Integer> {
  /** How often BENCH60 calls PICKPLACE: 9 × 6.4 s ≈ 58 s. */
  static final int CYCLES = 9;

  @Option(names = "--repeats", defaultValue = "5", description = "Measured runs of each workload (default: ${DEFAULT-VALUE}).")
  int repeats;

  @Option(names = "--robots", defaultValue = "1", paramLabel = "N",
      description = "Robots in the cell for workload 1, 1..4 (default: ${DEFAULT-VALUE}).")
  int robots;

  /** Distance between neighbouring robots of a --robots cell (mm): beyond both arms' reach together. */
  static final double ROBOT_SPACING_MM = 1500;

  @Override
  public Integer call() throws IOException {
    if (repeats < 1 || repeats > 1000) {
      throw new UserError("--repeats: expected 1..1000, got " + repeats);
    }
    if (robots < 1 || robots > 4) {
      throw new UserError("--robots: expected 1..4, got " + robots);
    }
    RobotModel model = RobotDefinitions.defaultRobot();
    Program pickPlace = example("PICKPLACE");
    Program bench = parse("BENCH60", """
        /PROG  BENCH60
        /ATTR
        /MN
           1:  FOR R[5]=1 TO %d ;
           2:  CALL PICKPLACE ;
           3:  ENDFOR ;
        /END
        """.formatted(CYCLES));

    ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    for (boolean collisions : new boolean[] {true, false}) {
      double[] speed = new double[repeats];
      double[] cpuSpeed = new double[repeats];
      double simSeconds = 0;
      long ticks = 0;
      for (int k = -1; k < repeats; k++) {
        Simulation sim = cell(model, robots);
        sim.setCollisionChecking(collisions);
        java.util.Map<Controller, String> programs = new java.util.LinkedHashMap<>();
        for (Controller c : sim.controllers()) {
          c.saveProgram(pickPlace);
          c.saveProgram(bench);
          programs.put(c, "BENCH60");
        }
        long cpu0 = threads.getCurrentThreadCpuTime();
        long t0 = System.nanoTime();
        HeadlessRun.CellResult r = HeadlessRun.runCell(sim, programs, 600, s -> {}, () -> false, "");
        long ns = System.nanoTime() - t0;
        long cpuNs = threads.getCurrentThreadCpuTime() - cpu0;
        if (r.status() != HeadlessRun.Status.FINISHED) {
          throw new UserError("benchmark program did not finish: " + r.alarm().map(a -> a.display()).orElse("?"), Main.EXIT_FAILED);
        }
        if (k >= 0) {
          speed[k] = r.simTimeSec() / (ns / 1e9);
          cpuSpeed[k] = r.simTimeSec() / (cpuNs / 1e9);
        }
        simSeconds = r.simTimeSec();
        ticks = r.ticks();
      }
      Arrays.sort(speed);
      Arrays.sort(cpuSpeed);
      System.out.printf(Locale.ROOT,
          "robots=%d collisions=%s sim_speed_x=%.0f median_x=%.0f cpu_speed_x=%.0f cpu_median_x=%.0f sim_seconds=%.3f ticks=%d repeats=%d%n",
          robots, collisions ? "on" : "off", speed[repeats - 1], speed[repeats / 2], cpuSpeed[repeats - 1], cpuSpeed[repeats / 2],
          simSeconds, ticks, repeats);
    }

    double[] tickUs = new double[repeats];
    int linearTicks = 0;
    for (int k = -3; k < repeats; k++) {
      double[] q0 = {0, 0.2, -0.1, 0.3, -1.2, 0.4};
      Transform tool = Transform.translation(0, 0, 100);
      MotionRunner runner = new MotionRunner(model, MotionLimits.forModel(model), q0, MotionListener.NONE);
      Transform X_WT = ForwardKinematics.flangePoseInWorld(model, q0).compose(tool);
      Transform target = X_WT.withTranslation(X_WT.x(), X_WT.y() + 250, X_WT.z() - 433);
      runner.enqueue(new MoveRequest.Linear(target, tool, Speed.mmPerSec(100), Termination.fine(), 1, 1));
      int n = 0;
      long t0 = System.nanoTime();
      while (!runner.idle()) {
        runner.tick(Simulation.DEFAULT_TICK_SEC);
        n++;
      }
      long ns = System.nanoTime() - t0;
      if (k >= 0) {
        tickUs[k] = ns / 1e3 / n;
      }
      linearTicks = n;
    }
    double[] ts = tickUs.clone();
    Arrays.sort(ts);
    System.out.printf(Locale.ROOT, "linear_tick_us=%.2f median_us=%.2f ticks=%d repeats=%d%n",
        ts[0], ts[ts.length / 2], linearTicks, repeats);
    return Main.EXIT_OK;
  }

  /**
   * {@code n} default robots (as {@link DefaultCell}) in a row along the cell's y axis,
   * {@link #ROBOT_SPACING_MM} apart, every other one turned to face the previous.
   */
  static Simulation cell(RobotModel model, int n) {
    if (n == 1) {
      return DefaultCell.simulation(model);
    }
    java.util.List<Controller> cs = new java.util.ArrayList<>();
    java.util.List<Transform> X_CW = new java.util.ArrayList<>();
    for (int i = 0; i < n; i++) {
      cs.add(DefaultCell.controller(model, "robot" + (i + 1)));
      Transform at = Transform.translation(0, i * ROBOT_SPACING_MM, 0);
      X_CW.add(i % 2 == 0 ? at : at.compose(Transform.rotation(0, 0, 1, Math.PI)));
    }
    return new Simulation(cs, X_CW, org.robotrun.world.World.empty(), model.X_WB().z(), Simulation.DEFAULT_TICK_SEC);
  }

  /** A program shipped in the jar under /examples. */
  static Program example(String name) throws IOException {
    try (InputStream in = BenchSimCommand.class.getResourceAsStream("/examples/" + name + ".LS")) {
      if (in == null) {
        throw new UserError("missing resource /examples/" + name + ".LS", Main.EXIT_FAILED);
      }
      return parse(name, new String(in.readAllBytes(), StandardCharsets.UTF_8));
    }
  }

  private static Program parse(String name, String text) {
    LsReadResult r = LsReader.parse(name + ".LS", text);
    if (r.hasErrors()) {
      throw new UserError("built-in program " + name + ": " + r.diagnostics(), Main.EXIT_FAILED);
    }
    return r.program();
  }
}
