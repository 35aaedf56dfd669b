package org.robotrun.pendant;

import java.util.Optional;
import org.robotrun.program.Instruction;
import org.robotrun.program.Program;

/**
 * Reads one TP statement from its text, for "uncomment" of a {@code //} line the pendant did not
 * comment out itself. The .LS reader lives in {@code io}, which the pendant may not import, so
 * the application passes it in.
 */
@FunctionalInterface
public interface LineParser {
  /** The statement {@code text} holds, or empty when it is not one. */
  Optional<Instruction> parse(String text);

  /**
   * Why the controller would not take {@code edited} as the pendant made it (a line or position
   * that would not be written and read back as the same program), or empty when it would. The
   * pendant refuses such an edit, so what it saves {@code check} accepts. Lines equal to a line
   * of {@code before} are not checked again (a file may hold lines RobotRun only keeps).
   */
  default Optional<String> refusal(Program before, Program edited) {
    return Optional.empty();
  }

  /** No parser: only lines commented out on this pendant can be uncommented. */
  LineParser NONE = text -> Optional.empty();
}
