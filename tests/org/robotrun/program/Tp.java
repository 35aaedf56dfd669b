package org.robotrun.program;

import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;

/** Tiny builder for programs in tests (the .LS reader lives in io). */
final class Tp {
  private Tp() {}

  static Expr num(int v) {
    return new Expr.IntConst(v);
  }

  static Expr real(double v) {
    return new Expr.RealConst(v);
  }

  static Expr on() {
    return new Expr.OnOff(true);
  }

  static Expr off() {
    return new Expr.OnOff(false);
  }

  static Expr r(int i) {
    return new Expr.Register(Item.of(i));
  }

  /** R[R[j]]. */
  static Expr rr(int j) {
    return new Expr.Register(new Item(Index.viaRegister(j), ""));
  }

  static Expr ar(int i) {
    return new Expr.Arg(Index.of(i));
  }

  static Expr io(IoKind k, int i) {
    return new Expr.Io(k, Item.of(i));
  }

  static Expr timer(int i) {
    return new Expr.Timer(Item.of(i));
  }

  static Expr prEl(int i, int j) {
    return new Expr.PosElement(Item.of(i), j);
  }

  static Expr op(Expr a, Expr.BinaryOp op, Expr b) {
    return new Expr.Binary(op, a, b);
  }

  static Expr group(Expr e) {
    return new Expr.Group(e);
  }

  static Expr neg(Expr e) {
    return new Expr.Unary(Expr.UnaryOp.MINUS, e);
  }

  static Expr not(Expr e) {
    return new Expr.Unary(Expr.UnaryOp.NOT, e);
  }

  static Instruction setR(int i, Expr e) {
    return new Instruction.AssignRegister(Item.of(i), e);
  }

  static Instruction setRR(int j, Expr e) {
    return new Instruction.AssignRegister(new Item(Index.viaRegister(j), ""), e);
  }

  static Instruction lbl(int n) {
    return new Instruction.Label(n, "");
  }

  static Instruction.Jump jmp(int n) {
    return new Instruction.Jump(LabelRef.of(n));
  }

  static Instruction.Jump jmpR(int reg) {
    return new Instruction.Jump(new LabelRef(Index.viaRegister(reg), ""));
  }

  static Instruction.Call call(String name, Expr... args) {
    return new Instruction.Call(name, List.of(args));
  }

  static Instruction end() {
    return new Instruction.End();
  }

  static Instruction ifJ(Expr cond, Instruction.Branch b) {
    return new Instruction.If(cond, b);
  }

  static Instruction ifThen(Expr cond) {
    return new Instruction.IfThen(cond);
  }

  static Instruction els() {
    return new Instruction.Else();
  }

  static Instruction endIf() {
    return new Instruction.EndIf();
  }

  static Instruction forUp(int reg, Expr a, Expr b) {
    return new Instruction.For(Item.of(reg), a, false, b);
  }

  static Instruction forDown(int reg, Expr a, Expr b) {
    return new Instruction.For(Item.of(reg), a, true, b);
  }

  static Instruction endFor() {
    return new Instruction.EndFor();
  }

  static Instruction waitSec(double s) {
    return new Instruction.WaitTime(new Expr.RealConst(s));
  }

  static Instruction waitFor(Expr cond) {
    return new Instruction.WaitCondition(cond, Optional.empty());
  }

  static Instruction waitFor(Expr cond, int timeoutLabel) {
    return new Instruction.WaitCondition(cond, Optional.of(LabelRef.of(timeoutLabel)));
  }

  static Instruction timerSet(int i, Instruction.TimerAction a) {
    return new Instruction.TimerSet(Item.of(i), a);
  }

  static Instruction setIo(IoKind k, int i, Expr v) {
    return new Instruction.SetIo(k, Item.of(i), v);
  }

  static Instruction pulse(IoKind k, int i, double widthSec) {
    return new Instruction.Pulse(k, Item.of(i), OptionalDouble.of(widthSec));
  }

  static Instruction comment(String s) {
    return new Instruction.Comment(s);
  }

  static Motion.Speed mmPerSec(double v) {
    return new Motion.Speed(new Motion.SpeedConst(v), Motion.SpeedUnit.MM_PER_SEC);
  }

  static Motion.Speed pct(double v) {
    return new Motion.Speed(new Motion.SpeedConst(v), Motion.SpeedUnit.PERCENT);
  }

  static Motion.Target p(int n) {
    return new Motion.Local(n, "");
  }

  static Motion.Target pr(int n) {
    return new Motion.Register(Item.of(n));
  }

  /** {@code L P[n] 100mm/sec FINE}. */
  static Instruction.Move lin(int n, Motion.Option... options) {
    return Instruction.Move.of(Motion.Type.L, p(n), mmPerSec(100), new Motion.Fine(), List.of(options));
  }

  /** {@code J P[n] 50% FINE}. */
  static Instruction.Move joint(int n) {
    return Instruction.Move.of(Motion.Type.J, p(n), pct(50), new Motion.Fine(), List.of());
  }

  /** A Cartesian P[n] in UF 0 / UT 0 at x = 100·n mm. */
  static LocalPosition pos(int n) {
    return new LocalPosition(n, "", 0, 0, new Position.Cartesian(100 * n, 0, 300, 180, 0, 0, Config.DEFAULT));
  }

  static Program prog(String name, Instruction... lines) {
    return Program.of(name, List.of(lines));
  }

  static Program progWithPositions(String name, int positions, Instruction... lines) {
    List<LocalPosition> ps = new java.util.ArrayList<>();
    for (int n = 1; n <= positions; n++) {
      ps.add(pos(n));
    }
    return Program.of(name, List.of(lines), ps);
  }
}
