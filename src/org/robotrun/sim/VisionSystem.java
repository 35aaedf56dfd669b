package org.robotrun.sim;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.AlarmCode;
import org.robotrun.program.Config;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.program.VisionPort;
import org.robotrun.program.VisionResult;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.world.PartPlacement;
import org.robotrun.world.VisionSetup;
import org.robotrun.world.WorldObject;

/**
 * The cell's vision system: runs the scenario's vision processes the way an iRVision 2D/3D
 * single-view process answers, without image processing. The simulator knows where every part
 * is; a part is found when it matches one of the process's models and its origin projects into
 * the camera's search window (pinhole model, perfect calibration). Found poses get the camera's
 * seeded noise and misses: the same seed and the same program give the same results.
 *
 * <p>2D processes measure X, Y and the rotation R about the user frame's z axis; Z, W and P are the
 * reference position's (a 2D camera cannot see them). 3D processes measure the full pose.
 */
public final class VisionSystem {
  private final Simulation sim;
  private final VisionSetup setup;
  private final Map<String, Integer> runs = new HashMap<>();
  private final Map<String, List<Detection>> last = new HashMap<>();

  /** One part found by the last RUN_FIND of a process: which part, where it was seen, what was reported. */
  public record Detection(String part, Transform X_CFound, VisionResult result) {}

  private VisionSystem(Simulation sim, VisionSetup setup) {
    this.sim = sim;
    this.setup = setup;
  }

  /** Connects a vision system for {@code setup} to every controller of {@code sim}. */
  public static VisionSystem attach(Simulation sim, VisionSetup setup) {
    VisionSystem v = new VisionSystem(sim, setup);
    for (Controller c : sim.controllers()) {
      c.interpreter().setVisionPort(v.portFor(c));
    }
    sim.setVision(v);
    return v;
  }

  /**
   * Reset with a new seed (the window's Reset): parts placed anew, vision results and registers
   * cleared, noise drawn from the new seed. Answers the new vision system (also {@code sim.vision()}).
   */
  public static VisionSystem reseed(Simulation sim, VisionSetup setup, long seed) {
    VisionSetup s = setup.withSeed(seed);
    sim.replaceWorld(PartPlacement.place(sim.world().reset(), s));
    for (Controller c : sim.controllers()) {
      c.registers().vision().clearAll();
    }
    return attach(sim, s);
  }

  public VisionSetup setup() {
    return setup;
  }

  /** The parts the last RUN_FIND of {@code process} found (empty before it ran). */
  public List<Detection> lastFound(String process) {
    return last.getOrDefault(process.toUpperCase(Locale.ROOT), List.of());
  }

  /** The camera's pose in the cell now ({@code X_CK}): fixed, or following its robot's flange. */
  public Transform cameraPose(VisionSetup.Camera cam) {
    if (cam.robot().isEmpty()) {
      return cam.pose();
    }
    List<Controller> cs = sim.controllers();
    for (int i = 0; i < cs.size(); i++) {
      Controller c = cs.get(i);
      if (c.name().equals(cam.robot().get())) {
        return sim.robotPlacements().get(i).compose(ForwardKinematics.flangePoseInWorld(c.model(), c.jointsRad()))
            .compose(cam.pose());
      }
    }
    throw new IllegalStateException("no robot named " + cam.robot().get());
  }

  private VisionPort portFor(Controller c) {
    return new VisionPort() {
      @Override
      public boolean hasProcess(String name) {
        return setup.process(name).isPresent();
      }

      @Override
      public Outcome runFind(String name) {
        Optional<VisionSetup.Process> p = setup.process(name);
        if (p.isEmpty()) {
          return new Outcome.Failed(AlarmCode.CVIS_015.code(), "vision process '" + name + "' not found");
        }
        return new Outcome.Found(find(c, p.get()).stream().map(Detection::result).toList());
      }
    };
  }

  /**
   * {@code VISION RUN_FIND 'process'} as the program of controller {@code c} runs it (benchmarks,
   * the camera view): the parts found, best score first.
   *
   * @throws IllegalArgumentException if there is no such process
   */
  public List<Detection> runFind(Controller c, String process) {
    return find(c, setup.process(process).orElseThrow(() -> new IllegalArgumentException(
        "no vision process named '" + process + "'")));
  }

