package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
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
    // UNSUPP.LS holds an unsupported statement on purpose: it loads, and is kept as written.
    assertThat(first.diagnostics()).filteredOn(Diagnostic::isError)
        .filteredOn(d -> d.kind() != Diagnostic.Kind.UNSUPPORTED).isEmpty();

    String written = LsWriter.write(first.program());
    LsReadResult second = LsReader.parse(file.toString(), written);
    assertThat(second.diagnostics()).filteredOn(Diagnostic::isError)
        .filteredOn(d -> d.kind() != Diagnostic.Kind.UNSUPPORTED).isEmpty();
    assertThat(second.program()).isEqualTo(first.program());

    String rewritten = LsWriter.write(second.program());
    assertThat(rewritten).isEqualTo(written);
  }

  /** Files written as a controller writes them (PICK3.LS is the shared example) come back unchanged. */
  @ParameterizedTest(name = "{0}")
  @ValueSource(strings = {"PICK3.LS", "STATEMENTS.LS", "MOTIONS.LS", "EXPRS.LS", "BEEP.LS", "PICKN.LS"})
  void controllerFormattedFilesAreWrittenBackByteForByte(String name) throws IOException {
    Path file = PROGRAMS.resolve(name);
    String original = Files.readString(file, StandardCharsets.UTF_8);
    Program p = LsReader.read(file).program();
    assertThat(LsWriter.write(p)).isEqualTo(original);
  }

  @Test
  void writingToAFileReplacesItWholeAndLeavesNoTemporaryFile(@TempDir Path dir) throws IOException {
    Program p = LsReader.read(PROGRAMS.resolve("PICK3.LS")).program();
    Path out = dir.resolve("PICK3.LS");
    Files.writeString(out, "an older, longer version of the file that must disappear entirely\n".repeat(100));
    LsWriter.write(p, out);
    assertThat(Files.readString(out, StandardCharsets.UTF_8)).isEqualTo(LsWriter.write(p));
    try (Stream<Path> files = Files.list(dir)) {
      assertThat(files.map(f -> f.getFileName().toString()).toList()).containsExactly("PICK3.LS");
    }
  }

  @Test
  void ourGoldenProgramsCheckCleanAsASet() throws IOException {
    List<String> names = List.of("PICK3.LS", "STATEMENTS.LS", "MOTIONS.LS", "EXPRS.LS", "BEEP.LS", "PICKN.LS");
    Set<String> programs = Set.of("PICK3", "STATEMENTS", "MOTIONS", "EXPRS", "BEEP", "PICKN");
    for (String n : names) {
      LsReadResult r = LsReader.read(PROGRAMS.resolve(n), programs);
      assertThat(r.diagnostics()).as(n).isEmpty();
    }
  }
}
