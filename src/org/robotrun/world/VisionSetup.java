package org.robotrun.world;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.robotrun.math.Transform;

/**
 * Vision (issue 16): cameras, the models they find, named vision processes and seeded random
 * part placement, as an iRVision 2D/3D single-view setup describes them (docs/scenario-format.md,
 * "vision"). Lengths mm, angles rad.
 *
 * @param seed the seed of random placement and vision noise when none is given on the command
 *     line or in the window (same seed, same parts, same results)
 * @param cameras by unique name
 * @param models by unique name and unique model ID
 * @param processes by unique name (what {@code VISION RUN_FIND 'NAME'} names)
 * @param placements parts dropped at random within ranges
 */
public record VisionSetup(long seed, List<Camera> cameras, List<Model> models, List<Process> processes,
    List<Placement> placements) {

  /** None: the scenario does not use this. */
  public static final VisionSetup NONE = new VisionSetup(1, List.of(), List.of(), List.of(), List.of());

  /** Vision registers VR[1..10] (iRVision's default count). */
  public static final int VR_COUNT = 10;

  public VisionSetup {
    cameras = List.copyOf(cameras);
    models = List.copyOf(models);
    processes = List.copyOf(processes);
    placements = List.copyOf(placements);
  }

  /** True when the scenario has no vision section. */
  public boolean isEmpty() {
    return cameras.isEmpty() && models.isEmpty() && processes.isEmpty() && placements.isEmpty();
  }

  /** This setup with another seed. */
  public VisionSetup withSeed(long s) {
    return new VisionSetup(s, cameras, models, processes, placements);
  }

  public Optional<Camera> camera(String name) {
    return cameras.stream().filter(c -> c.name().equals(name)).findFirst();
  }

  public Optional<Model> model(String name) {
    return models.stream().filter(m -> m.name().equals(name)).findFirst();
  }

  /** The process of that name; iRVision matches vision process names case-insensitively. */
  public Optional<Process> process(String name) {
    return processes.stream().filter(p -> p.name().equalsIgnoreCase(name)).findFirst();
  }

  /**
   * A camera. Its frame K looks along +z (the optical axis), image columns grow along +x and rows
   * along +y (a pinhole camera, no lens distortion).
   *
   * @param name unique
   * @param robot the robot whose flange carries it (robot-mounted), or empty (fixed in the cell)
   * @param pose {@code X_CK} in the cell frame (fixed) or {@code X_FK} in the flange frame (robot-mounted)
   * @param fovRad the full vertical field of view, in (0, π)
   * @param widthPx image width (pixels)
   * @param heightPx image height (pixels)
   * @param window the search window in the image (pixels): where parts are looked for
   * @param noiseMm standard deviation of the found position along each axis (mm, ≥ 0)
   * @param noiseRad standard deviation of the found rotation (rad, ≥ 0)
   * @param missProbability chance that a part in view is not found in one RUN_FIND, 0..1
   */
  public record Camera(String name, Optional<String> robot, Transform pose, double fovRad, int widthPx, int heightPx,
      Window window, double noiseMm, double noiseRad, double missProbability) {
    public Camera {
      Objects.requireNonNull(name, "name");
      Objects.requireNonNull(robot, "robot");
      Objects.requireNonNull(pose, "pose");
      Objects.requireNonNull(window, "window");
      if (!(fovRad > 0 && fovRad < Math.PI)) {
        throw new IllegalArgumentException("field of view must be in (0, 180) deg");
      }
      if (widthPx < 1 || heightPx < 1) {
        throw new IllegalArgumentException("image size must be at least 1 x 1 pixels");
      }
      if (!(noiseMm >= 0) || !(noiseRad >= 0) || !(missProbability >= 0 && missProbability <= 1)) {
        throw new IllegalArgumentException("noise must be >= 0 and the miss probability in 0..1");
      }
    }

    /** Focal length in pixels (pinhole: rows/2 = f·tan(fov/2)). */
    public double focalPx() {
      return heightPx / 2.0 / Math.tan(fovRad / 2);
    }

    /**
     * Where point {@code p_KQ} (camera frame, mm) falls in the image: {u, v} in pixels, or null
     * when it is behind the camera or closer than 1 mm.
     */
    public double[] project(double x, double y, double z) {
      if (!(z > 1)) {
        return null;
      }
      double f = focalPx();
      return new double[] {widthPx / 2.0 + f * x / z, heightPx / 2.0 + f * y / z};
    }
  }

  /** A rectangle in the image, pixels: left ≤ u &lt; right, top ≤ v &lt; bottom. */
  public record Window(double left, double top, double right, double bottom) {
    public Window {
      if (!(left < right && top < bottom)) {
        throw new IllegalArgumentException("a search window needs left < right and top < bottom");
      }
    }

    public boolean contains(double u, double v) {
      return u >= left && u < right && v >= top && v < bottom;
    }
  }

  /**
   * What a locator tool is taught to find: a part matches when every criterion given matches
   * (no criterion: every part).
   *
   * @param name unique
   * @param id the model ID reported in VR[i].MODELID (1..)
   * @param namePrefix parts whose name starts with it
   * @param colour parts of this colour
   * @param shape parts of this shape kind: "box", "cylinder" or "mesh"
   */
  public record Model(String name, int id, Optional<String> namePrefix, Optional<Rgb> colour, Optional<String> shape) {
    public Model {
      Objects.requireNonNull(name, "name");
      Objects.requireNonNull(namePrefix, "namePrefix");
      Objects.requireNonNull(colour, "colour");
      Objects.requireNonNull(shape, "shape");
    }

    public boolean matches(WorldObject o) {
      return o.kind() == ObjectKind.PART
          && namePrefix.map(p -> o.name().startsWith(p)).orElse(true)
          && colour.map(c -> c.equals(o.colour())).orElse(true)
          && shape.map(s -> s.equals(shapeKind(o.shape()))).orElse(true);
    }

    /** "box", "cylinder" or "mesh". */
    public static String shapeKind(Shape s) {
      return switch (s) {
        case Shape.Box b -> "box";
        case Shape.Cylinder c -> "cylinder";
        case Shape.Mesh m -> "mesh";
      };
    }
  }

  /** 2D single view (X, Y, R on a plane) or 3D (the full pose). */
  public enum ProcessType {
    TWO_D("2D"), THREE_D("3D");

    private final String text;

    ProcessType(String text) {
      this.text = text;
    }

    /** "2D" or "3D", as the scenario file writes it. */
    public String text() {
      return text;
    }
  }

  /**
   * A vision process.
   *
   * @param name what {@code VISION RUN_FIND 'NAME'} names (unique, case-insensitive)
   * @param camera the camera's name
   * @param models the models its locator tools find (at least one)
   * @param userFrame the application user frame UF[n] (0..10) found poses and offsets are in
   * @param reference {@code X_UR}: the part's pose in that frame when the program's positions
   *     were taught (the reference position iRVision's SET_REFERENCE records)
   * @param type 2D single view or 3D
   * @param maxFound the locator's "number to find" (1..100)
   */
  public record Process(String name, String camera, List<String> models, int userFrame, Transform reference,
      ProcessType type, int maxFound) {
    public Process {
      Objects.requireNonNull(name, "name");
      Objects.requireNonNull(camera, "camera");
      models = List.copyOf(models);
      Objects.requireNonNull(reference, "reference");
      Objects.requireNonNull(type, "type");
      if (models.isEmpty()) {
        throw new IllegalArgumentException("a vision process needs at least one model");
      }
      if (userFrame < 0 || userFrame > 10) {
        throw new IllegalArgumentException("user frame must be 0..10");
      }
      if (maxFound < 1 || maxFound > 100) {
        throw new IllegalArgumentException("number to find must be 1..100");
      }
    }
  }

  /**
   * Parts dropped at random: each listed part gets a position and a rotation about its parent's z
   * axis drawn uniformly from the ranges (in its parent's frame, or the cell's), at least
   * {@code minGapMm} from the others of the group (centre to centre), and, when kinds are given,
   * one of them (its shape and colour).
   */
  public record Placement(List<String> parts, double xMinMm, double xMaxMm, double yMinMm, double yMaxMm,
      double rMinRad, double rMaxRad, double minGapMm, List<Kind> kinds) {
    public Placement {
      parts = List.copyOf(parts);
      kinds = List.copyOf(kinds);
      if (!(xMinMm <= xMaxMm && yMinMm <= yMaxMm && rMinRad <= rMaxRad && minGapMm >= 0)) {
        throw new IllegalArgumentException("placement ranges need min <= max and a gap >= 0");
      }
    }
  }

  /** One kind a placed part may become: its shape and colour. */
  public record Kind(Shape shape, Rgb colour) {
    public Kind {
      Objects.requireNonNull(shape, "shape");
      Objects.requireNonNull(colour, "colour");
    }
  }
}
