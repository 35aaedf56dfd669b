package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Xyzwpr;
import org.robotrun.motion.JogState;
import org.robotrun.program.Program;
import org.robotrun.robot.RobotModel;

/** Programs run through the controller: motion, frames, alarms, HOLD, override, determinism. */
class ControllerTest {
  static final RobotModel MODEL = RobotDefinitions.defaultRobot();

  static final String POS = """
      /POS
      P[1:"HOME"]{
         GP1:
      	UF : 1, UT : 1,
      	J1=     0.000 deg,	J2=     0.000 deg,	J3=     0.000 deg,
      	J4=     0.000 deg,	J5=   -90.000 deg,	J6=     0.000 deg
      };
      P[2:"A"]{
         GP1:
      	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
      	X =   350.000  mm,	Y =  -120.000  mm,	Z =    40.000  mm,
      	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
      };
      P[3:"B"]{
         GP1:
      	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
      	X =   350.000  mm,	Y =   150.000  mm,	Z =    40.000  mm,
      	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
      };
      P[4:"FAR"]{
         GP1:
      	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
      	X =  1500.000  mm,	Y =     0.000  mm,	Z =    40.000  mm,
      	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
      };
      P[5:"UF2"]{
         GP1:
      	UF : 2, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
      	X =   350.000  mm,	Y =     0.000  mm,	Z =    40.000  mm,
      	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
      };
      /END
      """;

