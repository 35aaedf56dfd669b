package org.robotrun.grade;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.Set;
import java.util.regex.Pattern;
import org.robotrun.io.JsonFieldReader;
import org.robotrun.io.LocatedJson;
import org.robotrun.io.LocatedJson.JArray;
import org.robotrun.io.LocatedJson.JObject;
import org.robotrun.io.LocatedJson.JString;
import org.robotrun.io.ScenarioError;
import org.robotrun.io.ScenarioLoad;
import org.robotrun.io.ScenarioReader;
import org.robotrun.math.PoseLimits;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Scenario;
import org.robotrun.world.WorldObject;

/**
 * Reads task files ({@code "format": 1}, docs/grading.md) as strictly as scenarios are read:
 * unknown fields, wrong types, out-of-range numbers, duplicate check names and parts or fixtures
 * the scenario does not have are each reported with file, line and JSON path. The task's
 * scenario is loaded too; its errors are the task's.
 */
public final class TaskReader {
  public static final int FORMAT = 1;
  /** Largest task file accepted. */
  public static final long MAX_FILE_BYTES = 1L << 20;
  /** Most variations a task may ask for. */
  public static final int MAX_VARIATIONS = 100;

  private static final Set<String> TOP = Set.of(
      "format", "title", "scenario", "program", "robots", "limits", "variations", "checks", "autograder");
  private static final Set<String> AUTOGRADER = Set.of("hiddenVisibility", "leaderboard");
  private static final Set<String> ROBOT = Set.of("program");
  /** The check types that look at one robot (the others look at the whole cell). */
  private static final Set<String> ROBOT_TYPES = Set.of("runsToEnd", "noMotionStop", "cycleTime", "programUse",
      "endState", "frame");
  private static final Set<String> LIMITS = Set.of("simSeconds", "wallSeconds");
  private static final Set<String> VARIATIONS = Set.of("count", "seed", "overridePct", "parts", "varyVisionSeed");
  private static final Set<String> OVERRIDE = Set.of("min", "max");
  private static final Set<String> JITTER = Set.of("part", "xMm", "yMm", "rDeg", "offsetRegister");
  private static final Set<String> COMMON = Set.of("name", "type", "points", "message", "hidden", "runs");
  private static final Map<String, Set<String>> TYPES = new LinkedHashMap<>();
  private static final Pattern REGISTER = Pattern.compile("(R|F|DO|DI|RO|RI|GO|GI)\\[([1-9][0-9]{0,3})\\]");

  static {
    TYPES.put("handIn", Set.of());
    TYPES.put("programs", Set.of());
    TYPES.put("runsToEnd", Set.of("alarm"));
    TYPES.put("partAt", Set.of("part", "fixture", "position", "toleranceMm", "rDeg", "toleranceDeg"));
    TYPES.put("nothingHeld", Set.of());
    TYPES.put("noneDropped", Set.of());
    TYPES.put("noCollision", Set.of("maxWarnings"));
    TYPES.put("noMotionStop", Set.of());
    TYPES.put("cycleTime", Set.of("maxSec"));
    TYPES.put("programUse", Set.of("requires", "forbids", "maxMotionLines"));
    TYPES.put("endState", Set.of("values", "tolerance"));
    TYPES.put("frame", Set.of("frame", "pose", "toleranceMm", "toleranceDeg"));
    TYPES.put("positionRegister", Set.of("register", "position", "toleranceMm"));
    TYPES.put("tcpVisits", Set.of("targets", "toleranceMm"));
  }

  private TaskReader() {}

