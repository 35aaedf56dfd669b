package org.robotrun.io;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.robotrun.io.LocatedJson.JArray;
import org.robotrun.io.LocatedJson.JNumber;
import org.robotrun.io.LocatedJson.JObject;
import org.robotrun.io.LocatedJson.JString;
import org.robotrun.math.PoseLimits;
import org.robotrun.program.Config;
import org.robotrun.program.IoKind;
import org.robotrun.program.Position;
import org.robotrun.program.Registers;
import org.robotrun.sim.FrameTable;

/**
 * The {@code "state"} section of a workspace's {@code cell.json} ({@link SavedState}): written
 * by {@link ScenarioWriter}, read by {@link ScenarioReader} with a JSON path and line for every
 * problem.
 */
final class StateJson {
  private static final Set<String> FIELDS = Set.of(
      "overridePct", "utool", "uframe", "registers", "positionRegisters", "outputs", "comments", "created", "toolFrames", "userFrames", "robots", "stringRegisters");
  private static final Set<String> CARTESIAN = Set.of("x", "y", "z", "w", "p", "r", "config");
  private static final Set<String> JOINT = Set.of("joints");
  private static final Pattern CONFIG = Pattern.compile(
      "\\s*([NF])\\s+([UD])\\s+([TB])\\s*,\\s*(-?\\d+)\\s*,\\s*(-?\\d+)\\s*,\\s*(-?\\d+)\\s*");

  private StateJson() {}

  // ---- writing --------------------------------------------------------------------------------

  static void write(JsonGenerator g, SavedState s) throws IOException {
    g.writeObjectFieldStart("state");
    writeFields(g, s);
    g.writeEndObject();
  }

  private static void writeFields(JsonGenerator g, SavedState s) throws IOException {
    if (!s.created().isEmpty()) {
      g.writeStringField("created", s.created());
    }
    if (s.overridePct() > 0) {
      g.writeNumberField("overridePct", s.overridePct());
    }
    if (s.activeTool() >= 0) {
      g.writeNumberField("utool", s.activeTool());
    }
    if (s.activeUser() >= 0) {
      g.writeNumberField("uframe", s.activeUser());
    }
    if (!s.registers().isEmpty()) {
      g.writeObjectFieldStart("registers");
      for (Map.Entry<Integer, SavedState.Register> e : s.registers().entrySet()) {
        g.writeFieldName(e.getKey().toString());
        SavedState.Register r = e.getValue();
        // A real keeps a fraction in the file ("3.0"), so that it comes back as a real.
        g.writeNumber(r.integer() ? Long.toString((long) r.value()) : exactRealText(r.value()));
      }
      g.writeEndObject();
    }
    if (!s.stringRegisters().isEmpty()) {
      g.writeObjectFieldStart("stringRegisters");
      for (Map.Entry<Integer, String> e : s.stringRegisters().entrySet()) {
        g.writeStringField(e.getKey().toString(), e.getValue());
      }
      g.writeEndObject();
    }
    positions(g, "positionRegisters", s.positionRegisters());
    if (!s.outputs().isEmpty()) {
      g.writeObjectFieldStart("outputs");
      for (Map.Entry<String, Integer> e : s.outputs().entrySet()) {
        g.writeNumberField(e.getKey(), e.getValue());
      }
      g.writeEndObject();
    }
    if (!s.comments().isEmpty()) {
      g.writeObjectFieldStart("comments");
      for (Map.Entry<String, String> e : s.comments().entrySet()) {
        g.writeStringField(e.getKey(), e.getValue());
      }
      g.writeEndObject();
    }
    positions(g, "toolFrames", s.toolFrames());
    positions(g, "userFrames", s.userFrames());
    if (!s.robots().isEmpty()) {
      g.writeObjectFieldStart("robots");
      for (Map.Entry<String, SavedState> e : s.robots().entrySet()) {
        g.writeObjectFieldStart(e.getKey());
        writeFields(g, e.getValue());
        g.writeEndObject();
      }
      g.writeEndObject();
    }
  }

