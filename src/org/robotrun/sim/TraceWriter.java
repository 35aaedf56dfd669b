package org.robotrun.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.util.List;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Position;

/**
 * Writes a CSV trace, one row per tick: {@code time_s}, then per robot J1..J6 (deg, pendant
 * convention), the active tool's TCP in WORLD (x, y, z in mm; w, p, r in deg) and the flange's
 * origin in WORLD (fx, fy, fz in mm; T1 caps the speed of both). Numbers are
 * fixed-point with a fixed number of decimals and no locale, so equal states give equal bytes.
 * With more than one robot the columns are prefixed with the robot's name.
 */
public final class TraceWriter {
  private static final String[] COLUMNS = {"j1_deg", "j2_deg", "j3_deg", "j4_deg", "j5_deg", "j6_deg",
      "x_mm", "y_mm", "z_mm", "w_deg", "p_deg", "r_deg", "fx_mm", "fy_mm", "fz_mm"};

  private final Writer out;
  private final StringBuilder row = new StringBuilder(256);

  /** Writes the header line at once. */
  public TraceWriter(Writer out, List<Controller> controllers) {
    this.out = out;
    row.append("time_s");
    for (Controller c : controllers) {
      for (String col : COLUMNS) {
        row.append(',');
        if (controllers.size() > 1) {
          row.append(c.name()).append('_');
        }
        row.append(col);
      }
    }
    flushRow();
  }

  /** Appends the row for the simulation's current state. */
  public void write(Simulation sim) {
    appendFixed(row, sim.timeSec(), 3);
    for (Controller c : sim.controllers()) {
      Position.Joint j = c.currentJoints();
      for (int i = 1; i <= 6; i++) {
        row.append(',');
        appendFixed(row, j.element(i), 6);
      }
      Xyzwpr p = c.tcpInWorld();
      for (double v : new double[] {p.x(), p.y(), p.z()}) {
        row.append(',');
        appendFixed(row, v, 4);
      }
      for (double v : new double[] {p.wDeg(), p.pDeg(), p.rDeg()}) {
        row.append(',');
        appendFixed(row, v, 4);
      }
      org.robotrun.math.Vec3 f = c.flangeInWorld();
      for (double v : new double[] {f.x(), f.y(), f.z()}) {
        row.append(',');
        appendFixed(row, v, 4);
      }
    }
    flushRow();
  }

  private void flushRow() {
    row.append('\n');
    try {
      out.append(row);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
    row.setLength(0);
  }

  /** {@code value} rounded to {@code decimals} places, e.g. -0.5 with 3 → "-0.500"; never "-0.000". */
  static void appendFixed(StringBuilder sb, double value, int decimals) {
    if (!Double.isFinite(value)) {
      sb.append(value);
      return;
    }
    long scale = 1;
    for (int i = 0; i < decimals; i++) {
      scale *= 10;
    }
    long n = Math.round(Math.abs(value) * scale);
    if (value < 0 && n != 0) {
      sb.append('-');
    }
    sb.append(n / scale);
    if (decimals > 0) {
      sb.append('.');
      String frac = Long.toString(n % scale);
      for (int i = frac.length(); i < decimals; i++) {
        sb.append('0');
      }
      sb.append(frac);
    }
  }
}
