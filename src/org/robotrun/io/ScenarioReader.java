package org.robotrun.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import org.robotrun.program.IoKind;
import org.robotrun.program.IoRanges;
import org.robotrun.io.LocatedJson.JArray;
import org.robotrun.io.LocatedJson.JNumber;
import org.robotrun.io.LocatedJson.JObject;
import org.robotrun.io.LocatedJson.JString;
import org.robotrun.math.PoseLimits;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;
import org.robotrun.world.CameraView;
import org.robotrun.world.CollisionResponse;
import org.robotrun.world.ToolIo;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Rgb;
import org.robotrun.world.ProductionSetup;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.Wiring;
import org.robotrun.world.Shape;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/**
 * Reads scenario files ({@code "format": 1}, see docs/scenario-format.md). Degrees become
 * radians here, once; relative paths are resolved against the scenario's folder.
 *
 * <p>Every problem is collected with its JSON path and line — unknown fields, wrong types,
 * non-finite or out-of-range numbers, missing files, duplicate names, bad parents — and the
 * result is either the whole scenario or the list of errors ({@link ScenarioLoad}); a syntax
 * error stops at the first one, since nothing after it can be trusted.
 */
public final class ScenarioReader {
  /** The format this reader understands. */
  public static final int FORMAT = 1;

  /** Longest name of a robot or an object (a robot's is also its programs folder's, docs/workspace.md). */
  public static final int MAX_NAME_LENGTH = 64;
  /** Longest macro name (the controller's macro table holds up to 36 characters). */
  public static final int MAX_MACRO_NAME = 36;
  /** Longest scenario name (a window title, a hand-in's manifest). */
  public static final int MAX_SCENARIO_NAME = 200;

  /** Largest scenario file accepted (meshes are separate files). */
  public static final long MAX_FILE_BYTES = 16L << 20;
  /** Largest position coordinate or size, in mm (the bound every position entry shares). */
  public static final double MAX_LENGTH_MM = PoseLimits.MAX_COORDINATE_MM;

  /**
   * Most objects in one scenario: every one is a collision body checked each tick, and a cell
   * for teaching holds tens, not hundred thousands. Loading is linear in the objects either way.
   */
  public static final int MAX_OBJECTS = 100_000;

  /** Highest register index a scenario may preset. */
  public static final int MAX_REGISTER = 200;

  /** Highest tool or user frame number. */
  public static final int MAX_FRAME = 10;

  private static final Set<String> TOP = Set.of(
      "format", "name", "description", "robots", "objects", "programs", "mainProgram", "registers", "frames", "camera",
      "onCollision", "state", "mode", "wiring", "production", VisionJson.KEY);
  private static final Set<String> ROBOT = Set.of("name", "model", "basePose", "endEffector", "jointsDeg", "toolIo",
      "io", "userAlarms", "programs", "mainProgram", "macros", "registers", "frames", "mode", "packages");
  /** Highest UALM[i] a scenario may give a text for. */
  static final int MAX_USER_ALARM = 200;
  private static final Set<String> TOOL_IO = Set.of("output", "actuated", "holding");
  private static final Set<String> OBJECT = Set.of(
      "name", "kind", "shape", "size", "radius", "height", "file", "scale", "color", "pose", "parent", "touchable",
      "startPose", "startParent");
  private static final Map<String, Set<String>> SHAPE_FIELDS = Map.of(
      "box", Set.of("size"), "cylinder", Set.of("radius", "height"), "mesh", Set.of("file", "scale"));
  private static final Set<String> POSE = Set.of("x", "y", "z", "w", "p", "r");
  private static final Set<String> XYZ = Set.of("x", "y", "z");
  private static final Set<String> CAMERA = Set.of("target", "distance", "yawDeg", "pitchDeg");

  private ScenarioReader() {}

  /**
   * Loads a scenario file. Never throws for bad content: errors come back in the result. A
   * {@code "state"} section (a workspace's saved controller state) is checked but not applied:
   * open the folder as a workspace for that.
   */
  public static ScenarioLoad read(Path file) {
    return switch (readCell(file, false)) {
      case CellLoad.Loaded l -> new ScenarioLoad.Loaded(l.scenario());
      case CellLoad.Failed f -> new ScenarioLoad.Failed(f.errors());
    };
  }

  /**
   * Loads a scenario file with its {@code "state"} section, checked as {@link #read} checks it
   * ({@code robotrun run --scenario} applies the state to every robot).
   */
  public static CellLoad readWithState(Path file) {
    return readCell(file, false);
  }

  /**
   * Loads a workspace's {@code cell.json}: a scenario plus its {@code "state"} section. The
   * programs live in the workspace's {@code programs/} folder, so {@code mainProgram} need not be
   * listed in {@code "programs"}.
   */
  public static CellLoad readCell(Path file) {
    return readCell(file, true, false);
  }

  /**
   * Loads a hand-in's {@code cell.json} (or another cell file of a hand-in) as
   * {@link #readCell(Path)} does, with every file it names (meshes, programs) read only from
   * inside the file's own folder: a path that leaves it, or a link out of it, is an error naming
   * the field (a hand-in must not make the grader read its machine's files).
   */
  public static CellLoad readHandInCell(Path file) {
    return readCell(file, true, true);
  }

  private static CellLoad readCell(Path file, boolean workspace) {
    return readCell(file, workspace, false);
  }

