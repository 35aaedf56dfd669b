package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.robotrun.program.Expr.BinaryOp.ADD;
import static org.robotrun.program.Expr.BinaryOp.EQ;
import static org.robotrun.program.Expr.BinaryOp.GT;
import static org.robotrun.program.Expr.BinaryOp.LT;
import static org.robotrun.program.Expr.BinaryOp.MUL;
import static org.robotrun.program.Tp.ar;
import static org.robotrun.program.Tp.call;
import static org.robotrun.program.Tp.comment;
import static org.robotrun.program.Tp.els;
import static org.robotrun.program.Tp.end;
import static org.robotrun.program.Tp.endFor;
import static org.robotrun.program.Tp.endIf;
import static org.robotrun.program.Tp.forDown;
import static org.robotrun.program.Tp.forUp;
import static org.robotrun.program.Tp.group;
import static org.robotrun.program.Tp.ifJ;
import static org.robotrun.program.Tp.ifThen;
import static org.robotrun.program.Tp.io;
import static org.robotrun.program.Tp.jmp;
import static org.robotrun.program.Tp.jmpR;
import static org.robotrun.program.Tp.lbl;
import static org.robotrun.program.Tp.num;
import static org.robotrun.program.Tp.on;
import static org.robotrun.program.Tp.op;
import static org.robotrun.program.Tp.prog;
import static org.robotrun.program.Tp.pulse;
import static org.robotrun.program.Tp.r;
import static org.robotrun.program.Tp.real;
import static org.robotrun.program.Tp.setIo;
import static org.robotrun.program.Tp.setR;
import static org.robotrun.program.Tp.timer;
import static org.robotrun.program.Tp.timerSet;
import static org.robotrun.program.Tp.waitFor;
import static org.robotrun.program.Tp.waitSec;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Flow of control: END, CALL, SELECT, FOR, IF, JMP, WAIT, TIMER, I/O. */
class InterpreterFlowTest {

