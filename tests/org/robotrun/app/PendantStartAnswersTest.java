package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl.ExecState;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * Every start answers on the prompt line what happened or why not (issue 29): CYCLE START and
 * SHIFT+FWD with the cursor left on the END where the last run ended, and a mode switch that
 * stops a run. Read from the LCD text model on the real controller.
 */
class PendantStartAnswersTest {
  private final Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
  private final ControllerPort control = new ControllerPort(sim.controllers().get(0));
  private final org.robotrun.sim.CellStepper stepper = new org.robotrun.sim.CellStepper(sim);
  private final Pendant p = new Pendant(control, new LsLineParser());

  private void keys(String script) {
    KeyScript s = switch (KeyScript.parse("test.keys", script.lines().toList())) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new AssertionError(bad.error().display());
    };
    s.run(p, stepper::advance, text -> { });
  }

  private void store(String name, String... lines) {
    List<String> ls = new ArrayList<>(List.of("/PROG  " + name, "/ATTR", "/MN"));
    for (int i = 0; i < lines.length; i++) {
      ls.add(String.format("%4d:  %s ;", i + 1, lines[i]));
    }
    ls.addAll(List.of("/POS", "/END"));
    LsReadResult r = LsReader.parse(name + ".LS", String.join("\n", ls) + "\n");
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    control.saveProgram(r.program());
  }

  private double r1() {
    return control.registers().number(1);
  }

  @Test
  void cycleStartOnTheEndWhereTheLastRunEndedSaysTheProgramEndedAtOnce() {
    store("ENDS", "R[1]=R[1]+1", "WAIT 0.50(sec)", "END", "LBL[99]", "R[1]=100");
    keys("""
        SELECT
        ENTER
        TP OFF
        MODE AUTO
        CYCLE START
        WAIT 1
        """);
    assertThat(r1()).isEqualTo(1.0);
    // the run ended on line 3 (END) and the cursor stayed there
    assertThat(p.lcd().statusLine()).contains("LINE 3").contains("ABORTED");
    assertThat(p.lcd().promptLine()).isBlank();
    keys("CYCLE START\nWAIT 1");
    assertThat(r1()).as("nothing ran").isEqualTo(1.0);
    assertThat(p.lcd().promptLine()).contains("line 3").contains("ENDS").contains("END")
        .contains("ended at once").contains("line 1");
    // from line 1 it is an ordinary start, with no notice
    keys("UP\nUP\nCYCLE START\nWAIT 1");
    assertThat(r1()).isEqualTo(2.0);
    assertThat(p.lcd().promptLine()).isBlank();
  }

  @Test
  void shiftFwdOnAnEndInT1SaysTheSame() {
    store("ENDS", "R[1]=R[1]+1", "END", "R[1]=100");
    keys("""
        SELECT
        ENTER
        DOWN
        HOLD DEADMAN
        HOLD SHIFT
        FWD
        WAIT 1
        RELEASE SHIFT
        """);
    assertThat(r1()).isEqualTo(0.0);
    assertThat(p.lcd().promptLine()).contains("line 2 of ENDS, an END").contains("line 1");
  }

  @Test
  void aModeSwitchThatStopsARunSaysWhichProgramPausedAndWhere() {
    store("SLOW", "R[1]=1", "WAIT 5.00(sec)", "R[1]=2");
    keys("""
        SELECT
        ENTER
        TP OFF
        MODE AUTO
        CYCLE START
        WAIT 1
        """);
    assertThat(control.status().state()).isEqualTo(ExecState.RUNNING);
    keys("MODE T1");
    assertThat(control.status().state()).isEqualTo(ExecState.PAUSED);
    assertThat(p.lcd().promptLine()).contains("Mode T1").contains("SLOW paused at line 2");
    // a switch with nothing running only names the mode
    keys("MODE T2");
    assertThat(p.lcd().promptLine().strip()).isEqualTo("Mode T2");
  }
}
