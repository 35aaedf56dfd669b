package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.pendant.PendantKeys.run;

import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.Instruction;
import org.robotrun.program.Motion;
import org.robotrun.program.Program;

/** Every statement of the program model (one record per TP statement) can be entered with keys. */
class InstructionReachabilityTest {
  private final RobotControl control = RealController.control();
  private final Pendant p = new Pendant(control);

  private static Set<Class<?>> statementTypes() {
    // Unsupported holds what RobotRun cannot run (read from a file, or uncommented with the .LS
    // line parser); the pendant's menus offer only what runs.
    return Arrays.stream(Instruction.class.getPermittedSubclasses())
        .filter(c -> !c.isInterface() && c != Instruction.Unsupported.class)
        .collect(Collectors.toSet());
  }

  private Program program() {
    return control.program("ALL").orElseThrow();
  }

  /** Picks item {@code n} (1-based) of the open choice list with arrows and ENTER. */
  private void pick(int n) {
    // a list opens on the field's current value: go to its top first
    for (int i = 0; i < 100; i++) {
      p.tap(Key.UP);
    }
    for (int i = 1; i < n; i++) {
      p.tap(Key.DOWN);
    }
    p.tap(Key.ENTER);
  }

  @Test
  void everyStatementIsReachableThroughPointInstAndEdcmd() {
    run(p, """
        SELECT
        F1
        TYPE ALL
        ENTER
        SHIFT+F1
        """);
    for (int c = 0; c < InstMenu.CATEGORIES.size(); c++) {
      for (int t = 0; t < InstMenu.CATEGORIES.get(c).templates().size(); t++) {
        p.tap(Key.ITEM);
        p.type(Integer.toString(program().lineCount() + 1));
        p.tap(Key.ENTER);
        p.tap(Key.F2);
        pick(c + 1);
        pick(t + 1);
        assertThat(p.lcd().promptLine()).as("template %d/%d", c, t).contains("Inserted");
      }
    }
    // EDCMD: blank lines and comment-out (of line 2, line 1 is the motion)
    run(p, """
        F3
        1
        ENTER
        ITEM
        TYPE 2
        ENTER
        F3
        8
        """);
    Set<Class<?>> seen = new HashSet<>();
    program().lines().forEach(i -> seen.add(i.getClass()));
    assertThat(seen).containsExactlyInAnyOrderElementsOf(statementTypes());
    // lang3's 40, RUN (Instruction.Run), IF with an action (issue 25), the four iRVision statements (issue 23)
    assertThat(statementTypes()).hasSize(46);
  }

  @Test
  void motionFormsTypesTargetsUnitsTerminationsAndOptions() {
    run(p, """
        SELECT
        F1
        TYPE ALL
        ENTER
        SHIFT+F1
        RIGHT
        ENTER
        3
        """);
    Instruction.Move m = (Instruction.Move) program().line(1);
    assertThat(m.type()).isEqualTo(Motion.Type.C);
    assertThat(m.circularEnd()).contains(new Motion.Local(2, ""));
    assertThat(m.speed().unit()).isEqualTo(Motion.SpeedUnit.MM_PER_SEC);
    // target to PR[R[3]] by typed entry; speed by register; CNT R[2]
    run(p, """
        ENTER
        1
        RIGHT
        TYPE PR[R[3]]
        ENTER
        RIGHT
        TYPE R[4]
        ENTER
        RIGHT
        ENTER
        2
        RIGHT
        TYPE R[2]
        ENTER
        """);
    m = (Instruction.Move) program().line(1);
    assertThat(m.type()).isEqualTo(Motion.Type.J);
    assertThat(TpLine.text(m, program(), List.of())).isEqualTo("J PR[R[3]] R[4]sec CNT R[2]");
    // every option through [CHOICE] on the line number
    for (int o = 1; o <= InstMenu.MOTION_OPTIONS.size(); o++) {
      run(p, "LEFT *6\nF4\n" + o);
    }
    m = (Instruction.Move) program().line(1);
    assertThat(TpLine.text(m, program(), List.of()))
        .isEqualTo("J PR[R[3]] R[4]sec CNT R[2] Offset Offset,PR[1] Tool_Offset,PR[1] ACC100 Skip,LBL[1] Wjnt INC VOFFSET,VR[1]");
  }

  @Test
  void positionRegisterSourcesAndBranchesByChoice() {
    run(p, """
        SELECT
        F1
        TYPE ALL
        ENTER
        F2
        1
        4
        RIGHT
        """);
    String[] expected = {"PR[1]=PR[1]", "PR[1]=P[1]", "PR[1]=LPOS", "PR[1]=JPOS", "PR[1]=UFRAME[1]", "PR[1]=UTOOL[1]",
        "PR[1]=PR[1]+PR[2]", "PR[1]=PR[1]-PR[2]"};
    for (int i = 0; i < expected.length; i++) {
      p.tap(Key.F4);
      pick(i + 1);
      assertThat(TpLine.text(program().line(1), program(), List.of())).isEqualTo(expected[i]);
    }
    // IF ... ,CALL by choosing the branch, then naming the program by typing
    run(p, """
        DOWN
        F2
        3
        1
        RIGHT
        ENTER
        2
        TYPE PICK(1,'A')
        ENTER
        """);
    assertThat(TpLine.text(program().line(2), program(), List.of())).isEqualTo("IF R[1]>0,CALL PICK(1,'A')");
  }
}
