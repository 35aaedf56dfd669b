package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.Instruction;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Motion;
import org.robotrun.program.Position;
import org.robotrun.program.Program;

/** No key sequence makes the pendant throw: user errors end on the prompt line. */
class PendantRobustnessTest {
  private static final List<String> WORDS = List.of("PICK", "1", "R[2]+1", "abc", "-5", "P[3]", "LBL[2]", "(R[1]>2)",
      "CNT R[1]", "L", "", "200", "DO[1]=ON", "1.2.3", "99999999999", "'x'", "R[R[1]]", "PR[1,2]");

  @Test
  void randomKeysNeverThrowAndTheLcdStaysWellFormed() {
    Key[] keys = Key.values();
    for (long seed = 1; seed <= 4; seed++) {
      Random rnd = new Random(seed);
      RobotControl control = RealController.control();
      control.saveProgram(sample());
      Pendant p = new Pendant(control);
      p.tap(Key.SELECT);
      p.tap(Key.ENTER);
      long s = seed;
      assertThatCode(() -> {
        for (int i = 0; i < 2000; i++) {
          int what = rnd.nextInt(20);
          if (what == 0) {
            p.type(WORDS.get(rnd.nextInt(WORDS.size())));
          } else if (what == 1) {
            PendantKeys.advance(p, rnd.nextDouble() * 0.3);
          } else if (what == 2) {
            p.press(Key.SHIFT);
          } else if (what == 3) {
            p.release(Key.SHIFT);
          } else {
            Key k = keys[rnd.nextInt(keys.length)];
            p.press(k);
            if (rnd.nextInt(4) > 0) {
              p.release(k);
            }
          }
          Lcd lcd = p.lcd();
          assertThat(lcd.rows()).hasSize(Lcd.HEIGHT).allMatch(r -> r.length() == Lcd.WIDTH);
        }
      }).as("seed " + s).doesNotThrowAnyException();
    }
  }

  @Test
  void randomEditingKeysNeverThrow() {
    Key[] keys = {Key.UP, Key.DOWN, Key.LEFT, Key.RIGHT, Key.ENTER, Key.F1, Key.F2, Key.F3, Key.F4, Key.F5, Key.NEXT,
        Key.PREV, Key.ITEM, Key.D1, Key.D2, Key.D3, Key.D5, Key.D9, Key.MINUS, Key.DOT, Key.BACKSPACE, Key.EDIT};
    for (long seed = 100; seed < 104; seed++) {
      Random rnd = new Random(seed);
      RobotControl control = RealController.control();
      control.saveProgram(sample());
      Pendant p = new Pendant(control);
      p.tap(Key.SELECT);
      p.tap(Key.ENTER);
      long s = seed;
      assertThatCode(() -> {
        for (int i = 0; i < 2000; i++) {
          int what = rnd.nextInt(12);
          if (what == 0) {
            p.type(WORDS.get(rnd.nextInt(WORDS.size())));
          } else if (what == 1) {
            p.press(Key.SHIFT);
            p.tap(keys[rnd.nextInt(keys.length)]);
            p.release(Key.SHIFT);
          } else {
            p.tap(keys[rnd.nextInt(keys.length)]);
          }
          p.lcd();
        }
      }).as("seed " + s).doesNotThrowAnyException();
    }
  }

  private static Program sample() {
    Motion.Speed pct = new Motion.Speed(new Motion.SpeedConst(50), Motion.SpeedUnit.PERCENT);
    List<Instruction> lines = List.of(
        Instruction.Move.of(Motion.Type.J, new Motion.Local(1, ""), pct, new Motion.Fine(), List.of()),
        new Instruction.Label(1, "LOOP"),
        Instruction.Move.of(Motion.Type.J, new Motion.Local(2, ""), pct, new Motion.Cnt(50), List.of()),
        new Instruction.Jump(org.robotrun.program.LabelRef.of(1)));
    return Program.of("SAMPLE", lines, List.of(
        new LocalPosition(1, "", 0, 0, new Position.Joint(0, 0, 0, 0, 0, 0)),
        new LocalPosition(2, "", 0, 0, new Position.Joint(20, 10, 0, 0, 0, 0))));
  }
}