  private static CellLoad readCell(Path file, boolean workspace, boolean confined) {
    String name = file.toString();
    String text;
    try {
      text = BoundedFiles.readUtf8(file, MAX_FILE_BYTES, "scenario files (meshes are separate files)");
    } catch (UnreadableFileException e) {
      return fail(name, 0, e.getMessage());
    } catch (FileFormatException e) {
      return fail(name, e.line(), e.reason());
    }
    Path dir = file.toAbsolutePath().normalize().getParent();
    Session session = new Session(name, dir, workspace);
    session.confined = confined;
    return session.read(text);
  }

  private static CellLoad fail(String file, int line, String message) {
    return new CellLoad.Failed(List.of(new ScenarioError(file, line, "", message)));
  }

  /** One load: the file, its folder and the errors found so far. */
  private static final class Session extends JsonFieldReader {
    private final Path dir;
    private final Map<String, RobotModel> models = new HashMap<>();
    // What RobotSetup.modelId holds for each model text: the library id, or the robot file's absolute path.
    private final Map<String, String> modelRefs = new HashMap<>();
    /** Where each name was first defined, for duplicate messages. */
    private final Map<String, String> definedAt = new HashMap<>();

    private final boolean workspace;
    /** Whether the files named must lie inside {@link #dir} (a hand-in's cell). */
    private boolean confined;

    Session(String file, Path dir, boolean workspace) {
      super(file);
      this.dir = dir;
      this.workspace = workspace;
    }

    CellLoad read(String text) {
      JObject top = topObject(text, TOP);
      if (top == null) {
        return new CellLoad.Failed(errors);
      }
      format(top, FORMAT);
      String title = string(top, "name", "", false).orElse("");
      if (title.length() > MAX_SCENARIO_NAME) {
        error(top.keyLines().getOrDefault("name", top.line()), "name", "a scenario name is at most " + MAX_SCENARIO_NAME
            + " characters, got " + title.length());
      }
      String description = string(top, "description", "", false).orElse("");
      List<RobotSetup> robots = robots(top);
      List<WorldObject> objects = objects(top);
      List<Path> programs = programs(top, "");
      Optional<String> mainProgram = mainProgram(top, "");
      TreeMap<Integer, Double> registers = registers(top, "");
      TreeMap<Integer, Transform> toolFrames = new TreeMap<>();
      TreeMap<Integer, Transform> userFrames = new TreeMap<>();
      frames(top, "", toolFrames, userFrames);
      firstRobotOnce(top);
      Optional<CameraView> camera = camera(top);
      CollisionResponse onCollision = string(top, "onCollision", "", false).map(s -> onCollision(s, top))
          .orElse(CollisionResponse.ALARM);
      Optional<String> mode = string(top, "mode", "", false).map(m -> mode(m, top, ""));
      Wiring wiring = WiringJson.read(this, top, robots);
      ProductionSetup production = ProductionJson.read(top, file, robots, errors::add);
      SavedState state = null;
      LocatedJson stateJson = top.members().get("state");
      if (stateJson instanceof JObject so) {
        state = StateJson.read(so, this::error);
        // state.robots holds each later robot's state: one the cell lacks would be dropped at the next save
        if (so.members().get("robots") instanceof JObject saved) {
          List<String> later = robots.stream().skip(1).map(RobotSetup::name).toList();
          for (String name : saved.members().keySet()) {
            if (!later.contains(name)) {
              error(saved.keyLines().getOrDefault(name, saved.line()), "state.robots." + name, "no robot '" + name
                  + "' after the first in this cell" + (later.isEmpty() ? " (it has one robot)" : " (robots after the first: "
                  + String.join(", ", later) + ")") + "; its saved state would be lost at the next save");
            }
          }
        }
      } else if (stateJson != null) {
        error(stateJson.line(), "state", "expected an object, got " + stateJson.describe());
      }
      org.robotrun.world.VisionSetup vision = VisionJson.read(top, file, robots.stream().map(RobotSetup::name).toList(),
          objects, errors);
      if (!errors.isEmpty()) {
        errors.sort((a, b) -> Integer.compare(a.line(), b.line()));
        return new CellLoad.Failed(errors);
      }
      try {
        return new CellLoad.Loaded(new Scenario(title, description, robots, new World(objects), programs,
            mainProgram, registers, toolFrames, userFrames, camera, onCollision, mode).withWiring(wiring)
                .withProduction(production)
                .withVision(vision),
            Optional.ofNullable(state));
      } catch (IllegalArgumentException e) {
        // The checks above should catch everything; this keeps a missed case a clean error.
        return new CellLoad.Failed(List.of(new ScenarioError(file, 0, "", e.getMessage())));
      }
    }

    // ---- robots ---------------------------------------------------------------------------

