package org.robotrun.io;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.util.ArrayList;
import java.util.AbstractMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.Consumer;
import org.robotrun.io.LocatedJson.JArray;
import org.robotrun.io.LocatedJson.JBool;
import org.robotrun.io.LocatedJson.JObject;
import org.robotrun.program.IoKind;
import org.robotrun.program.IoRanges;
import org.robotrun.program.Program;
import org.robotrun.world.ProductionSetup;
import org.robotrun.world.ProductionSetup.PlcStep;
import org.robotrun.world.ProductionSetup.ReferencePosition;
import org.robotrun.world.ProductionSetup.Selection;
import org.robotrun.world.ProductionSetup.Signal;
import org.robotrun.world.RobotSetup;

/**
 * The scenario's {@code "production"} section (docs/scenario-format.md, "Production start"):
 * per robot, by name, the UOP setup, program selection, reference positions, BG Logic and a PLC
 * sequence. Read with located errors (JSON path and line) and written back in the same shape.
 */
public final class ProductionJson extends JsonFieldReader {
  private static final Set<String> ROBOT = Set.of("uop", "remote", "selection", "pnsBase", "rsrBase", "rsr", "styles",
      "ackPulseMs", "startForContinueOnly", "cstopiAborts", "homeProgram", "referencePositions", "backgroundLogic",
      "bgScanMs", "plc", "runStartsFromPlc");
  private static final Set<String> REF = Set.of("number", "comment", "jointsDeg", "toleranceDeg", "output");
  private static final Set<String> STEP = Set.of("waitFor", "state", "delayMs", "set", "note");
  /** Highest program number a PNS/RSR name can carry (four digits). */
  static final int MAX_PROGRAM_NUMBER = 9999;

  /** The I/O sizes of the robot whose section is being read. */
  private IoRanges ranges = IoRanges.DEFAULT;

  private ProductionJson(String file) {
    super(file);
  }

  /**
   * Reads {@code top.production}, if present.
   *
   * @param robots the scenario's robots (a setup for another name is an error; signal indexes are
   *     checked against that robot's I/O sizes)
   * @param errors where each problem goes
   */
  static ProductionSetup read(JObject top, String file, List<RobotSetup> robots, Consumer<ScenarioError> errors) {
    ProductionJson r = new ProductionJson(file);
    ProductionSetup out = r.section(top, robots);
    r.errors.forEach(errors);
    return out;
  }

  private ProductionSetup section(JObject top, List<RobotSetup> setups) {
    List<String> robotNames = setups.stream().map(RobotSetup::name).toList();
    JObject p = member(top, "production", "", null, false);
    if (p == null) {
      return ProductionSetup.NONE;
    }
    TreeMap<String, ProductionSetup.Robot> robots = new TreeMap<>();
    for (Map.Entry<String, LocatedJson> e : p.members().entrySet()) {
      String at = "production." + e.getKey();
      int line = p.keyLines().get(e.getKey());
      if (!robotNames.contains(e.getKey())) {
        error(line, at, "no robot named '" + e.getKey() + "' in this scenario (robots: " + String.join(", ", robotNames) + ")");
        continue;
      }
      JObject o = object(e.getValue(), at, ROBOT);
      if (o != null) {
        RobotSetup setup = setups.get(robotNames.indexOf(e.getKey()));
        try {
          ranges = IoRanges.of(setup.io());
        } catch (IllegalArgumentException bad) {
          ranges = IoRanges.DEFAULT;  // the robot's "io" has its own error
        }
        ProductionSetup.Robot robot = robot(o, at);
        if (robot != null) {
          robots.put(e.getKey(), robot);
        }
      }
    }
    return new ProductionSetup(robots);
  }

