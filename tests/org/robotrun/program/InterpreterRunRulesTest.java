package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;

/**
 * How the interpreter runs, pauses, resumes and ends programs, as docs/tp-execution.md and
 * docs/alarms.md state it: the cursor during waits, STEP, pausing alarms inside a CALL (RESET,
 * then SHIFT+FWD re-runs the faulty line), RUN's warning, condition monitors and their action
 * programs, TIME BEFORE/AFTER actions, CALL arguments, motion option ranges (ACC 0..150, CNT
 * 0..100), OFFSET CONDITION in the world frame. Fake motions take {@link #MOTION_SEC}.
 */
class InterpreterRunRulesTest {
  private static final double MOTION_SEC = 0.1;
  private static final double DT = 0.004;

  /** A program read from .LS text; {@code header} is the name (and sub-type); P[1..positions] at x = 100·n. */
  static Program ls(String header, boolean group, int positions, String... lines) {
    StringBuilder sb = new StringBuilder("/PROG  " + header + "\n/ATTR\nDEFAULT_GROUP\t= "
        + (group ? "1,*,*,*,*" : "*,*,*,*,*") + ";\n/MN\n");
    for (int i = 0; i < lines.length; i++) {
      sb.append(String.format(Locale.ROOT, "%4d:%s ;%n", i + 1, lines[i]));
    }
    sb.append("/POS\n");
    for (int p = 1; p <= positions; p++) {
      sb.append("P[").append(p).append("]{\n   GP1:\n\tUF : 0, UT : 0,\t\tCONFIG : 'N U T, 0, 0, 0',\n")
          .append(String.format(Locale.ROOT, "\tX =   %d.000  mm,\tY =     0.000  mm,\tZ =   300.000  mm,%n", 100 * p))
          .append("\tW =   180.000 deg,\tP =     0.000 deg,\tR =     0.000 deg\n};\n");
    }
    sb.append("/END\n");
    String name = header.split("\\s+")[0];
    LsReadResult r = LsReader.parse(name + ".LS", sb.toString());
    assertThat(r.hasAnyError()).as(r.diagnostics() + "\n" + sb).isFalse();
    return r.program();
  }

  static Program main(String... lines) {
    return ls("MAIN", false, 0, lines);
  }

  static Program moving(String... lines) {
    return ls("MAIN", true, 3, lines);
  }

  private static void ticks(Rig rig, int n) {
    for (int i = 0; i < n; i++) {
      rig.tick(DT);
    }
  }

  // ------------------------------------------------------------------ cursor, STEP, WAIT

