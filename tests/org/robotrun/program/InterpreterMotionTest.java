package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.robotrun.program.Tp.call;
import static org.robotrun.program.Tp.comment;
import static org.robotrun.program.Tp.joint;
import static org.robotrun.program.Tp.lin;
import static org.robotrun.program.Tp.num;
import static org.robotrun.program.Tp.pos;
import static org.robotrun.program.Tp.progWithPositions;
import static org.robotrun.program.Tp.setR;
import static org.robotrun.program.Tp.waitSec;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** Motion lines: waiting for the port, STEP, HOLD, backward execution, request contents. */
class InterpreterMotionTest {

  private static final double MOTION_SEC = 0.1;
  private static final double DT = 0.02;

  private static Program threeMoves() {
    return progWithPositions("MOVES", 3,
        joint(1),
        lin(2),
        setR(1, num(1)),
        comment("back over this"),
        lin(3),
        setR(2, num(2)));
  }

  private static double x(MotionRequest r) {
    return ((Position.Cartesian) r.target().position()).xMm();
  }

  @Test
  void forwardWaitsForEachMotionThenFinishes() {
    Rig rig = new Rig(threeMoves());
    rig.interp.forward();
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.WaitingForMotion.class);
    assertThat(rig.port.requests()).hasSize(1);
    assertThat(rig.interp.cursorLine()).isEqualTo(1);
    Outcome o = rig.runUntilStopped(DT, 1000);
    assertThat(o).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.port.requests()).extracting(InterpreterMotionTest::x).containsExactly(100.0, 200.0, 300.0);
    assertThat(rig.port.requests()).extracting(MotionRequest::type)
        .containsExactly(Motion.Type.J, Motion.Type.L, Motion.Type.L);
    assertThat(rig.regs.number(2)).isEqualTo(2);
  }

  @Test
  void stepRunsOneLineAndAMotionLineStopsAtItsEndPoint() {
    Rig rig = new Rig(threeMoves());
    rig.interp.setStepMode(true);
    rig.interp.forward();
    // Line 1 (motion): waits, then pauses at its end point.
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.WaitingForMotion.class);
    assertThat(rig.runUntilStopped(DT, 100)).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.port.requests()).hasSize(1);
    assertThat(rig.interp.cursorLine()).isEqualTo(2);
    // Paused stays paused without FWD.
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.Paused.class);
    // Line 2 (motion), then line 3 (register) one at a time.
    assertThat(rig.run()).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.port.requests()).hasSize(2);
    assertThat(rig.regs.number(1)).isZero();
    rig.interp.forward();
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.regs.number(1)).isEqualTo(1);
    assertThat(rig.interp.cursorLine()).isEqualTo(4);
  }

  @Test
  void stepRunsCntMotionsAsFine() {
    Instruction.Move cnt = Instruction.Move.of(Motion.Type.L, Tp.p(1), Tp.mmPerSec(100), new Motion.Cnt(50), List.of());
    Rig stepping = new Rig(progWithPositions("C", 1, cnt));
    stepping.interp.setStepMode(true);
    stepping.run();
    assertThat(stepping.port.requests().get(0).fine()).isTrue();
    Rig running = new Rig(progWithPositions("C", 1, cnt));
    running.run();
    assertThat(running.port.requests().get(0).fine()).isFalse();
    assertThat(running.port.requests().get(0).cnt()).isEqualTo(50);
  }

  @Test
  void stepGoesIntoACalledProgram() {
    Program main = Tp.prog("MAIN", call("SUB"), setR(1, num(1)));
    Program sub = Tp.prog("SUB", setR(2, num(2)), setR(3, num(3)));
    Rig rig = new Rig(main, sub);
    rig.interp.setStepMode(true);
    rig.interp.forward();
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.interp.currentProgram()).isEqualTo("SUB");
    assertThat(rig.interp.callDepth()).isEqualTo(2);
    rig.interp.forward();
    rig.tick(DT);
    assertThat(rig.regs.number(2)).isEqualTo(2);
    assertThat(rig.regs.number(3)).isZero();
  }

  @Test
  void holdFreezesTheMotionAndForwardResumesIt() {
    Rig rig = new Rig(threeMoves());
    rig.interp.forward();
    rig.tick(DT);
    rig.interp.hold();
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.PAUSED);
    assertThat(rig.port.isHeld(1)).isTrue();
    for (int i = 0; i < 50; i++) {
      assertThat(rig.tick(DT)).isInstanceOf(Outcome.Paused.class);
    }
    assertThat(rig.port.requests()).hasSize(1);
    rig.interp.forward();
    assertThat(rig.port.isHeld(1)).isFalse();
    assertThat(rig.runUntilStopped(DT, 1000)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.port.requests()).hasSize(3);
  }

  @Test
  void abortEndsTheProgramAndCancelsItsMotion() {
    Rig rig = new Rig(threeMoves());
    rig.interp.forward();
    rig.tick(DT);
    rig.interp.abort();
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.IDLE);
    assertThat(rig.port.cancelled()).containsExactly(1L);
    assertThat(rig.tick(DT)).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.interp.cursorLine()).isEqualTo(1);
  }

  @Test
  void holdDuringWaitKeepsTheRemainingTime() {
    Rig rig = new Rig(Tp.prog("W", waitSec(0.1), setR(1, num(1))));
    rig.interp.forward();
    rig.tick(0.05);
    rig.interp.hold();
    rig.tick(1.0);
    rig.interp.forward();
    assertThat(rig.tick(0.04)).isInstanceOf(Outcome.WaitingOnTime.class);
    assertThat(rig.tick(0.06)).isInstanceOf(Outcome.Finished.class);
  }

  @Test
  void backwardRunsMotionLinesInReverseAndPassesOverAssignments() {
    Rig rig = new Rig(threeMoves());
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    // The cursor rests on the last line; the robot stands at P[3].
    rig.interp.setCursor(6);
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.WaitingForMotion.class);
    MotionRequest back = rig.port.requests().get(3);
    assertThat(back.backward()).isTrue();
    assertThat(x(back)).isEqualTo(200.0);
    // It backs out of line 5 (L), so the motion is linear at line 5's speed, FINE.
    assertThat(back.type()).isEqualTo(Motion.Type.L);
    assertThat(back.fine()).isTrue();
    assertThat(back.line()).isEqualTo(2);
    assertThat(rig.runUntilStopped(DT, 1000)).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.interp.cursorLine()).isEqualTo(5);
    // Register lines were passed over, not undone or re-run.
    assertThat(rig.regs.number(1)).isEqualTo(1);

    assertThat(rig.interp.backward()).isInstanceOf(Outcome.WaitingForMotion.class);
    assertThat(x(rig.port.requests().get(4))).isEqualTo(100.0);
    assertThat(rig.port.requests().get(4).type()).isEqualTo(Motion.Type.L);
    rig.runUntilStopped(DT, 1000);
    assertThat(rig.interp.cursorLine()).isEqualTo(2);

    // At the first motion line there is nothing further back.
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.interp.notice()).contains("top of program");
    assertThat(rig.port.requests()).hasSize(5);

    // SHIFT+FWD from here re-runs line 2 forward; the BWD notice belongs to the BWD and goes.
    rig.interp.setStepMode(true);
    rig.interp.forward();
    assertThat(rig.interp.notice()).isEmpty();
    rig.runUntilStopped(DT, 1000);
    assertThat(x(rig.port.requests().get(5))).isEqualTo(200.0);
    assertThat(rig.port.requests().get(5).backward()).isFalse();
  }

  @Test
  void backwardRightAfterARunBacksOutOfTheLastLine() {
    // The last line is a motion: the run ends with the cursor left on it (line 3) and the robot
    // at P[3]. SHIFT+BWD goes to P[2] (not P[1]) and the cursor lands on line 3.
    Rig rig = new Rig(progWithPositions("ENDMOVE", 3, joint(1), lin(2), lin(3)));
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.interp.cursorLine()).isEqualTo(3);
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.WaitingForMotion.class);
    assertThat(x(rig.port.requests().get(3))).isEqualTo(200.0);
    assertThat(rig.runUntilStopped(DT, 1000)).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.interp.cursorLine()).isEqualTo(3);
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.WaitingForMotion.class);
    assertThat(x(rig.port.requests().get(4))).isEqualTo(100.0);
  }

  @Test
  void backwardStopsAtALineThatCannotRunBackward() {
    Program p = progWithPositions("B", 2, joint(1), call("SUB"), lin(2));
    Rig rig = new Rig(p, Tp.prog("SUB", setR(1, num(1))));
    rig.run();
    rig.interp.setCursor(4);
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.Paused.class);
    assertThat(rig.interp.notice()).isEqualTo("BWD stopped at line 2: CALL cannot run backward");
    assertThat(rig.port.requests()).hasSize(2);
  }

  @Test
  void backwardRefusesWhileRunning() {
    Rig rig = new Rig(threeMoves());
    rig.interp.forward();
    rig.tick(DT);
    assertThat(rig.interp.backward()).isInstanceOf(Outcome.Continue.class);
    assertThat(rig.interp.notice()).contains("HOLD first");
  }

  @Test
  void motionRequestCarriesResolvedSpeedTerminationAndOptions() {
    Instruction.Move move = Instruction.Move.of(Motion.Type.L, Tp.pr(4),
        new Motion.Speed(new Motion.SpeedRegister(Item.of(7)), Motion.SpeedUnit.MM_PER_SEC),
        new Motion.CntRegister(Item.of(8)),
        List.of(new Motion.OffsetPr(Item.of(10)), new Motion.ToolOffsetPr(Item.of(12)), new Motion.Acc(80),
            new Motion.Wjnt()));
    Rig rig = new Rig(Tp.prog("OPT", move));
    Position.Cartesian target = new Position.Cartesian(1, 2, 3, 4, 5, 6, Config.DEFAULT);
    Position.Cartesian shift = new Position.Cartesian(0, 0, 20, 0, 0, 0, Config.DEFAULT);
    Position.Cartesian up = new Position.Cartesian(0, 0, -50, 0, 0, 0, Config.DEFAULT);
    rig.regs.setPosition(4, target);
    rig.regs.setPosition(10, shift);
    rig.regs.setPosition(12, up);
    rig.regs.setInteger(7, 400);
    rig.regs.setInteger(8, 50);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    MotionRequest req = rig.port.requests().get(0);
    assertThat(req.target().position()).isEqualTo(target);
    assertThat(req.target().name()).isEqualTo("PR[4]");
    assertThat(req.speed()).isEqualTo(400);
    assertThat(req.fine()).isFalse();
    assertThat(req.cnt()).isEqualTo(50);
    assertThat(req.offset()).contains(shift);
    assertThat(req.toolOffset()).contains(up);
    assertThat(req.accPercent()).isEqualTo(80);
    assertThat(req.wristJoint()).isTrue();
    assertThat(req.incremental()).isFalse();
    assertThat(req.program()).isEqualTo("OPT");
    assertThat(req.line()).isEqualTo(1);
  }

  @Test
  void circularMotionCarriesViaAndEnd() {
    Instruction.Move c = Instruction.Move.circular(Tp.p(2), Tp.p(3), Tp.mmPerSec(250), new Motion.Cnt(100), List.of());
    Rig rig = new Rig(progWithPositions("CIRC", 3, joint(1), c));
    rig.run();
    MotionRequest req = rig.port.requests().get(1);
    assertThat(req.type()).isEqualTo(Motion.Type.C);
    assertThat(req.via().map(w -> w.position())).contains(pos(2).position());
    assertThat(req.target().position()).isEqualTo(pos(3).position());
    assertThat(req.speed()).isEqualTo(250);
    assertThat(req.cnt()).isEqualTo(100);
  }

  @Test
  void skipLabelJumpsAfterTheMotion() {
    Program p = progWithPositions("SK", 1,
        lin(1, new Motion.Skip(LabelRef.of(5))),
        setR(1, num(1)),
        new Instruction.End(),
        Tp.lbl(5),
        setR(1, num(5)));
    Rig rig = new Rig(p);
    rig.run();
    assertThat(rig.regs.number(1)).isEqualTo(5);
  }

  @Test
  void skipConditionTurningTrueStopsTheMotionAndGoesOnWithoutTheJump() {
    Program p = progWithPositions("SK", 1,
        new Instruction.SkipCondition(new Expr.Binary(Expr.BinaryOp.EQ, Tp.io(IoKind.DI, 1), Tp.on())),
        lin(1, new Motion.Skip(LabelRef.of(5))),
        setR(1, num(1)),
        new Instruction.End(),
        Tp.lbl(5),
        setR(1, num(5)));
    Rig rig = new Rig(InterpreterSettings.defaults(), 1.0, p);
    rig.interp.forward();
    for (int i = 0; i < 25; i++) {
      rig.tick(Rig.TICK_SEC);
    }
    // 0.1 s into a 1 s motion: still moving, nothing cancelled.
    assertThat(rig.port.cancelled()).isEmpty();
    assertThat(rig.interp.state()).isEqualTo(Interpreter.State.RUNNING);
    rig.regs.setBit(IoKind.DI, 1, true);
    assertThat(rig.runUntilStopped(Rig.TICK_SEC, 1000)).isInstanceOf(Outcome.Finished.class);
    // The arm was stopped (the motion cancelled) and the line after the motion ran: no jump.
    assertThat(rig.port.cancelled()).hasSize(1);
    assertThat(rig.regs.number(1)).isEqualTo(1);
  }

  @Test
  void skipConditionThatNeverTurnsTrueJumpsAfterTheMotion() {
    Program p = progWithPositions("SK", 1,
        new Instruction.SkipCondition(new Expr.Binary(Expr.BinaryOp.EQ, Tp.io(IoKind.DI, 1), Tp.on())),
        lin(1, new Motion.Skip(LabelRef.of(5))),
        setR(1, num(1)),
        new Instruction.End(),
        Tp.lbl(5),
        setR(1, num(5)));
    Rig rig = new Rig(p);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.port.cancelled()).isEmpty();
    assertThat(rig.regs.number(1)).isEqualTo(5);
  }

  @Test
  void plainOffsetUsesTheOffsetConditionsRegisterWhenTheMotionStarts() {
    Position.Cartesian shift = new Position.Cartesian(10, 20, 30, 0, 0, 0, Config.DEFAULT);
    Program p = progWithPositions("OF", 1,
        new Instruction.OffsetCondition(Item.of(4)),
        lin(1, new Motion.Offset()),
        lin(1));
    Rig rig = new Rig(p);
    rig.regs.setPosition(4, shift);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    assertThat(rig.port.requests().get(0).offset()).contains(shift);
    assertThat(rig.port.requests().get(1).offset()).isEmpty();
  }

  @Test
  void anOffsetInAnotherUserFrameIsTurnedIntoTheMotionsFrame() {
    // UFRAME[2] is turned 90 deg about Z: its +X is the world's +Y. The motion runs in UFRAME 0.
    Position.Cartesian along2x = new Position.Cartesian(10, 0, 0, 0, 0, 0, Config.DEFAULT);
    Program p = progWithPositions("OFU", 1,
        new Instruction.OffsetCondition(Item.of(4), java.util.Optional.of(Index.of(2))),
        lin(1, new Motion.Offset()),
        new Instruction.OffsetCondition(Item.of(4), java.util.Optional.of(Index.of(0))),
        lin(1, new Motion.Offset()));
    Rig rig = new Rig(p);
    rig.port.setFrame(Instruction.FrameKind.USER, 2, new Position.Cartesian(500, 0, 0, 0, 0, 90, Config.DEFAULT));
    rig.regs.setPosition(4, along2x);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    Position.Cartesian first = (Position.Cartesian) rig.port.requests().get(0).offset().orElseThrow();
    assertThat(first.xMm()).isCloseTo(0, within(1e-9));
    assertThat(first.yMm()).isCloseTo(10, within(1e-9));
    assertThat(first.zMm()).isCloseTo(0, within(1e-9));
    assertThat(first.rDeg()).isCloseTo(0, within(1e-9));
    // in the motion's own frame (UFRAME[0] here) the offset is the PR as it is
    assertThat(rig.port.requests().get(1).offset()).contains(along2x);
  }

  @Test
  void localPositionCarriesItsTaughtFrames() {
    LocalPosition inUf1 = new LocalPosition(1, "PICK", 1, 1, pos(1).position());
    Program p = Program.of("F", List.of(
        new Instruction.SelectFrame(Instruction.FrameKind.USER, Index.of(1)),
        new Instruction.SelectFrame(Instruction.FrameKind.TOOL, new Index.Indirect(3, "")),
        Instruction.Move.of(Motion.Type.L, new Motion.Local(1, "PICK"), Tp.mmPerSec(100), new Motion.Fine(), List.of())),
        List.of(inUf1));
    Rig rig = new Rig(p);
    rig.regs.setInteger(3, 1);
    assertThat(rig.run()).isInstanceOf(Outcome.Finished.class);
    MotionRequest.Waypoint w = rig.port.requests().get(0).target();
    assertThat(w.name()).isEqualTo("P[1:PICK]");
    assertThat(w.userFrame()).isEqualTo(1);
    assertThat(w.toolFrame()).isEqualTo(1);
    assertThat(rig.port.requests().get(0).via()).isEqualTo(Optional.empty());
  }

  @Test
  void speedFromARegisterMustBePositive() {
    Instruction.Move move = Instruction.Move.of(Motion.Type.J, Tp.p(1),
        new Motion.Speed(new Motion.SpeedRegister(Item.of(1)), Motion.SpeedUnit.PERCENT), new Motion.Fine(), List.of());
    Rig rig = new Rig(progWithPositions("S", 1, move));
    Alarm a = rig.alarm(rig.run());
    assertThat(a.kind()).isEqualTo(AlarmKind.BAD_VALUE);
  }
}
