package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Position;

/**
 * The trace format of docs/run-report.md: one header line, then one row per write; {@code time_s}
 * with 3 decimals, J1..J6 in pendant degrees with 6, the active tool's TCP (mm, deg) and the
 * flange's origin with 4, fixed-point with '.' whatever the locale, never "-0.000"; with several
 * robots every column after {@code time_s} is prefixed with the robot's name. The expected row is
 * built with {@link String#format} from the controller's own pose readings.
 */
class TraceFormatTest {
  private static final String COLUMNS =
      "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg,x_mm,y_mm,z_mm,w_deg,p_deg,r_deg,fx_mm,fy_mm,fz_mm";

  /** {@code %.Nf}, with a negative zero written as zero. */
  private static String fixed(double v, int decimals) {
    String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
    return s.matches("-0\\.0*") || s.equals("-0") ? s.substring(1) : s;
  }

  private static String expectedRow(Simulation sim) {
    List<String> f = new ArrayList<>();
    f.add(fixed(sim.timeSec(), 3));
    for (Controller c : sim.controllers()) {
      Position.Joint j = c.currentJoints();
      for (int i = 1; i <= 6; i++) {
        f.add(fixed(j.element(i), 6));
      }
      Xyzwpr p = c.tcpInWorld();
      for (double v : new double[] {p.x(), p.y(), p.z(), p.wDeg(), p.pDeg(), p.rDeg()}) {
        f.add(fixed(v, 4));
      }
      Vec3 fl = c.flangeInWorld();
      for (double v : new double[] {fl.x(), fl.y(), fl.z()}) {
        f.add(fixed(v, 4));
      }
    }
    return String.join(",", f);
  }

  @Test
  void aHeaderLineThenOneRowPerWriteWithTheDocumentedDecimals() {
    Locale before = Locale.getDefault();
    Locale.setDefault(Locale.GERMANY); // a decimal comma must not leak into the CSV
    try {
      Simulation sim = ControllerTest.cell();
      Controller c = sim.controllers().get(0);
      c.saveProgram(ControllerTest.jointProgram("GO", "J P[2] 40% FINE", new double[] {0, 0, 0, 0, -90, 0},
          new double[] {-12.3456789, 10, -5, 20, -60, 33.3}));
      StringWriter out = new StringWriter();
      TraceWriter tw = new TraceWriter(out, sim.controllers());
      List<String> rows = new ArrayList<>();
      tw.write(sim);
      rows.add(expectedRow(sim));
      c.run("GO", 1, true);
      for (int k = 0; k < 150; k++) {
        sim.step();
        tw.write(sim);
        rows.add(expectedRow(sim));
      }
      String[] lines = out.toString().split("\n", -1);
      assertThat(lines[0]).isEqualTo("time_s," + COLUMNS);
      assertThat(lines).hasSize(rows.size() + 2);
      assertThat(lines[lines.length - 1]).isEmpty(); // every row ends with '\n'
      for (int k = 0; k < rows.size(); k++) {
        assertThat(lines[k + 1]).as("row %d", k).isEqualTo(rows.get(k));
        assertThat(lines[k + 1].split(",")).hasSize(16);
      }
      assertThat(lines[1]).startsWith("0.000,");
      assertThat(lines[2]).startsWith("0.004,");
    } finally {
      Locale.setDefault(before);
    }
  }

  @Test
  void withSeveralRobotsEveryColumnIsPrefixedWithTheRobotsName() {
    Controller a = DefaultCell.controller(ControllerTest.MODEL, "left");
    Controller b = DefaultCell.controller(ControllerTest.MODEL, "right");
    StringWriter out = new StringWriter();
    new TraceWriter(out, List.of(a, b));
    StringBuilder want = new StringBuilder("time_s");
    for (String robot : List.of("left", "right")) {
      for (String col : COLUMNS.split(",")) {
        want.append(',').append(robot).append('_').append(col);
      }
    }
    assertThat(out.toString()).isEqualTo(want + "\n");
  }

  @Test
  void fixedPointRoundsHalfAwayFromZeroAndNeverWritesMinusZero() {
    Object[][] cases = {
        {-0.5, 3, "-0.500"},
        {0.0, 3, "0.000"},
        {-0.0, 4, "0.0000"},
        {-0.00004, 4, "0.0000"},
        {-0.00005, 4, "-0.0001"},
        {1.005, 3, "1.005"},
        {2.0001, 4, "2.0001"},
        {-2.0001, 4, "-2.0001"},
        {0.25, 1, "0.3"},
        {-0.25, 1, "-0.3"},
        {12.5, 0, "13"},
        {-12.5, 0, "-13"},
        {123456.7, 2, "123456.70"},
        {9.9999996, 6, "10.000000"},
        {-179.99999, 4, "-180.0000"},
        {Double.NaN, 3, "NaN"},
        {Double.POSITIVE_INFINITY, 3, "Infinity"},
    };
    for (Object[] k : cases) {
      StringBuilder sb = new StringBuilder("x");
      TraceWriter.appendFixed(sb, (double) k[0], (int) k[1]);
      assertThat(sb.toString()).as("%s with %s decimals", k[0], k[1]).isEqualTo("x" + k[2]);
    }
  }
}
