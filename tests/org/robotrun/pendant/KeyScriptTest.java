package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;

class KeyScriptTest {

  private static KeyScript.Parsed parse(String text) {
    return KeyScript.parse("t.keys", text.lines().toList());
  }

  @Test
  void parsesEveryLineForm() {
    KeyScript.Parsed r = parse("""
        # a comment

        SHIFT+F1
        ENTER
        DOWN *3
        TYPE Pick 1
        HOLD SHIFT
        HOLD +X
        RELEASE +X
        RELEASE SHIFT
        HOLD
        WAIT 2.5
        SHOW
        I/O
        +%
        J6-
        CLICK -Y
        """);
    assertThat(r).isInstanceOf(KeyScript.Parsed.Ok.class);
    List<KeyScript.Step> s = ((KeyScript.Parsed.Ok) r).script().steps();
    assertThat(s).containsExactly(
        new KeyScript.Step.Tap(3, Key.F1, true, 1),
        new KeyScript.Step.Tap(4, Key.ENTER, false, 1),
        new KeyScript.Step.Tap(5, Key.DOWN, false, 3),
        new KeyScript.Step.Type(6, "Pick 1"),
        new KeyScript.Step.Press(7, Key.SHIFT),
        new KeyScript.Step.Press(8, Key.JOG_PLUS_1),
        new KeyScript.Step.Release(9, Key.JOG_PLUS_1),
        new KeyScript.Step.Release(10, Key.SHIFT),
        new KeyScript.Step.Tap(11, Key.HOLD, false, 1),
        new KeyScript.Step.Wait(12, 2.5),
        new KeyScript.Step.Show(13),
        new KeyScript.Step.Tap(14, Key.IO, false, 1),
        new KeyScript.Step.Tap(15, Key.OVERRIDE_UP, false, 1),
        new KeyScript.Step.Tap(16, Key.JOG_MINUS_6, false, 1),
        new KeyScript.Step.Click(17, Key.JOG_MINUS_2));
  }

  @Test
  void parsesTheSafetyLines() {
    KeyScript.Parsed r = parse("""
        TP OFF
        tp on
        HOLD DEADMAN
        RELEASE DEADMAN
        MODE AUTO
        mode t2
        ESTOP
        ESTOP PANEL
        RELEASE ESTOP
        CYCLE START
        """);
    assertThat(r).isInstanceOf(KeyScript.Parsed.Ok.class);
    assertThat(((KeyScript.Parsed.Ok) r).script().steps()).containsExactly(
        new KeyScript.Step.TpSwitch(1, false),
        new KeyScript.Step.TpSwitch(2, true),
        new KeyScript.Step.Press(3, Key.DEADMAN),
        new KeyScript.Step.Release(4, Key.DEADMAN),
        new KeyScript.Step.Mode(5, RobotControl.Mode.AUTO),
        new KeyScript.Step.Mode(6, RobotControl.Mode.T2),
        new KeyScript.Step.Estop(7, true),
        new KeyScript.Step.Estop(8, false),
        new KeyScript.Step.ReleaseEstop(9),
        new KeyScript.Step.CycleStart(10));
    assertThat(bad("TP MAYBE")).isEqualTo("t.keys:1: TP needs ON or OFF, got 'MAYBE'");
    assertThat(bad("MODE T3")).isEqualTo("t.keys:1: MODE needs T1, T2 or AUTO, got 'T3'");
    assertThat(bad("ESTOP DOOR")).startsWith("t.keys:1: ESTOP takes nothing");
    assertThat(bad("CYCLE STOP")).isEqualTo("t.keys:1: did you mean CYCLE START? got 'CYCLE STOP'");
  }

  @Test
  void malformedLinesNameFileAndLine() {
    assertThat(bad("ENTER\nFROB\n")).isEqualTo("t.keys:2: unknown key or command 'FROB' (keys: F1..F5, ENTER, SHIFT+FWD, "
        + "+X/J1...; commands: TYPE, HOLD, RELEASE, CLICK, TP, MODE, ESTOP, CYCLE START, ROBOT, UI[i] ON/OFF, DI[i] ON/OFF, "
        + "WAIT, SHOW)");
    assertThat(bad("UI[19] ON")).isEqualTo("t.keys:1: UI[19]: index out of range (expected 1..18)");
    assertThat(bad("WAIT soon")).isEqualTo("t.keys:1: WAIT needs seconds (e.g. WAIT 2.5), got 'soon'");
    assertThat(bad("WAIT -1")).startsWith("t.keys:1: WAIT seconds must be 0..3600");
    assertThat(bad("\n\nTYPE")).isEqualTo("t.keys:3: TYPE needs the text to type");
    assertThat(bad("RELEASE")).isEqualTo("t.keys:1: RELEASE needs a key name");
    assertThat(bad("HOLD NOPE")).isEqualTo("t.keys:1: unknown key 'NOPE'");
    assertThat(bad("DOWN *x")).isEqualTo("t.keys:1: repeat count after * must be a whole number");
    assertThat(bad("SHOW now")).isEqualTo("t.keys:1: SHOW takes nothing after it");
  }

  @Test
  void plcInputLinesSetTheInputOnTheController() {
    KeyScript s = ((KeyScript.Parsed.Ok) parse("UI[6] ON\ndi[3] on\nUI[6] OFF\nUI[8] ON\n")).script();
    assertThat(s.steps()).containsExactly(new KeyScript.Step.Input(1, org.robotrun.program.IoKind.UI, 6, true),
        new KeyScript.Step.Input(2, org.robotrun.program.IoKind.DI, 3, true),
        new KeyScript.Step.Input(3, org.robotrun.program.IoKind.UI, 6, false),
        new KeyScript.Step.Input(4, org.robotrun.program.IoKind.UI, 8, true));
    Pendant p = new Pendant(RealController.control());
    s.run(p, PendantKeys.clock(p), x -> {});
    assertThat(p.control().registers().bit(org.robotrun.program.IoKind.UI, 6)).isFalse();
    assertThat(p.control().registers().bit(org.robotrun.program.IoKind.UI, 8)).isTrue();
    assertThat(p.control().registers().bit(org.robotrun.program.IoKind.DI, 3)).isTrue();
  }

  private static String bad(String text) {
    return ((KeyScript.Parsed.Bad) parse(text)).error().display();
  }

  @Test
  void showPrintsTheLcdWithTime() {
    KeyScript s = ((KeyScript.Parsed.Ok) parse("WAIT 0.5\nSHOW\n")).script();
    StringBuilder out = new StringBuilder();
    Pendant p = new Pendant(RealController.control());
    s.run(p, PendantKeys.clock(p), out::append);
    assertThat(out.toString()).startsWith("-- SHOW (line 2, t=0.500 s) --").contains("SELECT");
    assertThat(out.toString().lines().filter(l -> l.startsWith("|"))).hasSize(Lcd.HEIGHT);
  }
}
