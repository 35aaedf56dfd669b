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
import org.robotrun.program.Program;

/**
 * Motion timing against the specification, not against the code's own output (issue 31): each
 * expected duration is computed here from the robot's data sheet (the joint speeds in
 * {@code resources/robots/lrmate200id.json}, read here with a plain JSON parser) and the ramps
 * {@code docs/motion.md} documents, then compared with what a real program takes on the
 * controller, for J, L and C moves and every speed unit a program can state.
 *
 * <p>The rules used (docs/motion.md, "Moves"): every move is one trapezoid over its path. A J move
 * at n% runs each joint at most at n% of its maximum speed and accelerates each joint at most at
 * its maximum speed per 0.25 s; the slowest joint sets the pace. An L or C move reaches its
 * commanded TCP speed in 0.2 s, and the orientation turns at most 180 °/s (reached in 0.2 s as
 * well), or at the {@code deg/sec} speed. {@code sec}/{@code msec} give the duration. The
 * override scales the time rate (50 % takes twice as long). Ticks are 4 ms, so a measured time is
 * within a tick or two of the exact one.
 */
class MotionTimingSpecTest {
  static final double TICK = Simulation.DEFAULT_TICK_SEC;
  /** A measured duration may be late by the tick in which the move ends and the one it starts in. */
  static final double TICKS_2 = 2 * TICK + 1e-9;

  static final double JOINT_ACCEL_TIME = 0.25; // docs/motion.md: a joint reaches its maximum speed in 0.25 s
  static final double LINEAR_ACCEL_TIME = 0.2; // docs/motion.md: the commanded speed is reached in 0.2 s
  static final double ROTATION_MAX_DEG_S = 180; // docs/motion.md: the TCP never turns faster than 180 °/s

  /** Maximum joint speeds (deg/s) from the robot's data file, J1..J6. */
  static final double[] DATA_SHEET_DEG_S = org.robotrun.DataSheet.maxSpeedsDegPerSec();

  /** Time (s) to cover {@code d} from rest to rest at peak speed {@code v} and acceleration {@code a} (trapezoid or triangle). */
  static double trapezoid(double d, double v, double a) {
    if (d <= 0) {
      return 0;
    }
    return d * a >= v * v ? d / v + v / a : 2 * Math.sqrt(d / a);
  }

  /** A J move's duration: the slowest joint of a joint-space trapezoid at {@code pct}% and ACC{@code acc}. */
  static double jointMoveSec(double[] fromDeg, double[] toDeg, double pct, double acc) {
    double t = 0;
    for (int i = 0; i < 6; i++) {
      double vmax = DATA_SHEET_DEG_S[i];
      t = Math.max(t, trapezoid(Math.abs(toDeg[i] - fromDeg[i]), pct / 100 * vmax, Math.min(1, acc / 100) * vmax / JOINT_ACCEL_TIME));
    }
    return t;
  }

