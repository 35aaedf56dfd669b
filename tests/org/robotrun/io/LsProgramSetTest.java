package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

class LsProgramSetTest {

  private static LsReadResult program(String file, String name, String... mn) {
    StringBuilder sb = new StringBuilder("/PROG  " + name + "\n/MN\n");
    for (int i = 0; i < mn.length; i++) {
      sb.append(String.format("%4d:  %s ;%n", i + 1, mn[i]));
    }
    return LsReader.parse(file, sb.append("/POS\n/END\n").toString());
  }

  private static List<String> messages(List<LsReadResult> rs) {
    return rs.stream().flatMap(r -> r.diagnostics().stream()).map(Diagnostic::toString).toList();
  }

  @Test
  void callsAreCheckedAcrossTheSetAndAgainstExtraNames() {
    LsReadResult main = program("MAIN.LS", "MAIN", "CALL SUB", "IF R[1]=1,CALL ELSEWHERE", "SELECT R[2]=1,CALL GHOST", "CALL main");
    LsReadResult sub = program("SUB.LS", "SUB", "END");
    assertThat(messages(LsProgramSet.crossCheck(List.of(main, sub), Set.of("elsewhere"))))
        .containsExactly("MAIN.LS:5: CALL GHOST: no program named GHOST is known");
    assertThat(messages(LsProgramSet.crossCheck(List.of(main), Set.of())))
        .containsExactly(
            "MAIN.LS:3: CALL SUB: no program named SUB is known",
            "MAIN.LS:4: CALL ELSEWHERE: no program named ELSEWHERE is known",
            "MAIN.LS:5: CALL GHOST: no program named GHOST is known");
  }

  @Test
  void runTargetsAreCheckedLikeCallTargets() {
    LsReadResult main = program("MAIN.LS", "MAIN", "RUN SUB", "RUN NOWHERE");
    LsReadResult sub = program("SUB.LS", "SUB", "END");
    assertThat(messages(LsProgramSet.crossCheck(List.of(main, sub), Set.of())))
        .containsExactly("MAIN.LS:4: RUN NOWHERE: no program named NOWHERE is known");
  }

  @Test
  void aProgramDefinedTwiceIsReportedOnTheLaterFile() {
    List<LsReadResult> rs = LsProgramSet.crossCheck(
        List.of(program("a/SUB.LS", "SUB", "END"), program("b/SUB.LS", "sub", "END")), Set.of());
    assertThat(messages(rs)).containsExactly("b/SUB.LS:1: program SUB is also defined in a/SUB.LS");
    assertThat(rs.get(1).hasAnyError()).isTrue();
    assertThat(rs.get(0).hasAnyError()).isFalse();
  }
}