    private List<RobotSetup> robots(JObject top) {
      List<RobotSetup> out = new ArrayList<>();
      JArray arr = array(top, "robots", "", true);
      if (arr == null) {
        return out;
      }
      if (arr.items().isEmpty()) {
        error(arr.line(), "robots", "expected at least one robot");
      }
      Map<String, String> folders = new java.util.HashMap<>();
      for (int i = 0; i < arr.items().size(); i++) {
        String at = "robots[" + i + "]";
        JObject r = object(arr.items().get(i), at, ROBOT);
        if (r == null) {
          continue;
        }
        String robotName = string(r, "name", at, false).orElse("robot" + (i + 1));
        int nameLine = r.keyLines().getOrDefault("name", r.line());
        defineName(robotName, at + ".name", nameLine);
        // Each robot after the first keeps its programs in programs/FOLDER/ of a workspace or hand-in
        // (Workspace.robotFolder): two names that give one folder (on any file system) would mix them.
        String folder = Workspace.robotFolder(robotName).toLowerCase(java.util.Locale.ROOT);
        String clash = folders.putIfAbsent(folder, robotName);
        if (clash != null && !clash.equals(robotName)) {
          error(nameLine, at + ".name", "robot names '" + clash + "' and '" + robotName
              + "' would share one programs folder in a workspace; give the robots names that differ in letters or digits");
        }
        if (i > 0 && folder.endsWith(".ls")) {
          // programs/LOADER.LS/ would stand where the first robot's program LOADER.LS is saved: every save would fail
          error(nameLine, at + ".name", "robot name '" + robotName + "' ends in .LS: its programs folder programs/"
              + Workspace.robotFolder(robotName) + "/ would collide with a program file; give the robot another name");
        }
        Optional<String> modelText = string(r, "model", at, true);
        Map<String, Path> packages = packages(r, at, modelText);
        Optional<RobotModel> model = packages == null ? Optional.empty() : modelText.flatMap(m -> model(m, r, at, packages));
        Transform X_CB = r.members().containsKey("basePose") ? pose(r, "basePose", at) : Transform.IDENTITY;
        EndEffectorType tool = string(r, "endEffector", at, false).map(s -> endEffector(s, r, at)).orElse(EndEffectorType.FACEPLATE);
        double[] jointsRad = joints(r, at, model);
        TreeMap<String, Integer> ioSizes = ioSizes(r, at);
        ToolIo io = toolIo(r, at, ioSizes);
        TreeMap<Integer, String> userAlarms = userAlarms(r, at);
        List<Path> ownPrograms = programs(r, at);
        Optional<String> ownMain = mainProgram(r, at);
        List<RobotSetup.Macro> macros = macros(r, at);
        TreeMap<Integer, Double> ownRegisters = registers(r, at);
        TreeMap<Integer, Transform> ownTools = new TreeMap<>();
        TreeMap<Integer, Transform> ownUsers = new TreeMap<>();
        frames(r, at, ownTools, ownUsers);
        Optional<String> ownMode = string(r, "mode", at, false).map(m -> mode(m, r, at));
        if (model.isPresent() && X_CB != null && tool != null && jointsRad != null && io != null && ioSizes != null) {
          out.add(new RobotSetup(robotName, modelKey(modelText.get()), X_CB, tool,
              Arrays.stream(jointsRad).boxed().toList(), io, ioSizes, userAlarms, ownPrograms, ownMain, macros,
              ownRegisters, ownTools, ownUsers, ownMode));
        }
      }
      return out;
    }

    /** The robot's {@code "io"} sizes ({@code {"DO": 1024}}); null after an error. */
    private TreeMap<String, Integer> ioSizes(JObject r, String at) {
      TreeMap<String, Integer> out = new TreeMap<>();
      JObject o = member(r, "io", at, null, false);
      if (o == null) {
        return r.members().containsKey("io") ? null : out;
      }
      boolean ok = true;
      for (Map.Entry<String, LocatedJson> e : o.members().entrySet()) {
        String path = join(at, "io." + e.getKey());
        int line = o.keyLines().get(e.getKey());
        try {
          IoRanges.kind(e.getKey());
        } catch (IllegalArgumentException x) {
          error(line, path, x.getMessage());
          ok = false;
          continue;
        }
        Optional<Long> n = integer(o, e.getKey(), join(at, "io"), 1, IoRanges.MAX_SIZE, true);
        n.ifPresent(size -> out.put(e.getKey(), size.intValue()));
        ok &= n.isPresent();
      }
      return ok ? out : null;
    }

    /**
     * The robot's {@code "macros"}: the macro table, {@code [{"name": "HAND1 OPEN", "program": "HOPEN"}, ...]}.
     * A name is one or more words of letters, digits and '_' (the words a TP line holds), unique in
     * the table whatever the case; the program is a program name.
     */
    private List<RobotSetup.Macro> macros(JObject r, String at) {
      List<RobotSetup.Macro> out = new ArrayList<>();
      JArray arr = array(r, "macros", at, false);
      if (arr == null) {
        return out;
      }
      java.util.Set<String> seen = new java.util.HashSet<>();
      for (int i = 0; i < arr.items().size(); i++) {
        String path = join(at, "macros[" + i + "]");
        LocatedJson v = arr.items().get(i);
        if (!(v instanceof JObject m)) {
          error(v.line(), path, "expected {\"name\": \"HAND1 OPEN\", \"program\": \"HOPEN\"}, got " + v.describe());
          continue;
        }
        for (String key : m.members().keySet()) {
          if (!key.equals("name") && !key.equals("program")) {
            error(m.keyLines().get(key), path + "." + key, "unknown field (expected name, program)");
          }
        }
        Optional<String> name = string(m, "name", path, true);
        Optional<String> program = string(m, "program", path, true);
        boolean ok = name.isPresent() && program.isPresent();
        if (name.isPresent() && name.get().length() > MAX_MACRO_NAME) {
          error(m.members().get("name").line(), path + ".name", "a macro name is at most " + MAX_MACRO_NAME
              + " characters, got " + name.get().length());
          ok = false;
        } else if (name.isPresent() && !isMacroName(name.get())) {
          error(m.members().get("name").line(), path + ".name", "expected a macro name: words of letters, digits and '_' "
              + "separated by one space (\"HAND1 OPEN\"), got \"" + name.get() + "\"");
          ok = false;
        } else if (name.isPresent() && !seen.add(name.get().toUpperCase(Locale.ROOT))) {
          error(m.members().get("name").line(), path + ".name", "macro \"" + name.get() + "\" is already in the table");
          ok = false;
        }
        if (program.isPresent() && !org.robotrun.program.Program.isValidName(program.get().toUpperCase(Locale.ROOT))) {
          error(m.members().get("program").line(), path + ".program", "expected a program name (letters, digits, '_'), got \""
              + program.get() + "\"");
          ok = false;
        }
        if (ok) {
          out.add(new RobotSetup.Macro(name.get(), program.get().toUpperCase(Locale.ROOT)));
        }
      }
      return out;
    }