  private ProductionSetup.Robot robot(JObject o, String at) {
    int before = errors.size();
    ProductionSetup.Robot d = ProductionSetup.Robot.defaults();
    boolean uop = bool(o, "uop", at).orElse(d.uopEnabled());
    boolean remote = bool(o, "remote", at).orElse(d.remote());
    Selection selection = string(o, "selection", at, false).map(s -> selection(s, o, at)).orElse(Selection.OTHER);
    int pnsBase = integer(o, "pnsBase", at, 0, MAX_PROGRAM_NUMBER - 255, 0);
    int rsrBase = integer(o, "rsrBase", at, 0, MAX_PROGRAM_NUMBER, 0);
    List<Integer> rsr = new ArrayList<>(d.rsrNumbers());
    int[] ra = integers(o, "rsr", at, false, "an array of at most 8 program numbers (RSR1..8, 0: not used)", 0,
        MAX_PROGRAM_NUMBER, 0, 1, 2, 3, 4, 5, 6, 7, 8);
    for (int i = 0; ra != null && i < ra.length; i++) {
      rsr.set(i, ra[i]);
      if (rsrBase + ra[i] > MAX_PROGRAM_NUMBER) {
        error(((JArray) o.members().get("rsr")).items().get(i).line(), join(at, "rsr[" + i + "]"),
            "rsrBase + number must be at most 9999 (RSRnnnn has four digits)");
      }
    }
    TreeMap<Integer, String> styles = new TreeMap<>();
    JObject so = member(o, "styles", at, null, false);
    if (so != null) {
      for (Map.Entry<String, LocatedJson> e : so.members().entrySet()) {
        String path = join(at, "styles." + e.getKey());
        int line = so.keyLines().get(e.getKey());
        Integer n = keyIndex(e.getKey(), 255, line, path, "style");
        if (n == null) {
          continue;
        }
        if (!(e.getValue() instanceof LocatedJson.JString s) || !Program.isValidName(s.value().toUpperCase(Locale.ROOT))) {
          error(e.getValue().line(), path, "expected a program name, got " + e.getValue().describe());
          continue;
        }
        styles.put(n, s.value().toUpperCase(Locale.ROOT));
      }
    }
    double ackSec = integer(o, "ackPulseMs", at, 1, 10_000, (int) Math.round(d.ackPulseSec() * 1000)) / 1000.0;
    boolean contOnly = bool(o, "startForContinueOnly", at).orElse(false);
    boolean cstopi = bool(o, "cstopiAborts", at).orElse(false);
    Optional<String> home = string(o, "homeProgram", at, false).map(s -> s.toUpperCase(Locale.ROOT));
    if (home.isPresent() && !Program.isValidName(home.get())) {
      error(o.keyLines().get("homeProgram"), join(at, "homeProgram"), "'" + home.get() + "' is not a program name");
    }
    List<ReferencePosition> refs = refs(o, at);
    List<String> bg = new ArrayList<>();
    JArray ba = array(o, "backgroundLogic", at, false);
    if (ba != null) {
      if (ba.items().size() > 8) {
        error(ba.line(), join(at, "backgroundLogic"), "at most 8 BG Logic programs (8 slots), got " + ba.items().size());
      }
      for (int i = 0; i < ba.items().size(); i++) {
        LocatedJson v = ba.items().get(i);
        if (!(v instanceof LocatedJson.JString s) || !Program.isValidName(s.value().toUpperCase(Locale.ROOT))) {
          error(v.line(), join(at, "backgroundLogic[" + i + "]"), "expected a program name, got " + v.describe());
        } else {
          bg.add(s.value().toUpperCase(Locale.ROOT));
        }
      }
    }
    double scanSec = integer(o, "bgScanMs", at, 4, 1000, 8) / 1000.0;
    List<PlcStep> plc = plc(o, at);
    boolean fromPlc = bool(o, "runStartsFromPlc", at).orElse(false);
    // the selection needs its table
    if (selection == Selection.RSR && rsr.stream().allMatch(n -> n == 0)) {
      error(o.line(), join(at, "rsr"), "selection RSR needs at least one RSR program number (\"rsr\": [1, 2])");
    }
    if (selection == Selection.STYLE && styles.isEmpty()) {
      error(o.line(), join(at, "styles"), "selection STYLE needs a style table (\"styles\": {\"1\": \"PROG\"})");
    }
    if (fromPlc && plc.isEmpty()) {
      error(o.keyLines().get("runStartsFromPlc"), join(at, "runStartsFromPlc"),
          "the run starts from the PLC, but there is no \"plc\" sequence to start it");
    }
    if (fromPlc && !uop) {
      error(o.keyLines().get("runStartsFromPlc"), join(at, "runStartsFromPlc"),
          "the run starts from the PLC, but \"uop\" is false (the controller ignores UI signals)");
    }
    if (errors.size() > before) {
      return null;
    }
    return new ProductionSetup.Robot(uop, remote, selection, pnsBase, rsrBase, rsr, styles, ackSec, contOnly, cstopi,
        home, refs, bg, scanSec, plc, fromPlc);
  }

  private Selection selection(String s, JObject o, String at) {
    for (Selection v : Selection.values()) {
      if (v.name().equals(s)) {
        return v;
      }
    }
    error(o.keyLines().get("selection"), join(at, "selection"), "unknown selection '" + s + "': expected OTHER, RSR, PNS or STYLE");
    return Selection.OTHER;
  }

