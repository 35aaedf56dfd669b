package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.robotrun.sim.TaskProgs.steps;

import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.math.Xyzwpr;

/**
 * docs/alarms.md, severity SERVO (E-stop, DEADMAN): the arm stops at once, without decelerating
 * along its path; the program pauses; RESET needs every E-stop released; then SHIFT+FWD resumes
 * the interrupted move from where the arm stands to its target, and the program goes on. A move
 * the arm was blending out of (CNT) counts as done. The targets are ControllerTest's P[2:A]
 * (350, -120, 40) and P[3:B] (350, 150, 40) in WORLD, tool pointing down.
 */
class ServoStopResumeTest {

  private static void assertAt(Controller c, double x, double y, double z) {
    Xyzwpr t = c.tcpInWorld();
    assertThat(t.x()).isCloseTo(x, within(0.01));
    assertThat(t.y()).isCloseTo(y, within(0.01));
    assertThat(t.z()).isCloseTo(z, within(0.01));
  }

  private static void runToEnd(Simulation sim, Controller c) {
    for (int i = 0; i < 5000 && c.busy(); i++) {
      sim.step();
    }
  }

  @Test
  void anEstopStopsTheArmAtOnceAndShiftFwdResumesTheMoveToItsTarget() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(ControllerTest.program("GO", "J P[1:HOME] 100% FINE", "L P[2:A] 100mm/sec FINE", "R[1]=1"));
    c.run("GO", 1, true);
    // HOME is where the arm stands; the line to A is about 190 mm long at 100 mm/s
    steps(sim, 250);
    Xyzwpr before = c.tcpInWorld();
    c.emergencyStop(false);
    sim.step();
    Xyzwpr at = c.tcpInWorld();
    // at 100 mm/s a decelerating arm would still travel; a servo stop does not move one more tick
    assertThat(Math.hypot(at.x() - before.x(), at.y() - before.y())).isLessThan(0.5);
    steps(sim, 50);
    Xyzwpr later = c.tcpInWorld();
    assertThat(later.x()).isEqualTo(at.x());
    assertThat(later.y()).isEqualTo(at.y());
    assertThat(c.status().state()).isNotEqualTo(ExecutionStatus.State.RUNNING);
    assertThat(c.servoOff()).isTrue();
    // RESET before the release does nothing; after it, SHIFT+FWD goes on
    c.reset();
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-001");
    c.releaseEmergencyStop();
    c.reset();
    assertThat(c.run("GO", c.status().line(), true)).isInstanceOf(RobotControl.Result.Ok.class);
    runToEnd(sim, c);
    assertThat(c.activeAlarms()).isEmpty();
    assertAt(c, 350, -120, 40);
    assertThat(c.registers().number(1)).isEqualTo(1);
  }

  @Test
  void aDeadmanReleaseInABlendedMoveResumesToTheLastTarget() {
    Simulation sim = ControllerTest.cell();
    Controller c = sim.controllers().get(0);
    c.setMode(RobotControl.Mode.T2);
    c.saveProgram(ControllerTest.program("CNT", "J P[1:HOME] 100% FINE", "L P[2:A] 300mm/sec CNT100",
        "L P[3:B] 300mm/sec FINE", "R[2]=1"));
    c.run("CNT", 1, true);
    // run until the arm is past A's blend and on its way to B
    for (int i = 0; i < 2000 && c.tcpInWorld().y() < 0; i++) {
      sim.step();
    }
    steps(sim, 20);
    assertThat(c.tcpInWorld().y()).isBetween(0.0, 150.0);
    c.deadmanReleased();
    steps(sim, 10);
    assertThat(c.activeAlarms()).extracting(ControllerAlarm::code).containsExactly("SRVO-003");
    double y = c.tcpInWorld().y();
    steps(sim, 10);
    assertThat(c.tcpInWorld().y()).isEqualTo(y);
    c.reset();
    assertThat(c.run("CNT", c.status().line(), true)).isInstanceOf(RobotControl.Result.Ok.class);
    runToEnd(sim, c);
    assertThat(c.activeAlarms()).isEmpty();
    assertAt(c, 350, 150, 40);
    assertThat(c.registers().number(2)).isEqualTo(1);
  }
}
