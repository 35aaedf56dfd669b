package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.robotrun.program.Tp.call;
import static org.robotrun.program.Tp.comment;
import static org.robotrun.program.Tp.joint;
import static org.robotrun.program.Tp.lin;
import static org.robotrun.program.Tp.num;
import static org.robotrun.program.Tp.pos;
import static org.robotrun.program.Tp.progWithPositions;
import static org.robotrun.program.Tp.setR;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * SHIFT+BWD as docs/tp-execution.md ("Running") and TP-LANGUAGE.md ("Execution") state it: the
 * robot stands at the nearest motion line above the cursor and moves back to the motion line above
 * that one, with the motion type and speed of the line it backs out of, ending FINE; a held motion
 * is abandoned (backing out of it returns to its start point); an INC motion and the flow
 * statements stop it with a notice naming the line. P[n] stands at x = 100·n mm ({@link Tp#pos}),
 * so each expected target is the line's own point.
 */
class BackwardExecutionTest {
  private static final double DT = 0.02;

  private static double x(MotionRequest r) {
    return ((Position.Cartesian) r.target().position()).xMm();
  }

  /** J P[1] 50%; L P[2] 100mm/sec; L P[3] 100mm/sec, with a register line between. */
  private static Program threeMoves() {
    return progWithPositions("MOVES", 3, joint(1), lin(2), setR(1, num(1)), lin(3));
  }

  @Test
  void fromACursorPutOnALineTheRobotStandsAtTheMotionAboveItAndBacksToTheOneAboveThat() {
    // Idle, never run: the cursor is put on line 3 (the register line). The nearest motion above
    // it is line 2 (P[2]); the robot backs out of line 2 to line 1's P[1], at line 2's L speed.
    Rig rig = new Rig(threeMoves());
    rig.interp.setCursor(3);
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.WaitingForMotion.class);
    MotionRequest back = rig.port.requests().get(0);
    assertThat(x(back)).isEqualTo(100.0);
    assertThat(back.type()).isEqualTo(Motion.Type.L);
    assertThat(back.speed()).isEqualTo(100.0);
    assertThat(back.speedUnit()).isEqualTo(Motion.SpeedUnit.MM_PER_SEC);
    assertThat(back.backward()).isTrue();
    assertThat(back.fine()).isTrue();
    assertThat(back.line()).isEqualTo(1);
    // while it moves, the cursor is on the line whose point it moves to
    assertThat(rig.interp.cursorLine()).isEqualTo(1);
    assertThat(rig.runUntilStopped(DT, 1000)).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.interp.cursorLine()).isEqualTo(2);
    // register lines were passed over, not run
    assertThat(rig.regs.number(1)).isEqualTo(0);
  }

  @Test
  void aCursorOnAMotionLineMeansTheRobotStandsAtTheMotionAboveIt() {
    // The cursor on line 4 (L P[3], not yet run): the robot stands at line 2's P[2]; it backs to P[1].
    Rig rig = new Rig(threeMoves());
    rig.interp.setCursor(4);
    rig.interp.backward();
    assertThat(x(rig.port.requests().get(0))).isEqualTo(100.0);
  }

  @Test
  void aHeldMotionIsAbandonedAndBackingOutOfItReturnsToItsStartPoint() {
    Rig rig = new Rig(InterpreterSettings.defaults(), 1.0, threeMoves());
    rig.interp.forward();
    for (int i = 0; i < 60; i++) {
      rig.tick(DT); // line 1 takes 1 s, then line 2 starts
    }
    assertThat(rig.interp.cursorLine()).isEqualTo(2);
    rig.interp.hold();
    assertThat(rig.port.requests()).hasSize(2);
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.WaitingForMotion.class);
    // the held motion of line 2 (handle 2) is cancelled, not left to resume later
    assertThat(rig.port.cancelled()).containsExactly(2L);
    MotionRequest back = rig.port.requests().get(2);
    assertThat(back.backward()).isTrue();
    assertThat(x(back)).isEqualTo(100.0);
    assertThat(back.type()).isEqualTo(Motion.Type.L);
    assertThat(rig.runUntilStopped(DT, 1000)).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.interp.cursorLine()).isEqualTo(2);
  }

  @Test
  void anIncMotionStopsTheBackwardStepNamingItsLineWhetherBackedOutOfOrBackedInto() {
    // INC on the line backed out of (line 2)
    Program incOut = progWithPositions("INC1", 2, joint(1), lin(2, new Motion.Inc()), comment("x"));
    Rig rig = new Rig(incOut);
    rig.interp.setCursor(3);
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.interp.notice()).isEqualTo("BWD stopped at line 2: an INC motion cannot run backward");
    assertThat(rig.port.requests()).isEmpty();
    // INC on the line backed into (line 1)
    Program incIn = progWithPositions("INC2", 2, lin(1, new Motion.Inc()), lin(2), comment("x"));
    Rig rig2 = new Rig(incIn);
    rig2.interp.setCursor(3);
    assertThat(rig2.interp.backward()).isInstanceOf(Outcome.Paused.class);
    assertThat(rig2.interp.notice()).isEqualTo("BWD stopped at line 1: an INC motion cannot run backward");
    assertThat(rig2.port.requests()).isEmpty();
  }

  @Test
  void backingOutOfACircularMotionRunsTheCircleBackThroughItsOwnViaPoint() {
    // line 2: C P[2] P[3] (via P[2], end P[3]); the robot stands at P[3] and goes back to P[1] through P[2].
    Instruction.Move c = Instruction.Move.circular(Tp.p(2), Tp.p(3), Tp.mmPerSec(250), new Motion.Fine(), List.of());
    Rig rig = new Rig(progWithPositions("CIRC", 3, joint(1), c, comment("after")));
    rig.interp.setCursor(3);
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.WaitingForMotion.class);
    MotionRequest back = rig.port.requests().get(0);
    assertThat(back.type()).isEqualTo(Motion.Type.C);
    assertThat(back.via().map(w -> w.position())).contains(pos(2).position());
    assertThat(x(back)).isEqualTo(100.0);
    assertThat(back.speed()).isEqualTo(250.0);
    assertThat(back.viaOwnOffsets()).isFalse();

    // backing out of a linear motion into a circular one: no via point
    Rig rig2 = new Rig(progWithPositions("CIRC2", 4, c, lin(4), comment("after")));
    rig2.interp.setCursor(3);
    rig2.interp.backward();
    MotionRequest back2 = rig2.port.requests().get(0);
    assertThat(back2.type()).isEqualTo(Motion.Type.L);
    assertThat(back2.via()).isEmpty();
    assertThat(x(back2)).isEqualTo(300.0);
  }

  @Test
  void aPositionMissingFromTheLineBackedIntoAlarmsOnThatLine() {
    // P[5] is not in /POS: line 1's target cannot be resolved (INTP-311, on line 1).
    Program p = progWithPositions("MISS", 2, lin(5), lin(2), comment("x"));
    Rig rig = new Rig(p);
    rig.interp.setCursor(3);
    Alarm a = rig.alarm(rig.interp.backward());
    assertThat(a.code()).isEqualTo("INTP-311");
    assertThat(a.line()).isEqualTo(1);
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.ALARMED);
  }

  @Test
  void theTopOfTheProgramNoticeNamesTheLineTheRobotStandsAt() {
    Rig rig = new Rig(progWithPositions("TOP", 2, comment("a"), comment("b"), joint(1), lin(2)));
    rig.interp.setCursor(4);
    // the robot stands at line 3's P[1]; nothing moves above it
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.interp.notice()).isEqualTo("BWD: top of program reached above line 3");
    assertThat(rig.port.requests()).isEmpty();
    // no motion above the cursor at all
    Rig rig2 = new Rig(progWithPositions("TOP2", 1, comment("a"), comment("b"), joint(1)));
    rig2.interp.setCursor(2);
    rig2.interp.backward();
    assertThat(rig2.interp.notice()).isEqualTo("BWD: top of program reached above line 2");
  }

  @Test
  void backwardWhileAlarmedAnswersTheAlarmAndAnUnknownProgramGivesANotice() {
    Rig rig = new Rig(Tp.prog("DIV0", setR(1, Tp.op(num(1), Expr.BinaryOp.DIVIDE, num(0)))));
    Outcome alarmed = rig.run();
    Alarm a = rig.alarm(alarmed);
    assertThat(rig.interp.backward()).isEqualTo(alarmed);
    assertThat(rig.alarm(rig.interp.backward())).isEqualTo(a);

    Rig none = new Rig(Tp.prog("MAIN", comment("x")));
    none.interp.select("NOSUCH");
    assertThat(none.interp.backward()).isInstanceOf(Outcome.Finished.class);
    assertThat(none.interp.notice()).isEqualTo("BWD: no program NOSUCH");
    assertThat(none.port.requests()).isEmpty();
  }

  @Test
  void backwardRunsTheEditedProgramAfterAnEditWhilePaused() {
    // docs/tp-execution.md: the next SHIFT+BWD runs the edited code. Paused on line 3 of
    // J P[1]; L P[2]; R[1]=1; L P[3]; the edit puts J P[3] in place of J P[1] (line 1).
    Map<String, Program> store = new HashMap<>();
    Program before = progWithPositions("MAIN", 3, joint(1), lin(2), setR(1, num(1)), lin(3));
    store.put("MAIN", before);
    FakeMotionPort port = new FakeMotionPort(0.1);
    Interpreter in = new Interpreter(n -> Optional.ofNullable(store.get(n)), new Registers(), port,
        InterpreterSettings.defaults());
    in.select("MAIN");
    in.setStepMode(true);
    in.forward();
    Outcome o = null;
    for (int i = 0; i < 100; i++) {
      port.advance(DT);
      o = in.tick(DT);
      if (o instanceof Outcome.Paused) {
        if (in.cursorLine() >= 3) {
          break;
        }
        in.forward();
      }
    }
    assertThat(in.state()).isEqualTo(Interpreter.State.PAUSED);
    assertThat(in.cursorLine()).isEqualTo(3);
    int sent = port.requests().size();
    store.put("MAIN", new Program("MAIN", before.attributes(), before.comment(),
        List.of(joint(3), lin(2), setR(1, num(1)), lin(3)), before.positions()));
    assertThat(in.backward()).isInstanceOf(Outcome.WaitingForMotion.class);
    MotionRequest back = port.requests().get(sent);
    // backing out of line 2 (L) to the edited line 1's P[3], not the old P[1]
    assertThat(x(back)).isEqualTo(300.0);
    assertThat(back.type()).isEqualTo(Motion.Type.L);
  }

  @Test
  void anAlarmThatPausesKeepsTheProgramActiveUntilAbort() {
    // MOTN-017 is STOP (docs/alarms.md): the program stays on the stack, paused on the faulty line;
    // another program cannot be selected until FCTN ABORT ends it.
    Rig rig = new Rig(InterpreterSettings.defaults(), 1.0, progWithPositions("M", 2, joint(1), lin(2)));
    rig.interp.forward();
    rig.tick(DT);
    rig.port.failNextMotion("MOTN-017", "Limit error");
    Alarm a = rig.alarm(rig.runUntilStopped(DT, 1000));
    assertThat(a.code()).isEqualTo("MOTN-017");
    assertThat(rig.interp.callDepth()).isEqualTo(1);
    assertThatThrownBy(() -> rig.interp.select("M")).isInstanceOf(IllegalStateException.class);
    rig.interp.abort();
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.IDLE);
    assertThat(rig.interp.callDepth()).isZero();
    assertThat(rig.interp.alarm()).isEmpty();
    rig.interp.select("M");
    assertThat(rig.interp.cursorLine()).isEqualTo(1);
  }

  @Test
  void callIsABlockerEvenRightAboveTheCursor() {
    Rig rig = new Rig(progWithPositions("B", 2, joint(1), lin(2), call("SUB")), Tp.prog("SUB", comment("s")));
    rig.interp.setCursor(3);
    // the motion above the cursor is line 2, the CALL is below it: BWD runs
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.WaitingForMotion.class);
    Rig rig2 = new Rig(progWithPositions("B", 2, joint(1), lin(2), call("SUB"), comment("c")),
        Tp.prog("SUB", comment("s")));
    rig2.interp.setCursor(4);
    assertThat(rig2.interp.backward()).isInstanceOf(Outcome.Paused.class);
    assertThat(rig2.interp.notice()).isEqualTo("BWD stopped at line 3: CALL cannot run backward");
  }

  /**
   * docs/tp-execution.md: comments, labels, register/PR assignments, frame selection, TIMER,
   * PAYLOAD, OVERRIDE and MESSAGE are passed over (not run); CALL, JMP, IF, SELECT, FOR, WAIT, I/O
   * outputs, END, PAUSE, ABORT and UALM stop it with a notice naming the line.
   */
  @org.junit.jupiter.api.TestFactory
  java.util.stream.Stream<org.junit.jupiter.api.DynamicTest> everyStatementIsPassedOverOrStopsTheStep() {
    String[] passed = {"! remark", "//L P[9] 10mm/sec FINE", "LBL[7]", "MESSAGE[HELLO]", "$WAITTMOUT=100", "SR[1]='A'",
        "SKIP CONDITION DI[1]=ON", "OFFSET CONDITION PR[1]", "TOOL_OFFSET CONDITION PR[1]", "PAYLOAD[1]", "R[1]=1",
        "PR[1]=LPOS", "PR[1,1]=5", "UFRAME_NUM=0", "UTOOL_NUM=0", "UTOOL[1]=PR[1]", "UFRAME[1]=PR[1]", "TIMER[1]=START",
        "OVERRIDE=50%", "R[2]=R[1]+1"};
    String[][] stops = {{"CALL SUB", "CALL"}, {"JMP LBL[5]", "JMP"}, {"IF R[1]=1,JMP LBL[5]", "IF"},
        {"IF R[1]=1,R[2]=3", "IF"}, {"SELECT R[1]=1,JMP LBL[5]", "SELECT"}, {"FOR R[1]=1 TO 2", "FOR"},
        {"WAIT 1.00(sec)", "WAIT"}, {"WAIT DI[1]=ON", "WAIT"}, {"DO[1]=ON", "I/O"}, {"RO[1]=OFF", "I/O"},
        {"GO[1]=3", "I/O"}, {"DO[1]=PULSE", "PULSE"}, {"END", "END"}, {"PAUSE", "PAUSE"}, {"ABORT", "ABORT"},
        {"UALM[1]", "UALM"}, {"RUN SUB", "RUN"}, {"MONITOR COND", "MONITOR"}, {"IF (R[1]=1) THEN", "IF"}};
    java.util.List<org.junit.jupiter.api.DynamicTest> tests = new java.util.ArrayList<>();
    for (String line : passed) {
      tests.add(org.junit.jupiter.api.DynamicTest.dynamicTest("passes over " + line, () -> {
        Rig rig = bwdOver(line);
        assertThat(rig.interp.backward()).as(line).isInstanceOf(Outcome.WaitingForMotion.class);
        assertThat(x(rig.port.requests().get(0))).isEqualTo(200.0);
        rig.runUntilStopped(DT, 1000);
        assertThat(rig.interp.cursorLine()).isEqualTo(4);
        // passed over, not run
        assertThat(rig.regs.number(1)).isZero();
        assertThat(rig.regs.number(2)).isZero();
      }));
    }
    for (String[] stop : stops) {
      tests.add(org.junit.jupiter.api.DynamicTest.dynamicTest("stops at " + stop[0], () -> {
        Rig rig = bwdOver(stop[0]);
        assertThat(rig.interp.backward()).as(stop[0]).isInstanceOf(Outcome.Paused.class);
        assertThat(rig.interp.notice()).startsWith("BWD stopped at line 3: ").contains(stop[1]).endsWith("cannot run backward");
        assertThat(rig.port.requests()).isEmpty();
        assertThat(rig.regs.number(1)).isZero();
      }));
    }
    return tests.stream();
  }

  /** J P[1]; L P[2]; the statement; L P[3]; a remark, with the cursor on the remark. */
  private static Rig bwdOver(String statement) {
    StringBuilder sb = new StringBuilder("/PROG  BWD\n/ATTR\nDEFAULT_GROUP\t= 1,*,*,*,*;\n/MN\n");
    String[] lines = {"J P[1] 100% FINE", "L P[2] 100mm/sec FINE", "  " + statement, "L P[3] 100mm/sec FINE", "  ! end",
        "  LBL[5]", statement.startsWith("FOR") ? "  ENDFOR" : statement.startsWith("IF (") ? "  ENDIF" : "  ! -"};
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format(java.util.Locale.ROOT, "%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\n");
    for (int p = 1; p <= 3; p++) {
      sb.append("P[").append(p).append("]{\n   GP1:\n\tUF : 0, UT : 0,\t\tCONFIG : 'N U T, 0, 0, 0',\n")
          .append(String.format(java.util.Locale.ROOT, "\tX =   %d.000  mm,\tY =     0.000  mm,\tZ =   300.000  mm,%n", 100 * p))
          .append("\tW =   180.000 deg,\tP =     0.000 deg,\tR =     0.000 deg\n};\n");
    }
    sb.append("/END\n");
    org.robotrun.io.LsReadResult r = org.robotrun.io.LsReader.parse("BWD.LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics() + "\n" + sb).isFalse();
    Rig rig = new Rig(r.program(), Tp.prog("SUB", comment("s")));
    rig.interp.setCursor(5);
    return rig;
  }
}
