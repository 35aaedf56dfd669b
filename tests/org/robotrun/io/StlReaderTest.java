package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.RandomAccessFile;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.math.Vec3;
import org.robotrun.world.TriangleMesh;

class StlReaderTest {
  @TempDir Path dir;

  /** The 12 triangles of the cube [0, 10] × [0, 20] × [0, 30] (mm). */
  private static float[][] cube() {
    float[][] c = new float[8][];
    for (int i = 0; i < 8; i++) {
      c[i] = new float[] {(i & 1) * 10, ((i >> 1) & 1) * 20, ((i >> 2) & 1) * 30};
    }
    int[][] faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    float[][] tris = new float[12][];
    int t = 0;
    for (int[] f : faces) {
      tris[t++] = concat(c[f[0]], c[f[1]], c[f[2]]);
      tris[t++] = concat(c[f[0]], c[f[2]], c[f[3]]);
    }
    return tris;
  }

  private static float[] concat(float[] a, float[] b, float[] c) {
    float[] out = new float[9];
    System.arraycopy(a, 0, out, 0, 3);
    System.arraycopy(b, 0, out, 3, 3);
    System.arraycopy(c, 0, out, 6, 3);
    return out;
  }

  private static byte[] binary(float[][] tris, String header) {
    ByteBuffer b = ByteBuffer.allocate(84 + 50 * tris.length).order(ByteOrder.LITTLE_ENDIAN);
    byte[] h = Arrays.copyOf(header.getBytes(), 80);
    b.put(h).putInt(tris.length);
    for (float[] t : tris) {
      b.putFloat(0).putFloat(0).putFloat(0);
      for (float v : t) {
        b.putFloat(v);
      }
      b.putShort((short) 0);
    }
    return b.array();
  }

  private static String ascii(float[][] tris) {
    StringBuilder sb = new StringBuilder("solid cube\n");
    for (float[] t : tris) {
      sb.append("  facet normal 0 0 0\n    outer loop\n");
      for (int k = 0; k < 9; k += 3) {
        sb.append("      vertex ").append(t[k]).append(' ').append(t[k + 1]).append(' ').append(t[k + 2]).append('\n');
      }
      sb.append("    endloop\n  endfacet\n");
    }
    return sb.append("endsolid cube\n").toString();
  }

  @Test
  void binaryCubeHasTwelveTrianglesAndItsBounds() throws Exception {
    Path f = Files.write(dir.resolve("cube.stl"), binary(cube(), "binary cube"));
    TriangleMesh m = StlReader.read(f, 1);
    assertThat(m.triangleCount()).isEqualTo(12);
    assertThat(m.min()).isEqualTo(new Vec3(0, 0, 0));
    assertThat(m.max()).isEqualTo(new Vec3(10, 20, 30));
  }

  @Test
  void binaryWhoseHeaderSaysSolidIsStillBinary() throws Exception {
    Path f = Files.write(dir.resolve("cube.stl"), binary(cube(), "solid exported by a CAD tool"));
    assertThat(StlReader.read(f, 1).triangleCount()).isEqualTo(12);
  }

  @Test
  void asciiCubeScaledFromMetres() throws Exception {
    float[][] tris = cube();
    for (float[] t : tris) {
      for (int k = 0; k < 9; k++) {
        t[k] /= 1000; // metres
      }
    }
    Path f = Files.writeString(dir.resolve("cube.stl"), ascii(tris));
    TriangleMesh m = StlReader.read(f, 1000);
    assertThat(m.triangleCount()).isEqualTo(12);
    // Tolerance: float rounding of the metre values, 1e-4 mm.
    assertThat(m.max().x()).isCloseTo(10, org.assertj.core.api.Assertions.within(1e-4));
    assertThat(m.max().z()).isCloseTo(30, org.assertj.core.api.Assertions.within(1e-4));
    assertThat(m.min().y()).isCloseTo(0, org.assertj.core.api.Assertions.within(1e-4));
  }

