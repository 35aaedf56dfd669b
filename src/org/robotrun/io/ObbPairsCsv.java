package org.robotrun.io;

import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.robotrun.collision.Obb;

/**
 * Box pairs as CSV, the input of {@code robotrun bench collision}: a header line, then one
 * pair per row, 30 columns — for box A then box B: centre {@code cx,cy,cz} (mm), half extents
 * {@code hx,hy,hz} (mm, ≥ 0), rotation {@code r11..r33} row-major (columns are the box axes in
 * world). Rotations must be orthonormal to 1e-6.
 */
public final class ObbPairsCsv {
  /** Columns per row. */
  public static final int COLUMNS = 2 * Obb.STRIDE;

  private static final String[] BOX_COLUMNS = {
    "cx", "cy", "cz", "hx", "hy", "hz", "r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33"
  };

  private static final double ORTHONORMAL_TOL = 1e-6;

  private ObbPairsCsv() {}

  /**
   * Pairs in flat arrays ({@link Obb#STRIDE} doubles per box, {@link Obb#writeTo} order):
   * pair i is box i of {@code a} and box i of {@code b}.
   */
  public record Pairs(int count, double[] a, double[] b) {}

  /** The header line: {@code a_cx,...,a_r33,b_cx,...,b_r33}. */
  public static String header() {
    StringBuilder sb = new StringBuilder();
    for (String box : List.of("a_", "b_")) {
      for (String c : BOX_COLUMNS) {
        sb.append(sb.isEmpty() ? "" : ",").append(box).append(c);
      }
    }
    return sb.toString();
  }

  /** Largest pairs file read (1 million pairs of full-precision boxes is about 500 MiB; the
   * benchmark's 100 000 fit in 64 MiB). */
  public static final long MAX_FILE_BYTES = 256L << 20;

  /** Reads a pairs file; throws {@link FileFormatException} naming file:line and the problem. */
  public static Pairs read(Path file) throws IOException {
    String name = file.toString();
    double[] a = new double[1024 * Obb.STRIDE];
    double[] b = new double[1024 * Obb.STRIDE];
    int count = 0;
    byte[] bytes = BoundedFiles.read(file, MAX_FILE_BYTES, "pair files");
    try (BufferedReader in = new BufferedReader(new java.io.StringReader(BoundedFiles.decodeUtf8(name, bytes)))) {
      String header = in.readLine();
      if (header == null) {
        throw new FileFormatException(name, 1, "empty file: expected a header line and then rows of " + COLUMNS + " numbers");
      }
      int headerCols = header.split(",", -1).length;
      if (headerCols != COLUMNS) {
        throw new FileFormatException(name, 1, "header has " + headerCols + " columns, expected " + COLUMNS);
      }
      int lineNo = 1;
      double[] row = new double[COLUMNS];
      for (String line = in.readLine(); line != null; line = in.readLine()) {
        lineNo++;
        if (line.isBlank()) {
          continue;
        }
        parseRow(name, lineNo, line, row);
        if (count * Obb.STRIDE == a.length) {
          a = Arrays.copyOf(a, 2 * a.length);
          b = Arrays.copyOf(b, 2 * b.length);
        }
        System.arraycopy(row, 0, a, count * Obb.STRIDE, Obb.STRIDE);
        System.arraycopy(row, Obb.STRIDE, b, count * Obb.STRIDE, Obb.STRIDE);
        count++;
      }
    } catch (NoSuchFileException e) {
      throw new FileFormatException(name, 0, "no such file");
    }
    return new Pairs(count, Arrays.copyOf(a, count * Obb.STRIDE), Arrays.copyOf(b, count * Obb.STRIDE));
  }

  private static void parseRow(String file, int line, String text, double[] row) {
    String[] cells = text.split(",", -1);
    if (cells.length != COLUMNS) {
      throw new FileFormatException(file, line, "expected " + COLUMNS + " columns, got " + cells.length);
    }
    for (int i = 0; i < COLUMNS; i++) {
      String column = (i < Obb.STRIDE ? "a_" : "b_") + BOX_COLUMNS[i % Obb.STRIDE];
      double v;
      try {
        v = Double.parseDouble(cells[i].trim());
      } catch (NumberFormatException e) {
        throw new FileFormatException(file, line, "column " + column + ": expected a number, got '" + cells[i].trim() + "'");
      }
      if (!Double.isFinite(v)) {
        throw new FileFormatException(file, line, "column " + column + ": expected a finite number, got " + cells[i].trim());
      }
      if (i % Obb.STRIDE >= 3 && i % Obb.STRIDE < 6 && v < 0) {
        throw new FileFormatException(file, line, "column " + column + ": half extent must be >= 0, got " + v);
      }
      row[i] = v;
    }
    for (int box = 0; box < 2; box++) {
      int o = box * Obb.STRIDE + 6;
      if (!orthonormal(row, o)) {
        throw new FileFormatException(file, line, "box " + (box == 0 ? "a" : "b")
            + ": r11..r33 is not a rotation (columns must be orthonormal to 1e-6)");
      }
    }
  }

  private static boolean orthonormal(double[] r, int o) {
    for (int i = 0; i < 3; i++) {
      for (int j = i; j < 3; j++) {
        double d = r[o + i] * r[o + j] + r[o + 3 + i] * r[o + 3 + j] + r[o + 6 + i] * r[o + 6 + j];
        if (Math.abs(d - (i == j ? 1 : 0)) > ORTHONORMAL_TOL) {
          return false;
        }
      }
    }
    double det = r[o] * (r[o + 4] * r[o + 8] - r[o + 5] * r[o + 7])
        - r[o + 1] * (r[o + 3] * r[o + 8] - r[o + 5] * r[o + 6])
        + r[o + 2] * (r[o + 3] * r[o + 7] - r[o + 4] * r[o + 6]);
    return det > 0;
  }

  /** Writes pairs with full double precision (round-trips exactly). */
  public static void write(Path file, List<Obb> a, List<Obb> b) throws IOException {
    double[] box = new double[Obb.STRIDE];
    AtomicFiles.write(file, stream -> {
      BufferedWriter out = new BufferedWriter(new java.io.OutputStreamWriter(stream, StandardCharsets.UTF_8), 1 << 16);
      out.write(header());
      out.newLine();
      StringBuilder sb = new StringBuilder(512);
      for (int i = 0; i < a.size(); i++) {
        sb.setLength(0);
        for (Obb o : List.of(a.get(i), b.get(i))) {
          o.writeTo(box, 0);
          for (double v : box) {
            sb.append(sb.isEmpty() ? "" : ",").append(format(v));
          }
        }
        out.write(sb.toString());
        out.newLine();
      }
      out.flush();
    });
  }

  private static String format(double v) {
    return org.robotrun.math.DecimalText.plain(v);
  }
}