    /** Words of letters, digits and '_' separated by one space, checked without a regular expression (no recursion). */
    private static boolean isMacroName(String n) {
      if (n.isEmpty() || n.startsWith(" ") || n.endsWith(" ") || n.contains("  ")) {
        return false;
      }
      return n.chars().allMatch(c -> c == ' ' || c == '_' || c < 128 && Character.isLetterOrDigit(c));
    }

    /** The robot's {@code "userAlarms"}: UALM[i] texts by number. */
    private TreeMap<Integer, String> userAlarms(JObject r, String at) {
      TreeMap<Integer, String> out = new TreeMap<>();
      JObject o = member(r, "userAlarms", at, null, false);
      if (o == null) {
        return out;
      }
      for (Map.Entry<String, LocatedJson> e : o.members().entrySet()) {
        String path = join(at, "userAlarms." + e.getKey());
        Integer n = keyIndex(e.getKey(), MAX_USER_ALARM, o.keyLines().get(e.getKey()), path, "user alarm");
        if (!(e.getValue() instanceof JString text)) {
          error(e.getValue().line(), path, "expected the alarm text as a string, got " + e.getValue().describe());
          continue;
        }
        if (n != null) {
          out.put(n, text.value());
        }
      }
      return out;
    }

    /** The robot's {@code toolIo}: default RO[1], RI[1], RI[2]; null after an error. */
    private ToolIo toolIo(JObject r, String at, Map<String, Integer> ioSizes) {
      if (!r.members().containsKey("toolIo")) {
        return ToolIo.DEFAULT;
      }
      String path = join(at, "toolIo");
      JObject t = member(r, "toolIo", at, TOOL_IO, false);
      if (t == null) {
        return null;
      }
      Integer output = port(t, "output", path, ToolIo.DEFAULT.output());
      Integer actuated = port(t, "actuated", path, ToolIo.DEFAULT.actuatedInput());
      Integer holding = port(t, "holding", path, ToolIo.DEFAULT.holdingInput());
      if (output == null || actuated == null || holding == null) {
        return null;
      }
      if (actuated.equals(holding)) {
        error(t.line(), path, "actuated and holding must be different inputs, both are RI[" + holding + "]");
        return null;
      }
      if (ioSizes != null) {
        IoRanges ranges = IoRanges.of(ioSizes);
        boolean ok = true;
        for (var p : List.of(Map.entry("output", IoKind.RO), Map.entry("actuated", IoKind.RI), Map.entry("holding", IoKind.RI))) {
          int port = p.getKey().equals("output") ? output : p.getKey().equals("actuated") ? actuated : holding;
          int size = ranges.size(p.getValue());
          if (port > size && t.members().containsKey(p.getKey())) {
            error(t.members().get(p.getKey()).line(), join(path, p.getKey()), p.getValue() + "[" + port
                + "] is beyond this robot's " + p.getValue() + "[1.." + size + "] (raise io." + p.getValue() + ")");
            ok = false;
          }
        }
        if (!ok) {
          return null;
        }
      }
      return new ToolIo(output, actuated, holding);
    }

    private Integer port(JObject o, String key, String at, int fallback) {
      if (!o.members().containsKey(key)) {
        return fallback;
      }
      return integer(o, key, at, 1, ToolIo.MAX_PORT, true).map(Long::intValue).orElse(null);
    }

    /** What a robot setup keeps of its model: the library id, or a robot file's absolute path. */
    private String modelKey(String text) {
      return RobotDefinitions.isPath(text) ? dir.resolve(text).toAbsolutePath().normalize().toString() : text;
    }

    /**
     * The robot's {@code "packages"}: package name to folder (relative to the scenario) for a
     * {@code .urdf} model's {@code package://} mesh paths; empty when absent, null after an error.
     */
    private Map<String, Path> packages(JObject r, String at, Optional<String> modelText) {
      if (!r.members().containsKey("packages")) {
        return Map.of();
      }
      String where = join(at, "packages");
      JObject o = member(r, "packages", at, null, false);
      if (o == null) {
        return null;
      }
      if (modelText.isEmpty() || !modelText.get().toLowerCase(java.util.Locale.ROOT).endsWith(".urdf")) {
        error(r.keyLines().get("packages"), where, "package folders are for a model that names a .urdf file, got model '"
            + modelText.orElse("") + "'");
        return null;
      }
      Map<String, Path> out = new TreeMap<>();
      boolean ok = true;
      for (Map.Entry<String, LocatedJson> e : o.members().entrySet()) {
        String path = join(where, e.getKey());
        if (!(e.getValue() instanceof JString folder)) {
          error(e.getValue().line(), path, "expected the package's folder as a path (relative to the scenario), got "
              + e.getValue().describe());
          ok = false;
          continue;
        }
        Path p = resolve(folder.value(), folder.line(), path);
        if (p == null) {
          ok = false;
        } else if (!Files.isDirectory(p)) {
          error(folder.line(), path, "package folder not found: " + p);
          ok = false;
        } else {
          out.put(e.getKey(), p.toAbsolutePath().normalize());
        }
      }
      return ok ? out : null;
    }