  /** An L/C move's duration: path length at {@code mmPerSec}, orientation change at most 180 °/s. */
  static double cartesianMoveSec(double lengthMm, double mmPerSec, double turnDeg) {
    return Math.max(trapezoid(lengthMm, mmPerSec, mmPerSec / LINEAR_ACCEL_TIME),
        trapezoid(turnDeg, ROTATION_MAX_DEG_S, ROTATION_MAX_DEG_S / LINEAR_ACCEL_TIME));
  }

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
      	X =   470.000  mm,	Y =     0.000  mm,	Z =    40.000  mm,
      	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
      };
      P[5:"C_END"]{
         GP1:
      	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
      	X =   350.000  mm,	Y =   120.000  mm,	Z =    40.000  mm,
      	W =   180.000 deg,	P =     0.000 deg,	R =     0.000 deg
      };
      P[6:"TURNED"]{
         GP1:
      	UF : 1, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
      	X =   350.000  mm,	Y =  -120.000  mm,	Z =    40.000  mm,
      	W =   180.000 deg,	P =     0.000 deg,	R =    90.000 deg
      };
      P[7:"J1J4"]{
         GP1:
      	UF : 1, UT : 1,
      	J1=    90.000 deg,	J2=     0.000 deg,	J3=     0.000 deg,
      	J4=   120.000 deg,	J5=   -90.000 deg,	J6=     0.000 deg
      };
      P[8:"J6"]{
         GP1:
      	UF : 1, UT : 1,
      	J1=     0.000 deg,	J2=     0.000 deg,	J3=     0.000 deg,
      	J4=     0.000 deg,	J5=   -90.000 deg,	J6=   300.000 deg
      };
      P[9:"SHORT"]{
         GP1:
      	UF : 1, UT : 1,
      	J1=     5.000 deg,	J2=     0.000 deg,	J3=     0.000 deg,
      	J4=     0.000 deg,	J5=   -90.000 deg,	J6=     0.000 deg
      };
      /END
      """;

  static final double[] HOME = {0, 0, 0, 0, -90, 0};
  static final double[] J1J4 = {90, 0, 0, 120, -90, 0};
  static final double[] J6 = {0, 0, 0, 0, -90, 300};
  static final double[] SHORT = {5, 0, 0, 0, -90, 0};
  static final Vec3 A = new Vec3(350, -120, 40);
  static final Vec3 B = new Vec3(350, 150, 40);

  static Program program(String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  TIMING\n/ATTR\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format("%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append(POS);
    LsReadResult r = LsReader.parse("TIMING.LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    return r.program();
  }

  /** Runs the program at {@code overridePct} and returns every motion line's duration (s), in order. */
  static List<Double> durations(int overridePct, String... lines) {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.setOverridePct(overridePct);
    c.saveProgram(program(lines));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "TIMING", 120, s -> {});
    assertThat(r.status()).as(r.alarm().map(ControllerAlarm::display).orElse("")).isEqualTo(HeadlessRun.Status.FINISHED);
    List<Double> out = new ArrayList<>();
    for (MotionTiming m : c.motionTimings()) {
      out.add(m.durationSec());
    }
    return out;
  }

  @Test
  void jointMoveAtPercentTakesTheSlowestJointsTrapezoid() {
    // HOME -> J1 +90°, J4 +120°. At 100 % neither joint reaches its top speed (accelerating for 0.25 s to 450 °/s
    // takes 56° of J1's 45° half-way point), so both are triangles: J1 2·sqrt(90/1800) = 0.447 s, J4 (550 °/s,
    // 2200 °/s²) 2·sqrt(120/2200) = 0.467 s: J4 paces. At 30 % J4 cruises: 120/165 + 0.075 = 0.802 s.
    // 10 % of J6 over 300°: 300/100 + 0.025 = 3.025 s (J6's 1000 °/s on the data sheet).
    List<Double> t = durations(100, "J P[1:HOME] 100% FINE", "J P[7:J1J4] 100% FINE", "J P[1:HOME] 30% FINE",
        "J P[8:J6] 10% FINE", "J P[1:HOME] 100% FINE ACC50", "J P[9:SHORT] 100% FINE");
    assertThat(t.get(0)).isCloseTo(0, offset(TICKS_2));
    assertThat(t.get(1)).isCloseTo(jointMoveSec(HOME, J1J4, 100, 100), offset(TICKS_2));
    assertThat(jointMoveSec(HOME, J1J4, 100, 100)).isCloseTo(2 * Math.sqrt(120.0 / 2200), offset(1e-12));
    assertThat(jointMoveSec(J1J4, HOME, 30, 100)).isCloseTo(120.0 / 165 + 0.075, offset(1e-12));
    assertThat(t.get(2)).isCloseTo(jointMoveSec(J1J4, HOME, 30, 100), offset(TICKS_2));
    assertThat(t.get(3)).isCloseTo(jointMoveSec(HOME, J6, 10, 100), offset(TICKS_2));
    assertThat(jointMoveSec(HOME, J6, 10, 100)).isCloseTo(3.025, offset(1e-12));
    // ACC50: half the acceleration (2000 °/s² for J6), too little to reach 1000 °/s in 300°: 2·sqrt(300/2000) s.
    assertThat(t.get(4)).isCloseTo(jointMoveSec(J6, HOME, 100, 50), offset(TICKS_2));
    assertThat(jointMoveSec(J6, HOME, 100, 50)).isCloseTo(2 * Math.sqrt(300.0 / 2000), offset(1e-12));
    // 5° of J1 never reaches 450 °/s: a triangle, 2·sqrt(5 / 1800) = 0.105 s.
    assertThat(t.get(5)).isCloseTo(jointMoveSec(HOME, SHORT, 100, 100), offset(TICKS_2));
    assertThat(jointMoveSec(HOME, SHORT, 100, 100)).isCloseTo(2 * Math.sqrt(5.0 / 1800), offset(1e-12));
  }

  @Test
  void everyLinearSpeedUnitGivesTheDocumentedDuration() {
    double ab = A.distanceTo(B); // 270 mm
    List<Double> t = durations(100, "J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE",
        "L P[3:B] 500mm/sec FINE", // 500 mm/s
        "L P[2:A] 600cm/min FINE", // 600 cm/min = 100 mm/s
        "L P[3:B] 600inch/min FINE", // 600 inch/min = 254 mm/s
        "L P[2:A] 2sec FINE", // 2 s at 100 %
        "L P[3:B] 1500msec FINE"); // 1.5 s
    assertThat(t.get(2)).isCloseTo(cartesianMoveSec(ab, 500, 0), offset(TICKS_2));
    assertThat(cartesianMoveSec(ab, 500, 0)).isCloseTo(270.0 / 500 + 0.2, offset(1e-9));
    assertThat(t.get(3)).isCloseTo(cartesianMoveSec(ab, 600 * 10 / 60.0, 0), offset(TICKS_2));
    assertThat(t.get(3)).isCloseTo(2.9, offset(TICKS_2));
    assertThat(t.get(4)).isCloseTo(cartesianMoveSec(ab, 600 * 25.4 / 60, 0), offset(TICKS_2));
    assertThat(t.get(5)).isCloseTo(2.0, offset(TICKS_2));
    assertThat(t.get(6)).isCloseTo(1.5, offset(TICKS_2));
  }

  @Test
  void jointMoveInSecondsAndMillisecondsTakesThatLong() {
    List<Double> t = durations(100, "J P[1:HOME] 100% FINE", "J P[7:J1J4] 2sec FINE", "J P[1:HOME] 750msec FINE",
        "J P[7:J1J4] 10msec FINE");
    assertThat(t.get(1)).isCloseTo(2.0, offset(TICKS_2));
    assertThat(t.get(2)).isCloseTo(0.75, offset(TICKS_2));
    // Faster than the joints allow: never faster than the limits (the 100 % time).
    assertThat(t.get(3)).isCloseTo(jointMoveSec(HOME, J1J4, 100, 100), offset(TICKS_2));
  }

  @Test
  void orientationMoveAtDegPerSecAndTheRotationLimit() {
    // P[6] is A turned 90° about the tool's axis, same position: a pure orientation move.
    List<Double> t = durations(100, "J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE", "L P[6:TURNED] 45deg/sec FINE",
        "L P[2:A] 2000mm/sec FINE", "L P[3:B] 45deg/sec FINE");
    // 45 °/s over 90°, reached in 0.2 s: 90/45 + 0.2 = 2.2 s.
    assertThat(t.get(2)).isCloseTo(trapezoid(90, 45, 45 / LINEAR_ACCEL_TIME), offset(TICKS_2));
    assertThat(t.get(2)).isCloseTo(2.2, offset(TICKS_2));
    // mm/sec on a pure turn: the 180 °/s limit paces it, 90/180 + 0.2 = 0.7 s.
    assertThat(t.get(3)).isCloseTo(cartesianMoveSec(0, 2000, 90), offset(TICKS_2));
    assertThat(t.get(3)).isCloseTo(0.7, offset(TICKS_2));
    // deg/sec on a move with no turn: the path runs at the linear limit (2000 mm/s, reached in 0.2 s), which 270 mm
    // is too short to reach: a triangle, 2·sqrt(270 / 10000) = 0.329 s.
    assertThat(t.get(4)).isCloseTo(trapezoid(A.distanceTo(B), 2000, 2000 / LINEAR_ACCEL_TIME), offset(TICKS_2));
  }

  @Test
  void circularMoveTakesItsArcLengthAtTheCommandedSpeed() {
    // A (350,-120), VIA (470,0), end (350,120): a half circle of radius 120 about (350,0), 120π = 377 mm long.
    List<Double> t = durations(100, "J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE",
        "C P[4:VIA]\n    :  P[5:C_END] 200mm/sec FINE");
    double arc = Math.PI * 120;
    assertThat(t.get(2)).isCloseTo(cartesianMoveSec(arc, 200, 0), offset(TICKS_2));
    assertThat(t.get(2)).isCloseTo(arc / 200 + 0.2, offset(TICKS_2));
  }

  @Test
  void halfOverrideDoublesEveryMoveExactly() {
    // docs/motion.md: the override scales the time rate of the path; at 50 % a move takes twice as long,
    // a sec move too. Both runs start at rest, so no override ramp is involved.
    String[] prog = {"J P[1:HOME] 100% FINE", "J P[7:J1J4] 100% FINE", "J P[1:HOME] 30% FINE", "L P[2:A] 500mm/sec FINE",
        "L P[3:B] 600cm/min FINE", "L P[2:A] 2sec FINE", "C P[4:VIA]\n    :  P[5:C_END] 200mm/sec FINE"};
    List<Double> full = durations(100, prog);
    List<Double> half = durations(50, prog);
    List<Double> quarter = durations(25, prog);
    assertThat(half).hasSameSizeAs(full);
    for (int i = 1; i < full.size(); i++) {
      assertThat(half.get(i)).as("line %d at 50 %%", i + 1).isCloseTo(2 * full.get(i), offset(2 * TICKS_2));
      assertThat(quarter.get(i)).as("line %d at 25 %%", i + 1).isCloseTo(4 * full.get(i), offset(4 * TICKS_2));
    }
    assertThat(half.get(5)).isCloseTo(4.0, offset(2 * TICKS_2));
  }

  /** The TCP's fastest tick over a whole run, and over the 1000 mm/sec line from A to B (line 3). */
  record AToB(Controller controller, double fastest, double fastestOnAB) {}

  /** Runs HOME, then A at 500 mm/sec, then B at 1000 mm/sec, in {@code mode} at 100 % override, to the end. */
  static AToB runAToB(RobotControl.Mode mode) {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(program("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE", "L P[3:B] 1000mm/sec FINE"));
    c.setMode(mode);
    c.setDeadman(true);
    List<Vec3> tcp = new ArrayList<>();
    List<Integer> lines = new ArrayList<>();
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "TIMING", 60, s -> {
      tcp.add(c.tcpInWorld().position());
      lines.add(c.status().line());
    });
    assertThat(r.status()).as(r.alarm().map(ControllerAlarm::display).orElse("")).isEqualTo(HeadlessRun.Status.FINISHED);
    double fastest = 0;
    double fastestOnAB = 0;
    for (int i = 1; i < tcp.size(); i++) {
      double v = tcp.get(i).distanceTo(tcp.get(i - 1)) / TICK;
      fastest = Math.max(fastest, v);
      if (lines.get(i) == 3) {
        fastestOnAB = Math.max(fastestOnAB, v);
      }
    }
    return new AToB(c, fastest, fastestOnAB);
  }

  @Test
  void t1CapsTheTcpAt250MmPerSecondMeasuredTickByTick() {
    // docs/motion.md, Jog: in T1 no tick moves the TCP faster than 250 mm/s; a program move is slowed along its
    // path. A 1000 mm/sec move from A to B (270 mm) runs at the cap: at most 250 mm/s in every tick, and at
    // least 249 mm/s in its middle, so it takes the trapezoid of 250 mm/s (not of 1000 mm/s) or longer.
    AToB run = runAToB(RobotControl.Mode.T1);
    Controller c = run.controller();
    assertThat(run.fastest()).isLessThanOrEqualTo(250 + 1e-6);
    assertThat(run.fastestOnAB()).isGreaterThan(249);
    MotionTiming ab = c.motionTimings().get(2);
    assertThat(ab.durationSec()).isGreaterThanOrEqualTo(trapezoid(A.distanceTo(B), 250, 1000 / LINEAR_ACCEL_TIME) - TICKS_2);
    assertThat(c.tcpInWorld().position().distanceTo(B)).isLessThan(0.01);
  }

  @Test
  void t1CapsAJointJogAtTheTcpAndT2DoesNot() {
    // J1 at 25 % of 450 °/s swings a TCP ~450 mm from the axis at ~880 mm/s: T1 shortens every tick to 250 mm/s.
    for (RobotControl.Mode mode : new RobotControl.Mode[] {RobotControl.Mode.T1, RobotControl.Mode.T2}) {
      Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
      Controller c = sim.controllers().get(0);
      c.setMode(mode);
      c.setDeadman(true);
      c.setOverridePct(100);
      c.setCoordSystem(RobotControl.CoordSystem.JOINT);
      for (int i = 0; i < 10; i++) {
        sim.step(); // the override ramps to 100 %
      }
      assertThat(c.jogKeyDown(1, +1, org.robotrun.motion.JogState.Press.HELD)).isInstanceOf(RobotControl.Result.Ok.class);
      double fastest = 0;
      Vec3 prev = c.tcpInWorld().position();
      for (int i = 0; i < 100; i++) {
        sim.step();
        Vec3 p = c.tcpInWorld().position();
        fastest = Math.max(fastest, p.distanceTo(prev) / TICK);
        prev = p;
      }
      c.setDeadman(false);
      if (mode == RobotControl.Mode.T1) {
        assertThat(fastest).isLessThanOrEqualTo(250 + 1e-6).isGreaterThan(240);
      } else {
        assertThat(fastest).isGreaterThan(400);
      }
    }
  }
}