  private List<ReferencePosition> refs(JObject o, String at) {
    List<ReferencePosition> out = new ArrayList<>();
    JArray a = array(o, "referencePositions", at, false);
    if (a == null) {
      return out;
    }
    Set<Integer> seen = new java.util.HashSet<>();
    for (int i = 0; i < a.items().size(); i++) {
      String p = join(at, "referencePositions[" + i + "]");
      JObject r = object(a.items().get(i), p, REF);
      if (r == null) {
        continue;
      }
      int number = integer(r, "number", p, 1, 10, i + 1);
      if (!seen.add(number)) {
        error(r.line(), join(p, "number"), "reference position " + number + " is given twice");
      }
      String comment = string(r, "comment", p, false).orElse("");
      double[] joints = numbers(r, "jointsDeg", p, true, "an array of 6 joint angles (degrees)", -720, 720, 6);
      double[] tol = r.members().containsKey("toleranceDeg")
          ? numbers(r, "toleranceDeg", p, true, "an array of 6 tolerances (degrees), or of one for every joint", 0, 180, 6, 1)
          : new double[] {1.0};
      if (joints == null || tol == null) {
        continue;
      }
      List<Double> tol6 = tol.length == 1 ? java.util.Collections.nCopies(6, tol[0])
          : java.util.Arrays.stream(tol).boxed().toList();
      Optional<Signal> output = Optional.empty();
      Optional<String> os = string(r, "output", p, false);
      if (os.isPresent()) {
        Signal sg = signal(os.get(), r.keyLines().get("output"), join(p, "output"), Set.of(IoKind.DO, IoKind.RO, IoKind.F));
        if (sg == null) {
          continue;
        }
        output = Optional.of(sg);
      }
      out.add(new ReferencePosition(number, comment, java.util.Arrays.stream(joints).boxed().toList(), tol6, output));
    }
    return out;
  }

  private List<PlcStep> plc(JObject o, String at) {
    List<PlcStep> out = new ArrayList<>();
    JArray a = array(o, "plc", at, false);
    if (a == null) {
      return out;
    }
    for (int i = 0; i < a.items().size(); i++) {
      String p = join(at, "plc[" + i + "]");
      JObject s = object(a.items().get(i), p, STEP);
      if (s == null) {
        continue;
      }
      Optional<Map.Entry<Signal, Boolean>> waitFor = Optional.empty();
      Optional<String> w = string(s, "waitFor", p, false);
      if (w.isPresent()) {
        Signal sg = signal(w.get(), s.keyLines().get("waitFor"), join(p, "waitFor"), null);
        if (sg != null) {
          waitFor = Optional.of(new AbstractMap.SimpleImmutableEntry<>(sg, bool(s, "state", p).orElse(true)));
        }
      } else if (s.members().containsKey("state")) {
        error(s.keyLines().get("state"), join(p, "state"), "\"state\" belongs to a \"waitFor\"");
      }
      double delaySec = integer(s, "delayMs", p, 0, 3_600_000, 0) / 1000.0;
      Map<Signal, Boolean> set = new LinkedHashMap<>();
      JObject so = member(s, "set", p, null, false);
      if (so != null) {
        for (Map.Entry<String, LocatedJson> e : so.members().entrySet()) {
          String path = join(p, "set." + e.getKey());
          Signal sg = signal(e.getKey(), so.keyLines().get(e.getKey()), path, Set.of(IoKind.UI, IoKind.DI));
          if (sg == null) {
            continue;
          }
          if (!(e.getValue() instanceof JBool b)) {
            error(e.getValue().line(), path, "expected true (ON) or false (OFF), got " + e.getValue().describe());
            continue;
          }
          set.put(sg, b.value());
        }
      }
      if (waitFor.isEmpty() && set.isEmpty() && delaySec == 0) {
        error(s.line(), p, "a PLC step needs a \"waitFor\", a \"delayMs\" or a \"set\"");
      }
      out.add(new PlcStep(waitFor, delaySec, set, string(s, "note", p, false).orElse("")));
    }
    return out;
  }

  /** "UI[6]" as a signal of one of {@code kinds} (null: any kind) within its default range; null after an error. */
  private Signal signal(String text, int line, String path, Set<IoKind> kinds) {
    Optional<org.robotrun.program.IoAddress> m = org.robotrun.program.IoAddress.parse(text);
    String expected = kinds == null ? "a signal such as \"UO[1]\" or \"DO[5]\""
        : "a signal " + kinds.stream().map(k -> k.name() + "[i]").sorted().toList();
    if (m.isEmpty()) {
      error(line, path, "expected " + expected + ", got \"" + text + "\"");
      return null;
    }
    IoKind kind;
    try {
      kind = IoRanges.kind(m.get().kind());
    } catch (IllegalArgumentException e) {
      error(line, path, e.getMessage());
      return null;
    }
    if (kinds != null && !kinds.contains(kind)) {
      error(line, path, "expected " + expected + ", got \"" + text + "\"");
      return null;
    }
    int i = m.get().index();
    int size = ranges.size(kind);
    if (i < 1 || i > size) {
      error(line, path, kind + "[" + i + "]: index out of range (expected 1.." + size + ")");
      return null;
    }
    return new Signal(kind.name(), i);
  }

