package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.program.Program;

/** read → write → read is the identity on the model; write → read → write gives the same bytes. */
class LsRoundTripTest {

  static final Path PROGRAMS = Path.of("tests/resources/programs");

  static Stream<Path> goldenPrograms() throws IOException {
    try (Stream<Path> s = Files.list(PROGRAMS)) {
      List<Path> all = s.filter(p -> p.getFileName().toString().toUpperCase().endsWith(".LS")).sorted().toList();
      assertThat(all).isNotEmpty();
      return all.stream();
    }
  }

  @ParameterizedTest(name = "{0}")
  @MethodSource("goldenPrograms")
  void readWriteReadIsTheIdentityAndWritingIsStable(Path file) throws IOException {
    LsReadResult first = LsReader.read(file);
    assertThat(first.diagnostics()).filteredOn(Diagnostic::isError).isEmpty();

    String written = LsWriter.write(first.program());
    LsReadResult second = LsReader.parse(file.toString(), written);
    assertThat(second.diagnostics()).filteredOn(Diagnostic::isError).isEmpty();
    assertThat(second.program()).isEqualTo(first.program());

    String rewritten = LsWriter.write(second.program());
    assertThat(rewritten).isEqualTo(written);
  }

  @Test
  void pick3IsWrittenBackByteForByte() throws IOException {
    Path file = PROGRAMS.resolve("PICK3.LS");
    String original = Files.readString(file, StandardCharsets.UTF_8);
    Program p = LsReader.read(file).program();
    assertThat(LsWriter.write(p)).isEqualTo(original);
  }
}