  static Program program(String name, String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  " + name + "\n/ATTR\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format("%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append(POS);
    LsReadResult r = LsReader.parse(name + ".LS", sb.toString());
    assertThat(r.diagnostics()).as("parse of test program").noneMatch(d -> d.toString().contains("error"));
    return r.program();
  }

  static Program pickPlace() {
    return program("PP",
        "J P[1:HOME] 100% FINE",
        "L P[2:A] 500mm/sec CNT100",
        "L P[3:B] 500mm/sec FINE",
        "RO[1]=ON",
        "WAIT RI[1]=ON",
        "J P[1:HOME] 50% CNT50",
        "L P[2:A] 1000mm/sec FINE",
        "RO[1]=OFF",
        "R[1]=R[1]+1");
  }

  static Simulation cell() {
    return DefaultCell.simulation(MODEL);
  }

  @Test
  void programRunsToItsEndAndLandsOnTheLastPoint() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(pickPlace());
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "PP", 60, s -> {});
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(c.registers().number(1)).isEqualTo(1);
    Xyzwpr tcp = c.tcpInWorld();
    // P[2] in UF1 (= WORLD) with UT1, to 0.01 mm after a FINE move.
    assertThat(tcp.x()).isCloseTo(350, offset(0.01));
    assertThat(tcp.y()).isCloseTo(-120, offset(0.01));
    assertThat(tcp.z()).isCloseTo(40, offset(0.01));
    assertThat(c.lastCycleTimeSec()).isCloseTo(r.cycleTimeSec(), offset(0.0041));
    assertThat(c.motionTimings()).hasSize(5);
    assertThat(c.motionTimings().get(1).line()).isEqualTo(2);
  }

  @Test
  void sameProgramTwiceGivesByteIdenticalTraces() {
    String[] traces = new String[2];
    for (int k = 0; k < 2; k++) {
      Simulation sim = cell();
      Controller c = sim.controllers().get(0);
      c.saveProgram(pickPlace());
      StringWriter out = new StringWriter();
      TraceWriter tw = new TraceWriter(out, sim.controllers());
      HeadlessRun.run(sim, c, "PP", 60, tw::write);
      traces[k] = out.toString();
    }
    assertThat(traces[0].lines().count()).isGreaterThan(300);
    assertThat(traces[0]).isEqualTo(traces[1]);
  }

  @Test
  void halfOverrideTakesTwiceAsLong() {
    double[] cycle = new double[2];
    int k = 0;
    for (int pct : new int[] {100, 50}) {
      Simulation sim = cell();
      Controller c = sim.controllers().get(0);
      c.setOverridePct(pct);
      c.saveProgram(pickPlace());
      cycle[k++] = HeadlessRun.run(sim, c, "PP", 60, s -> {}).cycleTimeSec();
    }
    // docs/motion.md: the override scales the time rate of the path, so at 50 % every move takes exactly twice
    // as long. The one part of the cycle that does not scale is WAIT RI[1]=ON: the stand-in gripper answers
    // after its actuation time (0.1 s) whatever the override. Each of the 6 moves may end a tick or two later.
    double gripper = SimpleGripper.ACTUATION_SEC;
    assertThat(cycle[1] - gripper).isCloseTo((cycle[0] - gripper) * 2, offset(6 * 2 * Simulation.DEFAULT_TICK_SEC));
  }

  @Test
  void unreachablePointIsAnAlarmNamingTheLine() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("FARAWAY", "J P[1:HOME] 100% FINE", "L P[4:FAR] 100mm/sec FINE"));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "FARAWAY", 60, s -> {});
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.ALARM);
    ControllerAlarm a = r.alarm().orElseThrow();
    assertThat(a.code()).isEqualTo(MotionAlarms.UNREACHABLE);
    assertThat(a.program()).isEqualTo("FARAWAY");
    assertThat(a.line()).isEqualTo(2);
    for (double v : c.jointsRad()) {
      assertThat(Double.isFinite(v)).isTrue();
    }
    // RESET clears it; the history keeps it.
    c.reset();
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.alarmHistory()).hasSize(1);
  }

  @Test
  void positionTaughtInAnotherUserFrameIsAFrameMismatch() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("MISMATCH", "L P[5:UF2] 100mm/sec FINE"));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "MISMATCH", 60, s -> {});
    assertThat(r.alarm().orElseThrow().code()).isEqualTo(MotionAlarms.FRAME_MISMATCH);
    assertThat(r.alarm().orElseThrow().line()).isEqualTo(1);
  }

  @Test
  void holdStopsTheArmAndForwardResumes() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(pickPlace());
    c.run("PP", 1, true);
    for (int i = 0; i < 150; i++) {
      sim.step();
    }
    c.hold();
    for (int i = 0; i < 100; i++) {
      sim.step();
    }
    double[] held = c.jointsRad();
    for (int i = 0; i < 50; i++) {
      sim.step();
    }
    assertThat(c.jointsRad()).containsExactly(held);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    c.run("PP", c.status().line(), true);
    for (int i = 0; i < 20_000 && c.busy(); i++) {
      sim.step();
    }
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(c.registers().number(1)).isEqualTo(1);
  }

  @Test
  void jogNeedsTheDeadmanAndMovesInWorld() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    // a controller starts headless, as in AUTO: no jogging until the mode switch turns to T1
    assertThat(c.mode()).isEqualTo(RobotControl.Mode.AUTO);
    assertThat(c.jogKeyDown(1, +1, JogState.Press.HELD)).isInstanceOf(RobotControl.Result.Refused.class);
    c.setMode(RobotControl.Mode.T1);
    c.setDeadman(false);
    assertThat(c.jogKeyDown(1, +1, JogState.Press.HELD)).isInstanceOf(RobotControl.Result.Refused.class);
    c.setDeadman(true);
    c.setCoordSystem(RobotControl.CoordSystem.WORLD);
    Xyzwpr before = c.tcpInWorld();
    assertThat(c.jogKeyDown(3, -1, JogState.Press.HELD)).isInstanceOf(RobotControl.Result.Ok.class);
    for (int i = 0; i < 100; i++) {
      sim.step();
    }
    c.setDeadman(false);
    for (int i = 0; i < 10; i++) {
      sim.step();
    }
    Xyzwpr after = c.tcpInWorld();
    assertThat(after.z()).isLessThan(before.z() - 10);
    assertThat(after.x()).isCloseTo(before.x(), offset(0.01));
    assertThat(after.y()).isCloseTo(before.y(), offset(0.01));
    assertThat(c.jogDirection(3)).isZero();
  }

  @Test
  void overrideChangeAndHoldNeverMakeTheArmJump() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(pickPlace());
    c.run("PP", 1, true);
    double[] prev = c.jointsRad();
    double[] prevV = new double[6];
    double maxDv = 0;
    for (int i = 0; i < 2000 && c.busy(); i++) {
      if (i == 100) {
        c.setOverridePct(20);
      }
      if (i == 200) {
        c.setOverridePct(100);
      }
      if (i == 260) {
        c.hold();
      }
      if (i == 400) {
        c.run("PP", c.status().line(), true);
      }
      sim.step();
      double[] q = c.jointsRad();
      for (int j = 0; j < 6; j++) {
        double v = (q[j] - prev[j]) / Simulation.DEFAULT_TICK_SEC;
        maxDv = Math.max(maxDv, Math.abs(v - prevV[j]) / ControllerTest.MODEL.joint(j).maxSpeedRadPerSec());
        prevV[j] = v;
      }
      prev = q;
    }
    // Speed changes per tick stay a small fraction of each joint's maximum speed (no step).
    assertThat(maxDv).isLessThan(0.05);
  }

  @Test
  void stepModeStopsAfterEachLineAndBackwardReturnsToThePreviousPoint() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(pickPlace());
    c.setStepMode(true);
    c.run("PP", 1, true);
    runUntilStopped(sim, c);
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.PAUSED);
    c.run("PP", c.status().line(), true);
    runUntilStopped(sim, c);
    c.run("PP", c.status().line(), true);
    runUntilStopped(sim, c);
    // Two motion lines done (HOME, then A with CNT run as FINE), then B: the arm stands at B.
    assertThat(c.tcpInWorld().y()).isCloseTo(150, offset(0.01));
    c.run("PP", c.status().line(), false);
    runUntilStopped(sim, c);
    assertThat(c.hasActiveAlarm()).isFalse();
    assertThat(c.tcpInWorld().y()).isCloseTo(-120, offset(0.01));
  }

  /** Steps until the program pauses or ends (in STEP mode a motion line pauses with the arm at its point). */
  static void runUntilStopped(Simulation sim, Controller c) {
    for (int i = 0; i < 10_000 && c.status().state() == ExecutionStatus.State.RUNNING; i++) {
      sim.step();
    }
  }

  static Program jointProgram(String name, String line2, double[]... positionsDeg) {
    StringBuilder sb = new StringBuilder("/PROG  " + name + "\n/ATTR\n/MN\n   1:J P[1] 100% FINE ;\n   2:" + line2
        + " ;\n/POS\n");
    for (int k = 0; k < positionsDeg.length; k++) {
      double[] j = positionsDeg[k];
      sb.append(String.format(java.util.Locale.ROOT, "P[%d]{%n   GP1:%n\tUF : 1, UT : 1,%n"
          + "\tJ1= %.3f deg,\tJ2= %.3f deg,\tJ3= %.3f deg,%n\tJ4= %.3f deg,\tJ5= %.3f deg,\tJ6= %.3f deg%n};%n",
          k + 1, j[0], j[1], j[2], j[3], j[4], j[5]));
    }
    sb.append("/END\n");
    LsReadResult r = LsReader.parse(name + ".LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    return r.program();
  }

  @Test
  void linearMoveThroughTheWristSingularityIsAnAlarmNamingTheLine() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(jointProgram("WRIST", "L P[2] 100mm/sec FINE", new double[] {0, 0, 0, 20, -8, 0},
        new double[] {0, 0, 0, 20, 8, 0}));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "WRIST", 60, s -> {});
    ControllerAlarm a = r.alarm().orElseThrow();
    assertThat(a.code()).isEqualTo(MotionAlarms.SINGULARITY);
    assertThat(a.line()).isEqualTo(2);
    assertThat(a.message()).contains("wrist");
    for (double v : c.jointsRad()) {
      assertThat(Double.isFinite(v)).isTrue();
    }
  }

  @Test
  void jointTargetOutsideTheLimitsIsRefusedBeforeMoving() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(jointProgram("LIMIT", "J P[2] 50% FINE", new double[] {0, 0, 0, 0, -90, 0},
        new double[] {0, 0, 0, 0, -140, 0}));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "LIMIT", 60, s -> {});
    ControllerAlarm a = r.alarm().orElseThrow();
    assertThat(a.code()).isEqualTo(MotionAlarms.JOINT_LIMIT);
    assertThat(a.line()).isEqualTo(2);
    assertThat(c.currentJoints().j5Deg()).isCloseTo(-90, offset(1e-9));
  }

  @Test
  void abortWhileMovingDeceleratesThenEndsTheProgram() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(pickPlace());
    c.run("PP", 1, true);
    for (int i = 0; i < 150; i++) {
      sim.step();
    }
    c.abort();
    double[] prev = c.jointsRad();
    double[] prevV = null;
    int moving = 0;
    for (int i = 0; i < 200; i++) {
      sim.step();
      double[] q = c.jointsRad();
      double[] v = new double[6];
      for (int j = 0; j < 6; j++) {
        v[j] = (q[j] - prev[j]) / Simulation.DEFAULT_TICK_SEC;
        if (prevV != null) {
          // No velocity step: at most 5% of the joint's top speed per tick.
          assertThat(Math.abs(v[j] - prevV[j])).isLessThan(0.05 * MODEL.joint(j).maxSpeedRadPerSec());
        }
      }
      if (java.util.Arrays.stream(v).anyMatch(x -> x != 0)) {
        moving++;
      }
      prevV = v;
      prev = q;
    }
    assertThat(moving).isGreaterThan(3);
    assertThat(c.busy()).isFalse();
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
    assertThat(c.hasActiveAlarm()).isFalse();
  }

  @Test
  void theToolHittingTheFloorIsACollisionAlarm() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("FLOOR", "UFRAME_NUM=1", "UTOOL_NUM=1", "PR[1,1]=480", "PR[1,3]=(-340)", "PR[1,4]=180",
        "L PR[1] 200mm/sec FINE"));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "FLOOR", 60, s -> {});
    ControllerAlarm a = r.alarm().orElseThrow();
    assertThat(a.code()).isEqualTo(Simulation.COLLISION_ALARM);
    assertThat(a.line()).isEqualTo(6);
    assertThat(a.message()).isEqualTo("collision: robot1 tool touches floor");
    // The floor is 330 mm below WORLD: the tip stopped there (to one tick of travel).
    assertThat(c.tcpInWorld().z()).isBetween(-331.0, -329.0);
    assertThat(sim.collisionEvents()).hasSize(1);
    // The snapshot shows the tool in contact red.
    var tool = sim.snapshot().scene().items().stream().filter(d -> d.name().equals("robot1/tool")).findFirst().orElseThrow();
    assertThat(tool.color()).isEqualTo(Simulation.TOUCHING);
  }

  @Test
  void anArmWithoutAClosedFormUsesTheNumericSolver() {
    RobotModel m = MODEL;
    RobotModel noOpw = new RobotModel(m.id() + "-numeric", m.displayName(), m.joints(), m.X_6F(), m.X_WB(), m.links(),
        java.util.Optional.empty(), m.coupledJ3());
    Controller c = DefaultCell.controller(noOpw);
    Simulation sim = Simulation.of(c);
    c.saveProgram(program("NUM", "J P[2:A] 50% FINE", "L P[3:B] 300mm/sec FINE"));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "NUM", 60, s -> {});
    assertThat(r.status()).as(r.alarm().map(ControllerAlarm::display).orElse("")).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(c.tcpInWorld().y()).isCloseTo(150, offset(0.01));
  }

  @Test
  void headlessRunResumesAfterPause() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("PAUSING", "R[1]=1", "PAUSE", "R[1]=2"));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "PAUSING", 10, s -> {});
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(c.registers().number(1)).isEqualTo(2);
  }

  @Test
  void jointMoveOnTheCsvTraceArrivesTogetherWithinSpeedAndAcceleration() {
    Simulation sim = cell();
    Controller c = sim.controllers().get(0);
    c.saveProgram(jointProgram("JMOVE", "J P[2] 100% FINE", new double[] {0, 0, 0, 0, -90, 0},
        new double[] {70, 25, -20, 120, -30, 200}));
    StringWriter out = new StringWriter();
    TraceWriter tw = new TraceWriter(out, sim.controllers());
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "JMOVE", 60, tw::write);
    assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
    List<double[]> rows = out.toString().lines().skip(1)
        .map(l -> java.util.Arrays.stream(l.split(",")).mapToDouble(Double::parseDouble).toArray()).toList();
    double dt = Simulation.DEFAULT_TICK_SEC;
    double[] prevV = new double[6];
    int[] arrived = new int[6];
    double[] last = rows.get(rows.size() - 1);
    for (int k = 1; k < rows.size(); k++) {
      for (int j = 0; j < 6; j++) {
        // Limits hold for kinematic joints: J3 kinematic = J3 + J2 on the pendant.
        double now = rows.get(k)[1 + j] + (j == 2 ? rows.get(k)[2] : 0);
        double before = rows.get(k - 1)[1 + j] + (j == 2 ? rows.get(k - 1)[2] : 0);
        double v = (now - before) / dt;
        double vMax = Math.toDegrees(MODEL.joint(j).maxSpeedRadPerSec());
        // Trace values carry 1e-6 deg: tolerances are that rounding, far below the limits.
        assertThat(Math.abs(v)).isLessThanOrEqualTo(vMax * (1 + 1e-6) + 1e-3);
        assertThat(Math.abs(v - prevV[j]) / dt).isLessThanOrEqualTo(vMax / 0.25 * (1 + 1e-6) + 1);
        prevV[j] = v;
        if (arrived[j] == 0 && Math.abs(rows.get(k)[1 + j] - last[1 + j]) < 1e-6) {
          arrived[j] = k;
        }
      }
    }
    // Every joint reaches its target on the same tick.
    assertThat(java.util.Arrays.stream(arrived).distinct().count()).isEqualTo(1);
  }
}
