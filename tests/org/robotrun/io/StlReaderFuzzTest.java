package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Tuple;
import org.robotrun.math.PoseLimits;
import org.robotrun.world.TriangleMesh;

/**
 * Fuzzing the STL reader (issue 18): binary and ASCII meshes with corrupted counts, cut bodies,
 * spliced bytes and odd numbers must give a mesh within the coordinate bounds or a
 * {@link FileFormatException} naming the file, never another exception. Fixed seed, small
 * budget; {@link StlReaderFuzzCampaign} is the long campaign ({@code -Pfuzz}).
 */
class StlReaderFuzzTest {
  static final String ASCII = "solid part\n"
      + "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 10 0 0\n  vertex 0 10 0\n endloop\nendfacet\n"
      + "facet normal 0 0 1\n outer loop\n  vertex 0 0 5\n  vertex 10 0 5\n  vertex 0 10 5\n endloop\nendfacet\n"
      + "endsolid part\n";

  static byte[] binary(int triangles, float v) {
    ByteBuffer b = ByteBuffer.allocate(84 + 50 * triangles).order(ByteOrder.LITTLE_ENDIAN);
    b.position(80);
    b.putInt(triangles);
    for (int t = 0; t < triangles; t++) {
      b.putFloat(0).putFloat(0).putFloat(1);
      for (int k = 0; k < 9; k++) {
        b.putFloat(k % 4 == 0 ? v : k);
      }
      b.putShort((short) 0);
    }
    return b.array();
  }

  private static final List<String> NUMBERS = List.of("1e39", "-1e39", "1e30", "0x1p3", "1d", "NaN", "Infinity",
      "1e-400", "-0", ".5", "5.", "1e", "--1", "+1", "1_000", "99999", "100001");

  @Provide
  Arbitrary<byte[]> meshes() {
    byte[] ascii = ASCII.getBytes(StandardCharsets.US_ASCII);
    Arbitrary<Integer> at = Arbitraries.integers().between(0, ascii.length);
    Arbitrary<byte[]> numbers = Combinators.combine(Arbitraries.of(NUMBERS), Arbitraries.integers().between(0, 5))
        .as((n, which) -> ASCII.replaceFirst("vertex 10 0 0|vertex 0 10 0|vertex 0 0 5|vertex 10 0 5|vertex 0 10 5|vertex 0 0 0"
            .split("\\|")[which], "vertex " + n + " 0 0").getBytes(StandardCharsets.UTF_8));
    Arbitrary<byte[]> spliced = Combinators.combine(at, Arbitraries.strings().withCharRange('\u0000', '\u00ff').ofMaxLength(8))
        .as((n, s) -> (ASCII.substring(0, n) + s + ASCII.substring(n)).getBytes(StandardCharsets.ISO_8859_1));
    Arbitrary<byte[]> cutAscii = at.map(n -> Arrays.copyOf(ascii, n));
    Arbitrary<byte[]> bin = Combinators.combine(Arbitraries.integers().between(0, 6),
        Arbitraries.of(0f, 1f, 1e30f, Float.NaN, Float.POSITIVE_INFINITY, -3.4e38f)).as(StlReaderFuzzTest::binary);
    Arbitrary<byte[]> binCorrupt = Combinators.combine(bin, Arbitraries.integers().between(0, 400), Arbitraries.bytes())
        .as((b, i, v) -> {
          byte[] c = b.clone();
          if (c.length > 0) {
            c[i % c.length] = v;
          }
          return c;
        });
    Arbitrary<byte[]> binCut = Combinators.combine(bin, Arbitraries.integers().between(0, 400))
        .as((b, n) -> Arrays.copyOf(b, Math.min(n, b.length)));
    Arbitrary<byte[]> solidBinary = bin.map(b -> {
      byte[] c = b.clone();
      System.arraycopy("solid".getBytes(StandardCharsets.US_ASCII), 0, c, 0, 5);
      return c;
    });
    Arbitrary<byte[]> noise = Arbitraries.bytes().array(byte[].class).ofMaxSize(300);
    return Arbitraries.frequencyOf(Tuple.of(2, numbers), Tuple.of(2, spliced), Tuple.of(1, cutAscii),
        Tuple.of(2, binCorrupt), Tuple.of(1, binCut), Tuple.of(1, solidBinary), Tuple.of(1, noise));
  }

  @Property(seed = "18", tries = 1500)
  void anyBytesGiveABoundedMeshOrAFileError(@ForAll("meshes") byte[] bytes, @ForAll("scales") double scale) {
    check(bytes, scale);
  }

  @Provide
  Arbitrary<Double> scales() {
    return Arbitraries.of(1.0, 1000.0, 0.001, 1e-30);
  }

  static void check(byte[] bytes, double scale) {
    TriangleMesh mesh;
    try {
      mesh = StlReader.parse("fuzz.stl", bytes, scale);
    } catch (FileFormatException e) {
      assertThat(e.getMessage()).startsWith("fuzz.stl");
      return;
    }
    assertThat(mesh.triangleCount()).isPositive();
    float[] c = mesh.corners();
    for (float v : c) {
      assertThat(PoseLimits.coordinateOk(v)).as("coordinate %s", v).isTrue();
    }
  }
}
