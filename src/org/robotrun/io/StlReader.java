package org.robotrun.io;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.OptionalDouble;
import org.robotrun.math.DecimalText;
import org.robotrun.math.PoseLimits;
import org.robotrun.world.TriangleMesh;

/**
 * Reads STL meshes, binary or ASCII, scaling coordinates by a factor (1 for files in mm, 1000
 * for files in metres). Normals in the file are ignored.
 *
 * <p>Limits, so that a wrong file cannot exhaust memory: at most {@link #MAX_FILE_BYTES}
 * (64 MiB) are read, counted from the stream (a device or FIFO is refused unopened), at most
 * {@link #MAX_TRIANGLES} triangles are accepted, and every coordinate after scaling lies within
 * ±{@link PoseLimits#MAX_COORDINATE_MM}. A binary file is recognised by its size matching the
 * triangle count in its header (84 + 50·n bytes) unless it is plainly ASCII text; otherwise a
 * file starting with {@code solid} is read as ASCII (its name may hold any letters). Every
 * error names the file (and, for ASCII, the line).
 */
public final class StlReader {
  /** Largest file accepted (64 MiB). */
  public static final long MAX_FILE_BYTES = 64L << 20;

  /** Most triangles accepted (a binary file at the size limit holds about 1.34 million). */
  public static final int MAX_TRIANGLES = 2_000_000;

  private static final int HEADER_BYTES = 84;
  private static final int TRIANGLE_BYTES = 50;

  private StlReader() {}

  /**
   * Reads {@code file}, multiplying every coordinate by {@code scale} (finite, > 0).
   *
   * @throws FileFormatException missing, not a regular file, unreadable, above the size limit, or
   *     the content is not an STL mesh within the limits
   */
  public static TriangleMesh read(Path file, double scale) throws IOException {
    String name = file.toString();
    if (!(scale > 0) || !Double.isFinite(scale)) {
      throw new IllegalArgumentException("STL scale must be a finite number > 0, got " + scale);
    }
    byte[] bytes;
    try {
      bytes = BoundedFiles.read(file, MAX_FILE_BYTES, "STL meshes");
    } catch (UnreadableFileException e) {
      throw new FileFormatException(name, 0, e.getMessage());
    }
    return parse(name, bytes, scale);
  }

