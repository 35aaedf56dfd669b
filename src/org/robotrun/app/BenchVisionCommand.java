package org.robotrun.app;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import org.robotrun.sim.VisionSystem;
import org.robotrun.world.CollisionResponse;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Rgb;
import org.robotrun.world.Scenario;
import org.robotrun.world.Shape;
import org.robotrun.world.VisionSetup;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code robotrun bench vision}: the cost of one VISION RUN_FIND with many parts in view. */
@Command(
    name = "vision",
    mixinStandardHelpOptions = true,
    description = {"Time VISION RUN_FIND on a cell with N parts in a grid under a fixed camera (all in view, "
        + "noise and misses on) and print the median time of one RUN_FIND in microseconds."})
public final class BenchVisionCommand implements Runnable {
  @Spec CommandSpec spec;

  @Option(names = "--parts", defaultValue = "50", paramLabel = "N",
      description = "Parts in view, 1..100 (default: ${DEFAULT-VALUE}).")
  int parts;

  @Option(names = "--repeat", defaultValue = "2000", paramLabel = "R",
      description = "Timed RUN_FINDs after a warm-up; the median is reported (default: ${DEFAULT-VALUE}).")
  int repeat;

  @Override
  public void run() {
    if (parts < 1 || parts > 100) {
      throw new UserError("--parts must be 1..100, got " + parts);
    }
    if (repeat < 1) {
      throw new UserError("--repeat must be at least 1, got " + repeat);
    }
    Simulation sim = ScenarioCell.build(cell(parts), RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
    VisionSystem vs = sim.vision().orElseThrow();
    Controller c = sim.controllers().get(0);
    int found = 0;
    for (int w = 0; w < Math.max(200, repeat / 5); w++) {
      found = vs.runFind(c, "FIND").size();
    }
    long[] ns = new long[repeat];
    for (int r = 0; r < repeat; r++) {
      long s = System.nanoTime();
      found = vs.runFind(c, "FIND").size();
      ns[r] = System.nanoTime() - s;
    }
    Arrays.sort(ns);
    PrintWriter out = spec.commandLine().getOut();
    out.printf(Locale.ROOT, "parts=%d found=%d run_find_us=%.1f p90_us=%.1f%n", parts, found, ns[repeat / 2] / 1e3,
        ns[(int) (repeat * 0.9)] / 1e3);
    out.flush();
  }

  /** A table with {@code n} blocks in a 10-wide grid, 60 mm apart, and a camera 1.2 m above them. */
  static Scenario cell(int n) {
    List<WorldObject> objects = new ArrayList<>();
    objects.add(WorldObject.of("table", ObjectKind.FIXTURE, new Shape.Box(800, 800, 200), Rgb.GREY,
        Transform.translation(500, 0, -300), Optional.empty()));
    List<String> names = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      String name = "block" + (i + 1);
      names.add(name);
      objects.add(WorldObject.of(name, ObjectKind.PART, new Shape.Box(30, 30, 30), new Rgb(200, 60, 40),
          Xyzwpr.ofDegrees(-270 + 60 * (i % 10), -270 + 60 * (i / 10), 200, 0, 0, 7 * i).toTransform(),
          Optional.of("table")));
    }
    VisionSetup.Camera cam = new VisionSetup.Camera("CAM1", Optional.empty(),
        Xyzwpr.ofDegrees(500, 0, 1200, 180, 0, 0).toTransform(), Math.toRadians(60), 1280, 960,
        new VisionSetup.Window(0, 0, 1280, 960), 0.3, Math.toRadians(0.2), 0.01);
    VisionSetup v = new VisionSetup(1, List.of(cam),
        List.of(new VisionSetup.Model("BLOCK", 1, Optional.of("block"), Optional.empty(), Optional.of("box"))),
        List.of(new VisionSetup.Process("FIND", "CAM1", List.of("BLOCK"), 0, Transform.translation(500, 0, -100),
            VisionSetup.ProcessType.TWO_D, 100)),
        List.of());
    RobotSetup robot = new RobotSetup("robot1", RobotDefinitions.DEFAULT_ROBOT, Transform.IDENTITY,
        EndEffectorType.FACEPLATE, List.of(0.0, 0.0, 0.0, 0.0, -Math.PI / 2, 0.0));
    return new Scenario("bench vision", "", List.of(robot), new World(objects), List.of(), Optional.empty(),
        new java.util.TreeMap<>(), new java.util.TreeMap<>(), new java.util.TreeMap<>(), Optional.empty(),
        CollisionResponse.WARN).withVision(v);
  }
}