    /** The model a robot names: a library id or a robot file (relative to the scenario), via {@link RobotDefinitions#resolve}. */
    private Optional<RobotModel> model(String id, JObject r, String at, Map<String, Path> packages) {
      if (models.containsKey(id)) {
        return Optional.of(models.get(id));
      }
      if (RobotDefinitions.isFileReference(id)) {
        int line = r.members().get("model").line();
        if (confined) {
          // A hand-in carries no robot files (the hand-in reader takes cell.json, programs/ and scenarios/ only),
          // and a robot file or URDF names meshes of its own: a hand-in's robot comes from the library.
          error(line, at + ".model", "robot file '" + TerminalText.safe(id.length() > 100 ? id.substring(0, 100) + "..." : id)
              + "': a hand-in names its robot by a library id (robotrun robots lists them), not by a file");
          return Optional.empty();
        }
        Path file = resolve(id, line, at + ".model");
        if (file == null) {
          return Optional.empty();
        }
        if (file.toString().toLowerCase(java.util.Locale.ROOT).endsWith(".urdf")) {
          UrdfCache.rememberPackages(file, packages);
        }
        try {
          RobotModel m = RobotDefinitions.loadFile(file);
          models.put(id, m);
          modelRefs.put(id, file.toString());
          return Optional.of(m);
        } catch (FileFormatException e) {
          error(line, at + ".model", "cannot load robot file '" + id + "': " + e.getMessage());
          return Optional.empty();
        }
      }
      try {
        RobotModel m = RobotDefinitions.resolve(id, dir);
        models.put(id, m);
        modelRefs.put(id, m.id());
        return Optional.of(m);
      } catch (FileFormatException e) {
        int line = r.members().get("model").line();
        if (RobotDefinitions.isPath(id)) {
          error(line, at + ".model", "cannot load robot file '" + id + "': " + e.getMessage());
        } else {
          error(line, at + ".model", "unknown robot model '" + id + "': expected a library id ("
              + String.join(", ", RobotDefinitions.LIBRARY) + ") or a path to a robot .json or .urdf file");
        }
        return Optional.empty();
      } catch (java.nio.file.InvalidPathException e) {
        error(r.members().get("model").line(), at + ".model", "not a valid path: \"" + id + "\"");
        return Optional.empty();
      }
    }

    private String mode(String s, JObject o, String where) {
      if (!Scenario.MODES.contains(s)) {
        error(o.members().get("mode").line(), join(where, "mode"), "unknown mode '" + s + "': expected one of "
            + Scenario.MODES);
        return "T1";
      }
      return s;
    }

    /**
     * The first robot's registers and frames are the top-level ones or its own, not both: two
     * places for one robot's presets would leave which one wins to the reader.
     */
    private void firstRobotOnce(JObject top) {
      if (!(top.members().get("robots") instanceof JArray arr) || arr.items().isEmpty()
          || !(arr.items().get(0) instanceof JObject r0)) {
        return;
      }
      for (String key : List.of("registers", "frames")) {
        if (top.members().containsKey(key) && r0.members().containsKey(key)) {
          error(r0.keyLines().get(key), "robots[0]." + key, "the first robot's " + key + " are given at the top level too (\""
              + key + "\" at line " + top.keyLines().get(key) + "): give them in one place");
        }
      }
    }

    private CollisionResponse onCollision(String s, JObject top) {
      for (CollisionResponse c : CollisionResponse.values()) {
        if (c.fileName().equals(s)) {
          return c;
        }
      }
      error(top.members().get("onCollision").line(), "onCollision", "unknown response '" + s
          + "': expected one of " + Arrays.stream(CollisionResponse.values()).map(CollisionResponse::fileName).toList());
      return CollisionResponse.ALARM;
    }

    private EndEffectorType endEffector(String s, JObject r, String at) {
      for (EndEffectorType t : EndEffectorType.values()) {
        if (t.fileName().equals(s)) {
          return t;
        }
      }
      error(r.members().get("endEffector").line(), at + ".endEffector", "unknown end effector '" + s
          + "': expected one of " + Arrays.stream(EndEffectorType.values()).map(EndEffectorType::fileName).toList());
      return null;
    }

    private double[] joints(JObject r, String at, Optional<RobotModel> model) {
      if (!r.members().containsKey("jointsDeg")) {
        return new double[6];
      }
      String path = at + ".jointsDeg";
      double[] q = numbers(r, "jointsDeg", at, true, "an array of 6 joint angles (degrees)",
          -PoseLimits.MAX_ANGLE_DEG, PoseLimits.MAX_ANGLE_DEG, 6);
      if (q == null) {
        return null;
      }
      for (int k = 0; k < 6; k++) {
        q[k] = Math.toRadians(q[k]);
      }
      if (model.isEmpty()) {
        return q;
      }
      JArray a = (JArray) r.members().get("jointsDeg");
      RobotModel m = model.get();
      int bad = m.firstJointOutsideLimits(JointConvention.pendantToKinematic(m, q));
      if (bad >= 0) {
        error(a.items().get(bad).line(), path + "[" + bad + "]", String.format(Locale.ROOT,
            "J%d = %s deg puts the robot outside its joint limits (J%d must lie in [%.0f, %.0f] deg%s)",
            bad + 1, ((JNumber) a.items().get(bad)).text(), bad + 1,
            Math.toDegrees(m.joint(bad).lowerRad()), Math.toDegrees(m.joint(bad).upperRad()),
            m.coupledJ3() && bad == 2 ? " after adding J2: the pendant's J3 is coupled" : ""));
        return null;
      }
      return q;
    }

