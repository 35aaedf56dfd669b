package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import org.junit.jupiter.api.Test;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/**
 * A program may take a joint onto its limit, and only beyond it is refused: the LR Mate 200iD's
 * data sheet gives J1 −170..+170°, J4 −190..+190°, J5 −125..+125°, J6 −360..+360° as closed
 * ranges (resources/robots/lrmate200id.json; docs/motion.md: "Joint targets outside the limits
 * ... are refused before the arm moves"). The positions below are written in the test in
 * pendant degrees.
 */
class JointLimitProgramSpecTest {
  static Program program(String j1, String j4, String j5, String j6) {
    String ls = """
        /PROG  LIMITS
        /ATTR
        /MN
           1:J P[1] 100% FINE ;
           2:J P[2] 100% FINE ;
        /POS
        P[1]{
           GP1:
        	UF : 0, UT : 1,
        	J1=     0.000 deg,	J2=     0.000 deg,	J3=     0.000 deg,
        	J4=     0.000 deg,	J5=   -90.000 deg,	J6=     0.000 deg
        };
        P[2]{
           GP1:
        	UF : 0, UT : 1,
        	J1= $1 deg,	J2=     0.000 deg,	J3=     0.000 deg,
        	J4= $4 deg,	J5= $5 deg,	J6= $6 deg
        };
        /END
        """.replace("$1", j1).replace("$4", j4).replace("$5", j5).replace("$6", j6);
    LsReadResult r = LsReader.parse("LIMITS.LS", ls);
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    return r.program();
  }

  static HeadlessRun.Result run(Controller c, Simulation sim, Program p) {
    c.saveProgram(p);
    return HeadlessRun.run(sim, c, "LIMITS", 60, s -> {});
  }

  @Test
  void aJointMoveOntoTheUpperAndLowerLimitsRunsAndEndsThere() {
    String[][] cases = {{"170.000", "-190.000", "125.000", "360.000"}, {"-170.000", "190.000", "-125.000", "-360.000"}};
    for (String[] v : cases) {
      Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
      Controller c = sim.controllers().get(0);
      HeadlessRun.Result r = run(c, sim, program(v[0], v[1], v[2], v[3]));
      assertThat(r.status()).as(String.join(" ", v) + ": " + r.alarm().map(ControllerAlarm::display).orElse(""))
          .isEqualTo(HeadlessRun.Status.FINISHED);
      Position.Joint j = c.currentJoints();
      assertThat(j.j1Deg()).isCloseTo(Double.parseDouble(v[0]), offset(1e-9));
      assertThat(j.j4Deg()).isCloseTo(Double.parseDouble(v[1]), offset(1e-9));
      assertThat(j.j5Deg()).isCloseTo(Double.parseDouble(v[2]), offset(1e-9));
      assertThat(j.j6Deg()).isCloseTo(Double.parseDouble(v[3]), offset(1e-9));
    }
  }

  @Test
  void aThousandthOfADegreeBeyondIsRefusedNamingTheJointAndItsLimits() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    HeadlessRun.Result r = run(c, sim, program("170.001", "0.000", "-90.000", "0.000"));
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.ALARM);
    assertThat(r.alarm().orElseThrow().display()).contains("J1").contains("-170.0..170.0");
    assertThat(c.currentJoints().j1Deg()).isCloseTo(0, offset(1e-9));
  }
}