  /** Reads a task and its scenario. Never throws for bad content. */
  public static TaskLoad read(Path file) {
    String name = file.toString();
    String text;
    try {
      // Bounded, counted from the stream, and a regular file only (a FIFO does not block).
      byte[] bytes = org.robotrun.io.BoundedFiles.read(file, MAX_FILE_BYTES, "task files");
      text = StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(bytes)).toString();
      if (text.startsWith("\uFEFF")) {
        text = text.substring(1);
      }
    } catch (org.robotrun.io.UnreadableFileException e) {
      return fail(name, e.getMessage());  // "no such file", "a named pipe (FIFO), not a regular file", the limit
    } catch (CharacterCodingException e) {
      return fail(name, "not UTF-8 text");
    } catch (IOException e) {
      return fail(name, "cannot read: " + e.getMessage());
    }
    return new Session(name, file.toAbsolutePath().normalize().getParent()).read(text);
  }

  private static TaskLoad fail(String file, String message) {
    return new TaskLoad.Failed(List.of(new ScenarioError(file, 0, "", message)));
  }

  /** One read: the file and the errors found so far. */
  private static final class Session extends JsonFieldReader {
    private final Path dir;

    Session(String file, Path dir) {
      super(file);
      this.dir = dir;
    }

    TaskLoad read(String text) {
      JObject top = topObject(text, TOP);
      if (top == null) {
        return new TaskLoad.Failed(errors);
      }
      format(top, FORMAT);
      String title = string(top, "title", "", false).orElse("");
      Scenario scenario = scenario(top);
      String program = string(top, "program", "", false).map(s -> s.toUpperCase(Locale.ROOT))
          // As robotrun run: the first robot's own mainProgram, else the scenario's.
          .or(() -> scenario == null ? Optional.empty() : scenario.preload(0).mainProgram())
          .map(s -> s.toUpperCase(Locale.ROOT)).orElse(null);
      Map<String, String> others = robots(top, scenario, program);
      Task.Limits limits = limits(top);
      Task.Variations variations = variations(top, scenario);
      List<Check> checks = checks(top, scenario);
      Task.Autograder autograder = autograder(top);
      // A task whose checks look only at files, frames and recorded registers runs nothing (a pendant lab).
      boolean runs = checks.stream().anyMatch(c -> !(c instanceof Check.HandIn || c instanceof Check.ProgramsCheck
          || c instanceof Check.ProgramUse || c instanceof Check.Frame || c instanceof Check.PositionRegister));
      if (program == null && scenario != null) {
        if (runs) {
          error(top.line(), "program", "missing: name the program to run (the scenario names no main program)");
        } else {
          program = "";
        }
      }
      if (!errors.isEmpty() || scenario == null) {
        return new TaskLoad.Failed(errors);
      }
      Path scenarioFile = dir.resolve(((JString) top.members().get("scenario")).value()).normalize();
      return new TaskLoad.Loaded(new Task(file, title, scenarioFile, program, limits, variations, checks, others,
          autograder),
          scenario);
    }

    private Scenario scenario(JObject top) {
      Optional<String> rel = string(top, "scenario", "", true);
      if (rel.isEmpty()) {
        return null;
      }
      int line = top.members().get("scenario").line();
      Path p;
      try {
        p = dir.resolve(rel.get()).normalize();
      } catch (InvalidPathException e) {
        error(line, "scenario", "not a valid path: \"" + rel.get() + "\"");
        return null;
      }
      if (!Files.exists(p)) {
        error(line, "scenario", "scenario file not found: " + p + " (paths are relative to the task file)");
        return null;
      }
      try {
        org.robotrun.io.BoundedFiles.requireRegularFile(p);  // a device or FIFO is named, never opened
      } catch (org.robotrun.io.UnreadableFileException e) {
        error(line, "scenario", "cannot read the scenario " + p + ": " + e.getMessage());
        return null;
      }
      return switch (ScenarioReader.read(p)) {
        case ScenarioLoad.Loaded l -> l.scenario();
        case ScenarioLoad.Failed f -> {
          errors.addAll(f.errors());
          yield null;
        }
      };
    }

    /**
     * The program of each robot after the first: {@code robots.NAME.program}, else that robot's
     * {@code mainProgram} in the scenario; a robot with neither does not run. The first robot's
     * is {@code program}.
     */
    private Map<String, String> robots(JObject top, Scenario scenario, String program) {
      JObject o = member(top, "robots", "", null, false);
      Map<String, String> given = new LinkedHashMap<>();
      if (o != null && scenario != null) {
        List<String> names = scenario.robots().stream().map(r -> r.name()).toList();
        for (Map.Entry<String, LocatedJson> e : o.members().entrySet()) {
          String at = "robots." + e.getKey();
          int line = o.keyLines().get(e.getKey());
          if (!names.contains(e.getKey())) {
            error(line, at, "the scenario has no robot \"" + e.getKey() + "\" (robots: " + String.join(", ", names) + ")");
            continue;
          }
          if (e.getKey().equals(names.get(0))) {
            error(line, at, "the first robot's program is the task's \"program\"; list only the robots after it here");
            continue;
          }
          JObject r = object(e.getValue(), at, ROBOT);
          if (r != null) {
            string(r, "program", at, true).ifPresent(p -> given.put(e.getKey(), p.toUpperCase(Locale.ROOT)));
          }
        }
      }
      Map<String, String> out = new LinkedHashMap<>();
      if (scenario != null) {
        for (int i = 1; i < scenario.robots().size(); i++) {
          var r = scenario.robots().get(i);
          Optional<String> p = Optional.ofNullable(given.get(r.name())).or(r::mainProgram);
          p.ifPresent(x -> out.put(r.name(), x.toUpperCase(Locale.ROOT)));
        }
      }
      return out;
    }

    private Task.Autograder autograder(JObject top) {
      JObject o = member(top, "autograder", "", AUTOGRADER, false);
      if (o == null) {
        return Task.Autograder.DEFAULT;
      }
      String hidden = string(o, "hiddenVisibility", "autograder", false).orElse(Task.Autograder.DEFAULT.hiddenVisibility());
      if (!Task.Autograder.HIDDEN_VISIBILITIES.contains(hidden)) {
        error(o.members().get("hiddenVisibility").line(), "autograder.hiddenVisibility", "expected one of "
            + String.join(", ", Task.Autograder.HIDDEN_VISIBILITIES) + " (Gradescope's visibilities), got \"" + hidden + "\"");
      }
      boolean leaderboard = bool(o, "leaderboard", "autograder").orElse(false);
      return new Task.Autograder(hidden, leaderboard);
    }

    private Task.Limits limits(JObject top) {
      JObject o = member(top, "limits", "", LIMITS, false);
      if (o == null) {
        return Task.Limits.DEFAULT;
      }
      double sim = number(o, "simSeconds", "limits", false, 0.1, 3600).orElse(Task.Limits.DEFAULT.simSeconds());
      double wall = number(o, "wallSeconds", "limits", false, 0.1, 3600).orElse(Task.Limits.DEFAULT.wallSeconds());
      return new Task.Limits(sim, wall);
    }

    private Task.Variations variations(JObject top, Scenario scenario) {
      JObject o = member(top, "variations", "", VARIATIONS, false);
      if (o == null) {
        return Task.Variations.NONE;
      }
      int count = integer(o, "count", "variations", 0, MAX_VARIATIONS, true).orElse(0L).intValue();
      long seed = integer(o, "seed", "variations", 0, Long.MAX_VALUE >> 11, false).orElse(0L);
      int min = 100;
      int max = 100;
      JObject ov = member(o, "overridePct", "variations", OVERRIDE, false);
      if (ov != null) {
        min = integer(ov, "min", "variations.overridePct", 1, 100, true).orElse(100L).intValue();
        max = integer(ov, "max", "variations.overridePct", 1, 100, true).orElse(100L).intValue();
        if (min > max) {
          error(ov.line(), "variations.overridePct", "min " + min + " is above max " + max);
        }
      }
      List<Task.PartJitter> parts = new ArrayList<>();
      JArray arr = array(o, "parts", "variations", false);
      Set<String> seen = new HashSet<>();
      Set<Integer> registers = new HashSet<>();
      for (int i = 0; arr != null && i < arr.items().size(); i++) {
        String at = "variations.parts[" + i + "]";
        JObject j = object(arr.items().get(i), at, JITTER);
        if (j == null) {
          continue;
        }
        Optional<String> part = string(j, "part", at, true);
        part.ifPresent(p -> {
          checkObject(scenario, p, ObjectKind.PART, j.members().get("part").line(), at + ".part");
          if (!seen.add(p)) {
            error(j.members().get("part").line(), at + ".part", "part '" + p + "' is jittered twice");
          }
        });
        double x = number(j, "xMm", at, false, 0, 1000).orElse(0.0);
        double y = number(j, "yMm", at, false, 0, 1000).orElse(0.0);
        double r = number(j, "rDeg", at, false, 0, 180).orElse(0.0);
        Optional<Integer> reg = integer(j, "offsetRegister", at, 1, org.robotrun.program.Registers.PR_COUNT, false)
            .map(Long::intValue);
        reg.ifPresent(n -> {
          if (!registers.add(n)) {
            error(j.members().get("offsetRegister").line(), at + ".offsetRegister", "PR[" + n + "] is used twice");
          }
        });
        parts.add(new Task.PartJitter(part.orElse(""), x, y, r, reg));
      }
      boolean varyVision = bool(o, "varyVisionSeed", "variations").orElse(false);
      if (varyVision && scenario != null && scenario.vision().placements().isEmpty()) {
        error(o.members().get("varyVisionSeed").line(), "variations.varyVisionSeed", "the scenario has no vision "
            + "placements: another vision seed would move nothing (docs/vision.md, \"placements\")");
        varyVision = false;
      }
      return new Task.Variations(count, seed, parts, min, max, varyVision);
    }

    private List<Check> checks(JObject top, Scenario scenario) {
      List<Check> out = new ArrayList<>();
      JArray arr = array(top, "checks", "", false);
      if (arr == null) {
        if (!top.members().containsKey("checks")) {
          error(top.line(), "checks", "missing: expected an array of checks");
        }
        return out;
      }
      if (arr.items().isEmpty()) {
        error(arr.line(), "checks", "expected at least one check");
      }
      Set<String> names = new HashSet<>();
      for (int i = 0; i < arr.items().size(); i++) {
        String at = "checks[" + i + "]";
        LocatedJson v = arr.items().get(i);
        if (!(v instanceof JObject o)) {
          error(v.line(), at, "expected an object, got " + v.describe());
          continue;
        }
        Optional<String> type = string(o, "type", at, true);
        if (type.isEmpty()) {
          continue;
        }
        Set<String> extra = TYPES.get(type.get());
        if (extra == null) {
          error(o.members().get("type").line(), at + ".type", "unknown check type \"" + type.get()
              + "\" (expected one of: " + String.join(", ", TYPES.keySet()) + ")");
          continue;
        }
        Set<String> allowed = new HashSet<>(COMMON);
        allowed.addAll(extra);
        if (ROBOT_TYPES.contains(type.get()) || o.members().containsKey("robot")) {
          // A cell-wide check given a robot gets its own message below, not "unknown field".
          allowed.add("robot");
        }
        object(o, at, allowed);
        Optional<String> name = string(o, "name", at, true);
        name.ifPresent(n -> {
          if (n.isBlank() || n.length() > 80) {
            error(o.members().get("name").line(), at + ".name", "expected a name of 1 to 80 characters");
          } else if (!names.add(n)) {
            error(o.members().get("name").line(), at + ".name", "check name \"" + n + "\" is used twice");
          }
        });
        double points = number(o, "points", at, false, 0, 10000).orElse(0.0);
        if (!o.members().containsKey("points")) {
          error(o.line(), at + ".points", "missing: expected a number of points (0 or more)");
        }
        String message = string(o, "message", at, false).orElse("");
        boolean hidden = bool(o, "hidden", at).orElse(false);
        Check.Runs runs = string(o, "runs", at, false).map(s -> runs(s, o.members().get("runs").line(), at))
            .orElse(Check.Runs.NOMINAL);
        Optional<String> robot = string(o, "robot", at, false);
        if (robot.isPresent() && scenario != null) {
          int line = o.members().get("robot").line();
          List<String> robots = scenario.robots().stream().map(r -> r.name()).toList();
          if (!ROBOT_TYPES.contains(type.get())) {
            error(line, at + ".robot", "a " + type.get() + " check looks at the whole cell; \"robot\" is for "
                + String.join(", ", ROBOT_TYPES.stream().sorted().toList()) + " checks");
          } else if (!robots.contains(robot.get())) {
            error(line, at + ".robot", "the scenario has no robot \"" + robot.get() + "\" (robots: "
                + String.join(", ", robots) + ")");
          }
        }
        Check.Meta meta = new Check.Meta(name.orElse(""), points, message, hidden, runs, robot);
        Check c = check(type.get(), meta, o, at, scenario);
        if (c != null) {
          out.add(c);
        }
      }
      return out;
    }

    private Check.Runs runs(String s, int line, String at) {
      return switch (s) {
        case "nominal" -> Check.Runs.NOMINAL;
        case "variations" -> Check.Runs.VARIATIONS;
        case "all" -> Check.Runs.ALL;
        default -> {
          error(line, at + ".runs", "expected \"nominal\", \"variations\" or \"all\", got \"" + s + "\"");
          yield Check.Runs.NOMINAL;
        }
      };
    }

    private Check check(String type, Check.Meta m, JObject o, String at, Scenario scenario) {
      return switch (type) {
        case "handIn" -> new Check.HandIn(m);
        case "programs" -> new Check.ProgramsCheck(m);
        case "runsToEnd" -> new Check.RunsToEnd(m, string(o, "alarm", at, false));
        case "partAt" -> {
          Optional<String> part = string(o, "part", at, true);
          Optional<String> fixture = string(o, "fixture", at, true);
          part.ifPresent(p -> checkObject(scenario, p, ObjectKind.PART, o.members().get("part").line(), at + ".part"));
          fixture.ifPresent(f -> checkObject(scenario, f, ObjectKind.FIXTURE, o.members().get("fixture").line(),
              at + ".fixture"));
          Vec3 p = position(o, at);
          double tol = number(o, "toleranceMm", at, false, 0, 1000).orElse(2.0);
          Optional<Double> r = number(o, "rDeg", at, false, -180, 180);
          double tolDeg = number(o, "toleranceDeg", at, false, 0, 180).orElse(5.0);
          yield new Check.PartAt(m, part.orElse(""), fixture.orElse(""), p, tol, r, tolDeg);
        }
        case "nothingHeld" -> new Check.NothingHeld(m);
        case "noneDropped" -> new Check.NoneDropped(m);
        case "noCollision" -> new Check.NoCollision(m, integer(o, "maxWarnings", at, 0, 1000, false).orElse(0L).intValue());
        case "noMotionStop" -> new Check.NoMotionStop(m);
        case "cycleTime" -> new Check.CycleTime(m, number(o, "maxSec", at, false, 0.001, 3600).orElseGet(() -> {
          if (!o.members().containsKey("maxSec")) {
            error(o.line(), at + ".maxSec", "missing: expected the longest cycle time allowed, in seconds");
          }
          return 0.0;
        }));
        case "programUse" -> {
          Set<Check.Feature> requires = features(o, "requires", at);
          Set<Check.Feature> forbids = features(o, "forbids", at);
          OptionalInt max = integer(o, "maxMotionLines", at, 0, 100000, false)
              .map(l -> OptionalInt.of(l.intValue())).orElse(OptionalInt.empty());
          yield new Check.ProgramUse(m, requires, forbids, max);
        }
        case "endState" -> new Check.EndState(m, values(o, at), number(o, "tolerance", at, false, 0, 1e6).orElse(1e-6));
        case "frame" -> frame(m, o, at);
        case "tcpVisits" ->
            new Check.TcpVisits(m, points(o, at), number(o, "toleranceMm", at, false, 0, 1000).orElse(2.0));
        case "positionRegister" -> {
          long n = integer(o, "register", at, 1, 100, true).orElse(1L);
          Vec3 p = position(o, at);
          yield new Check.PositionRegister(m, (int) n, p, number(o, "toleranceMm", at, false, 0, 1000).orElse(1.0));
        }
        default -> throw new IllegalStateException(type);
      };
    }

    private Check frame(Check.Meta m, JObject o, String at) {
      Optional<String> f = string(o, "frame", at, true);
      boolean tool = false;
      int number = 1;
      if (f.isPresent()) {
        var matcher = Pattern.compile("(UT|UF)\\[([1-9]|10)\\]").matcher(f.get());
        if (matcher.matches()) {
          tool = matcher.group(1).equals("UT");
          number = Integer.parseInt(matcher.group(2));
        } else {
          error(o.members().get("frame").line(), at + ".frame", "expected UT[n] or UF[n] with n 1..10, got \""
              + f.get() + "\"");
        }
      }
      JObject p = member(o, "pose", at, Set.of("x", "y", "z", "w", "p", "r"), false);
      double[] v = new double[6];
      if (p == null) {
        error(o.line(), at + ".pose", "missing: expected the true frame {x, y, z, w, p, r} (mm, deg)");
      } else {
        String[] keys = {"x", "y", "z", "w", "p", "r"};
        for (int k = 0; k < 6; k++) {
          double lim = k < 3 ? PoseLimits.MAX_COORDINATE_MM : 180;
          v[k] = number(p, keys[k], at + ".pose", false, -lim, lim).orElse(0.0);
        }
      }
      double tolMm = number(o, "toleranceMm", at, false, 0, 1000).orElse(1.0);
      double tolDeg = number(o, "toleranceDeg", at, false, 0, 180).orElse(1.0);
      return new Check.Frame(m, tool, number, Xyzwpr.ofDegrees(v[0], v[1], v[2], v[3], v[4], v[5]).toTransform(),
          tolMm, tolDeg);
    }

    private List<Vec3> points(JObject o, String at) {
      LocatedJson v = o.members().get("targets");
      List<Vec3> out = new ArrayList<>();
      if (!(v instanceof LocatedJson.JArray a) || a.items().isEmpty()) {
        error(v == null ? o.line() : v.line(), at + ".targets", "expected a non-empty array of {x, y, z} (mm, WORLD)");
        return out;
      }
      double lim = PoseLimits.MAX_COORDINATE_MM;
      for (int i = 0; i < a.items().size(); i++) {
        String pat = at + ".targets[" + i + "]";
        JObject q = object(a.items().get(i), pat, Set.of("x", "y", "z"));
        if (q == null) {
          continue;
        }
        out.add(new Vec3(number(q, "x", pat, false, -lim, lim).orElse(0.0),
            number(q, "y", pat, false, -lim, lim).orElse(0.0), number(q, "z", pat, false, -lim, lim).orElse(0.0)));
      }
      return out;
    }

    private Vec3 position(JObject o, String at) {
      JObject p = member(o, "position", at, Set.of("x", "y", "z"), false);
      if (p == null) {
        error(o.line(), at + ".position", "missing: expected {x, y, z} in mm, in the fixture's frame");
        return Vec3.ZERO;
      }
      double lim = PoseLimits.MAX_COORDINATE_MM;
      return new Vec3(number(p, "x", at + ".position", false, -lim, lim).orElse(0.0),
          number(p, "y", at + ".position", false, -lim, lim).orElse(0.0),
          number(p, "z", at + ".position", false, -lim, lim).orElse(0.0));
    }

    private Set<Check.Feature> features(JObject o, String key, String at) {
      Set<Check.Feature> out = EnumSet.noneOf(Check.Feature.class);
      JArray arr = array(o, key, at, false);
      for (int i = 0; arr != null && i < arr.items().size(); i++) {
        LocatedJson v = arr.items().get(i);
        String path = at + "." + key + "[" + i + "]";
        if (!(v instanceof JString s)) {
          error(v.line(), path, "expected a feature name, got " + v.describe());
          continue;
        }
        Check.Feature.byKey(s.value()).ifPresentOrElse(out::add, () -> error(v.line(), path,
            "unknown feature \"" + s.value() + "\" (expected one of: " + String.join(", ", Check.Feature.keys()) + ")"));
      }
      return out;
    }

    private Map<String, Double> values(JObject o, String at) {
      Map<String, Double> out = new LinkedHashMap<>();
      JObject vals = member(o, "values", at, null, false);
      if (vals == null) {
        error(o.line(), at + ".values", "missing: expected {\"R[1]\": 3, \"DO[2]\": true, ...}");
        return out;
      }
      for (Map.Entry<String, LocatedJson> e : vals.members().entrySet()) {
        String path = at + ".values." + e.getKey();
        int line = vals.keyLines().get(e.getKey());
        var mt = REGISTER.matcher(e.getKey());
        if (!mt.matches()) {
          error(line, path, "expected a name like R[1], F[2], DO[3], RO[1], GO[1]");
          continue;
        }
        boolean bit = !mt.group(1).equals("R") && !mt.group(1).startsWith("G");
        Optional<Double> v = bit ? bool(vals, e.getKey(), at + ".values").map(b -> b ? 1.0 : 0.0)
            : finite(vals, e.getKey(), at + ".values", true);
        v.ifPresent(x -> out.put(e.getKey(), x));
      }
      return out;
    }

    private void checkObject(Scenario scenario, String name, ObjectKind kind, int line, String path) {
      if (scenario == null) {
        return;
      }
      Optional<WorldObject> o = scenario.world().find(name);
      if (o.isEmpty() || o.get().kind() != kind) {
        error(line, path, "the scenario has no " + kind.name().toLowerCase(Locale.ROOT) + " named '" + name + "'");
      }
    }
  }
}
