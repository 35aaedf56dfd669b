package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.LsWriter;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.program.Config;
import org.robotrun.program.Instruction;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * The pendant accepts a position value exactly when the .LS reader accepts it in a file: a value
 * typed into POSITION DETAIL is saved, and a value the pendant refuses would not read back.
 */
class PendantEntryRoundTripTest {
  private final Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
  private final Controller controller = sim.controllers().get(0);
  private final ControllerPort control = new ControllerPort(controller);
  private final org.robotrun.sim.CellStepper stepper = new org.robotrun.sim.CellStepper(sim);
  private final Pendant p = new Pendant(control, new LsLineParser());

  private void keys(String script) {
    KeyScript s = switch (KeyScript.parse("test.keys", script.lines().toList())) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new AssertionError(bad.error().display());
    };
    s.run(p, stepper::advance, text -> { });
  }

  private static final List<Double> VALUES = List.of(0.5, -0.25, 1e-9, 100_000.0, -100_000.0, 100_000.001, 36_000.0,
      -36_000.0, 36_000.001, -36_000.5, 99_999_999.0, 1e308, -1e308);

  /** Types {@code v} into element {@code j} of P[1] of program N on the pendant; whether it was taken. */
  private boolean pendantTakes(int j, double v) {
    Position before = p1();
    keys("UP *7\nDOWN *" + j + "\nTYPE " + v + "\nENTER\n");
    Position after = p1();
    return !after.equals(before) && after.element(j) == v;
  }

  private Position p1() {
    return control.program("N").orElseThrow().position(1).orElseThrow().position();
  }

  /** Whether a file with P[1] holding {@code v} in element {@code j} reads back without an error. */
  private static boolean readerTakes(Position pos, int j, double v) {
    Program prog = Program.of("N", List.of(new Instruction.End()),
        List.of(new LocalPosition(1, "", 0, 1, pos.withElement(j, v))));
    LsReadResult r = LsReader.parse("N.LS", LsWriter.write(prog));
    return !r.hasAnyError();
  }

  @Test
  void theEntryAndTheReaderAgreeOnEveryCoordinateAndAngle() {
    keys("""
        SELECT
        F1
        TYPE N
        ENTER
        SHIFT+F1
        UP
        NEXT
        F1
        """);
    assertThat(p1()).isInstanceOf(Position.Cartesian.class);
    for (int j = 1; j <= 6; j++) {
      for (double v : VALUES) {
        Position pos = p1();
        boolean reader = readerTakes(pos, j, v);
        assertThat(pendantTakes(j, v)).as("element %d = %s: the reader %s it", j, v, reader ? "takes" : "refuses")
            .isEqualTo(reader);
      }
    }
    // on the student's side: Z = 1e308 is refused with the field and the range, Z kept
    double z = p1().element(3);
    assertThat(pendantTakes(3, 1e308)).isFalse();
    assertThat(p.lcd().promptLine().strip()).isEqualTo("P[1] Z 1.0E308: out of range, enter -100000 to 100000 mm");
    assertThat(p1().element(3)).isEqualTo(z);
    // and the same in joint form
    Position.Joint joints = new Position.Joint(0, 0, 0, 0, -90, 0);
    for (double v : VALUES) {
      assertThat(readerTakes(joints, 5, v)).as("J5 = %s", v).isEqualTo(Math.abs(v) <= 36_000);
    }
    assertThat(readerTakes(new Position.Cartesian(0, 0, 0, 0, 0, 0, Config.DEFAULT), 1, 1e308)).isFalse();
  }
}
