package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.robotrun.program.Expr.BinaryOp.ADD;
import static org.robotrun.program.Expr.BinaryOp.AND;
import static org.robotrun.program.Expr.BinaryOp.DIV;
import static org.robotrun.program.Expr.BinaryOp.DIVIDE;
import static org.robotrun.program.Expr.BinaryOp.MOD;
import static org.robotrun.program.Tp.ar;
import static org.robotrun.program.Tp.call;
import static org.robotrun.program.Tp.end;
import static org.robotrun.program.Tp.endFor;
import static org.robotrun.program.Tp.forUp;
import static org.robotrun.program.Tp.group;
import static org.robotrun.program.Tp.io;
import static org.robotrun.program.Tp.jmp;
import static org.robotrun.program.Tp.jmpR;
import static org.robotrun.program.Tp.lbl;
import static org.robotrun.program.Tp.lin;
import static org.robotrun.program.Tp.num;
import static org.robotrun.program.Tp.on;
import static org.robotrun.program.Tp.op;
import static org.robotrun.program.Tp.prog;
import static org.robotrun.program.Tp.r;
import static org.robotrun.program.Tp.real;
import static org.robotrun.program.Tp.rr;
import static org.robotrun.program.Tp.setIo;
import static org.robotrun.program.Tp.setR;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Every alarm kind: raised with program, line, code and a message naming what went wrong. */
class InterpreterAlarmTest {

