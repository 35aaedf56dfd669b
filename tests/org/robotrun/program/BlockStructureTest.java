package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.program.Tp.comment;
import static org.robotrun.program.Tp.els;
import static org.robotrun.program.Tp.endFor;
import static org.robotrun.program.Tp.endIf;
import static org.robotrun.program.Tp.forUp;
import static org.robotrun.program.Tp.ifThen;
import static org.robotrun.program.Tp.jmp;
import static org.robotrun.program.Tp.num;
import static org.robotrun.program.Tp.on;
import static org.robotrun.program.Tp.setR;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Block structure as docs/alarms.md (SIMU-002) and docs/tp-language.md state it: FOR/ENDFOR and
 * IF…THEN/ELSE/ENDIF nest properly, SELECT case lines follow their SELECT; a broken structure
 * (which the reader refuses, but an edit may leave) alarms SIMU-002 on the line at fault when the
 * program starts; nested blocks run the branch their condition picks.
 */
class BlockStructureTest {

  private static Instruction select(int value) {
    return new Instruction.Select(Item.of(1), num(value), jmp(9));
  }

  private static Instruction selectCase(int value) {
    return new Instruction.SelectCase(num(value), jmp(9));
  }

  record Broken(String what, int line, List<Instruction> lines) {}

  @Test
  void everyBrokenStructureAlarmsOnTheLineAtFault() {
    List<Broken> cases = List.of(
        new Broken("ENDFOR alone", 2, List.of(comment("a"), endFor())),
        new Broken("FOR without ENDFOR", 2, List.of(comment("a"), forUp(1, num(1), num(2)), comment("b"))),
        new Broken("ELSE alone", 2, List.of(comment("a"), els(), endIf())),
        new Broken("ENDIF alone", 3, List.of(comment("a"), comment("b"), endIf())),
        new Broken("IF…THEN without ENDIF", 1, List.of(ifThen(on()), comment("b"))),
        new Broken("two ELSEs", 3, List.of(ifThen(on()), els(), els(), endIf())),
        new Broken("ENDIF closing a FOR", 3, List.of(ifThen(on()), forUp(1, num(1), num(2)), endIf(), endFor())),
        new Broken("ENDFOR closing an IF", 3, List.of(forUp(1, num(1), num(2)), ifThen(on()), endFor(), endIf())),
        new Broken("ELSE inside a FOR", 3, List.of(ifThen(on()), forUp(1, num(1), num(2)), els(), endFor(), endIf())),
        new Broken("a SELECT case alone", 2, List.of(comment("a"), selectCase(2), new Instruction.Label(9, ""))),
        new Broken("a SELECT case after another line", 3,
            List.of(select(1), comment("x"), selectCase(2), new Instruction.Label(9, ""))),
        new Broken("SELECT ELSE alone", 1, List.of(new Instruction.SelectElse(jmp(9)), new Instruction.Label(9, ""))));
    for (Broken b : cases) {
      Rig rig = new Rig(Program.of("B", b.lines()));
      Alarm a = rig.alarm(rig.run());
      assertThat(a.code()).as(b.what()).isEqualTo("SIMU-002");
      assertThat(a.line()).as(b.what()).isEqualTo(b.line());
      assertThat(rig.regs.number(1)).as(b.what() + ": nothing ran").isZero();
    }
  }

  @Test
  void theInnermostOpenBlockIsNamedInTheMessage() {
    Rig rig = new Rig(Program.of("B", List.of(forUp(1, num(1), num(2)), comment("x"), endIf(), endFor())));
    Alarm a = rig.alarm(rig.run());
    assertThat(a.message()).contains("ENDIF without IF…THEN").contains("FOR at line 1");
    Rig rig2 = new Rig(Program.of("B", List.of(comment("x"), ifThen(on()), endFor(), endIf())));
    assertThat(rig2.alarm(rig2.run()).message()).contains("ENDFOR without FOR").contains("IF…THEN at line 2");
  }

  @Test
  void nestedBlocksRunTheBranchesTheirConditionsPick() {
    // IF a THEN (FOR 1..2 (IF b THEN R[2]+1 ELSE R[3]+1 ENDIF) ENDFOR) ELSE (IF b THEN R[4]=1 ENDIF) ENDIF
    for (boolean a : new boolean[] {false, true}) {
      for (boolean b : new boolean[] {false, true}) {
        Rig rig = run(
            "F[1]=" + (a ? "ON" : "OFF"),
            "F[2]=" + (b ? "ON" : "OFF"),
            "IF (F[1]) THEN",
            "FOR R[1]=1 TO 2",
            "IF (F[2]) THEN",
            "R[2]=R[2]+1",
            "ELSE",
            "R[3]=R[3]+1",
            "ENDIF",
            "ENDFOR",
            "ELSE",
            "IF (F[2]) THEN",
            "R[4]=1",
            "ENDIF",
            "R[5]=1",
            "ENDIF",
            "R[6]=1");
        assertThat(rig.regs.number(2)).as("a=%s b=%s", a, b).isEqualTo(a && b ? 2 : 0);
        assertThat(rig.regs.number(3)).as("a=%s b=%s", a, b).isEqualTo(a && !b ? 2 : 0);
        assertThat(rig.regs.number(4)).as("a=%s b=%s", a, b).isEqualTo(!a && b ? 1 : 0);
        assertThat(rig.regs.number(5)).as("a=%s b=%s", a, b).isEqualTo(!a ? 1 : 0);
        assertThat(rig.regs.number(6)).isEqualTo(1);
      }
    }
  }

  @Test
  void aSelectGroupWithCallsReturnsAfterTheGroup() {
    for (int v = 1; v <= 4; v++) {
      Rig rig = new Rig(RunSemanticsTableTest.parse("R[1]=" + v, "SELECT R[1]=1,CALL SUBA", "       =2,CALL SUBB",
          "       ELSE,CALL SUBC", "R[9]=R[9]+1"), Tp.prog("SUBA", setR(2, num(1))), Tp.prog("SUBB", setR(3, num(1))),
          Tp.prog("SUBC", setR(4, num(1))));
      assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
      assertThat(rig.regs.number(2)).as("R[1]=%d", v).isEqualTo(v == 1 ? 1 : 0);
      assertThat(rig.regs.number(3)).as("R[1]=%d", v).isEqualTo(v == 2 ? 1 : 0);
      assertThat(rig.regs.number(4)).as("R[1]=%d", v).isEqualTo(v > 2 ? 1 : 0);
      // the line after the group runs once, whichever case was taken
      assertThat(rig.regs.number(9)).isEqualTo(1);
    }
  }

  private static Rig run(String... lines) {
    return RunSemanticsTableTest.run(lines);
  }
}