  /** RUN_FIND of {@code p} for the program of controller {@code c} (its user frames). */
  List<Detection> find(Controller c, VisionSetup.Process p) {
    String key = p.name().toUpperCase(Locale.ROOT);
    int run = runs.merge(key, 1, Integer::sum);
    Random rnd = new Random(PartPlacement.mix(PartPlacement.mix(setup.seed(), key.hashCode()), run));
    VisionSetup.Camera cam = setup.camera(p.camera()).orElseThrow();
    Transform X_KC = cameraPose(cam).inverse();
    int ci = sim.controllers().indexOf(c);
    Transform X_CU = sim.robotPlacements().get(ci).compose(c.frames().transform(FrameKind.USER, p.userFrame()));
    Transform X_UC = X_CU.inverse();
    Xyzwpr ref = Xyzwpr.fromTransform(p.reference());
    Transform X_RU = p.reference().inverse();
    Map<String, String> held = sim.heldParts();
    List<Detection> out = new ArrayList<>();
    List<VisionSetup.Model> models = p.models().stream().map(m -> setup.model(m).orElseThrow()).toList();
    for (WorldObject o : sim.world().objects()) {
      if (held.containsKey(o.name())) {
        continue;
      }
      Optional<VisionSetup.Model> model = models.stream().filter(m -> m.matches(o)).findFirst();
      if (model.isEmpty()) {
        continue;
      }
      Transform X_CP = sim.world().poseInCell(o.name());
      Vec3 p_KP = X_KC.apply(X_CP.translationVector());
      double[] uv = cam.project(p_KP.x(), p_KP.y(), p_KP.z());
      if (uv == null || !cam.window().contains(uv[0], uv[1])) {
        continue;
      }
      // Draws in a fixed order per part in view, so one part's miss does not shift the others' noise.
      double missDraw = rnd.nextDouble();
      double[] n = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(),
          rnd.nextGaussian()};
      double score = 100 - 20 * rnd.nextDouble();
      if (missDraw < cam.missProbability()) {
        continue;
      }
      Xyzwpr t = Xyzwpr.fromTransform(X_UC.compose(X_CP));
      double s = cam.noiseMm();
      double sr = cam.noiseRad();
      Xyzwpr found = switch (p.type()) {
        case TWO_D -> Xyzwpr.of(t.x() + s * n[0], t.y() + s * n[1], ref.z(), ref.w(), ref.p(), t.r() + sr * n[5]);
        case THREE_D -> Xyzwpr.of(t.x() + s * n[0], t.y() + s * n[1], t.z() + s * n[2], t.w() + sr * n[3],
            t.p() + sr * n[4], t.r() + sr * n[5]);
      };
      Transform X_UF = found.toTransform();
      Transform offset = X_UF.compose(X_RU);
      VisionResult r = new VisionResult(p.name(), model.get().id(), cartesian(X_UF), cartesian(offset), p.userFrame(),
          Math.round(score * 10) / 10.0);
      out.add(new Detection(o.name(), X_CU.compose(X_UF), r));
    }
    List<Detection> sorted = new ArrayList<>(out);
    sorted.sort(Comparator.comparingDouble((Detection d) -> -d.result().score()).thenComparing(Detection::part));
    List<Detection> kept = List.copyOf(sorted.subList(0, Math.min(p.maxFound(), sorted.size())));
    last.put(key, kept);
    return kept;
  }

  /** Colour of the outlines of found parts in a camera view. */
  public static final DrawItem.Color FOUND_COLOR = DrawItem.Color.rgb(0.1, 0.95, 0.2);

  /** The detections of the last RUN_FIND of every process that uses {@code camera}. */
  public List<Detection> lastFoundBy(String camera) {
    List<Detection> out = new ArrayList<>();
    for (VisionSetup.Process p : setup.processes()) {
      if (p.camera().equals(camera)) {
        out.addAll(lastFound(p.name()));
      }
    }
    return out;
  }

  /**
   * {@code scene} with the found parts of {@code camera}'s processes outlined: a wire box 10 %
   * larger than the part's box, at the pose the vision process found (not where the part is).
   */
  public SceneSnapshot withOutlines(SceneSnapshot scene, String camera) {
    List<DrawItem> items = new ArrayList<>(scene.items());
    for (Detection d : lastFoundBy(camera)) {
      Optional<WorldObject> o = sim.world().find(d.part());
      if (o.isEmpty()) {
        continue;
      }
      var box = o.get().shape().boundingBox();
      items.add(new DrawItem("vision/" + d.part(), new DrawShape.WireBox(new Vec3(2.2 * box.hxMm(), 2.2 * box.hyMm(),
          2.2 * box.hzMm())), d.X_CFound().compose(box.X_LB()), FOUND_COLOR));
    }
    return new SceneSnapshot(scene.simTimeSec(), items, scene.floorZ());
  }

  /**
   * A label for a found part in the camera's image: where to write it (pixels, the found origin's
   * projection), the outline of the part's top face at its found pose (four image points, u then v),
   * and the text (model ID, found X, Y, R in the process's user frame).
   */
  public record Label(double u, double v, double[] outline, String text) {}

  /** Labels of the last found parts of {@code camera}'s processes, in image pixels. */
  public List<Label> labels(VisionSetup.Camera cam) {
    Transform X_KC = cameraPose(cam).inverse();
    List<Label> out = new ArrayList<>();
    int k = 0;
    for (Detection d : lastFoundBy(cam.name())) {
      k++;
      Optional<WorldObject> o = sim.world().find(d.part());
      if (o.isEmpty()) {
        continue;
      }
      var box = o.get().shape().boundingBox();
      Transform X_KB = X_KC.compose(d.X_CFound()).compose(box.X_LB());
      double[] outline = new double[8];
      boolean visible = true;
      double[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (int c = 0; c < 4; c++) {
        Vec3 p = X_KB.apply(new Vec3(corners[c][0] * box.hxMm(), corners[c][1] * box.hyMm(), box.hzMm()));
        double[] uv = cam.project(p.x(), p.y(), p.z());
        if (uv == null) {
          visible = false;
          break;
        }
        outline[2 * c] = uv[0];
        outline[2 * c + 1] = uv[1];
      }
      Vec3 origin = X_KC.apply(d.X_CFound().translationVector());
      double[] at = cam.project(origin.x(), origin.y(), origin.z());
      if (!visible || at == null) {
        continue;
      }
      Position.Cartesian f = d.result().found();
      out.add(new Label(at[0], at[1], outline, String.format(Locale.ROOT, "%d: M%d X%.1f Y%.1f R%.1f", k,
          d.result().modelId(), f.xMm(), f.yMm(), f.rDeg())));
    }
    return out;
  }

  private static Position.Cartesian cartesian(Transform t) {
    return Position.Cartesian.of(Xyzwpr.fromTransform(t), Config.DEFAULT);
  }
}
