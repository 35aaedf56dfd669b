package org.robotrun.program;

import static org.assertj.core.api.Assertions.assertThat;
import static org.robotrun.program.Tp.endFor;
import static org.robotrun.program.Tp.forUp;
import static org.robotrun.program.Tp.lin;
import static org.robotrun.program.Tp.num;
import static org.robotrun.program.Tp.op;
import static org.robotrun.program.Tp.progWithPositions;
import static org.robotrun.program.Tp.r;
import static org.robotrun.program.Tp.setR;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** A paused program edited in the store goes on in the edited code (Interpreter.reload, LineMap). */
class InterpreterEditTest {
  private static final double TICK = 0.004;

  private final Map<String, Program> store = new HashMap<>();
  private final Registers regs = new Registers();
  private final FakeMotionPort port = new FakeMotionPort(1.0);
  private final Interpreter in = new Interpreter(n -> Optional.ofNullable(store.get(n)), regs, port,
      InterpreterSettings.defaults());

  private void save(Program p) {
    store.put(p.name(), p);
  }

  private Outcome ticks(int n) {
    Outcome o = null;
    for (int i = 0; i < n; i++) {
      port.advance(TICK);
      o = in.tick(TICK);
    }
    return o;
  }

  private Outcome runToEnd() {
    in.forward();
    Outcome o = ticks(1);
    for (int i = 0; i < 10_000 && !(o instanceof Outcome.Finished || o instanceof Outcome.Alarmed
        || o instanceof Outcome.Paused); i++) {
      o = ticks(1);
    }
    return o;
  }

  private static Program withLines(Program p, Instruction... lines) {
    return new Program(p.name(), p.attributes(), p.comment(), List.of(lines), p.positions());
  }

  /** MAIN: L P[1], L P[2]; held half-way along P[2] (line 2). */
  private Program heldOnLine2() {
    Program main = progWithPositions("MAIN", 3, lin(1), lin(2));
    save(main);
    in.select("MAIN");
    in.forward();
    ticks(300); // P[1] takes 1 s
    ticks(100);
    assertThat(in.cursorLine()).isEqualTo(2);
    in.hold();
    assertThat(port.requests()).hasSize(2);
    return main;
  }

  @Test
  void aHeldMotionWhoseLineIsUntouchedStaysHeldAndResumesWhereItStopped() {
    Program main = heldOnLine2();
    save(withLines(main, setR(1, num(7)), lin(1), lin(2)));
    in.reload();
    assertThat(in.cursorLine()).isEqualTo(3);
    assertThat(port.cancelled()).isEmpty();
    assertThat(runToEnd()).isInstanceOf(Outcome.Finished.class);
    // the held motion went on (no new request); the line inserted above did not run
    assertThat(port.requests()).hasSize(2);
    assertThat(regs.number(1)).isZero();
  }

  @Test
  void aHeldMotionWhoseLineWasEditedRunsTheEditedLineFromWhereTheRobotStands() {
    heldOnLine2();
    save(progWithPositions("MAIN", 3, lin(1), lin(3)));
    assertThat(runToEnd()).isInstanceOf(Outcome.Finished.class);
    assertThat(port.cancelled()).hasSize(1);
    assertThat(port.requests()).hasSize(3);
    MotionRequest again = port.requests().get(2);
    assertThat(again.line()).isEqualTo(2);
    assertThat(again.target().name()).isEqualTo("P[3]");
  }

  @Test
  void aTouchedUpPositionOfTheHeldLineIsRunAgainWithTheNewPosition() {
    Program main = heldOnLine2();
    Map<Integer, LocalPosition> ps = new HashMap<>(main.positions());
    LocalPosition moved = new LocalPosition(2, "", 0, 0, new Position.Cartesian(250, 50, 300, 180, 0, 0, Config.DEFAULT));
    ps.put(2, moved);
    save(new Program("MAIN", main.attributes(), main.comment(), main.lines(), ps));
    assertThat(runToEnd()).isInstanceOf(Outcome.Finished.class);
    assertThat(port.requests()).hasSize(3);
    assertThat(port.requests().get(2).target().position()).isEqualTo(moved.position());
  }

  @Test
  void deletingThePausedLastLineEndsTheProgram() {
    Program main = Tp.prog("MAIN", setR(1, num(1)), setR(2, num(2)));
    save(main);
    in.select("MAIN");
    in.setStepMode(true);
    in.forward();
    ticks(1);
    assertThat(in.cursorLine()).isEqualTo(2);
    save(withLines(main, setR(1, num(1))));
    in.setStepMode(false);
    assertThat(runToEnd()).isInstanceOf(Outcome.Finished.class);
    assertThat(regs.number(2)).isZero();
  }

  @Test
  void aRunningForLoopSurvivesAnEditAboveIt() {
    Program main = Tp.prog("MAIN", forUp(1, num(1), num(3)), setR(2, op(r(2), Expr.BinaryOp.ADD, num(1))), endFor());
    save(main);
    in.select("MAIN");
    in.setStepMode(true);
    in.forward();
    ticks(1);
    in.forward();
    ticks(1);
    assertThat(in.cursorLine()).isEqualTo(3);
    List<Instruction> lines = new ArrayList<>(main.lines());
    lines.add(0, Tp.comment("inserted"));
    save(withLines(main, lines.toArray(Instruction[]::new)));
    in.setStepMode(false);
    assertThat(runToEnd()).isInstanceOf(Outcome.Finished.class);
    assertThat(regs.number(2)).isEqualTo(3);
  }

  @Test
  void anEditThatBreaksTheBlockStructureAlarmsOnResume() {
    Program main = Tp.prog("MAIN", setR(1, num(1)), forUp(2, num(1), num(3)), setR(3, num(1)), endFor());
    save(main);
    in.select("MAIN");
    in.setStepMode(true);
    in.forward();
    ticks(1);
    save(withLines(main, setR(1, num(1)), forUp(2, num(1), num(3)), setR(3, num(1))));
    Outcome o = runToEnd();
    assertThat(o).isInstanceOf(Outcome.Alarmed.class);
    assertThat(((Outcome.Alarmed) o).alarm().kind()).isEqualTo(AlarmKind.STRUCTURE);
  }

  @Test
  void lineMapMatchesUntouchedLinesAndPlacesChangedOnesAtTheirReplacement() {
    List<Instruction> before = List.of(setR(1, num(1)), setR(2, num(2)), setR(3, num(3)), setR(4, num(4)));
    // line 1 deleted, line 3 changed, a line inserted before line 4
    List<Instruction> after = List.of(setR(2, num(2)), setR(3, num(30)), setR(9, num(9)), setR(4, num(4)));
    LineMap m = LineMap.between(before, after);
    assertThat(new int[] {m.kept(0), m.kept(1), m.kept(2), m.kept(3)}).containsExactly(-1, 0, -1, 3);
    assertThat(m.position(0)).isZero();
    assertThat(m.position(2)).isEqualTo(1);
    assertThat(m.position(4)).isEqualTo(4);
    assertThat(m.returnPoint(2)).isEqualTo(1);
    assertThat(m.returnPoint(3)).isEqualTo(3);
  }
}
