package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.LsWriter;
import org.robotrun.pendant.TpLine;
import org.robotrun.program.Program;

/**
 * The EDIT screen shows each line as the .LS file writes it (spacing aside). Two deliberate
 * differences: a local position shows its /POS comment ({@code P[3:PLACE]}), as a pendant does,
 * and a C motion shows on one line.
 */
class PendantDisplayTest {

  @ParameterizedTest
  @ValueSource(strings = {"STATEMENTS", "PICK3", "EXPRS", "FLOW", "IOTIME", "CALLARGS", "MOTIONS"})
  void everyLineReadsAsTheWriterWritesIt(String name) throws Exception {
    LsReadResult r = LsReader.read(Path.of("tests/resources/programs/" + name + ".LS"));
    Program p = r.program();
    List<String> written = LsWriter.write(p).lines().dropWhile(l -> !l.startsWith("/MN")).skip(1)
        .takeWhile(l -> !l.startsWith("/POS")).toList();
    List<String> fileLines = new ArrayList<>();
    for (String l : written) {
      String body = l.replaceFirst("^\\s*\\d+:\\s*", "").replaceFirst("\\s*;$", "").replaceAll("\\s+", " ").trim();
      if (l.trim().startsWith(":")) {
        // the continuation line of a C motion joins its first line, as the pendant shows it
        fileLines.set(fileLines.size() - 1, fileLines.get(fileLines.size() - 1) + " " + body);
      } else {
        fileLines.add(body);
      }
    }
    assertThat(fileLines).hasSize(p.lineCount());
    for (int n = 1; n <= p.lineCount(); n++) {
      // without the /POS block: positions show the comment their line gives them, as the file does
      String shown = TpLine.text(p.line(n), Program.of(p.name(), p.lines()), List.of()).replaceAll("\\s+", " ").trim();
      assertThat(shown).as("%s line %d", name, n).isEqualTo(fileLines.get(n - 1));
    }
  }
}
