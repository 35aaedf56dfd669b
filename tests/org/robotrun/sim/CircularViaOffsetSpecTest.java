package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Vec3;

/**
 * Offsets on a {@code C} motion's two points (docs/tp-language.md, "Offsets on a C motion's via
 * point"): with options on the via point, the via point takes its own {@code Offset} and the end
 * point its own; without them, both points take the end point's. The arc really run is checked
 * against points computed here from the taught points of {@link MotionTimingSpecTest#POS} (UF 0 is
 * WORLD, so {@code Offset,PR[]} adds to X, Y, Z directly): the TCP must pass through the offset via
 * point and stop on the offset end point.
 */
class CircularViaOffsetSpecTest {
  static final Vec3 A = MotionTimingSpecTest.A; // P[2] (350, -120, 40)
  static final Vec3 VIA = new Vec3(470, 0, 40); // P[4]
  static final Vec3 END = new Vec3(350, 120, 40); // P[5]
  /** PR[1]: the via point's offset. PR[2]: the end point's. */
  static final double[] PR1 = {0, 0, 30, 0, 0, 0};
  static final double[] PR2 = {-20, 10, 0, 0, 0, 0};

  static List<String> setPr(int pr, double[] v) {
    List<String> lines = new ArrayList<>();
    lines.add("PR[" + pr + "]=LPOS");
    for (int j = 0; j < 6; j++) {
      lines.add(String.format(java.util.Locale.ROOT, "PR[%d,%d]=%s", pr, j + 1, v[j] < 0 ? "(" + v[j] + ")" : String.valueOf(v[j])));
    }
    return lines;
  }

  /** Runs the lines and returns the TCP after every tick of the last motion line. */
  static List<Vec3> arcRun(String circularLine) {
    List<String> lines = new ArrayList<>();
    lines.add("J P[1:HOME] 100% FINE");
    lines.addAll(setPr(1, PR1));
    lines.addAll(setPr(2, PR2));
    // PR[i,4..6] were set to 0 above: keep the taught W, P, R (180, 0, 0) unchanged by the offsets
    lines.add("L P[2:A] 200mm/sec FINE");
    lines.add(circularLine);
    int last = lines.size();
    Simulation sim = DefaultCell.simulation(ControllerTest.MODEL);
    Controller c = sim.controllers().get(0);
    c.saveProgram(MotionTimingSpecTest.program(lines.toArray(String[]::new)));
    List<Vec3> tcp = new ArrayList<>();
    HeadlessRun.Result r = HeadlessRun.run(sim, c, "TIMING", 60, s -> {
      if (c.status().line() == last) {
        tcp.add(c.tcpInWorld().position());
      }
    });
    assertThat(r.status()).as(r.alarm().map(ControllerAlarm::display).orElse("")).isEqualTo(HeadlessRun.Status.FINISHED);
    assertThat(tcp).isNotEmpty();
    return tcp;
  }

  static double closest(List<Vec3> path, Vec3 p) {
    return path.stream().mapToDouble(q -> q.distanceTo(p)).min().orElseThrow();
  }

  static Vec3 plus(Vec3 p, double[] off) {
    return new Vec3(p.x() + off[0], p.y() + off[1], p.z() + off[2]);
  }

  @Test
  void aViaPointWithItsOwnOffsetTakesItAndTheEndPointTakesItsOwn() {
    List<Vec3> path = arcRun("C P[4:VIA] Offset,PR[1]\n    :  P[5:C_END] 200mm/sec FINE Offset,PR[2]");
    Vec3 via = plus(VIA, PR1); // (470, 0, 70)
    Vec3 end = plus(END, PR2); // (330, 130, 40)
    // at 200 mm/s and 4 ms ticks the TCP samples the arc every 0.8 mm: it passes within half of that
    assertThat(closest(path, via)).as("distance from the via point + PR[1]").isLessThan(0.5);
    assertThat(path.get(path.size() - 1).distanceTo(end)).as("end point + PR[2]").isLessThan(0.01);
    // and not through the via point with the end point's offset
    assertThat(closest(path, plus(VIA, PR2))).isGreaterThan(5);
  }

  @Test
  void withoutOptionsOnTheViaPointBothPointsTakeTheEndPointsOffset() {
    List<Vec3> path = arcRun("C P[4:VIA]\n    :  P[5:C_END] 200mm/sec FINE Offset,PR[2]");
    assertThat(closest(path, plus(VIA, PR2))).as("distance from the via point + PR[2]").isLessThan(0.5);
    assertThat(path.get(path.size() - 1).distanceTo(plus(END, PR2))).isLessThan(0.01);
  }
}