  @Test
  void asciiAndBinaryGiveTheSameMesh() throws Exception {
    Path b = Files.write(dir.resolve("b.stl"), binary(cube(), ""));
    Path a = Files.writeString(dir.resolve("a.stl"), ascii(cube()));
    assertThat(StlReader.read(a, 1)).isEqualTo(StlReader.read(b, 1));
  }

  @Test
  void emptyFile() throws Exception {
    Path f = Files.write(dir.resolve("empty.stl"), new byte[0]);
    assertError(f, f + ": empty file");
  }

  @Test
  void truncatedBinary() throws Exception {
    byte[] full = binary(cube(), "");
    Path f = Files.write(dir.resolve("cut.stl"), Arrays.copyOf(full, full.length - 30));
    assertError(f, "header says 12 triangles, which needs 684 bytes, but the file has 654 bytes");
    Path tiny = Files.write(dir.resolve("tiny.stl"), new byte[40]);
    assertError(tiny, "truncated: a binary STL needs at least an 84-byte header, the file has 40 bytes");
  }

  @Test
  void wrongSizeBinary() throws Exception {
    byte[] full = binary(cube(), "");
    Path f = Files.write(dir.resolve("long.stl"), Arrays.copyOf(full, full.length + 7));
    assertError(f, "the file has 691 bytes");
  }

  @Test
  void asciiErrorsNameTheLine() throws Exception {
    String text = ascii(cube());
    Path bad = Files.writeString(dir.resolve("bad.stl"), text.replaceFirst("vertex 0\\.0", "vertex zero"));
    assertError(bad, bad + ":4: expected a finite number, got 'zero'");
    Path cut = Files.writeString(dir.resolve("cut.stl"), text.substring(0, text.indexOf("endfacet")));
    assertError(cut, "truncated: the file ends inside a facet");
    Path none = Files.writeString(dir.resolve("none.stl"), "solid nothing\nendsolid nothing\n");
    assertError(none, "ASCII STL with no triangles");
  }

  @Test
  void twoHundredMegabytesIsRefusedWithoutReadingIt() throws Exception {
    Path f = dir.resolve("huge.stl");
    try (RandomAccessFile raf = new RandomAccessFile(f.toFile(), "rw")) {
      raf.setLength(200L << 20); // sparse: nothing is written, and the reader must not read it
    }
    assertError(f, "file is 200.0 MiB; STL meshes are limited to 64 MiB");
  }

  @Test
  void corruptedFilesGiveFileErrorsNeverOtherExceptions() throws Exception {
    // Method: 300 seeded corruptions (cut, flipped bytes, NaN coordinates) of both cube files;
    // each read returns a mesh or throws FileFormatException naming the file.
    java.util.Random random = new java.util.Random(77);
    byte[][] originals = {binary(cube(), "x"), ascii(cube()).getBytes()};
    Path f = dir.resolve("c.stl");
    for (int i = 0; i < 300; i++) {
      byte[] b = originals[i % 2].clone();
      switch (random.nextInt(3)) {
        case 0 -> b = Arrays.copyOf(b, random.nextInt(b.length));
        case 1 -> {
          for (int k = 0; k < 5; k++) {
            b[random.nextInt(b.length)] = (byte) random.nextInt(256);
          }
        }
        default -> {
          int at = 84 + 12 + 50 * random.nextInt(12);
          if (i % 2 == 0) {
            ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putFloat(at, Float.NaN);
          }
        }
      }
      Files.write(f, b);
      try {
        StlReader.read(f, 1);
      } catch (FileFormatException e) {
        assertThat(e.getMessage()).startsWith(f.toString());
      }
    }
  }

  @Test
  void missingFile() {
    Path f = dir.resolve("nope.stl");
    assertError(f, f + ": no such file");
  }

  private static void assertError(Path f, String expected) {
    assertThatThrownBy(() -> StlReader.read(f, 1))
        .isInstanceOf(FileFormatException.class)
        .hasMessageStartingWith(f.toString())
        .hasMessageContaining(expected);
  }
}
