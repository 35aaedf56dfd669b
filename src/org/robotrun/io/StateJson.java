package org.robotrun.io;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
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
final class StateJson extends JsonFieldReader {
  private static final Set<String> FIELDS = Set.of(
      "overridePct", "utool", "uframe", "registers", "positionRegisters", "outputs", "comments", "created", "toolFrames", "userFrames", "robots", "stringRegisters");
  private static final Set<String> CARTESIAN = Set.of("x", "y", "z", "w", "p", "r", "config");
  private static final Set<String> JOINT = Set.of("joints");
  private static final Pattern CONFIG = Pattern.compile(
      "\\s*([NF])\\s+([UD])\\s+([TB])\\s*,\\s*(-?\\d+)\\s*,\\s*(-?\\d+)\\s*,\\s*(-?\\d+)\\s*");

  /** Where this state's fields are: {@code state}, or {@code state.robots.NAME} for a later robot's. */
  private final String root;
  private int problems;

  private StateJson(ErrorSink errors, String root) {
    super(errors);
    this.root = root;
  }

  /** Counts the problems reported through {@code errors}, so a state with any is not taken. */
  private static ErrorSink counted(ErrorSink errors, int[] count) {
    return (line, path, message) -> {
      count[0]++;
      errors.add(line, path, message);
    };
  }

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

  /** The state in {@code o}, or null after reporting every problem to {@code errors}. */
  static SavedState read(JObject o, ErrorSink errors) {
    int[] count = {0};
    SavedState s = new StateJson(counted(errors, count), "state").state(o);
    return count[0] == 0 ? s : null;
  }

  /** The fields of one state object (the JSON field helpers are {@link JsonFieldReader}'s). */
  private SavedState state(JObject o) {
    object(o, root, FIELDS);
    int override = integer(o, "overridePct", root, 1, 100, -1);
    int utool = integer(o, "utool", root, 0, FrameTable.COUNT, -1);
    int uframe = integer(o, "uframe", root, 0, FrameTable.COUNT, -1);
    String created = string(o, "created", root, false).orElse("");
    TreeMap<Integer, SavedState.Register> registers = new TreeMap<>();
    JObject regs = member(o, "registers", root, null, false);
    if (regs != null) {
      regs.members().forEach((key, v) -> {
        String at = join(root, "registers." + key);
        Integer i = keyIndex(key, Registers.R_COUNT, regs.keyLines().get(key), at, "register");
        Optional<Double> n = finite(regs, key, join(root, "registers"), true);
        if (n.isPresent() && i != null) {
          // an integer is written without a fraction; any whole number a double holds exactly comes back one
          boolean integral = ((JNumber) v).integral() && Math.abs(n.get()) <= MAX_EXACT_INTEGER;
          registers.put(i, new SavedState.Register(n.get(), integral));
        }
      });
    }
    TreeMap<Integer, String> strings = new TreeMap<>();
    JObject srObj = member(o, "stringRegisters", root, null, false);
    if (srObj != null) {
      srObj.members().forEach((key, v) -> {
        String at = join(root, "stringRegisters." + key);
        Integer i = keyIndex(key, Registers.SR_COUNT, srObj.keyLines().get(key), at, "string register");
        Optional<String> t = string(srObj, key, join(root, "stringRegisters"), true);
        if (t.isPresent() && t.get().length() > Registers.SR_LENGTH) {
          error(v.line(), at, "expected at most " + Registers.SR_LENGTH + " characters, got " + t.get().length());
        } else if (t.isPresent() && i != null) {
          strings.put(i, t.get());
        }
      });
    }
    TreeMap<Integer, Position> prs = new TreeMap<>();
    JObject prObj = member(o, "positionRegisters", root, null, false);
    if (prObj != null) {
      prObj.members().forEach((key, v) -> {
        String at = join(root, "positionRegisters." + key);
        Integer i = keyIndex(key, Registers.PR_COUNT, prObj.keyLines().get(key), at, "position register");
        Position p = position(v, at);
        if (i != null && p != null) {
          prs.put(i, p);
        }
      });
    }
    TreeMap<String, Integer> outputs = new TreeMap<>();
    JObject outObj = member(o, "outputs", root, null, false);
    if (outObj != null) {
      outObj.members().forEach((key, v) -> {
        String at = join(root, "outputs." + key);
        SavedState.Item item = SavedState.Item.parse(key);
        IoKind kind = item == null ? null : ioKind(item.table());
        if (kind == null || !kind.writable() || item.index() < 1 || item.index() > org.robotrun.program.IoRanges.MAX_SIZE) {
          error(outObj.keyLines().get(key), at, "expected an output or flag such as DO[1], RO[1], GO[1], F[1], got \""
              + key + "\"");
        } else {
          int max = kind.group() ? Integer.MAX_VALUE : 1;
          integer(outObj, key, join(root, "outputs"), kind.group() ? -max : 0, max, true)
              .ifPresent(n -> outputs.put(kind.name() + "[" + item.index() + "]", n.intValue()));
        }
      });
    }
    TreeMap<String, String> comments = new TreeMap<>();
    JObject comObj = member(o, "comments", root, null, false);
    if (comObj != null) {
      comObj.members().forEach((key, v) -> {
        String at = join(root, "comments." + key);
        SavedState.Item item = SavedState.Item.parse(key);
        int max = item == null ? -1 : switch (item.table()) {
          case "R" -> Registers.R_COUNT;
          case "PR" -> Registers.PR_COUNT;
          case "UT", "UF" -> FrameTable.COUNT;
          default -> -1;
        };
        if (item == null || item.index() < 1 || item.index() > max) {
          error(comObj.keyLines().get(key), at, "expected R[i], PR[i], UT[i] or UF[i], got \"" + key + "\"");
        } else {
          string(comObj, key, join(root, "comments"), true)
              .ifPresent(text -> comments.put(item.table() + "[" + item.index() + "]", text));
        }
      });
    }
    TreeMap<Integer, Position> toolFrames = frames(o, "toolFrames", "tool frame");
    TreeMap<Integer, Position> userFrames = frames(o, "userFrames", "user frame");
    TreeMap<String, SavedState> robots = new TreeMap<>();
    JObject robObj = member(o, "robots", root, null, false);
    if (robObj != null) {
      robObj.members().forEach((name, v) -> {
        String at = join(root, "robots." + name);
        JObject ro = object(v, at, null);
        if (ro == null) {
          return;
        }
        if (ro.members().containsKey("robots")) {
          error(ro.keyLines().get("robots"), at + ".robots", "a robot's state holds no other robots");
          return;
        }
        // The same fields, their paths under this robot.
        int[] count = {0};
        SavedState rs = new StateJson(counted(this::error, count), at).state(ro);
        if (count[0] == 0) {
          robots.put(name, rs);
        }
      });
    }
    return new SavedState(override, utool, uframe, registers, prs, outputs, comments, created, toolFrames, userFrames,
        robots, strings);
  }