  @Test
  void theCursorShowsTheLineBeingWaitedOn() {
    Rig rig = new Rig(main("  R[1]=1", "  WAIT 0.10(sec)", "  R[2]=1", "  WAIT DI[1]=ON", "  R[3]=1"));
    rig.interp.forward();
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.WaitingOnTime.class);
    assertThat(rig.interp.cursorLine()).isEqualTo(2);
    ticks(rig, 30);
    assertThat(rig.interp.cursorLine()).isEqualTo(4);
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.WaitingOnCondition.class);
    assertThat(rig.regs.number(2)).isEqualTo(1);
    assertThat(rig.regs.number(3)).isZero();
    rig.regs.setBit(IoKind.DI, 1, true);
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(3)).isEqualTo(1);
  }

  @Test
  void aWaitOfZeroOrLessDoesNotWait() {
    for (String t : new String[] {"0", "0.00", "R[5]"}) {
      Rig rig = new Rig(main("  R[5]=(-1)", "  WAIT " + (t.startsWith("R") ? t : t + "(sec)"), "  R[1]=1"));
      rig.interp.forward();
      assertThat(rig.tick(0)).as("WAIT " + t).isInstanceOf(Outcome.Finished.class);
      assertThat(rig.regs.number(1)).isEqualTo(1);
    }
    // the shortest real wait still waits for its time to pass
    Rig rig = new Rig(main("  WAIT 0.01(sec)", "  R[1]=1"));
    rig.interp.forward();
    assertThat(rig.tick(0)).isInstanceOf(Outcome.WaitingOnTime.class);
    assertThat(rig.tick(0.008)).isInstanceOf(Outcome.WaitingOnTime.class);
    assertThat(rig.tick(0.004)).isInstanceOf(Outcome.Finished.class);
  }

  @Test
  void theCursorOfAPausedProgramMovesAndForwardRunsFromThere() {
    Rig rig = new Rig(main("  WAIT 1.00(sec)", "  R[1]=1", "  R[2]=1", "  R[3]=1"));
    rig.interp.forward();
    ticks(rig, 10);
    rig.interp.hold();
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.PAUSED);
    assertThatThrownBy(() -> rig.interp.setCursor(0)).isInstanceOf(IllegalArgumentException.class);
    rig.interp.setCursor(3);
    assertThat(rig.interp.cursorLine()).isEqualTo(3);
    rig.interp.forward();
    // the WAIT was left: lines 3 and 4 run at once, line 2 never
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isZero();
    assertThat(rig.regs.number(2)).isEqualTo(1);
    assertThat(rig.regs.number(3)).isEqualTo(1);
    // an idle program's cursor may be put on line 1
    rig.interp.setCursor(1);
    assertThat(rig.interp.cursorLine()).isEqualTo(1);
  }

  @Test
  void stepModeAndActivityAreVisible() {
    Rig rig = new Rig(main("  CALL SUB", "  R[1]=1"), ls("SUB", false, 0, "  WAIT 0.10(sec)"));
    assertThat(rig.interp.stepMode()).isFalse();
    rig.interp.setStepMode(true);
    assertThat(rig.interp.stepMode()).isTrue();
    rig.interp.setStepMode(false);
    assertThat(rig.interp.isActive("MAIN")).isFalse();
    rig.interp.forward();
    rig.tick(DT);
    assertThat(rig.interp.isActive("MAIN")).isTrue();
    assertThat(rig.interp.isActive("SUB")).isTrue();
    assertThat(rig.interp.isActive("OTHER")).isFalse();
    assertThat(rig.interp.callDepth()).isEqualTo(2);
    rig.runUntilStopped(DT, 1000);
    assertThat(rig.interp.isActive("MAIN")).isFalse();
    assertThat(rig.interp.isActive("SUB")).isFalse();
  }

  // ------------------------------------------------------------------ alarms that pause

  @Test
  void aStopAlarmInsideACallKeepsTheStackAndSecondForwardRerunsTheFaultyLineThenReturns() {
    // docs/alarms.md: PAUSE, STOP, SERVO pause the program on the faulty line with its call stack;
    // RESET, then SHIFT+FWD runs the faulty line again and the program returns to its caller.
    Program main = moving("J P[1] 100% FINE", "  CALL SUB", "  R[1]=1");
    Program sub = ls("SUB", true, 3, "  R[2]=1", "L P[2] 100mm/sec FINE", "  R[3]=1");
    Rig rig = new Rig(InterpreterSettings.defaults(), MOTION_SEC, main, sub);
    rig.interp.forward();
    ticks(rig, 30);
    assertThat(rig.interp.currentProgram()).isEqualTo("SUB");
    rig.port.failNextMotion("MOTN-017", "Limit error");
    Alarm a = rig.alarm(rig.runUntilStopped(DT, 1000));
    assertThat(a.code()).isEqualTo("MOTN-017");
    assertThat(a.program()).isEqualTo("SUB");
    assertThat(a.line()).isEqualTo(2);
    assertThat(rig.interp.callDepth()).isEqualTo(2);
    // still alarmed: SHIFT+FWD does nothing until RESET
    rig.interp.forward();
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.ALARMED);
    rig.interp.reset();
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.PAUSED);
    assertThat(rig.interp.currentProgram()).isEqualTo("SUB");
    assertThat(rig.interp.cursorLine()).isEqualTo(2);
    int sent = rig.port.requests().size();
    rig.interp.forward();
    assertThat(rig.runUntilStopped(DT, 1000)).isInstanceOf(Outcome.Finished.class);
    // line 2 of SUB ran again (one more request, to P[2]); line 1 did not run again
    assertThat(rig.port.requests()).hasSize(sent + 1);
    assertThat(((Position.Cartesian) rig.port.requests().get(sent).target().position()).xMm()).isEqualTo(200.0);
    assertThat(rig.port.requests().get(sent).line()).isEqualTo(2);
    assertThat(rig.regs.number(3)).isEqualTo(1);
    assertThat(rig.regs.number(1)).isEqualTo(1);
  }

  @Test
  void anAbortAlarmEndsTheProgramAndResetLeavesItIdleOnTheFaultyLine() {
    Rig rig = new Rig(main("  R[1]=1", "  CALL SUB", "  R[1]=2"), ls("SUB", false, 0, "  R[2]=1", "  R[3]=1/0"));
    Alarm a = rig.alarm(rig.run());
    assertThat(a.code()).isEqualTo("SIMU-001");
    assertThat(a.program()).isEqualTo("SUB");
    assertThat(a.line()).isEqualTo(2);
    assertThat(rig.interp.callDepth()).isZero();
    rig.interp.reset();
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.IDLE);
    // SHIFT+FWD starts the program that raised it, at that line (the caller is lost)
    assertThat(rig.interp.currentProgram()).isEqualTo("SUB");
    assertThat(rig.interp.cursorLine()).isEqualTo(2);
  }

  @Test
  void anAlarmWhileAMotionRunsStopsTheArm() {
    // A monitor's condition that alarms while the program waits for a motion: the arm is stopped
    // (its motion cancelled) and the program ends (INTP-204 is ABORT).
    Program main = moving("J P[1] 100% FINE", "  MONITOR COND", "L P[2] 100mm/sec FINE", "  R[1]=1");
    Program cond = ls("COND\t  Cond", false, 0, "  WHEN R[R[9]]=1,CALL ACT");
    Program act = ls("ACT", false, 0, "  R[2]=1");
    Rig rig = new Rig(InterpreterSettings.defaults(), 1.0, main, cond, act);
    rig.regs.setInteger(9, 1);
    rig.interp.forward();
    ticks(rig, 300);
    assertThat(rig.interp.cursorLine()).isEqualTo(3);
    rig.regs.setInteger(9, 0);
    Alarm a = rig.alarm(rig.tick(DT));
    assertThat(a.code()).isEqualTo("INTP-204");
    assertThat(a.line()).isEqualTo(3);
    assertThat(rig.port.cancelled()).containsExactly(2L);
    assertThat(rig.regs.number(1)).isZero();
  }

  @Test
  void anEditThatBreaksTheStructureAlarmsOnTheBrokenLineAndACallIntoItNamesItsLine() {
    Map<String, Program> store = new HashMap<>();
    Program main = main("  R[1]=1", "  PAUSE", "  R[2]=1", "  R[3]=1");
    store.put("MAIN", main);
    FakeMotionPort port = new FakeMotionPort(MOTION_SEC);
    Interpreter in = new Interpreter(n -> Optional.ofNullable(store.get(n)), new Registers(), port, InterpreterSettings.defaults());
    in.select("MAIN");
    in.forward();
    assertThat(in.tick(DT)).isInstanceOf(Outcome.Paused.class);
    // the reader refuses such a file; an edit on the pendant may leave it so while paused
    store.put("MAIN", Tp.prog("MAIN", Tp.setR(1, Tp.num(1)), new Instruction.Pause(), Tp.setR(2, Tp.num(1)), Tp.endFor()));
    in.forward();
    Alarm a = in.alarm().orElseThrow();
    assertThat(a.code()).isEqualTo("SIMU-002");
    assertThat(a.line()).isEqualTo(4);

    Rig rig = new Rig(main("  R[1]=1", "  CALL BROKEN"),
        Tp.prog("BROKEN", Tp.setR(1, Tp.num(2)), Tp.setR(1, Tp.num(3)), Tp.endIf()));
    Alarm c = rig.alarm(rig.run());
    assertThat(c.code()).isEqualTo("SIMU-002");
    assertThat(c.line()).isEqualTo(2);
    assertThat(c.message()).contains("line 3");
  }

  // ------------------------------------------------------------------ RUN

  @Test
  void aRefusedRunIsAWarningAndTheProgramGoesOn() {
    // docs/alarms.md: INTP-267 is WARN; the program that ran RUN goes on with its next line.
    List<Alarm> warnings = new ArrayList<>();
    List<String> started = new ArrayList<>();
    Rig rig = new Rig(main("  R[1]=1", "  RUN TASKB", "  RUN TASKC", "  R[2]=1"));
    rig.interp.setTaskPort(new TaskPort() {
      @Override
      public Optional<String> run(String program) {
        started.add(program);
        return program.equals("TASKB") ? Optional.of("PROG-007 Program is already running") : Optional.empty();
      }

      @Override
      public void warning(Alarm alarm) {
        warnings.add(alarm);
      }
    });
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(started).containsExactly("TASKB", "TASKC");
    assertThat(rig.regs.number(2)).isEqualTo(1);
    assertThat(warnings).hasSize(1);
    Alarm w = warnings.get(0);
    assertThat(w.code()).isEqualTo("INTP-267");
    assertThat(w.program()).isEqualTo("MAIN");
    assertThat(w.line()).isEqualTo(2);
    assertThat(w.message()).contains("PROG-007");
  }

  // ------------------------------------------------------------------ CALL arguments

  @Test
  void callArgumentsArriveInOrderWithTheirTypesAndServeAsIndices() {
    Program main = main("  R[7]=2.5", "  CALL SUB('ABC','XYZ',3,R[7],ON)", "  CALL IDX(4)", "  R[9]=1");
    Program sub = ls("SUB", false, 0, "  SR[1]=AR[1]", "  SR[2]=AR[2]", "  R[1]=AR[3]", "  R[2]=AR[4]", "  F[1]=(AR[5])",
        "  SR[3]=AR[1]+AR[3]");
    Program idx = ls("IDX", false, 0, "  R[AR[1]]=7", "  R[10]=R[AR[1]]");
    Rig rig = new Rig(main, sub, idx);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.string(1)).isEqualTo("ABC");
    assertThat(rig.regs.string(2)).isEqualTo("XYZ");
    assertThat(rig.regs.number(1)).isEqualTo(3);
    assertThat(rig.regs.isInteger(1)).isTrue();
    assertThat(rig.regs.number(2)).isEqualTo(2.5);
    assertThat(rig.regs.isInteger(2)).isFalse();
    assertThat(rig.regs.bit(IoKind.F, 1)).isTrue();
    assertThat(rig.regs.string(3)).isEqualTo("ABC3");
    assertThat(rig.regs.number(4)).isEqualTo(7);
    assertThat(rig.regs.number(10)).isEqualTo(7);
    // an argument index must be a whole number (INTP-204)
    for (String arg : new String[] {"2.5", "'A'"}) {
      Rig bad = new Rig(main("  CALL IDX(" + arg + ")"), idx);
      Alarm a = bad.alarm(bad.run());
      assertThat(a.code()).as(arg).isEqualTo("INTP-204");
      assertThat(a.program()).isEqualTo("IDX");
      assertThat(a.line()).isEqualTo(1);
    }
    // AR[i] beyond the arguments passed: INTP-204
    Rig missing = new Rig(main("  CALL SUB('A')"), sub);
    assertThat(missing.alarm(missing.run()).code()).isEqualTo("INTP-204");
  }

  // ------------------------------------------------------------------ motion option ranges

  @Test
  void accAndCntFromRegistersAreCheckedWhenTheMotionStarts() {
    // docs/tp-language.md: ACC R[i] a whole number 0..150, CNT 0..100, else INTP-304.
    double[] accs = {-1, 0, 150, 151, 80.5};
    for (double v : accs) {
      Rig rig = new Rig(moving("L P[1] 100mm/sec FINE ACC R[1]"));
      rig.regs.set(1, v, v == Math.rint(v));
      Outcome o = rig.run();
      boolean ok = v == Math.rint(v) && v >= 0 && v <= 150;
      if (ok) {
        assertThat(o).as("ACC %s", v).isInstanceOf(Outcome.Finished.class);
        assertThat(rig.port.requests().get(0).accPercent()).isEqualTo((int) v);
      } else {
        assertThat(rig.alarm(o).code()).as("ACC %s", v).isEqualTo("INTP-304");
      }
    }
    double[] cnts = {-1, 0, 100, 101, 50.5};
    for (double v : cnts) {
      Rig rig = new Rig(moving("L P[1] 100mm/sec CNT R[1]"));
      rig.regs.set(1, v, v == Math.rint(v));
      Outcome o = rig.run();
      boolean ok = v == Math.rint(v) && v >= 0 && v <= 100;
      if (ok) {
        assertThat(o).as("CNT %s", v).isInstanceOf(Outcome.Finished.class);
        assertThat(rig.port.requests().get(0).cnt()).isEqualTo((int) v);
        assertThat(rig.port.requests().get(0).fine()).isFalse();
      } else {
        // outside 0..100 is a bad value (INTP-304); a real where a whole number goes a type mismatch (INTP-205)
        assertThat(rig.alarm(o).code()).as("CNT %s", v).isEqualTo(v == Math.rint(v) ? "INTP-304" : "INTP-205");
      }
    }
    // a constant ACC of the model outside 0..150 (the reader keeps such a line unrun)
    for (int acc : new int[] {-1, 0, 150, 151}) {
      Instruction.Move mv = Instruction.Move.of(Motion.Type.L, Tp.p(1), Tp.mmPerSec(100), new Motion.Fine(),
          List.of(new Motion.Acc(acc)));
      Rig rig = new Rig(Tp.progWithPositions("A", 1, mv));
      Outcome o = rig.run();
      if (acc >= 0 && acc <= 150) {
        assertThat(o).as("ACC%d", acc).isInstanceOf(Outcome.Finished.class);
        assertThat(rig.port.requests().get(0).accPercent()).isEqualTo(acc);
      } else {
        assertThat(rig.alarm(o).code()).as("ACC%d", acc).isEqualTo("INTP-304");
      }
    }
  }

  @Test
  void anOffsetConditionInTheWorldFrameIsTurnedIntoTheActiveUserFrame() {
    // docs/tp-execution.md: O_u = F_u^-1 F_j O F_j^-1 F_u; with j = 0 (world, F_0 = I) and UFRAME 1
    // turned 90 deg about Z, a world +X shift of 10 mm is -Y 10 mm in UFRAME 1.
    Program p = moving("  UFRAME_NUM=1", "  OFFSET CONDITION PR[4],UFRAME[0]", "L PR[5] 100mm/sec FINE Offset");
    Rig rig = new Rig(p);
    rig.port.setFrame(Instruction.FrameKind.USER, 1, new Position.Cartesian(300, 50, 0, 0, 0, 90, Config.DEFAULT));
    rig.regs.setPosition(4, new Position.Cartesian(10, 0, 0, 0, 0, 0, Config.DEFAULT));
    rig.regs.setPosition(5, new Position.Cartesian(100, 0, 300, 180, 0, 0, Config.DEFAULT));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    Position.Cartesian o = (Position.Cartesian) rig.port.requests().get(0).offset().orElseThrow();
    assertThat(o.xMm()).isCloseTo(0, within(1e-9));
    assertThat(o.yMm()).isCloseTo(-10, within(1e-9));
    assertThat(o.zMm()).isCloseTo(0, within(1e-9));
  }

  // ------------------------------------------------------------------ TIME BEFORE / AFTER

  @Test
  void timeBeforeFiresItsTimeBeforeThePointAndTimeAfterItsTimeAfter() {
    // docs/tp-execution.md: TB t sec runs the action when the motion is t seconds from its end;
    // TA t sec t seconds after the motion is done. The fake motion takes 0.1 s.
    Rig rig = new Rig(InterpreterSettings.defaults(), MOTION_SEC,
        moving("L P[1] 100mm/sec FINE TB .04sec,DO[1]=ON", "L P[2] 100mm/sec FINE TA .05sec,DO[2]=ON",
            "  WAIT DI[9]=ON"));
    rig.interp.forward();
    rig.tick(0);
    double t = 0;
    double tb = Double.NaN;
    double motion2Done = Double.NaN;
    double ta = Double.NaN;
    for (int i = 0; i < 200; i++) {
      rig.tick(DT);
      t += DT;
      if (Double.isNaN(tb) && rig.regs.bit(IoKind.DO, 1)) {
        tb = t;
      }
      if (Double.isNaN(motion2Done) && rig.interp.cursorLine() == 3) {
        motion2Done = t;
      }
      if (Double.isNaN(ta) && rig.regs.bit(IoKind.DO, 2)) {
        ta = t;
      }
    }
    assertThat(tb).as("TB .04sec of a 0.1 s motion").isCloseTo(0.06, within(DT + 1e-9));
    assertThat(ta - motion2Done).as("TA .05sec").isCloseTo(0.05, within(DT + 1e-9));
  }

  @Test
  void aTimeBeforeLongerThanTheMotionFiresAtOnceAndOneStillPendingFiresAtThePoint() {
    Rig rig = new Rig(InterpreterSettings.defaults(), MOTION_SEC,
        moving("L P[1] 100mm/sec FINE TB 5.00sec,DO[1]=ON", "  R[1]=DO[1]"));
    rig.interp.forward();
    rig.tick(0);
    rig.tick(DT);
    assertThat(rig.regs.bit(IoKind.DO, 1)).isTrue();
    // TB 0 sec: due only when the motion arrives
    Rig zero = new Rig(InterpreterSettings.defaults(), MOTION_SEC, moving("L P[1] 100mm/sec FINE TB 0.00sec,DO[1]=ON",
        "  F[1]=(DO[1])"));
    zero.interp.forward();
    zero.tick(0);
    zero.tick(0.05);
    assertThat(zero.regs.bit(IoKind.DO, 1)).isFalse();
    assertThat(zero.runUntilStopped(DT, 1000)).isInstanceOf(Outcome.Finished.class);
    assertThat(zero.regs.bit(IoKind.F, 1)).as("fired at the point, before the next line").isTrue();
  }

  @Test
  void aTimeAfterStillPendingAtEndIsDropped() {
    // docs/tp-execution.md: at END or ABORT a pending TA action is dropped.
    Rig rig = new Rig(InterpreterSettings.defaults(), MOTION_SEC, moving("L P[1] 100mm/sec FINE TA .50sec,DO[1]=ON"));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    ticks(rig, 250);
    assertThat(rig.regs.bit(IoKind.DO, 1)).isFalse();
    // TA 0 sec runs at once when the motion is done
    Rig now = new Rig(InterpreterSettings.defaults(), MOTION_SEC, moving("L P[1] 100mm/sec FINE TA 0.00sec,DO[1]=ON",
        "  F[1]=(DO[1])"));
    assertThat(now.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(now.regs.bit(IoKind.F, 1)).isTrue();
  }

  @Test
  void aTimedCallRunsBesideTheMotionWithItsArguments() {
    Program main = moving("  R[5]=2.5", "L P[1] 100mm/sec FINE TB .05sec,CALL SIG(4,R[5])", "  WAIT 0.20(sec)");
    Program sig = ls("SIG", false, 0, "  R[1]=AR[1]", "  R[2]=AR[2]", "  WAIT 0.10(sec)", "  R[3]=1");
    Rig rig = new Rig(InterpreterSettings.defaults(), MOTION_SEC, main, sig);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(4);
    assertThat(rig.regs.number(2)).isEqualTo(2.5);
    assertThat(rig.regs.number(3)).isEqualTo(1);
    // a called program with motion group 1 is refused at the moment of the call (INTP-129)
    Rig grouped = new Rig(InterpreterSettings.defaults(), MOTION_SEC,
        moving("L P[1] 100mm/sec FINE TB .05sec,CALL GSIG", "  R[9]=1"), ls("GSIG", true, 0, "  R[1]=1"));
    Alarm a = grouped.alarm(grouped.run());
    assertThat(a.code()).isEqualTo("INTP-129");
    assertThat(a.line()).isEqualTo(1);
    assertThat(grouped.regs.number(1)).isZero();
    // an alarm in the called program is the motion line's
    Rig failing = new Rig(InterpreterSettings.defaults(), MOTION_SEC,
        moving("  R[9]=0", "L P[1] 100mm/sec FINE TA .01sec,CALL BAD", "  WAIT 0.10(sec)", "  R[9]=1"),
        ls("BAD", false, 0, "  R[1]=1/0"));
    Alarm b = failing.alarm(failing.run());
    assertThat(b.code()).isEqualTo("SIMU-001");
    assertThat(failing.regs.number(9)).isZero();
  }

  // ------------------------------------------------------------------ condition monitors

  @Test
  void aMonitorFiresOnceAndItsActionRunsBesideTheWaitingProgram() {
    Program main = main("  MONITOR COND", "  WAIT DI[2]=ON", "  R[5]=R[1]", "  MONITOR COND", "  WAIT DI[3]=ON",
        "  R[6]=R[1]");
    Program cond = ls("COND\t  Cond", false, 0, "  WHEN DI[1]=ON,CALL ACT");
    Program act = ls("ACT", false, 0, "  R[1]=R[1]+1", "  WAIT 0.10(sec)", "  R[2]=R[2]+1");
    Rig rig = new Rig(main, cond, act);
    rig.interp.forward();
    ticks(rig, 5);
    assertThat(rig.regs.number(1)).isZero();
    rig.regs.setBit(IoKind.DI, 1, true);
    rig.tick(DT);
    assertThat(rig.regs.number(1)).as("the action ran beside the waiting program").isEqualTo(1);
    assertThat(rig.interp.cursorLine()).isEqualTo(2);
    ticks(rig, 50);
    // one-shot: DI[1] stays ON, the action ran once
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.regs.number(2)).isEqualTo(1);
    rig.regs.setBit(IoKind.DI, 2, true);
    ticks(rig, 2);
    // MONITOR again re-arms it; DI[1] is still ON, so it fires again
    assertThat(rig.regs.number(5)).isEqualTo(1);
    assertThat(rig.regs.number(1)).isEqualTo(2);
    rig.regs.setBit(IoKind.DI, 3, true);
    assertThat(rig.runUntilStopped(DT, 1000)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(6)).isEqualTo(2);
  }

  @Test
  void whatTheProgramStartedEndsWithIt() {
    // docs/tp-execution.md: at END its condition monitors end and the action programs they started
    // are aborted.
    Program main = main("  MONITOR COND", "  WAIT 0.02(sec)", "  R[9]=1");
    Program cond = ls("COND\t  Cond", false, 0, "  WHEN DI[1]=ON,CALL ACT");
    Program act = ls("ACT", false, 0, "  R[1]=R[1]+1", "  WAIT 0.20(sec)", "  R[2]=1");
    Rig rig = new Rig(main, cond, act);
    rig.regs.setBit(IoKind.DI, 1, true);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(1);
    ticks(rig, 100);
    assertThat(rig.regs.number(2)).as("the action program was aborted at END").isZero();
    assertThat(rig.regs.number(1)).as("no monitor left").isEqualTo(1);
  }

  @Test
  void anActionProgramSharesTimersWithoutAdvancingThemTwice() {
    Program main = main("  TIMER[1]=RESET", "  TIMER[1]=START", "  MONITOR COND", "  WAIT 0.40(sec)", "  R[1]=TIMER[1]");
    Program cond = ls("COND\t  Cond", false, 0, "  WHEN DI[1]=ON,CALL ACT");
    Program act = ls("ACT", false, 0, "  WAIT 1.00(sec)");
    Rig rig = new Rig(main, cond, act);
    rig.regs.setBit(IoKind.DI, 1, true);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isCloseTo(0.4, within(2 * DT));
  }

  @Test
  void monitorFaults() {
    // an alarm in the action program stops the program too
    Rig bad = new Rig(main("  MONITOR COND", "  WAIT 0.10(sec)", "  R[9]=1"), ls("COND\t  Cond", false, 0,
        "  WHEN DI[1]=ON,CALL ACT"), ls("ACT", false, 0, "  R[1]=1", "  R[2]=R[1]/0"));
    bad.regs.setBit(IoKind.DI, 1, true);
    Alarm a = bad.alarm(bad.run());
    assertThat(a.code()).isEqualTo("SIMU-001");
    assertThat(a.program()).isEqualTo("ACT");
    assertThat(a.line()).isEqualTo(2);
    assertThat(bad.regs.number(9)).isZero();
    // an action program that moves: SIMU-012
    Rig mover = new Rig(main("  MONITOR COND", "  WAIT 0.10(sec)"), ls("COND\t  Cond", false, 0,
        "  WHEN DI[1]=ON,CALL MOVER"), ls("MOVER", false, 1, "J P[1] 100% FINE"));
    mover.regs.setBit(IoKind.DI, 1, true);
    assertThat(mover.alarm(mover.run()).code()).isEqualTo("SIMU-012");
    // MONITOR of a missing program: INTP-222; of a program without WHEN lines: INTP-304
    Rig missing = new Rig(main("  MONITOR NOSUCH"));
    assertThat(missing.alarm(missing.run()).code()).isEqualTo("INTP-222");
    Rig nowhen = new Rig(main("  MONITOR PLAIN"), ls("PLAIN", false, 0, "  R[1]=1"));
    assertThat(nowhen.alarm(nowhen.run()).code()).isEqualTo("INTP-304");
    // MONITOR END before it fires: the action never runs
    Rig ended = new Rig(main("  MONITOR COND", "  MONITOR END COND", "  WAIT 0.05(sec)"), ls("COND\t  Cond", false, 0,
        "  WHEN DI[1]=ON,CALL ACT"), ls("ACT", false, 0, "  R[1]=1"));
    ended.regs.setBit(IoKind.DI, 1, true);
    assertThat(ended.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(ended.regs.number(1)).isZero();
  }

  @Test
  void aMotionHeldOnTheFirstLineStaysHeldThroughAnEditBelowAndTakesTheEditedSkipLabel() {
    // docs/tp-execution.md: a held motion whose line and positions the edit left alone stays held
    // and SHIFT+FWD continues it; its label targets are the edited program's.
    Map<String, Program> store = new HashMap<>();
    Program before = Tp.progWithPositions("MAIN", 1, Tp.lin(1, new Motion.Skip(LabelRef.of(5))), Tp.setR(1, Tp.num(1)),
        Tp.lbl(5), Tp.setR(2, Tp.op(Tp.r(2), Expr.BinaryOp.ADD, Tp.num(1))));
    store.put("MAIN", before);
    FakeMotionPort port = new FakeMotionPort(1.0);
    Registers regs = new Registers();
    Interpreter in = new Interpreter(n -> Optional.ofNullable(store.get(n)), regs, port, InterpreterSettings.defaults());
    in.select("MAIN");
    in.forward();
    for (int i = 0; i < 50; i++) {
      port.advance(DT);
      in.tick(DT);
    }
    in.hold();
    assertThat(in.cursorLine()).isEqualTo(1);
    store.put("MAIN", new Program("MAIN", before.attributes(), before.comment(), List.of(
        Tp.lin(1, new Motion.Skip(LabelRef.of(5))), Tp.setR(1, Tp.num(1)), Tp.setR(3, Tp.num(1)), Tp.lbl(5),
        Tp.setR(2, Tp.op(Tp.r(2), Expr.BinaryOp.ADD, Tp.num(1)))), before.positions()));
    in.forward();
    Outcome o = null;
    for (int i = 0; i < 1000 && !(o instanceof Outcome.Finished || o instanceof Outcome.Alarmed); i++) {
      port.advance(DT);
      o = in.tick(DT);
    }
    assertThat(o).isInstanceOf(Outcome.Finished.class);
    // the held motion went on: no second request, nothing cancelled
    assertThat(port.requests()).hasSize(1);
    assertThat(port.cancelled()).isEmpty();
    // no skip condition: the motion ends and jumps to LBL[5] of the edited program (line 4)
    assertThat(regs.number(1)).isZero();
    assertThat(regs.number(3)).isZero();
    assertThat(regs.number(2)).isEqualTo(1);
  }
}