  /** Reads an STL mesh from its bytes; {@code name} names it in messages. */
  public static TriangleMesh parse(String name, byte[] bytes, double scale) {
    long size = bytes.length;
    if (size == 0) {
      throw new FileFormatException(name, 0, "empty file: expected a binary or ASCII STL mesh");
    }
    // An ASCII file starts with "solid" (after blanks); a binary header may too, but then its
    // size matches the triangle count, or its 80 header bytes hold a NUL.
    boolean startsWithSolid = startsWithSolid(bytes);
    if (size >= HEADER_BYTES) {
      long count = ByteBuffer.wrap(bytes, 80, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xFFFFFFFFL;
      long expected = HEADER_BYTES + TRIANGLE_BYTES * count;
      if (expected == size && !(startsWithSolid && looksAscii(bytes))) {
        return readBinary(name, bytes, (int) count, scale);
      }
      if (!startsWithSolid) {
        throw new FileFormatException(name, 0, "wrong size for a binary STL: the header says " + count
            + " triangles, which needs " + expected + " bytes, but the file has " + size + " bytes (truncated or corrupt)");
      }
    } else if (!startsWithSolid) {
      throw new FileFormatException(name, 0, "truncated: a binary STL needs at least an 84-byte header, the file has "
          + size + " bytes");
    }
    return readAscii(name, bytes, scale);
  }

  /** Whether the file starts with "solid" (after blanks) and its first 80 bytes hold no NUL. */
  private static boolean startsWithSolid(byte[] bytes) {
    int i = 0;
    while (i < bytes.length && i < 80 && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n')) {
      i++;
    }
    if (bytes.length - i < 5 || !new String(bytes, i, 5, StandardCharsets.US_ASCII).equals("solid")) {
      return false;
    }
    for (int k = 0; k < Math.min(bytes.length, 80); k++) {
      if (bytes[k] == 0) {
        return false;
      }
    }
    return true;
  }

  /** Whether the bytes after the header look like ASCII STL keywords (a binary body rarely does). */
  private static boolean looksAscii(byte[] bytes) {
    String tail = new String(bytes, 0, Math.min(bytes.length, 1024), StandardCharsets.ISO_8859_1);
    return tail.contains("facet") || tail.contains("endsolid");
  }

  private static TriangleMesh readBinary(String name, byte[] bytes, int count, double scale) {
    if (count == 0) {
      throw new FileFormatException(name, 0, "binary STL with no triangles");
    }
    if (count > MAX_TRIANGLES) {
      throw new FileFormatException(name, 0, count + " triangles; the limit is " + MAX_TRIANGLES);
    }
    float[] corners = new float[9 * count];
    ByteBuffer buf = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
    buf.position(HEADER_BYTES);
    for (int t = 0; t < count; t++) {
      buf.position(buf.position() + 12); // skip the normal
      for (int k = 0; k < 9; k++) {
        float v = buf.getFloat();
        if (!Float.isFinite(v)) {
          throw new FileFormatException(name, 0, "triangle " + (t + 1) + " has a non-finite coordinate");
        }
        corners[9 * t + k] = coordinate(name, 0, "triangle " + (t + 1), v * scale);
      }
      buf.position(buf.position() + 2); // attribute byte count
    }
    return new TriangleMesh(corners);
  }

  private static TriangleMesh readAscii(String name, byte[] bytes, double scale) {
    float[] corners = new float[9 * 1024];
    int floats = 0;
    int vertexInFacet = 0;
    int lineNo = 0;
    boolean inFacet = false;
    String[] lines = new String(bytes, StandardCharsets.ISO_8859_1).split("\r?\n|\r", -1);
    for (String line : lines) {
      lineNo++;
      String[] tok = line.trim().split("\\s+");
      switch (tok[0]) {
        case "", "solid", "endsolid", "outer", "endloop" -> { }
        case "facet" -> {
          if (inFacet) {
            throw new FileFormatException(name, lineNo, "'facet' inside a facet: expected 'endfacet' first");
          }
          inFacet = true;
          vertexInFacet = 0;
        }
        case "vertex" -> {
          if (!inFacet || vertexInFacet == 3) {
            throw new FileFormatException(name, lineNo, inFacet ? "a facet has more than 3 vertices" : "'vertex' outside a facet");
          }
          if (tok.length != 4) {
            throw new FileFormatException(name, lineNo, "expected 'vertex x y z'");
          }
          if (floats == corners.length) {
            if (floats / 9 >= MAX_TRIANGLES) {
              throw new FileFormatException(name, lineNo, "more than " + MAX_TRIANGLES + " triangles");
            }
            corners = Arrays.copyOf(corners, Math.min(2 * corners.length, 9 * MAX_TRIANGLES));
          }
          for (int k = 1; k <= 3; k++) {
            corners[floats++] = coordinate(name, lineNo, "vertex", number(name, lineNo, tok[k]) * scale);
          }
          vertexInFacet++;
        }
        case "endfacet" -> {
          if (!inFacet || vertexInFacet != 3) {
            throw new FileFormatException(name, lineNo, "a facet needs exactly 3 vertices, got " + vertexInFacet);
          }
          inFacet = false;
        }
        default -> throw new FileFormatException(name, lineNo, "unexpected '" + shorten(tok[0])
            + "': expected solid, facet, outer loop, vertex, endloop, endfacet or endsolid");
      }
    }
    if (inFacet) {
      throw new FileFormatException(name, lineNo, "truncated: the file ends inside a facet");
    }
    if (floats == 0) {
      throw new FileFormatException(name, 0, "ASCII STL with no triangles");
    }
    return new TriangleMesh(Arrays.copyOf(corners, floats));
  }

  /**
   * A scaled coordinate in mm as a float, within ±{@link PoseLimits#MAX_COORDINATE_MM}: a mesh
   * 100 m from its origin is a wrong unit or a broken file, and beyond it float precision (and
   * the collision boxes built from the mesh) stop meaning anything.
   */
  private static float coordinate(String name, int line, String where, double mm) {
    if (!PoseLimits.coordinateOk(mm)) {
      throw new FileFormatException(name, line, where + " has a coordinate of " + String.format(Locale.ROOT, "%.6g", mm)
          + " mm after scaling; meshes must lie within ±" + (long) PoseLimits.MAX_COORDINATE_MM
          + " mm (check the unit and \"scale\")");
    }
    return (float) mm;
  }

  private static String shorten(String s) {
    return s.length() > 40 ? s.substring(0, 40) + "…" : s;
  }

  private static double number(String name, int line, String text) {
    OptionalDouble v = DecimalText.parse(text);
    if (v.isPresent()) {
      return v.getAsDouble();
    }
    throw new FileFormatException(name, line, "expected a finite number, got '" + shorten(text) + "'");
  }
}
