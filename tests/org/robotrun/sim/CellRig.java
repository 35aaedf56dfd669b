package org.robotrun.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.io.ScenarioLoad;
import org.robotrun.io.ScenarioReader;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;

/** Loads example scenarios and programs for the cell tests. */
final class CellRig {
  private CellRig() {}

  static Scenario scenario(String file) {
    return switch (ScenarioReader.read(Path.of("scenarios", file))) {
      case ScenarioLoad.Loaded l -> l.scenario();
      case ScenarioLoad.Failed f -> throw new AssertionError(f.message());
    };
  }

  /** The scenario's cell with its programs loaded into the first robot. */
  static Simulation cell(Scenario sc) {
    Simulation sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
    for (Path p : sc.programs()) {
      try {
        LsReadResult r = LsReader.read(p);
        if (r.hasAnyError()) {
          throw new AssertionError(p + ": " + r.diagnostics());
        }
        sim.controllers().get(0).saveProgram(r.program());
      } catch (IOException e) {
        throw new UncheckedIOException(e);
      }
    }
    return sim;
  }

  /**
   * A program named TEST in UF[1]/UT[1] from numbered-free lines and a /POS section of
   * Cartesian points P[1..] given as "x,y,z" (W, P, R = 180, 0, 0: tool pointing down).
   */
  static Program program(String[] lines, String... points) {
    StringBuilder sb = new StringBuilder("/PROG  TEST\n/ATTR\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format("%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\n");
    for (int i = 0; i < points.length; i++) {
      String[] xyz = points[i].split(",");
      sb.append(String.format("""
          P[%d]{
             GP1:
          	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
          	X = %s  mm,	Y = %s  mm,	Z = %s  mm,
          	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
          };
          """, i + 1, xyz[0], xyz[1], xyz[2]));
    }
    sb.append("/END\n");
    LsReadResult r = LsReader.parse("TEST.LS", sb.toString());
    if (r.hasAnyError()) {
      throw new AssertionError(r.diagnostics());
    }
    return r.program();
  }

  /** Runs {@code program} on the first robot to its end (or an alarm). */
  static HeadlessRun.Result run(Simulation sim, Program program) {
    Controller c = sim.controllers().get(0);
    c.saveProgram(program);
    return HeadlessRun.run(sim, c, program.name(), 120, s -> {});
  }
}
