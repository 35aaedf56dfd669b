package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Tuple;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.Key;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * Fuzzing key scripts (issue 18): generated scripts of real keys, typed text (blank, long,
 * control characters, expressions, numbers in every spelling), waits and garbage, run on the
 * pendant driving the real controller. A script is either refused at one line ({@code file:line:
 * message}) or runs to its end; nothing throws. Fixed seed, small budget;
 * {@link KeyScriptFuzzCampaign} is the long campaign ({@code -Pfuzz}).
 */
class KeyScriptFuzzTest {
  private static final List<String> TYPED = List.of("", " ", "   ", "1", "-5", "0x1p3", "1d", "1e999", "NaN",
      "PICK1", "R[1]", "R[1]+(R[2]*3)", "((((((1))))))", "-".repeat(50) + "1", "\u001b[2J", "ÄÖÜ", "]", "[", "P[1:]]",
      "MAIN", "LBL[1]", "JMP LBL[1]", "J P[1] 100% FINE", "L P[1] 200mm/sec CNT50", "WAIT 1.00(sec)", "12.5",
      "x".repeat(300), "99999999999", "\t", "TIMER[1]", "DO[1]=ON", "GO[1]=PULSE", "MESSAGE[check R[1] now]");

  private static final List<String> COMMANDS = List.of("SHOW", "WAIT 0.05", "WAIT 0", "HOLD SHIFT", "RELEASE SHIFT",
      "HOLD DEADMAN", "RELEASE DEADMAN", "CLICK +X", "CLICK J1+", "DOWN *3", "UP *2", "HOLD +X/J1", "RELEASE +X/J1",
      "SHIFT+FWD", "SHIFT+BWD", "SHIFT+F1", "SHIFT+F5", "HOLD", "WAIT 0x1p3", "WAIT 1e3", "FROB", "TYPE", "* 3", "ENTER *0",
      "# a comment", "", "RELEASE");

  @Provide
  Arbitrary<List<String>> scripts() {
    Arbitrary<String> key = Arbitraries.of(Arrays.stream(Key.values()).map(Key::label).toList());
    Arbitrary<String> type = Arbitraries.oneOf(Arbitraries.of(TYPED), Arbitraries.strings().ofMaxLength(20))
        .map(t -> "TYPE " + t);
    Arbitrary<String> line = Arbitraries.frequencyOf(Tuple.of(8, key), Tuple.of(3, type),
        Tuple.of(2, Arbitraries.of(COMMANDS)), Tuple.of(1, Arbitraries.strings().ofMaxLength(10)));
    return line.list().ofMinSize(1).ofMaxSize(40);
  }

  @Property(seed = "18", tries = 60)
  void scriptsAreRefusedAtALineOrRunToTheirEnd(@ForAll("scripts") List<String> lines) {
    check(lines);
  }

  static void check(List<String> lines) {
    List<String> safe = new ArrayList<>(lines);
    switch (KeyScript.parse("f.keys", safe)) {
      case KeyScript.Parsed.Bad bad -> {
        assertThat(bad.error().line()).isBetween(1, lines.size());
        assertThat(bad.error().display()).startsWith("f.keys:" + bad.error().line() + ": ");
      }
      case KeyScript.Parsed.Ok ok -> {
        Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
        Pendant p = new Pendant(new ControllerPort(sim.controllers().get(0)), new LsLineParser());
        StringBuilder shown = new StringBuilder();
        ok.script().run(p, new org.robotrun.sim.CellStepper(sim)::advance, shown::append);
        assertThat(p.render()).isNotEmpty();
      }
    }
  }
}