  private static void positions(JsonGenerator g, String field, Map<Integer, Position> ps) throws IOException {
    if (ps.isEmpty()) {
      return;
    }
    g.writeObjectFieldStart(field);
    for (Map.Entry<Integer, Position> e : ps.entrySet()) {
      g.writeObjectFieldStart(e.getKey().toString());
      switch (e.getValue()) {
        case Position.Cartesian c -> {
          number(g, "x", c.xMm());
          number(g, "y", c.yMm());
          number(g, "z", c.zMm());
          number(g, "w", c.wDeg());
          number(g, "p", c.pDeg());
          number(g, "r", c.rDeg());
          g.writeStringField("config", configText(c.config()));
        }
        case Position.Joint j -> {
          g.writeArrayFieldStart("joints");
          for (int k = 1; k <= 6; k++) {
            g.writeNumber(realText(j.element(k)));
          }
          g.writeEndArray();
        }
      }
      g.writeEndObject();
    }
    g.writeEndObject();
  }

  static String configText(Config c) {
    return (c.flip() ? "F" : "N") + " " + (c.up() ? "U" : "D") + " " + (c.top() ? "T" : "B") + ", " + c.turn1() + ", "
        + c.turn2() + ", " + c.turn3();
  }

  private static void number(JsonGenerator g, String field, double v) throws IOException {
    g.writeFieldName(field);
    g.writeNumber(realText(v));
  }

  /**
   * A register's real as the shortest text that reads back as the same double, always with a
   * fraction or an exponent so it comes back as a real ("3.0", "0.1", "1.0E-320"): a saved
   * value never changes (15 digits turned 1/3 into another number and 1e-320 into 0.0).
   */
  static String exactRealText(double v) {
    return Double.toString(v);
  }

  /** 15 significant digits, always with a fraction ("3.0"); exact for what the pendant enters. */
  private static String realText(double v) {
    return org.robotrun.math.DecimalText.tidyReal(v);
  }

  /** 2^53: every whole number up to it is exact in a double. */
  static final double MAX_EXACT_INTEGER = 9007199254740992.0;

  // ---- reading --------------------------------------------------------------------------------

  /** Collects problems as {@link ScenarioError}s with the file's name. */
  interface Errors {
    void add(int line, String path, String message);
  }

