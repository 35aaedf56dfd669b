package org.robotrun.app;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.LsReader;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsWriter;
import org.robotrun.pendant.LineParser;
import org.robotrun.program.Instruction;
import org.robotrun.program.Program;

/**
 * The pendant's "uncomment" parser: reads one TP statement with the .LS reader by wrapping it
 * in a one-line program. Checks that need the rest of the program (a P[] missing from /POS, an
 * undefined label) do not count here; a line the reader cannot read at all is refused.
 */
public final class LsLineParser implements LineParser {
  @Override
  public Optional<Instruction> parse(String text) {
    if (text.contains("\n") || text.contains(";")) {
      return Optional.empty();
    }
    String source = "/PROG  LINE\n/ATTR\n/MN\n   1:  " + text.strip() + " ;\n/POS\n/END\n";
    LsReadResult r = LsReader.parse("line", source);
    if (r.program() == null || r.program().lineCount() != 1) {
      return Optional.empty();
    }
    Instruction in = r.program().line(1);
    // the reader keeps a line it cannot read as a commented-out line, with an error
    return in instanceof Instruction.CommentedOut ? Optional.empty() : Optional.of(in);
  }

  /**
   * Writes every line of {@code edited} that {@code before} does not have, and the positions when
   * they changed, as a controller file, reads it back, and answers the first reason it does not
   * come back the same: the pendant then refuses the edit, so whatever it saves {@code check}
   * accepts.
   */
  @Override
  public Optional<String> refusal(Program before, Program edited) {
    Map<Instruction, Integer> old = new HashMap<>();
    before.lines().forEach(in -> old.merge(in, 1, Integer::sum));
    for (Instruction in : edited.lines()) {
      Integer n = old.get(in);
      if (n != null && n > 0) {
        old.put(in, n - 1);
        continue;
      }
      Optional<String> bad = comesBack(Program.of("LINE", List.of(in)));
      if (bad.isPresent()) {
        return bad;
      }
    }
    if (!edited.positions().equals(before.positions())) {
      return comesBack(new Program("LINE", Map.of(), "", List.of(), edited.positions()));
    }
    return Optional.empty();
  }

  private static Optional<String> comesBack(Program p) {
    String text;
    try {
      text = LsWriter.write(p);
    } catch (IllegalArgumentException e) {
      return Optional.of(e.getMessage());
    }
    LsReadResult r = LsReader.parse("line", text);
    Optional<Diagnostic> error = r.diagnostics().stream()
        .filter(d -> d.isError() && d.kind() != Diagnostic.Kind.REFERENCE).findFirst();
    if (error.isPresent()) {
      return Optional.of("The controller would not read this back: " + error.get().message());
    }
    // Positions come back to 0.001 mm / deg, as a controller stores them; their number and form must hold.
    if (!r.program().lines().equals(p.lines()) || !r.program().positions().keySet().equals(p.positions().keySet())) {
      return Optional.of("The controller would read this back differently: "
          + LsWriter.write(p).lines().filter(l -> l.matches("\\s*\\d+:.*")).findFirst().orElse("a position").strip());
    }
    return Optional.empty();
  }
}
