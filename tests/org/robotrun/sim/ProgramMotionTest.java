package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.IoKind;
import org.robotrun.program.Program;

/** C, A, Offset, Tool_Offset and INC motions as a program states them, checked on the TCP path. */
class ProgramMotionTest {
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
      P[4:"VIA"]{
         GP1:
      	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
      	X =   450.000  mm,	Y =    15.000  mm,	Z =    40.000  mm,
      	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
      };
      P[5:"STEP"]{
         GP1:
      	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
      	X =     0.000  mm,	Y =    20.000  mm,	Z =     0.000  mm,
      	W =     0.000 deg,	P =     0.000 deg,	R =     0.000 deg
      };
      /END
      """;

  record Sample(double t, Vec3 p) {}

  static Program program(String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  FORMS\n/ATTR\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format("%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append(POS);
    LsReadResult r = LsReader.parse("FORMS.LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    return r.program();
  }

  static List<Sample> run(Controller c, Simulation sim) {
    List<Sample> samples = new ArrayList<>();
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "FORMS", 120,
        s -> samples.add(new Sample(s.timeSec(), c.tcpInWorld().position())));
    assertThat(r.status()).as(r.alarm().map(ControllerAlarm::display).orElse("")).isEqualTo(HeadlessRun.Status.FINISHED);
    return samples;
  }

  /** Largest distance (mm) of the samples of program line {@code line} from the circle through a, b, c. */
  static double offCircle(Controller c, List<Sample> samples, int line, Vec3 a, Vec3 b, Vec3 cc) {
    MotionTiming m = c.motionTimings().stream().filter(x -> x.line() == line).findFirst().orElseThrow();
    Vec3 u = b.minus(a);
    Vec3 v = cc.minus(a);
    Vec3 n = u.cross(v);
    Vec3 o = n.cross(u).times(v.dot(v)).plus(v.cross(n).times(u.dot(u))).times(1 / (2 * n.dot(n)));
    Vec3 center = a.plus(o);
    double radius = o.norm();
    Vec3 nHat = n.normalized();
    double worst = 0;
    for (Sample s : samples) {
      if (s.t() >= m.startSec() && s.t() <= m.endSec()) {
        Vec3 d = s.p().minus(center);
        double inPlane = d.minus(nHat.times(d.dot(nHat))).norm();
        worst = Math.max(worst, Math.hypot(inPlane - radius, d.dot(nHat)));
      }
    }
    return worst;
  }

  static final Vec3 A = new Vec3(350, -120, 40);
  static final Vec3 B = new Vec3(350, 150, 40);
  static final Vec3 VIA = new Vec3(450, 15, 40);

  @Test
  void circularMoveFollowsTheCircleThroughItsThreePoints() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE", "C P[4:VIA]\n    :  P[3:B] 300mm/sec FINE"));
    List<Sample> samples = run(c, sim);
    assertThat(offCircle(c, samples, 3, A, VIA, B)).isLessThanOrEqualTo(0.1);
    assertThat(c.tcpInWorld().position().distanceTo(B)).isLessThan(0.01);
  }

  @Test
  void arcMovesContinueTheCircleThroughConsecutivePoints() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("J P[1:HOME] 100% FINE", "L P[3:B] 500mm/sec FINE",
        "A P[2:A] 200mm/sec FINE", "A P[4:VIA] 200mm/sec FINE", "A P[3:B] 200mm/sec FINE"));
    List<Sample> samples = run(c, sim);
    // Lines 4 and 5 lie on the circle through B, A, VIA (= the circle through A, VIA, B).
    assertThat(offCircle(c, samples, 4, B, A, VIA)).isLessThanOrEqualTo(0.1);
    assertThat(offCircle(c, samples, 5, A, VIA, B)).isLessThanOrEqualTo(0.1);
    assertThat(c.tcpInWorld().position().distanceTo(B)).isLessThan(0.01);
  }

  @Test
  void offsetToolOffsetAndIncShiftTheTarget() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    // PAUSE after each stage: the test reads the TCP there and resumes.
    c.saveProgram(program("PR[1,3]=50", "PR[2,3]=(-30)", "J P[1:HOME] 100% FINE",
        "L P[2:A] 500mm/sec FINE Offset,PR[1]", "PAUSE",
        "L P[2:A] 500mm/sec FINE Tool_Offset,PR[2]", "PAUSE",
        "L P[5:STEP] 100mm/sec FINE INC"));
    c.run("FORMS", 1, true);
    List<Xyzwpr> atPauses = new ArrayList<>();
    for (int i = 0; i < 50_000 && (c.busy() || atPauses.isEmpty()); i++) {
      sim.step();
      if (c.status().state() == ExecutionStatus.State.PAUSED) {
        atPauses.add(c.tcpInWorld());
        c.run("FORMS", c.status().line(), true);
      }
    }
    assertThat(c.hasActiveAlarm()).isFalse();
    assertThat(atPauses).hasSize(2);
    // Offset adds PR[1] in the user frame: 50 mm up.
    assertThat(atPauses.get(0).z()).isCloseTo(90, offset(0.01));
    // Tool_Offset moves along the tool's z, which points down: −30 is 30 mm up.
    assertThat(atPauses.get(1).z()).isCloseTo(70, offset(0.01));
    assertThat(atPauses.get(1).x()).isCloseTo(350, offset(0.01));
    // INC adds P[5] (20 mm in y) to where the arm is.
    Xyzwpr end = c.tcpInWorld();
    assertThat(end.y()).isCloseTo(-100, offset(0.01));
    assertThat(end.z()).isCloseTo(70, offset(0.01));
  }

  @Test
  void skipConditionStopsTheArmBetweenItsPointsAndTheNextLineRuns() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE", "SKIP CONDITION DI[1]=ON",
        "L P[3:B] 100mm/sec FINE Skip,LBL[1]", "R[1]=1", "LBL[1]", "R[2]=2"));
    c.run("FORMS", 1, true);
    int steps = 0;
    while (c.status().line() != 4 && steps++ < 10_000) {
      sim.step();
    }
    // One second into the 2.7 s move from A to B, the sensor sees the part.
    for (int i = 0; i < 250; i++) {
      sim.step();
    }
    assertThat(c.status().line()).isEqualTo(4);
    c.registers().setBit(IoKind.DI, 1, true);
    for (int i = 0; i < 10_000 && c.busy(); i++) {
      sim.step();
    }
    assertThat(c.activeAlarms()).isEmpty();
    // The line after the motion ran (no jump), and the arm stopped short of B, on the line A-B.
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.registers().number(2)).isEqualTo(2);
    Vec3 p = c.tcpInWorld().position();
    assertThat(p.distanceTo(B)).isGreaterThan(100);
    assertThat(p.distanceTo(A)).isGreaterThan(50);
    assertThat(p.distanceTo(A) + p.distanceTo(B)).isCloseTo(A.distanceTo(B), org.assertj.core.data.Offset.offset(0.5));
  }

  @Test
  void timeBeforeTimeAfterAndDistanceBeforeSetTheirOutputsAtTheRightMoment() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE",
        "L P[3:B] 100mm/sec FINE TB 1.00sec,DO[1]=ON", "L P[2:A] 100mm/sec FINE TA .50sec,DO[2]=ON",
        "WAIT 1.00(sec)", "L P[3:B] 100mm/sec FINE DB 50.0mm,DO[3]=ON", "R[1]=1"));
    c.run("FORMS", 1, true);
    double doneB = -1;
    double on1 = -1;
    double doneA = -1;
    double on2 = -1;
    Vec3 at3 = null;
    for (int i = 0; i < 20_000 && c.busy(); i++) {
      sim.step();
      double t = sim.timeSec();
      int line = c.status().line();
      if (on1 < 0 && c.registers().bit(IoKind.DO, 1)) {
        on1 = t;
      }
      if (doneB < 0 && line == 4) {
        doneB = t;
      }
      if (doneA < 0 && line == 5) {
        doneA = t;
      }
      if (on2 < 0 && c.registers().bit(IoKind.DO, 2)) {
        on2 = t;
      }
      if (at3 == null && c.registers().bit(IoKind.DO, 3)) {
        at3 = c.tcpInWorld().position();
      }
    }
    // DO[3] turns on as the TCP comes within 50 mm of B (straight line), to within one tick's travel
    assertThat(at3).isNotNull();
    assertThat(at3.distanceTo(B)).isCloseTo(50, org.assertj.core.data.Offset.offset(100 * sim.tickSec() + 0.01));
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(1)).isEqualTo(1);
    double tick = sim.tickSec();
    // DO[1] turns on one second before the arm reaches B; DO[2] half a second after it is back at A
    assertThat(doneB - on1).isCloseTo(1.0, org.assertj.core.data.Offset.offset(2 * tick + 0.01));
    assertThat(on2 - doneA).isCloseTo(0.5, org.assertj.core.data.Offset.offset(2 * tick + 0.01));
  }

  /** A program with no positions, named {@code name}. */
  static Program plain(String name, String... lines) {
    return plainWithAttr(name, "", lines);
  }

  /** A program with no positions and no motion group, as TIME BEFORE/AFTER and DISTANCE BEFORE may CALL. */
  static Program groupless(String name, String... lines) {
    return plainWithAttr(name, "DEFAULT_GROUP\t= *,*,*,*,*;\n", lines);
  }

  private static Program plainWithAttr(String name, String attr, String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  " + name + "\n/ATTR\n" + attr + "/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format("%4d:  %s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\n/END\n");
    LsReadResult r = LsReader.parse(name + ".LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    return r.program();
  }

  @Test
  void timeBeforeTimeAfterAndDistanceBeforeCallTheirProgramBesideTheMotion() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    // SIGNAL sets DO[R[9]], waits 0.3 s (the motion goes on meanwhile, not delayed), then counts in R[8].
    c.saveProgram(groupless("SIGNAL", "DO[R[9]]=ON", "WAIT .30(sec)", "R[8]=R[8]+1"));
    c.saveProgram(program("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE", "R[9]=1",
        "L P[3:B] 100mm/sec FINE TB 1.00sec,CALL SIGNAL", "R[9]=2", "L P[2:A] 100mm/sec FINE TA .50sec,CALL SIGNAL",
        "WAIT 1.00(sec)", "R[9]=3", "L P[3:B] 100mm/sec FINE DB 50.0mm,CALL SIGNAL", "WAIT .50(sec)", "R[1]=1"));
    c.run("FORMS", 1, true);
    double doneB = -1;
    double on1 = -1;
    double doneA = -1;
    double on2 = -1;
    Vec3 at3 = null;
    boolean overlapped = false;
    for (int i = 0; i < 20_000 && c.busy(); i++) {
      sim.step();
      double t = sim.timeSec();
      int line = c.status().line();
      if (on1 < 0 && c.registers().bit(IoKind.DO, 1)) {
        on1 = t;
      }
      // The called program's WAIT ran while the motion went on: SIGNAL was done before B was reached.
      if (doneB < 0 && line >= 5) {
        doneB = t;
        overlapped = c.registers().number(8) == 1;
      }
      if (doneA < 0 && line == 7) {
        doneA = t;
      }
      if (on2 < 0 && c.registers().bit(IoKind.DO, 2)) {
        on2 = t;
      }
      if (at3 == null && c.registers().bit(IoKind.DO, 3)) {
        at3 = c.tcpInWorld().position();
      }
    }
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().number(1)).isEqualTo(1);
    assertThat(c.registers().number(8)).as("SIGNAL ran to its end three times").isEqualTo(3);
    double tick = sim.tickSec();
    assertThat(doneB - on1).isCloseTo(1.0, org.assertj.core.data.Offset.offset(2 * tick + 0.01));
    assertThat(overlapped).isTrue();
    assertThat(on2 - doneA).isCloseTo(0.5, org.assertj.core.data.Offset.offset(2 * tick + 0.01));
    assertThat(at3).isNotNull();
    assertThat(at3.distanceTo(B)).isCloseTo(50, org.assertj.core.data.Offset.offset(100 * tick + 0.01));
  }

  @Test
  void aTimeAfterActionPendingWhenTheProgramEndsIsDroppedNotThrownLater() {
    // The action would alarm (no such program); before, it fired after END and its alarm escaped the tick.
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE TA 1.00sec,CALL NOSUCH"));
    c.run("FORMS", 1, true);
    for (int i = 0; i < 20_000 && c.busy(); i++) {
      sim.step();
    }
    for (int i = 0; i < 500; i++) {  // 2 s more: past the moment the action was due
      sim.step();
    }
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.status().state()).isEqualTo(ExecutionStatus.State.IDLE);
  }

  @Test
  void aProgramCalledByTimeBeforeMustHaveNoMotionGroup() {
    // INTP-129 (the controller refuses the CALL when the called program has a motion group, moving or not).
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(plain("SIGNAL", "DO[1]=ON"));
    c.saveProgram(program("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE TB .50sec,CALL SIGNAL", "R[1]=1"));
    c.run("FORMS", 1, true);
    for (int i = 0; i < 20_000 && c.busy(); i++) {
      sim.step();
    }
    assertThat(c.activeAlarms()).singleElement().satisfies(a -> {
      assertThat(a.code()).isEqualTo("INTP-129");
      assertThat(a.message()).contains("SIGNAL has motion group 1");
    });
    assertThat(c.registers().bit(IoKind.DO, 1)).as("SIGNAL never ran").isFalse();
    assertThat(c.registers().number(1)).isZero();
  }

  @Test
  void aTimeBeforeCallPassesItsArgumentsReadWhenTheActionFires() {
    // TB ...,CALL PROG(args): the arguments land in the program's AR[] as with a CALL (read when it fires).
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(groupless("SIGNAL", "DO[AR[1]]=ON", "R[7]=AR[2]"));
    c.saveProgram(program("J P[1:HOME] 100% FINE", "R[5]=2.5", "L P[2:A] 500mm/sec FINE TB .50sec,CALL SIGNAL(4,R[5])",
        "R[1]=1"));
    c.run("FORMS", 1, true);
    for (int i = 0; i < 20_000 && c.busy(); i++) {
      sim.step();
    }
    assertThat(c.activeAlarms()).isEmpty();
    assertThat(c.registers().bit(IoKind.DO, 4)).isTrue();
    assertThat(c.registers().number(7)).isEqualTo(2.5);
    assertThat(c.registers().number(1)).isEqualTo(1);
  }

  @Test
  void aProgramCalledByTimeBeforeMayNotMove() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    // A program without a motion group that still holds a motion line (the controller's editor would not let it).
    c.saveProgram(groupless("MOVER", "J PR[1] 100% FINE"));
    c.saveProgram(program("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE TB .50sec,CALL MOVER"));
    c.run("FORMS", 1, true);
    for (int i = 0; i < 20_000 && c.busy(); i++) {
      sim.step();
    }
    assertThat(c.activeAlarms()).singleElement().satisfies(a -> assertThat(a.message())
        .contains("MOVER called by TIME BEFORE moves the robot"));
  }

  @Test
  void moveToGoesToATaughtPosition() {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    var target = new org.robotrun.program.Position.Cartesian(350, -120, 40, 180, 0, 0, org.robotrun.program.Config.DEFAULT);
    assertThat(c.moveTo(target, 1, 1)).isInstanceOf(RobotControl.Result.Ok.class);
    for (int i = 0; i < 5000 && c.busy(); i++) {
      sim.step();
    }
    assertThat(c.tcpInWorld().position().distanceTo(A)).isLessThan(0.01);
    var far = new org.robotrun.program.Position.Cartesian(3000, 0, 40, 180, 0, 0, org.robotrun.program.Config.DEFAULT);
    assertThat(c.moveTo(far, 1, 1)).isInstanceOf(RobotControl.Result.Refused.class);
    // HOLD stops a MOVE_TO half-way; a new MOVE_TO replaces it.
    var b = new org.robotrun.program.Position.Cartesian(350, 150, 40, 180, 0, 0, org.robotrun.program.Config.DEFAULT);
    assertThat(c.moveTo(b, 1, 1)).isInstanceOf(RobotControl.Result.Ok.class);
    for (int i = 0; i < 100; i++) {
      sim.step();
    }
    c.hold();
    for (int i = 0; i < 100; i++) {
      sim.step();
    }
    assertThat(c.moveTo(target, 1, 1)).isInstanceOf(RobotControl.Result.Ok.class);
    for (int i = 0; i < 5000 && c.busy(); i++) {
      sim.step();
    }
    assertThat(c.tcpInWorld().position().distanceTo(A)).isLessThan(0.01);
  }
}