  /** UT[i] / UF[i] of a robot after the first: Cartesian positions by number 1..10. */
  private TreeMap<Integer, Position> frames(JObject o, String key, String what) {
    TreeMap<Integer, Position> out = new TreeMap<>();
    JObject f = member(o, key, root, null, false);
    if (f != null) {
      f.members().forEach((k, v) -> {
        String at = join(root, key + "." + k);
        Integer i = keyIndex(k, FrameTable.COUNT, f.keyLines().get(k), at, what);
        Position p = position(v, at);
        if (p instanceof Position.Joint) {
          error(v.line(), at, "expected a Cartesian frame (x, y, z, w, p, r), got joint values");
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

  private Position position(LocatedJson v, String at) {
    if (!(v instanceof JObject p)) {
      error(v.line(), at, "expected {x, y, z, w, p, r, config} or {joints: [6 numbers]}, got " + v.describe());
      return null;
    }
    boolean joint = p.members().containsKey("joints");
    Set<String> allowed = joint ? JOINT : CARTESIAN;
    boolean ok = true;
    for (String key : p.members().keySet()) {
      if (!allowed.contains(key)) {
        error(p.keyLines().get(key), at + "." + key, "unknown field (expected " + (joint ? "joints" : "x, y, z, w, p, r, config") + ")");
        ok = false;
      }
    }
    if (joint) {
      double[] q = numbers(p, "joints", at, true, "an array of 6 joint angles (degrees)", -PoseLimits.MAX_ANGLE_DEG,
          PoseLimits.MAX_ANGLE_DEG, 6);
      return ok && q != null ? new Position.Joint(q[0], q[1], q[2], q[3], q[4], q[5]) : null;
    }
    double[] v6 = new double[6];
    String[] names = {"x", "y", "z", "w", "p", "r"};
    for (int k = 0; k < 6; k++) {
      // w, p, r default to 0, as in a scenario's poses
      double lim = k < 3 ? PoseLimits.MAX_COORDINATE_MM : PoseLimits.MAX_ANGLE_DEG;
      Optional<Double> d = number(p, names[k], at, k < 3, -lim, lim);
      ok &= d.isPresent() || (k >= 3 && !p.members().containsKey(names[k]));
      v6[k] = d.orElse(0.0);
    }
    Config config = Config.DEFAULT;
    LocatedJson c = p.members().get("config");
    if (c != null) {
      Matcher m = c instanceof JString s ? CONFIG.matcher(s.value()) : null;
      if (m == null || !m.matches()) {
        error(c.line(), at + ".config", "expected a configuration such as \"N U T, 0, 0, 0\", got " + c.describe());
        ok = false;
      } else {
        config = new Config(m.group(1).equals("F"), m.group(2).equals("U"), m.group(3).equals("T"),
            Integer.parseInt(m.group(4)), Integer.parseInt(m.group(5)), Integer.parseInt(m.group(6)));
      }
    }
    return ok ? new Position.Cartesian(v6[0], v6[1], v6[2], v6[3], v6[4], v6[5], config) : null;
  }

}