    // ---- objects --------------------------------------------------------------------------

    private record Parented(String name, String parent, String path, int line) {}

    private List<WorldObject> objects(JObject top) {
      List<WorldObject> out = new ArrayList<>();
      JArray arr = array(top, "objects", "", false);
      if (arr == null) {
        return out;
      }
      if (arr.items().size() > MAX_OBJECTS) {
        error(arr.line(), "objects", arr.items().size() + " objects; a scenario may hold at most " + MAX_OBJECTS);
        return out;
      }
      Map<String, ObjectKind> kinds = new LinkedHashMap<>();
      List<Parented> parented = new ArrayList<>();
      List<Parented> startParented = new ArrayList<>();
      for (int i = 0; i < arr.items().size(); i++) {
        String at = "objects[" + i + "]";
        JObject o = object(arr.items().get(i), at, OBJECT);
        if (o == null) {
          continue;
        }
        Optional<String> objName = string(o, "name", at, true).filter(n -> {
          if (n.isBlank()) {
            error(o.members().get("name").line(), at + ".name", "expected a non-empty name");
            return false;
          }
          defineName(n, at + ".name", o.members().get("name").line());
          return true;
        });
        Optional<ObjectKind> kind = string(o, "kind", at, true).flatMap(k -> switch (k) {
          case "fixture" -> Optional.of(ObjectKind.FIXTURE);
          case "part" -> Optional.of(ObjectKind.PART);
          default -> {
            error(o.members().get("kind").line(), at + ".kind", "expected \"fixture\" or \"part\", got \"" + k + "\"");
            yield Optional.empty();
          }
        });
        Shape shape = shape(o, at);
        Rgb colour = string(o, "color", at, false).map(c -> {
          Optional<Rgb> rgb = Rgb.parse(c);
          if (rgb.isEmpty()) {
            error(o.members().get("color").line(), at + ".color", "expected a colour as \"#rrggbb\", got \"" + c + "\"");
          }
          return rgb.orElse(Rgb.GREY);
        }).orElse(Rgb.GREY);
        Transform pose = pose(o, "pose", at);
        boolean touchable = bool(o, "touchable", at).orElse(false);
        Optional<String> parent = string(o, "parent", at, false);
        // Checked here, not with the other parents: the world object itself refuses it.
        boolean ownParent = objName.isPresent() && parent.isPresent() && parent.get().equals(objName.get());
        if (ownParent) {
          error(o.members().get("parent").line(), at + ".parent", "'" + objName.get() + "' cannot be its own parent");
        }
        if (objName.isPresent() && kind.isPresent()) {
          kinds.putIfAbsent(objName.get(), kind.get());
          if (!ownParent) {
            parent.ifPresent(p -> parented.add(new Parented(objName.get(), p, at + ".parent", o.members().get("parent").line())));
          }
        }
        // A saved cell whose object is not where Reset scene puts it: where it starts (issue 26).
        Transform startPose = pose;
        Optional<String> startParent = parent;
        boolean startOk = true;
        if (o.members().containsKey("startPose")) {
          startPose = pose(o, "startPose", at);
          startParent = string(o, "startParent", at, false);
          if (objName.isPresent() && startParent.isPresent() && startParent.get().equals(objName.get())) {
            error(o.members().get("startParent").line(), at + ".startParent", "'" + objName.get() + "' cannot be its own parent");
            startOk = false;
          } else if (objName.isPresent() && startParent.isPresent()) {
            startParented.add(new Parented(objName.get(), startParent.get(), at + ".startParent",
                o.members().get("startParent").line()));
          }
        } else if (o.members().containsKey("startParent")) {
          error(o.members().get("startParent").line(), at + ".startParent", "needs \"startPose\" beside it (where the object starts)");
          startOk = false;
        }
        if (objName.isPresent() && kind.isPresent() && shape != null && pose != null && !ownParent && startPose != null
            && startOk) {
          out.add(new WorldObject(objName.get(), kind.get(), shape, colour, pose, parent, startPose, startParent,
              touchable));
        }
      }
      checkParents(kinds, parented);
      checkParents(kinds, startParented);
      return out;
    }

    private void checkParents(Map<String, ObjectKind> kinds, List<Parented> parented) {
      Map<String, String> parentOf = new HashMap<>();
      for (Parented p : parented) {
        parentOf.put(p.name(), p.parent());
      }
      Set<String> inLoop = namesInLoops(parentOf);
      for (Parented p : parented) {
        ObjectKind k = kinds.get(p.parent());
        if (k == null) {
          error(p.line(), p.path(), "no object named '" + p.parent() + "' to be relative to");
        } else if (k != ObjectKind.FIXTURE) {
          error(p.line(), p.path(), "'" + p.parent() + "' is a part; only a fixture can be a parent");
        } else if (inLoop.contains(p.name())) {
          error(p.line(), p.path(), "parents form a loop through '" + p.name() + "'");
        }
      }
    }

    /**
     * The names that lie on a loop of parents, found in time linear in the number of objects:
     * each chain is walked once, and a walk stops at a name an earlier walk has finished.
     */
    private static Set<String> namesInLoops(Map<String, String> parentOf) {
      Map<String, Integer> state = new HashMap<>();  // absent: not seen, 1: on the current walk, 2: done
      Set<String> inLoop = new java.util.HashSet<>();
      List<String> walk = new ArrayList<>();
      for (String start : parentOf.keySet()) {
        walk.clear();
        String at = start;
        while (at != null && !state.containsKey(at)) {
          state.put(at, 1);
          walk.add(at);
          at = parentOf.get(at);
        }
        if (at != null && state.get(at) == 1) {
          // back on the current walk: the names from 'at' to the end form a loop
          inLoop.addAll(walk.subList(walk.indexOf(at), walk.size()));
        }
        for (String n : walk) {
          state.put(n, 2);
        }
      }
      return inLoop;
    }

