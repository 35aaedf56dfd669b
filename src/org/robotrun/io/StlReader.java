package org.robotrun.io;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Arrays;
import org.robotrun.world.TriangleMesh;

/**
 * Reads STL meshes, binary or ASCII, scaling coordinates by a factor (1 for files in mm, 1000
 * for files in metres). Normals in the file are ignored.
 *
 * <p>Limits, so that a wrong file cannot exhaust memory: files above {@link #MAX_FILE_BYTES}
 * (64 MiB) are refused from their size alone, before any byte is read, and at most
 * {@link #MAX_TRIANGLES} triangles are accepted. A binary file is recognised by its size
 * matching the triangle count in its header (84 + 50·n bytes); otherwise a file starting with
 * {@code solid} is read as ASCII. Every error names the file (and, for ASCII, the line).
 */
public final class StlReader {
  /** Largest file accepted (64 MiB). */
  public static final long MAX_FILE_BYTES = 64L << 20;

  /** Most triangles accepted (a binary file at the size limit holds about 1.34 million). */
  public static final int MAX_TRIANGLES = 2_000_000;

  private static final int HEADER_BYTES = 84;
  private static final int TRIANGLE_BYTES = 50;

  private StlReader() {}

  /** Reads {@code file}, multiplying every coordinate by {@code scale} (finite, > 0). */
  public static TriangleMesh read(Path file, double scale) throws IOException {
    String name = file.toString();
    if (!(scale > 0) || !Double.isFinite(scale)) {
      throw new IllegalArgumentException("STL scale must be a finite number > 0, got " + scale);
    }
    long size;
    try {
      size = Files.size(file);
    } catch (NoSuchFileException e) {
      throw new FileFormatException(name, 0, "no such file");
    }
    if (size == 0) {
      throw new FileFormatException(name, 0, "empty file: expected a binary or ASCII STL mesh");
    }
    if (size > MAX_FILE_BYTES) {
      throw new FileFormatException(name, 0, String.format(java.util.Locale.ROOT,
          "file is %.1f MiB; STL meshes are limited to %d MiB (simplify the mesh)", size / 1048576.0, MAX_FILE_BYTES >> 20));
    }
    byte[] head = new byte[(int) Math.min(size, HEADER_BYTES)];
    try (InputStream in = Files.newInputStream(file)) {
      int n = in.readNBytes(head, 0, head.length);
      if (n != head.length) {
        throw new FileFormatException(name, 0, "file shrank while being read");
      }
    }
    // Binary headers may also start with "solid"; a NUL or non-ASCII byte in it says binary.
    boolean startsWithSolid = new String(head, 0, Math.min(head.length, 5), StandardCharsets.US_ASCII).equals("solid")
        && isText(head);
    if (head.length == HEADER_BYTES) {
      long count = ByteBuffer.wrap(head, 80, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xFFFFFFFFL;
      long expected = HEADER_BYTES + TRIANGLE_BYTES * count;
      if (expected == size) {
        return readBinary(file, name, (int) count, scale);
      }
      if (!startsWithSolid) {
        throw new FileFormatException(name, 0, "wrong size for a binary STL: the header says " + count
            + " triangles, which needs " + expected + " bytes, but the file has " + size + " bytes (truncated or corrupt)");
      }
    } else if (!startsWithSolid) {
      throw new FileFormatException(name, 0, "truncated: a binary STL needs at least an 84-byte header, the file has "
          + size + " bytes");
    }
    return readAscii(file, name, scale);
  }

  private static TriangleMesh readBinary(Path file, String name, int count, double scale) throws IOException {
    if (count == 0) {
      throw new FileFormatException(name, 0, "binary STL with no triangles");
    }
    if (count > MAX_TRIANGLES) {
      throw new FileFormatException(name, 0, count + " triangles; the limit is " + MAX_TRIANGLES);
    }
    float[] corners = new float[9 * count];
    ByteBuffer buf = ByteBuffer.allocate(TRIANGLE_BYTES * 4096).order(ByteOrder.LITTLE_ENDIAN);
    try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
      ch.position(HEADER_BYTES);
      int t = 0;
      while (t < count) {
        buf.clear();
        buf.limit(Math.min(buf.capacity(), (count - t) * TRIANGLE_BYTES));
        while (buf.hasRemaining()) {
          if (ch.read(buf) < 0) {
            throw new FileFormatException(name, 0, "truncated: ended inside triangle " + (t + 1) + " of " + count);
          }
        }
        buf.flip();
        while (buf.remaining() >= TRIANGLE_BYTES) {
          buf.position(buf.position() + 12); // skip the normal
          for (int k = 0; k < 9; k++) {
            float v = buf.getFloat();
            if (!Float.isFinite(v)) {
              throw new FileFormatException(name, 0, "triangle " + (t + 1) + " has a non-finite coordinate");
            }
            corners[9 * t + k] = (float) (v * scale);
          }
          buf.position(buf.position() + 2); // attribute byte count
          t++;
        }
      }
    }
    return new TriangleMesh(corners);
  }

  private static TriangleMesh readAscii(Path file, String name, double scale) throws IOException {
    float[] corners = new float[9 * 1024];
    int floats = 0;
    int vertexInFacet = 0;
    int lineNo = 0;
    boolean inFacet = false;
    try (BufferedReader in = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1)) {
      for (String line = in.readLine(); line != null; line = in.readLine()) {
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
              corners[floats++] = (float) (number(name, lineNo, tok[k]) * scale);
            }
            vertexInFacet++;
          }
          case "endfacet" -> {
            if (!inFacet || vertexInFacet != 3) {
              throw new FileFormatException(name, lineNo, "a facet needs exactly 3 vertices, got " + vertexInFacet);
            }
            inFacet = false;
          }
          default -> throw new FileFormatException(name, lineNo, "unexpected '" + tok[0]
              + "': expected solid, facet, outer loop, vertex, endloop, endfacet or endsolid");
        }
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

  private static boolean isText(byte[] bytes) {
    for (byte b : bytes) {
      if (b == 0 || b < 0) {
        return false;
      }
    }
    return true;
  }

  private static double number(String name, int line, String text) {
    try {
      double v = Double.parseDouble(text);
      if (Double.isFinite(v)) {
        return v;
      }
    } catch (NumberFormatException e) {
      // reported below
    }
    throw new FileFormatException(name, line, "expected a finite number, got '" + text + "'");
  }
}