  // ---- writing ------------------------------------------------------------------------------

  /** Writes the section when there is one (nothing for {@link ProductionSetup#NONE}). */
  static void write(JsonGenerator g, ProductionSetup s) throws IOException {
    if (s.robots().isEmpty()) {
      return;
    }
    ProductionSetup.Robot d = ProductionSetup.Robot.defaults();
    g.writeObjectFieldStart("production");
    for (Map.Entry<String, ProductionSetup.Robot> e : s.robots().entrySet()) {
      ProductionSetup.Robot r = e.getValue();
      g.writeObjectFieldStart(e.getKey());
      g.writeBooleanField("uop", r.uopEnabled());
      g.writeBooleanField("remote", r.remote());
      g.writeStringField("selection", r.selection().name());
      if (r.pnsBase() != 0) {
        g.writeNumberField("pnsBase", r.pnsBase());
      }
      if (r.rsrBase() != 0) {
        g.writeNumberField("rsrBase", r.rsrBase());
      }
      if (!r.rsrNumbers().equals(d.rsrNumbers())) {
        g.writeArrayFieldStart("rsr");
        for (int n : r.rsrNumbers()) {
          g.writeNumber(n);
        }
        g.writeEndArray();
      }
      if (!r.styles().isEmpty()) {
        g.writeObjectFieldStart("styles");
        for (Map.Entry<Integer, String> st : r.styles().entrySet()) {
          g.writeStringField(Integer.toString(st.getKey()), st.getValue());
        }
        g.writeEndObject();
      }
      g.writeNumberField("ackPulseMs", (int) Math.round(r.ackPulseSec() * 1000));
      if (r.startForContinueOnly()) {
        g.writeBooleanField("startForContinueOnly", true);
      }
      if (r.cstopiAborts()) {
        g.writeBooleanField("cstopiAborts", true);
      }
      if (r.homeProgram().isPresent()) {
        g.writeStringField("homeProgram", r.homeProgram().get());
      }
      if (!r.referencePositions().isEmpty()) {
        g.writeArrayFieldStart("referencePositions");
        for (ReferencePosition rp : r.referencePositions()) {
          g.writeStartObject();
          g.writeNumberField("number", rp.number());
          if (!rp.comment().isEmpty()) {
            g.writeStringField("comment", rp.comment());
          }
          doubles(g, "jointsDeg", rp.jointsDeg());
          doubles(g, "toleranceDeg", rp.toleranceDeg());
          if (rp.output().isPresent()) {
            g.writeStringField("output", rp.output().get().toString());
          }
          g.writeEndObject();
        }
        g.writeEndArray();
      }
      if (!r.backgroundLogic().isEmpty()) {
        g.writeArrayFieldStart("backgroundLogic");
        for (String p : r.backgroundLogic()) {
          g.writeString(p);
        }
        g.writeEndArray();
      }
      g.writeNumberField("bgScanMs", (int) Math.round(r.bgScanSec() * 1000));
      if (!r.plc().isEmpty()) {
        g.writeArrayFieldStart("plc");
        for (PlcStep st : r.plc()) {
          g.writeStartObject();
          if (st.waitFor().isPresent()) {
            g.writeStringField("waitFor", st.waitFor().get().getKey().toString());
            if (!st.waitFor().get().getValue()) {
              g.writeBooleanField("state", false);
            }
          }
          if (st.delaySec() > 0) {
            g.writeNumberField("delayMs", (int) Math.round(st.delaySec() * 1000));
          }
          if (!st.set().isEmpty()) {
            g.writeObjectFieldStart("set");
            for (Map.Entry<Signal, Boolean> x : st.set().entrySet()) {
              g.writeBooleanField(x.getKey().toString(), x.getValue());
            }
            g.writeEndObject();
          }
          if (!st.note().isEmpty()) {
            g.writeStringField("note", st.note());
          }
          g.writeEndObject();
        }
        g.writeEndArray();
      }
      if (r.startFromPlc()) {
        g.writeBooleanField("runStartsFromPlc", true);
      }
      g.writeEndObject();
    }
    g.writeEndObject();
  }

  private static void doubles(JsonGenerator g, String field, List<Double> values) throws IOException {
    g.writeArrayFieldStart(field);
    for (double v : values) {
      if (v == Math.rint(v) && Math.abs(v) < 1e9) {
        g.writeNumber((long) v);
      } else {
        g.writeNumber(v);
      }
    }
    g.writeEndArray();
  }
}
