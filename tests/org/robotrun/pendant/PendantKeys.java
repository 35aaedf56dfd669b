package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;

/** Test helper: runs .keys text on a pendant and collects what SHOW printed. */
final class PendantKeys {
  private PendantKeys() {}

  /** Runs {@code script} (the .keys format) and returns the SHOW outputs. */
  static List<String> run(Pendant p, String script) {
    KeyScript s = switch (KeyScript.parse("test.keys", script.lines().toList())) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new AssertionError("malformed test script: " + bad.error().display());
    };
    List<String> shows = new ArrayList<>();
    s.run(p, clock(p), shows::add);
    return shows;
  }

  /** The simulated time of {@code p}'s controller: its cell's stepper ({@link RealController#clock}). */
  static java.util.function.DoubleConsumer clock(Pendant p) {
    return RealController.clock(p.control());
  }

  /** Advances {@code p}'s controller by {@code dtSec}, the pendant following as in a key script's WAIT. */
  static void advance(Pendant p, double dtSec) {
    KeyScript.advance(p, clock(p), dtSec);
  }

  /** The body rows joined, for contains-assertions. */
  static String body(Pendant p) {
    return String.join("\n", p.lcd().body());
  }
}