    private Shape shape(JObject o, String at) {
      Optional<String> type = string(o, "shape", at, true);
      if (type.isEmpty()) {
        return null;
      }
      Set<String> own = SHAPE_FIELDS.get(type.get());
      if (own == null) {
        error(o.members().get("shape").line(), at + ".shape", "expected \"box\", \"cylinder\" or \"mesh\", got \"" + type.get() + "\"");
        return null;
      }
      for (Map.Entry<String, Set<String>> e : SHAPE_FIELDS.entrySet()) {
        for (String f : e.getValue()) {
          if (!own.contains(f) && o.members().containsKey(f)) {
            error(o.keyLines().get(f), at + "." + f, "does not apply to a " + type.get() + " (it belongs to a " + e.getKey() + ")");
          }
        }
      }
      return switch (type.get()) {
        case "box" -> {
          JObject size = member(o, "size", at, XYZ, true);
          if (size == null) {
            yield null;
          }
          Double x = positive(size, "x", at + ".size", true, MAX_LENGTH_MM).orElse(null);
          Double y = positive(size, "y", at + ".size", true, MAX_LENGTH_MM).orElse(null);
          Double z = positive(size, "z", at + ".size", true, MAX_LENGTH_MM).orElse(null);
          yield x == null || y == null || z == null ? null : new Shape.Box(x, y, z);
        }
        case "cylinder" -> {
          Double r = positive(o, "radius", at, true, MAX_LENGTH_MM).orElse(null);
          Double h = positive(o, "height", at, true, MAX_LENGTH_MM).orElse(null);
          yield r == null || h == null ? null : new Shape.Cylinder(r, h);
        }
        default -> mesh(o, at);
      };
    }

    private Shape mesh(JObject o, String at) {
      Double scale = o.members().containsKey("scale") ? positive(o, "scale", at, true, MAX_LENGTH_MM).orElse(null) : Double.valueOf(1);
      Optional<String> rel = string(o, "file", at, true);
      if (rel.isEmpty() || scale == null) {
        return null;
      }
      int line = o.members().get("file").line();
      Path meshFile = resolve(rel.get(), line, at + ".file");
      if (meshFile == null) {
        return null;
      }
      if (!Files.exists(meshFile)) {
        error(line, at + ".file", "mesh file not found: " + meshFile + " (paths are relative to the scenario file)");
        return null;
      }
      try {
        return new Shape.Mesh(meshFile, scale, StlReader.read(meshFile, scale));
      } catch (FileFormatException e) {
        error(line, at + ".file", "bad mesh: " + e.getMessage());
      } catch (UnreadableFileException e) {
        error(line, at + ".file", "cannot read mesh " + meshFile + ": " + e.getMessage());
      } catch (IOException e) {
        error(line, at + ".file", "cannot read mesh " + meshFile + ": " + e.getMessage());
      }
      return null;
    }

    // ---- programs, registers, frames, camera ----------------------------------------------

    /** The {@code "programs"} of the top level ({@code where} "") or of a robot ("robots[1]"). */
    private List<Path> programs(JObject top, String where) {
      List<Path> out = new ArrayList<>();
      JArray arr = array(top, "programs", where, false);
      if (arr == null) {
        return out;
      }
      for (int i = 0; i < arr.items().size(); i++) {
        String at = join(where, "programs[" + i + "]");
        LocatedJson v = arr.items().get(i);
        if (!(v instanceof JString s)) {
          error(v.line(), at, "expected a path to a .LS file, got " + v.describe());
          continue;
        }
        Path p = resolve(s.value(), v.line(), at);
        if (p == null) {
          continue;
        }
        if (!s.value().toLowerCase(Locale.ROOT).endsWith(".ls")) {
          error(v.line(), at, "expected a .LS program file, got \"" + s.value() + "\"");
        } else if (!Files.exists(p)) {
          error(v.line(), at, "program file not found: " + p + " (paths are relative to the scenario file)");
        } else if (!Files.isRegularFile(p)) {
          error(v.line(), at, "program file " + p + " is not a regular file");
        } else {
          out.add(p);
        }
      }
      return out;
    }

    /** The {@code "mainProgram"} of the top level ({@code where} "") or of a robot; it must be one of the same object's programs. */
    private Optional<String> mainProgram(JObject top, String where) {
      Optional<String> main = string(top, "mainProgram", where, false);
      if (main.isEmpty()) {
        return main;
      }
      int line = top.members().get("mainProgram").line();
      boolean listed = false;
      JArray listedPrograms = top.members().get("programs") instanceof JArray a ? a : null;
      if (listedPrograms != null) {
        for (LocatedJson v : listedPrograms.items()) {
          if (v instanceof JString s && programName(s.value()).equalsIgnoreCase(main.get())) {
            listed = true;
          }
        }
      }
      if (!listed && !workspace) {
        error(line, join(where, "mainProgram"), "'" + main.get() + "' is not one of the programs listed in \""
            + join(where, "programs") + "\"");
        return Optional.empty();
      }
      return Optional.of(main.get().toUpperCase(Locale.ROOT));
    }

