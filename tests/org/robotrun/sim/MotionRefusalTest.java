package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.program.Program;

/**
 * What a motion line is refused with before the arm moves, each with the code of docs/alarms.md
 * (INTP-304 a register speed not above 0, SIMU-008 above 100 %, SIMU-009 invalid offset, MOTN-017 a joint target outside the data
 * sheet's limits of resources/robots/lrmate200id.json, J3 named with the pendant's coupling) and
 * its line: the run ends on the alarm and the arm stands where it started (HOME).
 */
class MotionRefusalTest {
  private static final double[] HOME = {0, 0, 0, 0, -90, 0};

  private static ControllerAlarm runToAlarm(Program p) {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(p);
    HeadlessRun.Result r = HeadlessRun.run(sim, c, p.name(), 30, s -> {});
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.ALARM);
    ControllerAlarm a = r.alarm().orElseThrow();
    assertThat(a.program()).isEqualTo(p.name());
    for (int i = 1; i <= 6; i++) {
      assertThat(c.currentJoints().element(i)).isCloseTo(HOME[i - 1], org.assertj.core.data.Offset.offset(1e-6));
    }
    return a;
  }

  @Test
  void aRegisterSpeedNotAboveZeroIsIntp304AndAPercentageAboveAHundredSimu008() {
    // docs/alarms.md INTP-304: "a speed not above 0"; SIMU-008: a speed out of range for its unit (1..100 %)
    for (String[] k : new String[][] {{"0", "L P[2:A] R[1]mm/sec FINE"}, {"-5", "J P[2:A] R[1]% FINE"}}) {
      ControllerAlarm a = runToAlarm(ControllerTest.program("SPD", "R[1]=" + k[0], k[1]));
      assertThat(a.code()).as(k[0]).isEqualTo("INTP-304");
      assertThat(a.line()).as(k[0]).isEqualTo(2);
    }
    ControllerAlarm over = runToAlarm(ControllerTest.program("SPD101", "R[1]=101", "J P[2:A] R[1]% FINE"));
    assertThat(over.code()).isEqualTo("SIMU-008");
    assertThat(over.line()).isEqualTo(2);
    assertThat(over.message()).contains("at most 100%").contains("101");
    // 100 % is the top of the range: it runs
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(ControllerTest.program("SPD100", "R[1]=100", "J P[2:A] R[1]% FINE"));
    assertThat(HeadlessRun.run(sim, c, "SPD100", 30, s -> {}).status()).isEqualTo(HeadlessRun.Status.FINISHED);
  }

  @Test
  void aJointPrCannotOffsetACartesianTargetNorBeAToolOffset() {
    ControllerAlarm off = runToAlarm(ControllerTest.program("OFFJ", "PR[1]=JPOS", "L P[2:A] 100mm/sec FINE Offset,PR[1]"));
    assertThat(off.code()).isEqualTo("SIMU-009");
    assertThat(off.line()).isEqualTo(2);
    assertThat(off.message()).contains("joint PR cannot offset");
    ControllerAlarm tool = runToAlarm(ControllerTest.program("TOFFJ", "PR[1]=JPOS",
        "L P[2:A] 100mm/sec FINE Tool_Offset,PR[1]"));
    assertThat(tool.code()).isEqualTo("SIMU-009");
    assertThat(tool.message()).contains("Tool_Offset needs a Cartesian PR");
  }

  @Test
  void aJointTargetOutsideTheDataSheetLimitsIsMotn017NamingTheJointAndItsRange() {
    ControllerAlarm j1 = runToAlarm(ControllerTest.jointProgram("J1OUT", "J P[2] 50% FINE", HOME,
        new double[] {200, 0, 0, 0, -90, 0}));
    assertThat(j1.code()).isEqualTo("MOTN-017");
    assertThat(j1.line()).isEqualTo(2);
    assertThat(j1.message()).contains("needs J1 = 200.0 deg, outside -170.0..170.0 deg").doesNotContain("J2 + J3");
    ControllerAlarm j6 = runToAlarm(ControllerTest.jointProgram("J6OUT", "J P[2] 50% FINE", HOME,
        new double[] {0, 0, 0, 0, -90, 400}));
    assertThat(j6.message()).contains("needs J6 = 400.0 deg, outside -360.0..360.0 deg");
    // J3's limits hold for J2 + J3 as the pendant shows them (FANUC's coupled J3): J2 = 0, J3 = -80 is below -70
    ControllerAlarm j3 = runToAlarm(ControllerTest.jointProgram("J3OUT", "J P[2] 50% FINE", HOME,
        new double[] {0, 0, -80, 0, -90, 0}));
    assertThat(j3.code()).isEqualTo("MOTN-017");
    assertThat(j3.message()).contains("needs J3 = ").contains("(J2 + J3 as the pendant shows them)")
        .contains("outside -70.0..205.0 deg");
  }
}
