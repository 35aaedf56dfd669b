package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/**
 * Issue 18 fuzzing of the .LS reader (fixed seed, small budget; {@code -Pfuzz} may raise the
 * tries with {@code -Djqwik.tries.default}): corpus files with bytes inserted, deleted and
 * replaced never throw, a file read and written without an edit comes back byte for byte, and
 * what is read writes afresh and reads back as the same program.
 */
class LsReaderFuzzTest {

  private static final List<byte[]> CORPUS = load();

  private static List<byte[]> load() {
    try (Stream<Path> s = Files.list(Path.of("tests/resources/corpus"))) {
      return s.filter(p -> p.toString().endsWith(".LS")).sorted().map(p -> {
        try {
          return Files.readAllBytes(p);
        } catch (IOException e) {
          throw new UncheckedIOException(e);
        }
      }).toList();
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  @Property(tries = 300, seed = "14180001")
  void damagedControllerFilesNeverThrowAndComeBackAsRead(@ForAll("damaged") byte[] file) {
    LsReadResult r = LsReader.read("fuzz.LS", file);
    if (r.program().source().isPresent()) {
      assertThat(LsWriter.bytes(r.program())).isEqualTo(file);
    }
    org.robotrun.program.Program fresh = r.program();
    String text = LsWriter.write(fresh.withoutSource());
    assertThat(LsReader.parse("fuzz.LS", text).program()).as(text).isEqualTo(fresh);
  }

  private record Edit(int kind, int at, byte value) {}

  @Provide
  Arbitrary<byte[]> damaged() {
    Arbitrary<byte[]> base = Arbitraries.of(CORPUS);
    Arbitrary<List<Edit>> edits = Combinators.combine(Arbitraries.integers().between(0, 2),
        Arbitraries.integers().between(0, 1 << 20),
        Arbitraries.of((byte) '[', (byte) ']', (byte) ';', (byte) ':', (byte) '\n', (byte) '\r', (byte) '(',
            (byte) '-', (byte) '$', (byte) 0xE9, (byte) 0, (byte) 'R', (byte) '1', (byte) ' ', (byte) '"'))
        .as(Edit::new).list().ofMinSize(1).ofMaxSize(6);
    return Combinators.combine(base, edits).as((b, es) -> {
      java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
      byte[] cur = b.clone();
      for (Edit e : es) {
        int at = cur.length == 0 ? 0 : e.at() % cur.length;
        out.reset();
        out.write(cur, 0, at);
        switch (e.kind()) {
          case 0 -> out.write(cur, Math.min(at + 1, cur.length), cur.length - Math.min(at + 1, cur.length));
          case 1 -> {
            out.write(e.value());
            out.write(cur, at, cur.length - at);
          }
          default -> {
            out.write(e.value());
            out.write(cur, Math.min(at + 1, cur.length), cur.length - Math.min(at + 1, cur.length));
          }
        }
        cur = out.toByteArray();
      }
      return cur;
    });
  }
}