  /** The state in {@code o}, or null after reporting every problem to {@code errors}. */
  static SavedState read(JObject o, Errors errors) {
    int[] count = {0};
    Errors counting = (line, path, message) -> {
      count[0]++;
      errors.add(line, path, message);
    };
    for (String key : o.members().keySet()) {
      if (!FIELDS.contains(key)) {
        counting.add(o.keyLines().get(key), "state." + key, "unknown field (expected one of " + String.join(", ",
            FIELDS.stream().sorted().toList()) + ")");
      }
    }
    int override = integer(o, "overridePct", 1, 100, -1, counting);
    int utool = integer(o, "utool", 0, FrameTable.COUNT, -1, counting);
    int uframe = integer(o, "uframe", 0, FrameTable.COUNT, -1, counting);
    String created = o.members().get("created") instanceof JString s ? s.value() : "";
    if (o.members().containsKey("created") && !(o.members().get("created") instanceof JString)) {
      counting.add(o.members().get("created").line(), "state.created", "expected a time as text, got "
          + o.members().get("created").describe());
    }
    TreeMap<Integer, SavedState.Register> registers = new TreeMap<>();
    JObject regs = object(o, "registers", counting);
    if (regs != null) {
      regs.members().forEach((key, v) -> {
        String at = "state.registers." + key;
        Integer i = index(key, Registers.R_COUNT, regs.keyLines().get(key), at, counting);
        if (!(v instanceof JNumber n) || !Double.isFinite(n.value())) {
          counting.add(v.line(), at, "expected a number, got " + v.describe());
        } else if (i != null) {
          // an integer is written without a fraction; any whole number a double holds exactly comes back one
          registers.put(i, new SavedState.Register(n.value(), n.integral() && Math.abs(n.value()) <= MAX_EXACT_INTEGER));
        }
      });
    }
    TreeMap<Integer, String> strings = new TreeMap<>();
    JObject srObj = object(o, "stringRegisters", counting);
    if (srObj != null) {
      srObj.members().forEach((key, v) -> {
        String at = "state.stringRegisters." + key;
        Integer i = index(key, Registers.SR_COUNT, srObj.keyLines().get(key), at, counting);
        if (!(v instanceof JString t)) {
          counting.add(v.line(), at, "expected text, got " + v.describe());
        } else if (t.value().length() > Registers.SR_LENGTH) {
          counting.add(v.line(), at, "expected at most " + Registers.SR_LENGTH + " characters, got " + t.value().length());
        } else if (i != null) {
          strings.put(i, t.value());
        }
      });
    }
    TreeMap<Integer, Position> prs = new TreeMap<>();
    JObject prObj = object(o, "positionRegisters", counting);
    if (prObj != null) {
      prObj.members().forEach((key, v) -> {
        String at = "state.positionRegisters." + key;
        Integer i = index(key, Registers.PR_COUNT, prObj.keyLines().get(key), at, counting);
        Position p = position(v, at, counting);
        if (i != null && p != null) {
          prs.put(i, p);
        }
      });
    }
    TreeMap<String, Integer> outputs = new TreeMap<>();
    JObject outObj = object(o, "outputs", counting);
    if (outObj != null) {
      outObj.members().forEach((key, v) -> {
        String at = "state.outputs." + key;
        SavedState.Item item = SavedState.Item.parse(key);
        IoKind kind = item == null ? null : ioKind(item.table());
        if (kind == null || !kind.writable() || item.index() < 1 || item.index() > org.robotrun.program.IoRanges.MAX_SIZE) {
          counting.add(outObj.keyLines().get(key), at, "expected an output or flag such as DO[1], RO[1], GO[1], F[1], got \""
              + key + "\"");
        } else if (!(v instanceof JNumber n) || !n.integral() || (!kind.group() && n.value() != 0 && n.value() != 1)
            || Math.abs(n.value()) > Integer.MAX_VALUE) {
          counting.add(v.line(), at, kind.group() ? "expected an integer, got " + v.describe() : "expected 0 or 1, got " + v.describe());
        } else {
          outputs.put(kind.name() + "[" + item.index() + "]", (int) n.value());
        }
      });
    }
    TreeMap<String, String> comments = new TreeMap<>();
    JObject comObj = object(o, "comments", counting);
    if (comObj != null) {
      comObj.members().forEach((key, v) -> {
        String at = "state.comments." + key;
        SavedState.Item item = SavedState.Item.parse(key);
        int max = item == null ? -1 : switch (item.table()) {
          case "R" -> Registers.R_COUNT;
          case "PR" -> Registers.PR_COUNT;
          case "UT", "UF" -> FrameTable.COUNT;
          default -> -1;
        };
        if (item == null || item.index() < 1 || item.index() > max) {
          counting.add(comObj.keyLines().get(key), at, "expected R[i], PR[i], UT[i] or UF[i], got \"" + key + "\"");
        } else if (!(v instanceof JString s)) {
          counting.add(v.line(), at, "expected text, got " + v.describe());
        } else {
          comments.put(item.table() + "[" + item.index() + "]", s.value());
        }
      });
    }
    TreeMap<Integer, Position> toolFrames = frames(o, "toolFrames", counting);
    TreeMap<Integer, Position> userFrames = frames(o, "userFrames", counting);
    TreeMap<String, SavedState> robots = new TreeMap<>();
    JObject robObj = object(o, "robots", counting);
    if (robObj != null) {
      robObj.members().forEach((name, v) -> {
        String at = "state.robots." + name;
        if (!(v instanceof JObject ro)) {
          counting.add(v.line(), at, "expected an object, got " + v.describe());
          return;
        }
        if (ro.members().containsKey("robots")) {
          counting.add(ro.keyLines().get("robots"), at + ".robots", "a robot's state holds no other robots");
          return;
        }
        // The same fields, their paths under this robot.
        SavedState rs = read(ro, (line, path, message) -> counting.add(line,
            path.startsWith("state.") ? at + path.substring("state".length()) : path, message));
        if (rs != null) {
          robots.put(name, rs);
        }
      });
    }
    if (count[0] != 0) {
      return null;
    }
    return new SavedState(override, utool, uframe, registers, prs, outputs, comments, created, toolFrames, userFrames,
        robots, strings);
  }

  /** UT[i] / UF[i] of a robot after the first: Cartesian positions by number 1..10. */
  private static TreeMap<Integer, Position> frames(JObject o, String key, Errors errors) {
    TreeMap<Integer, Position> out = new TreeMap<>();
    JObject f = object(o, key, errors);
    if (f != null) {
      f.members().forEach((k, v) -> {
        String at = "state." + key + "." + k;
        Integer i = index(k, FrameTable.COUNT, f.keyLines().get(k), at, errors);
        Position p = position(v, at, errors);
        if (p instanceof Position.Joint) {
          errors.add(v.line(), at, "expected a Cartesian frame (x, y, z, w, p, r), got joint values");
        } else if (i != null && p != null) {
          out.put(i, p);
        }
      });
    }
    return out;
  }

  private static IoKind ioKind(String table) {
    for (IoKind k : IoKind.values()) {
      if (k.name().equals(table)) {
        return k;
      }
    }
    return null;
  }

