package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.robotrun.program.Instruction;
import org.robotrun.program.Program;
import org.robotrun.program.TpModels;
import org.robotrun.program.TpText;

/**
 * The pendant shows a line as a file holds it: the EDIT screen's fields of any instruction, put
 * together, are the one printer's text ({@link TpText}), blanks aside (the pendant drops FANUC's
 * padding and shows a C motion's continuation on the same line). jqwik, fixed seed.
 */
class PendantLineTextPropertyTest {

  @Property(tries = 1500, seed = "2311202604")
  void theEditScreenShowsThePrintersText(@ForAll("instructions") Instruction in) {
    Program empty = Program.of("T", List.of(in));
    String shown = TpLine.text(in, empty, List.of());
    assertThat(blanksFolded(shown)).as(shown).isEqualTo(blanksFolded(TpText.statement(in)));
  }

  private static String blanksFolded(String s) {
    return s.replaceAll("\\s+", " ").strip();
  }

  @Provide
  Arbitrary<Instruction> instructions() {
    return TpModels.instruction();
  }
}
