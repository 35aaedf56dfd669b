package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;
import static org.robotrun.sim.MotionTimingSpecTest.A;
import static org.robotrun.sim.MotionTimingSpecTest.B;
import static org.robotrun.sim.MotionTimingSpecTest.HOME;
import static org.robotrun.sim.MotionTimingSpecTest.J1J4;
import static org.robotrun.sim.MotionTimingSpecTest.LINEAR_ACCEL_TIME;
import static org.robotrun.sim.MotionTimingSpecTest.TICKS_2;
import static org.robotrun.sim.MotionTimingSpecTest.cartesianMoveSec;
import static org.robotrun.sim.MotionTimingSpecTest.jointMoveSec;
import static org.robotrun.sim.MotionTimingSpecTest.trapezoid;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Every speed unit a program can state (`%`, `mm/sec`, `cm/min`, `inch/min`, `deg/sec`, `sec`,
 * `msec`) in ONE program, one after another, each motion's time computed here from the data
 * sheet's joint speeds and the ramps of docs/motion.md (see {@link MotionTimingSpecTest}): a
 * motion's time depends on its own unit and path, not on the unit of the motion before it, so
 * the same lines in the reverse order take the same times; and a CNT corner between two units
 * saves exactly the blend: the next motion starts n % of the first one's 0.2 s deceleration
 * before its end.
 */
class MixedSpeedUnitsSpecTest {

  /** The program's lines with the time each must take (s); NaN for a move that only positions the arm. */
  record Line(String text, double sec) {}

  static final double AB = A.distanceTo(B); // 270 mm

  static List<Line> lines() {
    return List.of(
        new Line("J P[1:HOME] 100% FINE", Double.NaN),
        // 50 % of each joint's data-sheet speed, 0.25 s to reach it.
        new Line("J P[7:J1J4] 50% FINE", jointMoveSec(HOME, J1J4, 50, 100)),
        // 1.2 s is longer than the 100 % time (J4's 120° triangle, 0.467 s): it takes 1.2 s.
        new Line("J P[1:HOME] 1200msec FINE", 1.2),
        new Line("L P[2:A] 500mm/sec FINE", Double.NaN),
        // 1200 cm/min = 200 mm/s over 270 mm: 270/200 + 0.2 = 1.55 s.
        new Line("L P[3:B] 1200cm/min FINE", cartesianMoveSec(AB, 1200 * 10 / 60.0, 0)),
        // 1800 inch/min = 762 mm/s, reached in 0.2 s: 270/762 + 0.2 s.
        new Line("L P[2:A] 1800inch/min FINE", cartesianMoveSec(AB, 1800 * 25.4 / 60, 0)),
        // A pure 90° turn at 30 deg/sec: 90/30 + 0.2 = 3.2 s.
        new Line("L P[6:TURNED] 30deg/sec FINE", trapezoid(90, 30, 30 / LINEAR_ACCEL_TIME)),
        // Back in 1.5 s (the 180 °/s limit would allow 0.7 s).
        new Line("L P[2:A] 1.5sec FINE", 1.5),
        // 2000 mm/sec over 270 mm never reaches its speed: 2·sqrt(270 / 10000) s.
        new Line("L P[3:B] 2000mm/sec FINE", cartesianMoveSec(AB, 2000, 0)),
        new Line("J P[1:HOME] 100% FINE", Double.NaN));
  }

  static List<MotionTiming> run(List<String> program) {
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(MotionTimingSpecTest.program(program.toArray(String[]::new)));
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "TIMING", 120, s -> {});
    assertThat(r.status()).as(r.alarm().map(ControllerAlarm::display).orElse("")).isEqualTo(HeadlessRun.Status.FINISHED);
    return c.motionTimings();
  }

  @Test
  void everyUnitInOneProgramTakesItsOwnDerivedTime() {
    assertThat(cartesianMoveSec(AB, 200, 0)).isCloseTo(1.55, offset(1e-9));
    assertThat(trapezoid(90, 30, 150)).isCloseTo(3.2, offset(1e-9));
    List<Line> lines = lines();
    List<String> text = new ArrayList<>();
    lines.forEach(l -> text.add(l.text()));
    List<MotionTiming> t = run(text);
    assertThat(t).hasSize(lines.size());
    for (int i = 0; i < lines.size(); i++) {
      assertThat(t.get(i).line()).isEqualTo(i + 1);
      if (!Double.isNaN(lines.get(i).sec())) {
        assertThat(t.get(i).durationSec()).as("line %d: %s", i + 1, lines.get(i).text())
            .isCloseTo(lines.get(i).sec(), offset(TICKS_2));
      }
    }
  }

  @Test
  void theUnitOfThePreviousMotionDoesNotChangeAMotionsTime() {
    // The measured moves in the reverse order between the same points: each keeps its time.
    List<String> reversed = List.of("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE", "L P[3:B] 2000mm/sec FINE",
        "L P[2:A] 1800inch/min FINE", "L P[3:B] 1200cm/min FINE", "L P[2:A] 500mm/sec FINE", "L P[6:TURNED] 30deg/sec FINE",
        "L P[2:A] 1.5sec FINE", "J P[1:HOME] 100% FINE", "J P[7:J1J4] 1200msec FINE", "J P[1:HOME] 50% FINE");
    List<MotionTiming> t = run(reversed);
    assertThat(t.get(2).durationSec()).isCloseTo(cartesianMoveSec(AB, 2000, 0), offset(TICKS_2));
    assertThat(t.get(3).durationSec()).isCloseTo(cartesianMoveSec(AB, 762, 0), offset(TICKS_2));
    assertThat(t.get(4).durationSec()).isCloseTo(1.55, offset(TICKS_2));
    assertThat(t.get(6).durationSec()).isCloseTo(3.2, offset(TICKS_2));
    assertThat(t.get(7).durationSec()).isCloseTo(1.5, offset(TICKS_2));
    assertThat(t.get(9).durationSec()).isCloseTo(1.2, offset(TICKS_2));
    assertThat(t.get(10).durationSec()).isCloseTo(jointMoveSec(J1J4, HOME, 50, 100), offset(TICKS_2));
  }

  @Test
  void aCntCornerBetweenTwoUnitsSavesExactlyTheBlend() {
    // cm/min CNT50 into inch/min: the second move starts 50 % of the first's 0.2 s deceleration before
    // its end, so the pair takes T1 + T2 − 0.1 s; with CNT100, T1 + T2 − 0.2 s; with FINE, T1 + T2.
    double t1 = cartesianMoveSec(AB, 200, 0);
    double t2 = cartesianMoveSec(AB, 762, 0);
    for (int cnt : new int[] {50, 100}) {
      List<MotionTiming> t = run(List.of("J P[1:HOME] 100% FINE", "L P[2:A] 500mm/sec FINE",
          "L P[3:B] 1200cm/min CNT" + cnt, "L P[2:A] 1800inch/min FINE"));
      double pair = t.get(3).endSec() - t.get(2).startSec();
      assertThat(pair).as("CNT%d", cnt).isCloseTo(t1 + t2 - cnt / 100.0 * LINEAR_ACCEL_TIME, offset(TICKS_2));
      assertThat(t.get(2).durationSec()).as("CNT%d: the first move itself", cnt).isCloseTo(t1, offset(TICKS_2));
    }
  }
}