  private static Position position(LocatedJson v, String at, Errors errors) {
    if (!(v instanceof JObject p)) {
      errors.add(v.line(), at, "expected {x, y, z, w, p, r, config} or {joints: [6 numbers]}, got " + v.describe());
      return null;
    }
    boolean joint = p.members().containsKey("joints");
    Set<String> allowed = joint ? JOINT : CARTESIAN;
    boolean ok = true;
    for (String key : p.members().keySet()) {
      if (!allowed.contains(key)) {
        errors.add(p.keyLines().get(key), at + "." + key, "unknown field (expected " + (joint ? "joints" : "x, y, z, w, p, r, config") + ")");
        ok = false;
      }
    }
    if (joint) {
      if (!(p.members().get("joints") instanceof JArray a) || a.items().size() != 6) {
        errors.add(p.members().get("joints").line(), at + ".joints", "expected an array of 6 joint angles in degrees");
        return null;
      }
      double[] q = new double[6];
      for (int k = 0; k < 6; k++) {
        if (a.items().get(k) instanceof JNumber n && PoseLimits.angleOk(n.value())) {
          q[k] = n.value();
        } else {
          errors.add(a.items().get(k).line(), at + ".joints[" + k + "]", "expected an angle within +-"
              + (long) PoseLimits.MAX_ANGLE_DEG + " deg, got " + a.items().get(k).describe());
          ok = false;
        }
      }
      return ok ? new Position.Joint(q[0], q[1], q[2], q[3], q[4], q[5]) : null;
    }
    double[] v6 = new double[6];
    String[] names = {"x", "y", "z", "w", "p", "r"};
    for (int k = 0; k < 6; k++) {
      LocatedJson f = p.members().get(names[k]);
      if (f == null && k >= 3) {
        continue;  // w, p, r default to 0, as in a scenario's poses
      }
      boolean good = f instanceof JNumber n && (k < 3 ? Math.abs(n.value()) <= PoseLimits.MAX_COORDINATE_MM : PoseLimits.angleOk(n.value()));
      if (!good) {
        errors.add(f == null ? p.line() : f.line(), at + "." + names[k], f == null ? "missing" : (k < 3
            ? "expected a position within +-" + (long) PoseLimits.MAX_COORDINATE_MM + " mm, got "
            : "expected an angle within +-" + (long) PoseLimits.MAX_ANGLE_DEG + " deg, got ") + f.describe());
        ok = false;
      } else {
        v6[k] = ((JNumber) f).value();
      }
    }
    Config config = Config.DEFAULT;
    LocatedJson c = p.members().get("config");
    if (c != null) {
      Matcher m = c instanceof JString s ? CONFIG.matcher(s.value()) : null;
      if (m == null || !m.matches()) {
        errors.add(c.line(), at + ".config", "expected a configuration such as \"N U T, 0, 0, 0\", got " + c.describe());
        ok = false;
      } else {
        config = new Config(m.group(1).equals("F"), m.group(2).equals("U"), m.group(3).equals("T"),
            Integer.parseInt(m.group(4)), Integer.parseInt(m.group(5)), Integer.parseInt(m.group(6)));
      }
    }
    return ok ? new Position.Cartesian(v6[0], v6[1], v6[2], v6[3], v6[4], v6[5], config) : null;
  }

  private static JObject object(JObject o, String key, Errors errors) {
    LocatedJson v = o.members().get(key);
    if (v == null) {
      return null;
    }
    if (v instanceof JObject obj) {
      return obj;
    }
    errors.add(v.line(), "state." + key, "expected an object, got " + v.describe());
    return null;
  }

  private static int integer(JObject o, String key, int min, int max, int fallback, Errors errors) {
    LocatedJson v = o.members().get(key);
    if (v == null) {
      return fallback;
    }
    if (v instanceof JNumber n && n.integral() && n.value() >= min && n.value() <= max) {
      return (int) n.value();
    }
    errors.add(v.line(), "state." + key, "expected an integer " + min + ".." + max + ", got " + v.describe());
    return fallback;
  }

  private static Integer index(String key, int max, int line, String at, Errors errors) {
    try {
      int n = Integer.parseInt(key);
      if (n >= 1 && n <= max) {
        return n;
      }
    } catch (NumberFormatException e) {
      // reported below
    }
    errors.add(line, at, "expected an index 1.." + max + " as the key, got \"" + key + "\"");
    return null;
  }
}
