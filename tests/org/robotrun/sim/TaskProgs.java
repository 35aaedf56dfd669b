package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Locale;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.program.Program;

/** Small .LS programs for the multitasking, BG logic and UOP tests. */
final class TaskProgs {
  private TaskProgs() {}

  /** A program with motion group 1 ("1,*,*,*,*") or none ("*,*,*,*,*"). */
  static Program program(String name, boolean group, String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  " + name + "\n/ATTR\nDEFAULT_GROUP\t= "
        + (group ? "1,*,*,*,*" : "*,*,*,*,*") + ";\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format(Locale.ROOT, "%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\n/END\n");
    LsReadResult r = LsReader.parse(name + ".LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics().toString()).isFalse();
    return r.program();
  }

  static void steps(Simulation sim, int n) {
    for (int i = 0; i < n; i++) {
      sim.step();
    }
  }
}
