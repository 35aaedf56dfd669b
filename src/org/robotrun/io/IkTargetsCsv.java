package org.robotrun.io;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.robotrun.math.Transform;

/**
 * Reads the reference IK target format (see shared/robots/README.md): one row per target with
 * ground-truth joints, the flange pose in base_link (metres, row-major rotation) and two start
 * vectors. Positions are converted to millimetres here.
 */
public final class IkTargetsCsv {
  private IkTargetsCsv() {}

  /**
   * One target.
   *
   * @param id row id
   * @param q ground-truth joints (rad, kinematic convention)
   * @param X_BF flange pose in the robot base frame (mm)
   * @param randomStart the "random" start joints (rad)
   * @param nearStart the "near" start joints (rad)
   */
  public record Target(int id, double[] q, Transform X_BF, double[] randomStart, double[] nearStart) {}

  private static final String[] REQUIRED = {
    "id", "q1", "q2", "q3", "q4", "q5", "q6", "x", "y", "z",
    "r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33",
    "s1", "s2", "s3", "s4", "s5", "s6", "n1", "n2", "n3", "n4", "n5", "n6"
  };

  /** Largest targets file read (the 2 000-row reference file is under 1 MiB). */
  public static final long MAX_FILE_BYTES = 64L << 20;

  public static List<Target> read(Path file) throws IOException {
    List<String> lines = BoundedFiles.readUtf8(file, MAX_FILE_BYTES, "IK target files").lines().toList();
    String name = file.toString();
    if (lines.isEmpty()) {
      throw new FileFormatException(name, 1, "empty file: expected a header line");
    }
    String[] header = lines.get(0).trim().split(",");
    Map<String, Integer> col = new HashMap<>();
    for (int i = 0; i < header.length; i++) {
      col.put(header[i].trim(), i);
    }
    for (String c : REQUIRED) {
      if (!col.containsKey(c)) {
        throw new FileFormatException(name, 1, "header is missing column '" + c + "'");
      }
    }
    List<Target> out = new ArrayList<>();
    for (int ln = 1; ln < lines.size(); ln++) {
      String line = lines.get(ln).trim();
      if (line.isEmpty()) {
        continue;
      }
      String[] f = line.split(",");
      int lineNo = ln + 1;
      Cells c = new Cells(name, lineNo, f, col);
      double[] r = new double[9];
      String[] rn = {"r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33"};
      for (int i = 0; i < 9; i++) {
        r[i] = c.num(rn[i]);
      }
      out.add(new Target(
          (int) c.num("id"),
          c.six("q"),
          Transform.of(r, c.num("x") * 1000, c.num("y") * 1000, c.num("z") * 1000),
          c.six("s"),
          c.six("n")));
    }
    return out;
  }

  /**
   * Writes targets in the reference format (metres, row-major rotation, plus the quaternion
   * columns qw..qz with qw ≥ 0), through the atomic writer.
   */
  public static void write(Path file, List<Target> targets) throws IOException {
    StringBuilder sb = new StringBuilder("id,q1,q2,q3,q4,q5,q6,x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33,qw,qx,qy,qz,"
        + "s1,s2,s3,s4,s5,s6,n1,n2,n3,n4,n5,n6\n");
    for (Target t : targets) {
      Transform x = t.X_BF();
      sb.append(t.id());
      for (double v : t.q()) {
        sb.append(',').append(v);
      }
      sb.append(',').append(x.x() / 1000).append(',').append(x.y() / 1000).append(',').append(x.z() / 1000);
      for (double v : x.rotationRowMajor()) {
        sb.append(',').append(v);
      }
      org.robotrun.math.Quaternion q = org.robotrun.math.Quaternion.fromTransform(x);
      double sgn = q.w() < 0 ? -1 : 1;
      sb.append(',').append(sgn * q.w()).append(',').append(sgn * q.x()).append(',').append(sgn * q.y())
          .append(',').append(sgn * q.z());
      for (double v : t.randomStart()) {
        sb.append(',').append(v);
      }
      for (double v : t.nearStart()) {
        sb.append(',').append(v);
      }
      sb.append('\n');
    }
    AtomicFiles.write(file, sb.toString().getBytes(java.nio.charset.StandardCharsets.UTF_8));
  }

  private record Cells(String file, int line, String[] f, Map<String, Integer> col) {
    double num(String name) {
      int i = col.get(name);
      if (i >= f.length) {
        throw new FileFormatException(file, line, "missing value for column '" + name + "'");
      }
      try {
        double v = Double.parseDouble(f[i].trim());
        if (!Double.isFinite(v)) {
          throw new NumberFormatException();
        }
        return v;
      } catch (NumberFormatException e) {
        throw new FileFormatException(file, line, "column '" + name + "': expected a finite number, got '" + f[i] + "'");
      }
    }

    double[] six(String prefix) {
      double[] out = new double[6];
      for (int i = 0; i < 6; i++) {
        out[i] = num(prefix + (i + 1));
      }
      return out;
    }
  }
}