  @Test
  void forwardRunsToEndAndNotBeyond() {
    Rig rig = new Rig(prog("MAIN", setR(1, num(1)), comment("done"), end(), setR(1, num(2))));
    Outcome o = rig.run();
    assertThat(o).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.IDLE);
    assertThat(rig.interp.cursorLine()).isEqualTo(3);
  }

  @Test
  void runningPastTheLastLineFinishes() {
    Rig rig = new Rig(prog("MAIN", setR(1, num(5))));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(5);
  }

  @Test
  void forwardStartsAtTheCursorLine() {
    Rig rig = new Rig(prog("MAIN", setR(1, num(1)), setR(2, num(2))));
    rig.interp.setCursor(2);
    rig.run();
    assertThat(rig.regs.number(1)).isEqualTo(0);
    assertThat(rig.regs.number(2)).isEqualTo(2);
  }

  @Test
  void callPassesArgumentsAndReturnsToTheNextLine() {
    Program main = prog("MAIN",
        setR(9, num(4)),
        call("ADD2", num(3), real(2.5), r(9)),
        setR(2, op(r(1), ADD, num(100))));
    Program sub = prog("ADD2",
        setR(1, op(op(ar(1), ADD, ar(2)), ADD, ar(3))),
        end(),
        setR(1, num(-1)));
    Rig rig = new Rig(main, sub);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(9.5);
    assertThat(rig.regs.number(2)).isEqualTo(109.5);
  }

  @Test
  void nestedCallsUnwindInOrder() {
    Program a = prog("A", setR(1, num(1)), call("B"), setR(3, op(r(2), MUL, num(10))));
    Program b = prog("B", call("C"), setR(2, op(r(4), ADD, num(1))));
    Program c = prog("C", setR(4, num(6)));
    Rig rig = new Rig(a, b, c);
    rig.run();
    assertThat(rig.regs.number(3)).isEqualTo(70);
    assertThat(rig.interp.callDepth()).isZero();
  }

  @Test
  void stringArgumentsCompareInTheCallee() {
    Program main = prog("MAIN", call("SUB", new Expr.StringConst("PART_A")));
    Program sub = prog("SUB", ifJ(op(ar(1), EQ, new Expr.StringConst("PART_A")), jmp(1)), setR(1, num(1)), end(),
        lbl(1), setR(1, num(2)));
    Rig rig = new Rig(main, sub);
    rig.run();
    assertThat(rig.regs.number(1)).isEqualTo(2);
  }

  private static Program select(boolean withElse) {
    List<Instruction> lines = new java.util.ArrayList<>(List.of(
        new Instruction.Select(Item.of(1), num(1), jmp(10)),
        new Instruction.SelectCase(num(2), jmp(20)),
        new Instruction.SelectCase(num(3), call("SUB"))));
    if (withElse) {
      lines.add(new Instruction.SelectElse(jmp(30)));
    }
    lines.addAll(List.of(
        setR(2, num(-1)), end(),
        lbl(10), setR(2, num(10)), end(),
        lbl(20), setR(2, num(20)), end(),
        lbl(30), setR(2, num(30)), end()));
    return Program.of("SEL", lines);
  }

  private static double runSelect(boolean withElse, int value) {
    Rig rig = new Rig(select(withElse), prog("SUB", setR(3, num(33))));
    rig.regs.setInteger(1, value);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    if (value == 3) {
      assertThat(rig.regs.number(3)).isEqualTo(33);
    }
    return rig.regs.number(2);
  }

  @Test
  void selectTakesTheMatchingCaseOrElse() {
    assertThat(runSelect(true, 1)).isEqualTo(10);
    assertThat(runSelect(true, 2)).isEqualTo(20);
    assertThat(runSelect(true, 7)).isEqualTo(30);
    // CALL from a case returns to the line after the whole SELECT.
    assertThat(runSelect(true, 3)).isEqualTo(-1);
  }

  @Test
  void selectWithoutElseFallsThroughAfterTheGroup() {
    assertThat(runSelect(false, 7)).isEqualTo(-1);
  }

  @Test
  void forCountsUpAndLeavesTheCounterAtTheEnd() {
    Rig rig = new Rig(prog("F",
        forUp(1, num(1), num(4)),
        setR(2, op(r(2), ADD, r(1))),
        setR(3, op(r(3), ADD, num(1))),
        endFor()));
    rig.run();
    assertThat(rig.regs.number(2)).isEqualTo(1 + 2 + 3 + 4);
    assertThat(rig.regs.number(3)).isEqualTo(4);
    assertThat(rig.regs.number(1)).isEqualTo(4);
  }

  @Test
  void forCountsDown() {
    Rig rig = new Rig(prog("F",
        forDown(1, num(3), num(1)),
        setR(2, op(op(r(2), MUL, num(10)), ADD, r(1))),
        endFor()));
    rig.run();
    assertThat(rig.regs.number(2)).isEqualTo(321);
  }

  @Test
  void forSkipsTheBodyWhenStartIsPastTheEnd() {
    Rig rig = new Rig(prog("F",
        forUp(1, num(5), num(4)),
        setR(2, num(1)),
        endFor(),
        forDown(3, num(1), num(2)),
        setR(4, num(1)),
        endFor(),
        setR(5, num(1))));
    rig.run();
    assertThat(rig.regs.number(2)).isZero();
    assertThat(rig.regs.number(4)).isZero();
    assertThat(rig.regs.number(5)).isEqualTo(1);
    assertThat(rig.regs.number(1)).isEqualTo(5);
  }

  @Test
  void nestedForLoopsWithRegisterBounds() {
    Rig rig = new Rig(prog("F",
        forUp(1, num(1), r(10)),
        forUp(2, num(1), r(1)),
        setR(3, op(r(3), ADD, num(1))),
        endFor(),
        endFor()));
    rig.regs.setInteger(10, 4);
    rig.run();
    assertThat(rig.regs.number(3)).isEqualTo(1 + 2 + 3 + 4);
  }

  @Test
  void ifThenElseTakesOneBranch() {
    Program p = prog("I",
        ifThen(group(op(r(1), GT, num(0)))),
        setR(2, num(1)),
        ifThen(group(op(r(1), GT, num(5)))),
        setR(3, num(1)),
        endIf(),
        els(),
        setR(2, num(-1)),
        endIf(),
        setR(4, num(1)));
    Rig pos = new Rig(p);
    pos.regs.setInteger(1, 3);
    pos.run();
    assertThat(pos.regs.number(2)).isEqualTo(1);
    assertThat(pos.regs.number(3)).isZero();
    assertThat(pos.regs.number(4)).isEqualTo(1);

    Rig neg = new Rig(p);
    neg.regs.setInteger(1, -3);
    neg.run();
    assertThat(neg.regs.number(2)).isEqualTo(-1);
    assertThat(neg.regs.number(4)).isEqualTo(1);
  }

  @Test
  void ifJumpAndIfCall() {
    Rig rig = new Rig(
        prog("I", ifJ(op(r(1), EQ, num(0)), call("SUB")), ifJ(op(r(5), LT, num(10)), jmp(1)), setR(2, num(-1)),
            end(), lbl(1), setR(2, num(1))),
        prog("SUB", setR(5, num(3))));
    rig.run();
    assertThat(rig.regs.number(5)).isEqualTo(3);
    assertThat(rig.regs.number(2)).isEqualTo(1);
  }

  @Test
  void jumpToALabelHeldInARegister() {
    Rig rig = new Rig(prog("J",
        jmpR(1),
        lbl(1), setR(2, num(1)), end(),
        lbl(2), setR(2, num(2)), end()));
    rig.regs.setInteger(1, 2);
    rig.run();
    assertThat(rig.regs.number(2)).isEqualTo(2);
  }

  @Test
  void loopWithJumpsCounts() {
    Rig rig = new Rig(prog("L",
        lbl(1),
        setR(1, op(r(1), ADD, num(1))),
        ifJ(op(r(1), LT, num(1000)), jmp(1))));
    rig.run();
    assertThat(rig.regs.number(1)).isEqualTo(1000);
  }

  @Test
  void waitTimeLastsTheSimulatedTime() {
    Rig rig = new Rig(prog("W", waitSec(0.5), setR(1, num(1))));
    rig.interp.forward();
    assertThat(rig.tick(0.1)).isInstanceOf(Outcome.WaitingOnTime.class);
    for (int i = 0; i < 4; i++) {
      assertThat(rig.tick(0.1)).isInstanceOf(Outcome.WaitingOnTime.class);
    }
    assertThat(rig.regs.number(1)).isZero();
    assertThat(rig.tick(0.1)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(1);
  }

  @Test
  void waitConditionProceedsWhenTheInputComesOn() {
    Rig rig = new Rig(prog("W", waitFor(op(io(IoKind.DI, 3), EQ, on())), setR(1, num(1))));
    rig.interp.forward();
    for (int i = 0; i < 10; i++) {
      assertThat(rig.tick(0.1)).isInstanceOf(Outcome.WaitingOnCondition.class);
    }
    rig.regs.setBit(IoKind.DI, 3, true);
    assertThat(rig.tick(0.1)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(1);
  }

  @Test
  void waitConditionTimesOutToItsLabelAfterWaitTmout() {
    Program p = prog("W",
        waitFor(op(io(IoKind.RI, 1), EQ, on()), 99),
        setR(1, num(1)),
        end(),
        lbl(99),
        setR(1, num(99)));
    Rig rig = new Rig(InterpreterSettings.defaults().withWaitTimeoutSec(1.0), 0.1, p);
    rig.interp.forward();
    assertThat(rig.tick(0.25)).isInstanceOf(Outcome.WaitingOnCondition.class);
    assertThat(rig.tick(0.25)).isInstanceOf(Outcome.WaitingOnCondition.class);
    assertThat(rig.tick(0.25)).isInstanceOf(Outcome.WaitingOnCondition.class);
    assertThat(rig.tick(0.25)).isInstanceOf(Outcome.WaitingOnCondition.class);
    assertThat(rig.tick(0.25)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(99);
  }

  @Test
  void timerCountsSimulatedTimeBetweenStartAndStop() {
    Rig rig = new Rig(prog("T",
        timerSet(1, Instruction.TimerAction.RESET),
        timerSet(1, Instruction.TimerAction.START),
        waitSec(1.0),
        timerSet(1, Instruction.TimerAction.STOP),
        waitSec(0.5),
        setR(1, timer(1))));
    rig.interp.forward();
    Outcome o = rig.runUntilStopped(0.05, 1000);
    assertThat(o).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.timerSec(1)).isCloseTo(1.0, within(1e-9));
    assertThat(rig.regs.number(1)).isCloseTo(1.0, within(1e-9));
    assertThat(rig.regs.isInteger(1)).isFalse();
  }

  @Test
  void outputsFlagsAndGroups() {
    Rig rig = new Rig(prog("IO",
        setIo(IoKind.DO, 1, on()),
        setIo(IoKind.RO, 2, r(1)),
        setIo(IoKind.GO, 3, num(12)),
        setIo(IoKind.F, 4, group(op(r(1), GT, num(1)))),
        setR(2, io(IoKind.GO, 3))));
    rig.regs.setInteger(1, 5);
    rig.run();
    assertThat(rig.regs.bit(IoKind.DO, 1)).isTrue();
    assertThat(rig.regs.bit(IoKind.RO, 2)).isTrue();
    assertThat(rig.regs.value(IoKind.GO, 3)).isEqualTo(12);
    assertThat(rig.regs.bit(IoKind.F, 4)).isTrue();
    assertThat(rig.regs.number(2)).isEqualTo(12);
  }

  @Test
  void pulseTurnsTheOutputOnThenOffAfterItsWidth() {
    Rig rig = new Rig(prog("P", pulse(IoKind.DO, 2, 0.3), setR(1, num(1))));
    rig.interp.forward();
    assertThat(rig.tick(0.1)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.regs.bit(IoKind.DO, 2)).isTrue();
    rig.tick(0.1);
    rig.tick(0.1);
    assertThat(rig.regs.bit(IoKind.DO, 2)).isTrue();
    rig.tick(0.1);
    assertThat(rig.regs.bit(IoKind.DO, 2)).isFalse();
  }

  @Test
  void pauseStopsAndForwardResumes() {
    Rig rig = new Rig(prog("P", setR(1, num(1)), new Instruction.Pause(), setR(1, num(2))));
    assertThat(rig.run()).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.interp.cursorLine()).isEqualTo(3);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.number(1)).isEqualTo(2);
  }

  @Test
  void messageAndOverride() {
    Rig rig = new Rig(prog("M", new Instruction.Message("Gripper did not close"),
        new Instruction.SetOverride(num(35))));
    rig.run();
    assertThat(rig.interp.userScreen()).containsExactly("Gripper did not close");
    assertThat(rig.port.overridePct()).isEqualTo(35);
  }

  @Test
  void positionRegistersAndFrames() {
    Position.Cartesian a = new Position.Cartesian(10, 20, 30, 0, 0, 90, Config.DEFAULT);
    Position.Cartesian b = new Position.Cartesian(1, 2, 3, 0, 0, 0, Config.DEFAULT);
    Program p = Program.of("PR", List.of(
        new Instruction.AssignPosReg(Item.of(3), new Instruction.PosArithmetic(Item.of(1), true, Item.of(2))),
        new Instruction.AssignPosReg(Item.of(4), new Instruction.PosArithmetic(Item.of(1), false, Item.of(2))),
        new Instruction.AssignPosElement(Item.of(4, "STACK"), 3, op(num(2), MUL, num(20))),
        setR(1, Tp.prEl(3, 6)),
        new Instruction.AssignPosReg(Item.of(5), new Instruction.FromLocal(2, "")),
        new Instruction.AssignPosReg(Item.of(6), new Instruction.CurrentJpos()),
        new Instruction.SetFrame(Instruction.FrameKind.USER, Index.of(2), Item.of(1)),
        new Instruction.SelectFrame(Instruction.FrameKind.USER, Index.of(2)),
        new Instruction.AssignPosReg(Item.of(7), new Instruction.FromFrame(Instruction.FrameKind.USER, Index.of(2))),
        new Instruction.Payload(Index.of(1))),
        List.of(Tp.pos(2)));
    Rig rig = new Rig(p);
    rig.regs.setPosition(1, a);
    rig.regs.setPosition(2, b);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.regs.position(3)).isEqualTo(new Position.Cartesian(11, 22, 33, 0, 0, 90, Config.DEFAULT));
    assertThat(rig.regs.position(4)).isEqualTo(new Position.Cartesian(9, 18, 40, 0, 0, 90, Config.DEFAULT));
    assertThat(rig.regs.number(1)).isEqualTo(90);
    assertThat(rig.regs.position(5)).isEqualTo(Tp.pos(2).position());
    assertThat(rig.regs.position(6)).isInstanceOf(Position.Joint.class);
    assertThat(rig.port.activeFrame(Instruction.FrameKind.USER)).isEqualTo(2);
    assertThat(rig.regs.position(7)).isEqualTo(a);
  }

  @Test
  void aMacroRunsTheProgramTheMacroTableNames() {
    Program main = prog("MAIN", new Instruction.MacroCall("HAND1 OPEN"), new Instruction.MacroCall("OPEN_HAND"),
        Tp.setR(3, num(3)));
    Rig rig = new Rig(InterpreterSettings.defaults().withMacros(Map.of("hand1  open", "HOPEN")), 0.1, main,
        prog("HOPEN", Tp.setR(1, num(1))), prog("OPEN_HAND", Tp.setR(2, num(2))));
    assertThat(rig.run()).isEqualTo(Outcome.FINISHED);
    // the table's program for a name of several words (any case, any spacing); a one-word macro
    // the table does not hold runs the program of its own name
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.regs.number(2)).isEqualTo(2);
    assertThat(rig.regs.number(3)).isEqualTo(3);
  }

  @Test
  void aMacroOfSeveralWordsNotInTheTableAlarms() {
    Rig rig = new Rig(prog("MAIN", Tp.setR(1, num(1)), new Instruction.MacroCall("GRIP CLOSE"), Tp.setR(2, num(2))));
    Alarm a = rig.alarm(rig.run());
    assertThat(a.kind()).isEqualTo(AlarmKind.UNKNOWN_PROGRAM);
    assertThat(a.line()).isEqualTo(2);
    assertThat(a.message()).contains("GRIP CLOSE").contains("not in the macro table");
    assertThat(rig.regs.number(2)).isZero();
  }

  @Test
  void userAlarmTextComesFromTheSettings() {
    Rig rig = new Rig(InterpreterSettings.defaults().withUserAlarmMessages(Map.of(3, "Part missing")), 0.1,
        prog("U", new Instruction.UserAlarm(Index.of(3))));
    Alarm a = rig.alarm(rig.run());
    assertThat(a.kind()).isEqualTo(AlarmKind.USER_ALARM);
    assertThat(a.message()).isEqualTo("Part missing");
    assertThat(a.display()).isEqualTo("INTP-213 (U, 1) Part missing");
  }

  @Test
  void waittmoutSetByTheProgramTimesTheWaitAndStaysSet() {
    Program w = prog("W", new Instruction.SetSysVar(SystemVariables.WAITTMOUT, num(50)),
        Tp.waitFor(io(IoKind.DI, 1), 1), lbl(1));
    Program again = prog("W2", Tp.waitFor(io(IoKind.DI, 1), 1), lbl(1));
    Rig rig = new Rig(w, again);
    rig.interp.forward();
    int ticks = 0;
    Outcome o;
    do {
      o = rig.tick(Rig.TICK_SEC);
      ticks++;
    } while (!(o instanceof Outcome.Finished) && ticks < 100_000);
    assertThat(o).isEqualTo(Outcome.FINISHED);
    // 50 hundredths of a second, to within a tick (the 30 s default would take 7500 ticks).
    assertThat(ticks * Rig.TICK_SEC).isCloseTo(0.5, within(2 * Rig.TICK_SEC));
    // The variable is global: another program's WAIT ... TIMEOUT uses the new value.
    rig.interp.select("W2");
    rig.interp.forward();
    ticks = 0;
    do {
      o = rig.tick(Rig.TICK_SEC);
      ticks++;
    } while (!(o instanceof Outcome.Finished) && ticks < 100_000);
    assertThat(ticks * Rig.TICK_SEC).isCloseTo(0.5, within(2 * Rig.TICK_SEC));
  }
}