  private static Alarm alarmOf(Program... programs) {
    Rig rig = new Rig(programs);
    Outcome o = rig.run();
    Alarm a = rig.alarm(o);
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.ALARMED);
    assertThat(rig.interp.alarm()).contains(a);
    return a;
  }

  @Test
  void divisionByZeroNamesTheLine() {
    for (Expr.BinaryOp op : List.of(DIVIDE, DIV, MOD)) {
      Alarm a = alarmOf(prog("MAIN", setR(1, num(1)), setR(2, op(num(5), op, r(3)))));
      assertThat(a.kind()).isEqualTo(AlarmKind.DIVIDE_BY_ZERO);
      assertThat(a.code()).isEqualTo("SIMU-001");
      assertThat(a.program()).isEqualTo("MAIN");
      assertThat(a.line()).isEqualTo(2);
      assertThat(a.message()).contains(op.symbol());
    }
  }

  @Test
  void ioRangesAreTheControllersConfiguredSizes() {
    InterpreterSettings big = InterpreterSettings.defaults()
        .withIoRanges(IoRanges.of(java.util.Map.of("DO", 1024, "RI", 16)));
    Rig ok = new Rig(big, 0.1, prog("A", setIo(IoKind.DO, 1024, on()), setIo(IoKind.RO, 8, on())));
    assertThat(ok.run()).isEqualTo(Outcome.FINISHED);
    assertThat(ok.regs.bit(IoKind.DO, 1024)).isTrue();
    assertThat(ok.regs.ioSize(IoKind.RI)).isEqualTo(16);
    Rig bad = new Rig(big, 0.1, prog("A", setIo(IoKind.DO, 1025, on())));
    Alarm a = bad.alarm(bad.run());
    assertThat(a.kind()).isEqualTo(AlarmKind.BAD_INDEX);
    assertThat(a.message()).isEqualTo("DO[1025]: index out of range (expected 1..1024)");
    // Robot outputs default to the 8 of the end-effector connector.
    assertThat(alarmOf(prog("A", setIo(IoKind.RO, 9, on()))).message()).contains("RO[9]").contains("1..8");
    assertThatThrownBy(() -> IoRanges.of(java.util.Map.of("XO", 4))).hasMessageContaining("unknown I/O kind 'XO'");
    assertThatThrownBy(() -> IoRanges.of(java.util.Map.of("DI", 0))).hasMessageContaining("DI: expected a number of ports 1..4096");
  }

  @Test
  void indexOutOfRangeIsABadIndex() {
    assertThat(alarmOf(prog("A", setR(201, num(1)))).message()).isEqualTo("R[201]: index out of range (expected 1..200)");
    assertThat(alarmOf(prog("A", setR(1, r(0)))).kind()).isEqualTo(AlarmKind.BAD_INDEX);
    assertThat(alarmOf(prog("A", setIo(IoKind.DO, 513, on()))).message()).contains("DO[513]").contains("1..512");
    assertThat(alarmOf(prog("A", setR(1, Tp.prEl(1, 7)))).kind()).isEqualTo(AlarmKind.BAD_INDEX);
    assertThat(alarmOf(prog("A", setR(1, Tp.timer(11)))).kind()).isEqualTo(AlarmKind.BAD_INDEX);
    // R[R[1]] with R[1] = 0.5 is not an index.
    Alarm a = alarmOf(prog("A", setR(1, real(0.5)), setR(2, rr(1))));
    assertThat(a.kind()).isEqualTo(AlarmKind.BAD_INDEX);
    assertThat(a.line()).isEqualTo(2);
  }

  @Test
  void argumentNotPassedIsABadIndex() {
    Alarm a = alarmOf(prog("MAIN", call("SUB", num(1))), prog("SUB", setR(1, ar(2))));
    assertThat(a.kind()).isEqualTo(AlarmKind.BAD_INDEX);
    assertThat(a.program()).isEqualTo("SUB");
    assertThat(a.message()).isEqualTo("AR[2]: SUB was called with 1 argument");
  }

  @Test
  void unknownLabelDirectAndIndirect() {
    Alarm direct = alarmOf(prog("J", setR(1, num(1)), jmp(7)));
    assertThat(direct.kind()).isEqualTo(AlarmKind.UNKNOWN_LABEL);
    assertThat(direct.line()).isEqualTo(2);
    assertThat(direct.message()).isEqualTo("LBL[7] is not in program J");
    Alarm indirect = alarmOf(prog("J", setR(1, num(3)), lbl(2), jmpR(1)));
    assertThat(indirect.kind()).isEqualTo(AlarmKind.UNKNOWN_LABEL);
    assertThat(indirect.message()).contains("LBL[3]");
  }

  @Test
  void typeMismatches() {
    assertThat(alarmOf(prog("T", setR(1, op(io(IoKind.DI, 1), ADD, num(1))))).kind()).isEqualTo(AlarmKind.TYPE_MISMATCH);
    assertThat(alarmOf(prog("T", setR(1, group(op(r(2), AND, on()))))).message())
        .isEqualTo("AND needs ON/OFF or a condition, got an integer");
    assertThat(alarmOf(prog("T", Tp.ifJ(r(1), jmp(1)), lbl(1))).kind()).isEqualTo(AlarmKind.TYPE_MISMATCH);
    assertThat(alarmOf(prog("T", forUp(1, num(1), real(2.5)), endFor())).kind()).isEqualTo(AlarmKind.TYPE_MISMATCH);
    assertThat(alarmOf(prog("T", setIo(IoKind.GO, 1, on()))).kind()).isEqualTo(AlarmKind.TYPE_MISMATCH);
    // PR[1] (Cartesian) + PR[2] (joint).
    Rig rig = new Rig(Program.of("T", List.of(
        new Instruction.AssignPosReg(Item.of(3), new Instruction.PosArithmetic(Item.of(1), true, Item.of(2))))));
    rig.regs.setPosition(2, Position.Joint.ZERO);
    assertThat(rig.alarm(rig.run()).kind()).isEqualTo(AlarmKind.TYPE_MISMATCH);
  }

  @Test
  void callDeeperThan32IsAnAlarm() {
    // R[1] counts the depth reached; the program calls itself forever.
    Alarm a = alarmOf(prog("REC", setR(1, op(r(1), ADD, num(1))), call("REC")));
    assertThat(a.kind()).isEqualTo(AlarmKind.CALL_DEPTH);
    assertThat(a.program()).isEqualTo("REC");
    assertThat(a.line()).isEqualTo(2);
  }

  @Test
  void callDepthOf32IsAllowed() {
    Rig rig = new Rig(prog("REC", setR(1, op(r(1), ADD, num(1))),
        Tp.ifJ(op(r(1), Expr.BinaryOp.LT, num(32)), call("REC"))));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(32);
  }

  @Test
  void unknownProgramOnCallAndOnStart() {
    Alarm a = alarmOf(prog("MAIN", call("BEEP")));
    assertThat(a.kind()).isEqualTo(AlarmKind.UNKNOWN_PROGRAM);
    assertThat(a.message()).isEqualTo("CALL BEEP: no such program");
    Rig rig = new Rig(prog("MAIN"));
    rig.interp.select("NOPE");
    rig.interp.forward();
    assertThat(rig.alarm(rig.tick(0.004)).kind()).isEqualTo(AlarmKind.UNKNOWN_PROGRAM);
  }

  @Test
  void runawayLoopWithoutMotionOrWaitIsAnAlarmNotAFreeze() {
    Rig rig = new Rig(InterpreterSettings.defaults().withBudget(10_000), 0.1,
        prog("LOOP", lbl(1), setR(1, op(r(1), ADD, num(1))), jmp(1)));
    rig.interp.forward();
    Alarm a = rig.alarm(rig.tick(0.004));
    assertThat(a.kind()).isEqualTo(AlarmKind.RUNAWAY);
    assertThat(a.message()).contains("10000");
    assertThat(rig.interp.executedLines()).isEqualTo(10_000);
  }

  @Test
  void aLoopThatWaitsEachTimeIsNotARunaway() {
    Rig rig = new Rig(InterpreterSettings.defaults().withBudget(100), 0.1,
        prog("LOOP", forUp(1, num(1), num(500)), Tp.waitSec(0.001), endFor()));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
  }

  @Test
  void frameMismatchReportedByThePort() {
    Program p = Program.of("F", List.of(lin(1)), List.of(new LocalPosition(1, "", 1, 1, Tp.pos(1).position())));
    Alarm a = alarmOf(p);
    assertThat(a.kind()).isEqualTo(AlarmKind.MOTION);
    assertThat(a.code()).isEqualTo(FakeMotionPort.FRAME_MISMATCH);
    assertThat(a.line()).isEqualTo(1);
    assertThat(a.message()).contains("UF 1").contains("UF 0");
  }

  @Test
  void motionFailureWhileMovingIsAnAlarmAtTheMotionLine() {
    Rig rig = new Rig(Tp.progWithPositions("M", 1, setR(1, num(1)), lin(1)));
    rig.interp.forward();
    rig.tick(0.004);
    rig.port.failNextMotion("MOTN-017", "Limit error (G:1^2, A:2^3 hex)");
    Alarm a = rig.alarm(rig.tick(0.004));
    assertThat(a.code()).isEqualTo("MOTN-017");
    assertThat(a.line()).isEqualTo(2);
  }

  @Test
  void userAlarmAndAbort() {
    Alarm u = alarmOf(prog("U", setR(1, num(4)), new Instruction.UserAlarm(new Index.Indirect(1, ""))));
    assertThat(u.kind()).isEqualTo(AlarmKind.USER_ALARM);
    assertThat(u.message()).isEqualTo("UALM[4]");
    Alarm abort = alarmOf(prog("A", new Instruction.Abort(), setR(1, num(1))));
    assertThat(abort.kind()).isEqualTo(AlarmKind.ABORTED);
    assertThat(abort.line()).isEqualTo(1);
  }

  @Test
  void missingPositionAndPlainOffset() {
    assertThat(alarmOf(prog("P", lin(3))).kind()).isEqualTo(AlarmKind.UNDEFINED_POSITION);
    assertThat(alarmOf(Tp.progWithPositions("P", 1, lin(1, new Motion.Offset()))).message()).contains("OFFSET CONDITION");
  }

  @Test
  void brokenBlockStructureIsReportedWhenTheProgramStarts() {
    Alarm a = alarmOf(prog("S", setR(1, num(1)), forUp(2, num(1), num(2)), setR(3, num(1))));
    assertThat(a.kind()).isEqualTo(AlarmKind.STRUCTURE);
    assertThat(a.line()).isEqualTo(2);
    assertThat(a.message()).isEqualTo("FOR without ENDFOR");
    Alarm endif = alarmOf(prog("S", Tp.endIf()));
    assertThat(endif.message()).startsWith("ENDIF without IF");
    Alarm sel = alarmOf(prog("S", new Instruction.SelectCase(num(1), jmp(1)), lbl(1)));
    assertThat(sel.kind()).isEqualTo(AlarmKind.STRUCTURE);
  }

  @Test
  void badValuesAndWritingInputs() {
    assertThat(alarmOf(prog("O", new Instruction.SetOverride(num(0)))).kind()).isEqualTo(AlarmKind.BAD_VALUE);
    assertThat(alarmOf(prog("O", new Instruction.SelectFrame(Instruction.FrameKind.USER, Index.of(11)))).kind())
        .isEqualTo(AlarmKind.BAD_VALUE);
    Alarm di = alarmOf(prog("O", setIo(IoKind.DI, 1, on())));
    assertThat(di.kind()).isEqualTo(AlarmKind.WRITE_PROTECTED);
    assertThat(di.code()).isEqualTo("SIMU-004");
  }

  @Test
  void resetClearsTheAlarmAndForwardRunsOnFromTheCursor() {
    Rig rig = new Rig(prog("MAIN", setR(1, num(1)), setR(2, op(num(1), DIVIDE, r(3))), setR(4, num(4))));
    Alarm a = rig.alarm(rig.run());
    assertThat(a.line()).isEqualTo(2);
    assertThat(rig.tick(0.004)).isInstanceOf(Outcome.Alarmed.class);
    rig.interp.forward();
    assertThat(rig.tick(0.004)).isInstanceOf(Outcome.Alarmed.class);
    rig.interp.reset();
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.IDLE);
    assertThat(rig.interp.cursorLine()).isEqualTo(2);
    rig.regs.setInteger(3, 2);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(2)).isEqualTo(0.5);
    assertThat(rig.regs.number(4)).isEqualTo(4);
  }

  @Test
  void alarmInsideACallNamesTheCallee() {
    Alarm a = alarmOf(prog("MAIN", setR(1, num(0)), call("SUB"), end()), prog("SUB", setR(1, num(1)), setR(2, op(num(1), DIV, num(0)))));
    assertThat(a.program()).isEqualTo("SUB");
    assertThat(a.line()).isEqualTo(2);
    assertThat(a.display()).isEqualTo("SIMU-001 (SUB, 2) division by zero in 'DIV'");
  }
}
