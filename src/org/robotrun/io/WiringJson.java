package org.robotrun.io;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.robotrun.io.LocatedJson.JArray;
import org.robotrun.io.LocatedJson.JObject;
import org.robotrun.program.IoKind;
import org.robotrun.program.IoRanges;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Wiring;
import org.robotrun.world.Wiring.Signal;
import org.robotrun.world.Wiring.Wire;

/**
 * The scenario's {@code "wiring"} section (docs/scenario-format.md):
 * {@code [{"from": "robot1.DO[10]", "to": "robot2.DI[10]"}, ...]}. Each wire runs from an output
 * (DO, RO, GO: what a program writes) to an input (DI, RI, GI: what only the outside writes) of
 * the same width (bit to bit, group to group), on robots the scenario names, within their I/O
 * sizes. An input has at most one driver; an output may drive several inputs. Since an input
 * never drives anything, wires cannot form a loop; a wire from a port to itself is reported as one.
 */
final class WiringJson {
  private static final Set<String> WIRE = Set.of("from", "to");

  private WiringJson() {}

  /** Reads {@code top.wiring}; problems go to {@code r} with their JSON path and line. */
  static Wiring read(JsonFieldReader r, JObject top, List<RobotSetup> robots) {
    JArray arr = r.array(top, "wiring", "", false);
    if (arr == null) {
      return Wiring.NONE;
    }
    Map<String, RobotSetup> byName = new HashMap<>();
    robots.forEach(x -> byName.put(x.name(), x));
    List<Wire> out = new ArrayList<>();
    Map<String, String> driverOf = new HashMap<>();
    for (int i = 0; i < arr.items().size(); i++) {
      String at = "wiring[" + i + "]";
      JObject o = r.object(arr.items().get(i), at, WIRE);
      if (o == null) {
        continue;
      }
      Optional<Endpoint> from = endpoint(r, o, "from", at, true, byName);
      Optional<Endpoint> to = endpoint(r, o, "to", at, false, byName);
      if (from.isEmpty() || to.isEmpty()) {
        continue;
      }
      int line = o.keyLines().getOrDefault("to", o.line());
      Signal f = from.get().signal;
      Signal t = to.get().signal;
      if (f.equals(t)) {
        r.error(line, at, "a loop: " + f + " is wired to itself");
        continue;
      }
      if (from.get().kind.group() != to.get().kind.group()) {
        r.error(line, JsonFieldReader.join(at, "to"), f + " is a " + (from.get().kind.group() ? "group (an integer)" : "bit (ON/OFF)")
            + " and " + t + " is a " + (to.get().kind.group() ? "group" : "bit") + ": wire bits to bits (DO to DI) and "
            + "groups to groups (GO to GI)");
        continue;
      }
      String earlier = driverOf.putIfAbsent(t.toString(), f + " (" + at + ")");
      if (earlier != null) {
        r.error(line, JsonFieldReader.join(at, "to"), t + " is already driven by " + earlier + ": an input takes one output");
        continue;
      }
      out.add(new Wire(f, t));
    }
    return new Wiring(out);
  }

  private record Endpoint(Signal signal, IoKind kind) {}

  private static Optional<Endpoint> endpoint(JsonFieldReader r, JObject o, String key, String at, boolean output,
      Map<String, RobotSetup> robots) {
    Optional<String> text = r.string(o, key, at, true);
    if (text.isEmpty()) {
      return Optional.empty();
    }
    String path = JsonFieldReader.join(at, key);
    int line = o.keyLines().getOrDefault(key, o.line());
    // ROBOT.KIND[N], read by the one reader of I/O addresses
    Optional<Signal> s = org.robotrun.program.IoAddress.parseOnRobot(text.get())
        .map(a -> new Signal(a.robot(), a.address().kind(), a.address().index()));
    if (s.isEmpty()) {
      r.error(line, path, "expected a signal like \"robot1." + (output ? "DO" : "DI") + "[10]\", got \"" + text.get() + "\"");
      return Optional.empty();
    }
    Signal sig = s.get();
    RobotSetup robot = robots.get(sig.robot());
    if (robot == null) {
      r.error(line, path, "no robot named '" + sig.robot() + "' in this scenario (robots: "
          + String.join(", ", robots.keySet().stream().sorted().toList()) + ")");
      return Optional.empty();
    }
    IoKind kind;
    try {
      kind = IoRanges.kind(sig.kind());
    } catch (IllegalArgumentException e) {
      r.error(line, path, e.getMessage());
      return Optional.empty();
    }
    // The controller's rule (docs/scenario-format.md): a wire runs from an output a program writes
    // (DO, RO, GO) to an input only the outside writes (DI, RI, GI). UO/SO are driven by the
    // controller itself, UI/SI by the PLC and the panel, AI/AO are analog: none is a wire's end.
    boolean isOutput = kind == IoKind.DO || kind == IoKind.RO || kind == IoKind.GO;
    boolean isInput = kind == IoKind.DI || kind == IoKind.RI || kind == IoKind.GI;
    if (output && !isOutput) {
      r.error(line, path, sig + " is " + what(kind) + ": a wire runs from an output (" + names(true) + ")");
      return Optional.empty();
    }
    if (!output && !isInput) {
      r.error(line, path, sig + " is " + what(kind) + ": a wire runs to an input (" + names(false) + ")"
          + (kind == IoKind.UO || kind == IoKind.SO || kind.writable()
              ? "; an output wired to an output would have two drivers" : ""));
      return Optional.empty();
    }
    int size;
    try {
      size = IoRanges.of(robot.io()).size(kind);
    } catch (IllegalArgumentException e) {
      return Optional.empty();  // the robot's "io" section already reported it
    }
    if (sig.index() < 1 || sig.index() > size) {
      r.error(line, path, sig + " does not exist: " + sig.robot() + " has " + kind + "[1.." + size + "]");
      return Optional.empty();
    }
    return Optional.of(new Endpoint(sig, kind));
  }

  private static String names(boolean outputs) {
    return outputs ? "DO, RO, GO" : "DI, RI, GI";
  }

  /** What a port is, in the words of the controller. */
  private static String what(IoKind kind) {
    return switch (kind) {
      case DI, RI, GI -> "an input";
      case DO, RO, GO -> "an output";
      case F -> "a flag";
      case UO -> "a UOP output the controller drives";
      case SO -> "an SOP output the controller drives";
      case UI -> "a UOP input (set by the PLC)";
      case SI -> "an SOP input (the operator panel's)";
      case AI -> "an analog input";
      case AO -> "an analog output";
    };
  }

  /** Writes the section (nothing when there are no wires). */
  static void write(JsonGenerator g, Wiring w) throws IOException {
    if (w.isEmpty()) {
      return;
    }
    g.writeArrayFieldStart("wiring");
    for (Wire x : w.wires()) {
      g.writeStartObject();
      g.writeStringField("from", x.from().toString());
      g.writeStringField("to", x.to().toString());
      g.writeEndObject();
    }
    g.writeEndArray();
  }
}
