package org.robotrun.app;

import java.util.Optional;
import org.robotrun.io.LsReader;
import org.robotrun.io.LsReadResult;
import org.robotrun.pendant.LineParser;
import org.robotrun.program.Instruction;

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
}
