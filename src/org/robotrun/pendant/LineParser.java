package org.robotrun.pendant;

import java.util.Optional;
import org.robotrun.program.Instruction;

/**
 * Reads one TP statement from its text, for "uncomment" of a {@code //} line the pendant did not
 * comment out itself. The .LS reader lives in {@code io}, which the pendant may not import, so
 * the application passes it in.
 */
@FunctionalInterface
public interface LineParser {
  /** The statement {@code text} holds, or empty when it is not one. */
  Optional<Instruction> parse(String text);

  /** No parser: only lines commented out on this pendant can be uncommented. */
  LineParser NONE = text -> Optional.empty();
}