    /** {@code rel} against the scenario's folder, or null with an error when it is not a path. */
    private Path resolve(String rel, int line, String path) {
      Path p;
      try {
        p = dir.resolve(rel).normalize();
      } catch (InvalidPathException e) {
        error(line, path, "not a valid path: \"" + rel + "\"");
        return null;
      }
      if (confined && (!p.startsWith(dir) || throughLink(p))) {
        error(line, path, "\"" + TerminalText.safe(rel.length() > 100 ? rel.substring(0, 100) + "..." : rel)
            + "\" is outside the hand-in: a hand-in's files are read only from inside it");
        return null;
      }
      return p;
    }

    /** Whether a folder or file on the way from {@link #dir} to {@code p} is a symbolic link. */
    private boolean throughLink(Path p) {
      for (Path q = p; q != null && q.startsWith(dir) && !q.equals(dir); q = q.getParent()) {
        if (Files.isSymbolicLink(q)) {
          return true;
        }
      }
      return false;
    }

    private static String programName(String path) {
      String base = path.substring(Math.max(path.lastIndexOf('/'), path.lastIndexOf('\\')) + 1);
      int dot = base.lastIndexOf('.');
      return dot < 0 ? base : base.substring(0, dot);
    }

    /** The {@code "registers"} of the top level ({@code where} "") or of a robot ("robots[1]"). */
    private TreeMap<Integer, Double> registers(JObject top, String where) {
      TreeMap<Integer, Double> out = new TreeMap<>();
      JObject regs = member(top, "registers", where, null, false);
      if (regs == null) {
        return out;
      }
      for (Map.Entry<String, LocatedJson> e : regs.members().entrySet()) {
        String at = join(where, "registers." + e.getKey());
        Integer index = keyIndex(e.getKey(), MAX_REGISTER, regs.keyLines().get(e.getKey()), at, "register");
        Double v = finite(regs, e.getKey(), join(where, "registers"), true).orElse(null);
        if (index != null && v != null) {
          out.put(index, v);
        }
      }
      return out;
    }

    /** The {@code "frames"} of the top level ({@code where} "") or of a robot ("robots[1]"). */
    private void frames(JObject top, String where, Map<Integer, Transform> tool, Map<Integer, Transform> user) {
      JObject frames = member(top, "frames", where, Set.of("tool", "user"), false);
      if (frames == null) {
        return;
      }
      for (String kind : List.of("tool", "user")) {
        JObject set = member(frames, kind, join(where, "frames"), null, false);
        if (set == null) {
          continue;
        }
        for (String key : set.members().keySet()) {
          String at = join(where, "frames." + kind + "." + key);
          Integer n = keyIndex(key, MAX_FRAME, set.keyLines().get(key), at, kind + " frame");
          Transform pose = pose(set, key, join(where, "frames." + kind));
          if (n != null && pose != null) {
            (kind.equals("tool") ? tool : user).put(n, pose);
          }
        }
      }
    }

    private Optional<CameraView> camera(JObject top) {
      JObject c = member(top, "camera", "", CAMERA, false);
      if (c == null) {
        return Optional.empty();
      }
      JObject target = member(c, "target", "camera", XYZ, true);
      double lim = MAX_LENGTH_MM;
      Double x = target == null ? null : number(target, "x", "camera.target", true, -lim, lim).orElse(null);
      Double y = target == null ? null : number(target, "y", "camera.target", true, -lim, lim).orElse(null);
      Double z = target == null ? null : number(target, "z", "camera.target", true, -lim, lim).orElse(null);
      Double distance = positive(c, "distance", "camera", true, lim).orElse(null);
      double maxDeg = PoseLimits.MAX_ANGLE_DEG;
      Double yaw = c.members().containsKey("yawDeg") ? number(c, "yawDeg", "camera", true, -maxDeg, maxDeg).orElse(null) : Double.valueOf(0);
      Double pitch = c.members().containsKey("pitchDeg") ? number(c, "pitchDeg", "camera", true, -89, 89).orElse(null) : Double.valueOf(30);
      if (x == null || y == null || z == null || distance == null || yaw == null || pitch == null) {
        return Optional.empty();
      }
      return Optional.of(new CameraView(new Vec3(x, y, z), distance, Math.toRadians(yaw), Math.toRadians(pitch)));
    }

    // ---- typed access that records errors ---------------------------------------------------

    private void defineName(String name, String path, int line) {
      if (name.length() > MAX_NAME_LENGTH) {
        error(line, path, "a name is at most " + MAX_NAME_LENGTH + " characters, got " + name.length());
        return;
      }
      String first = definedAt.putIfAbsent(name, path + " (line " + line + ")");
      if (first != null) {
        error(line, path, "duplicate name '" + name + "': already used by " + first.replace(".name", ""));
      }
    }

    /** A pose object {x, y, z (mm), w, p, r (deg, default 0)}; null with errors when bad. */
    private Transform pose(JObject o, String key, String at) {
      JObject p = member(o, key, at, POSE, true);
      if (p == null) {
        return null;
      }
      String path = join(at, key);
      double[] v = new double[6];
      boolean ok = true;
      String[] names = {"x", "y", "z", "w", "p", "r"};
      for (int k = 0; k < 6; k++) {
        double lim = k < 3 ? MAX_LENGTH_MM : PoseLimits.MAX_ANGLE_DEG;
        Double d = k < 3 || p.members().containsKey(names[k]) ? number(p, names[k], path, true, -lim, lim).orElse(null) : Double.valueOf(0);
        ok &= d != null;
        v[k] = d == null ? 0 : d;
      }
      return ok ? Xyzwpr.ofDegrees(v[0], v[1], v[2], v[3], v[4], v[5]).toTransform() : null;
    }
  }
}
