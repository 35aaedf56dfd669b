package org.robotrun.pendant;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.robotrun.pendant.PendantKeys.body;
import static org.robotrun.pendant.PendantKeys.run;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.robotrun.control.RobotControl;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Position;

/**
 * Jogging, POSN, frames, position registers, I/O and alarms through keys, on the real controller
 * (the default cell's LR Mate 200iD). Expected positions and jog travel are worked out by hand in
 * {@link ArmByHand} from the robot file's chain and the documented jog rules, never read from a run.
 */
class PendantMotionAndDataTest {
  private final RobotControl control = RealController.control();
  private final Pendant p = new Pendant(control);

  /** HOME's pointer tip and flange in WORLD, X Y Z W P R (by hand: (385, 0, 185) and (385, 0, 285), facing down). */
  private static final double[] HOME_TCP = ArmByHand.xyzwpr(ArmByHand.tcp(ArmByHand.HOME));
  private static final double[] HOME_FLANGE = ArmByHand.xyzwpr(ArmByHand.flange(ArmByHand.HOME));

  /** One decimal as the pendant shows it, without a minus on zero. */
  private static String oneDecimal(double v) {
    return String.format(Locale.ROOT, "%.1f", Math.abs(v) < 0.05 ? 0.0 : v);
  }

  /** Asserts T1 and 100 % override, which the hand-worked jog figures assume. */
  private void assertT1At100Percent() {
    assertThat(control.mode()).isEqualTo(RobotControl.Mode.T1);
    assertThat(control.overridePct()).isEqualTo(100);
  }

  /** The number after {@code label} on the POSN screen's WORLD rows. */
  private static double posnValue(String body, String section, String axis) {
    String part = body.substring(body.indexOf(section));
    Matcher m = Pattern.compile("\\b" + axis + "\\s+(-?\\d+\\.\\d+)").matcher(part);
    assertThat(m.find()).as(axis + " in " + section).isTrue();
    return Double.parseDouble(m.group(1));
  }

  @Test
  void jogInWorldMovesTheTcpAndPosnShowsIt() {
    assertT1At100Percent();
    run(p, """
        POSN
        COORD *2
        """);
    assertThat(p.lcd().statusLine()).contains("WORLD");
    double x0 = posnValue(body(p), "WORLD", "X");
    double z0 = posnValue(body(p), "WORLD", "Z");
    // POSN shows the pointer's tip at HOME (three decimals)
    assertThat(x0).isCloseTo(HOME_TCP[0], within(0.001));
    assertThat(z0).isCloseTo(HOME_TCP[2], within(0.001));
    // 0.2 s held at 250 mm/s (100 % override) along world +X, then released and left to ramp
    // down: the linear ramp loses as much on the way up as it gives back on the way down, so the
    // TCP covers 250 mm/s × 0.2 s = 50 mm (docs/motion.md), a little less as T1 keeps it at
    // 249..250 mm/s (ArmByHand.worldJogRange)
    double[] moved = ArmByHand.worldJogRange(0.2, true);
    assertThat(moved[1]).isCloseTo(50, within(1e-9));
    run(p, """
        HOLD DEADMAN
        HOLD SHIFT
        HOLD +X
        WAIT 0.2
        RELEASE +X
        WAIT 0.2
        RELEASE SHIFT
        """);
    assertThat(posnValue(body(p), "WORLD", "X")).isBetween(x0 + moved[0] - 0.001, x0 + moved[1] + 0.001);
    assertThat(posnValue(body(p), "WORLD", "Z")).isCloseTo(z0, within(0.01));
    // the orientation is kept in a linear world jog
    assertThat(posnValue(body(p), "WORLD", "W")).isCloseTo(180, within(0.01));
  }

  @Test
  void jogNeedsTpEnableDeadmanAndShiftAndAShiftTapLatchesNothing() {
    assertT1At100Percent();
    // J1 jogs at a quarter of its data-sheet speed, but at HOME the TCP and the flange swing at
    // 385 mm from its axis, so T1's 250 mm/s cap sets the pace once the ramp passes it
    double radius = ArmByHand.radiusFromJ1(ArmByHand.tcp(ArmByHand.HOME));
    assertThat(ArmByHand.radiusFromJ1(ArmByHand.flange(ArmByHand.HOME))).isCloseTo(radius, within(1e-9));
    double[] in02 = ArmByHand.jointJogRange(1, radius, 0.2);
    double[] in01 = ArmByHand.jointJogRange(1, radius, 0.1);
    Position.Joint before = control.currentJoints();
    // SHIFT alone: the DEADMAN is missing
    run(p, """
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.5
        RELEASE +X/J1
        RELEASE SHIFT
        """);
    assertThat(control.currentJoints()).isEqualTo(before);
    assertThat(p.lcd().promptLine()).contains("Hold the DEADMAN");
    // DEADMAN alone: SHIFT is missing
    run(p, """
        HOLD DEADMAN
        HOLD +X/J1
        WAIT 0.5
        RELEASE +X/J1
        """);
    assertThat(control.currentJoints()).isEqualTo(before);
    assertThat(p.lcd().promptLine()).contains("Hold SHIFT");
    // TP disabled: refused with a message, though DEADMAN and SHIFT are held
    run(p, """
        TP OFF
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.5
        RELEASE +X/J1
        RELEASE SHIFT
        TP ON
        """);
    assertThat(control.currentJoints()).isEqualTo(before);
    assertThat(p.message()).isEqualTo("TP enabled");
    run(p, """
        TP OFF
        HOLD SHIFT
        HOLD +X/J1
        """);
    assertThat(p.lcd().promptLine()).contains("TP disabled");
    run(p, """
        RELEASE +X/J1
        RELEASE SHIFT
        TP ON
        """);
    // all three: the arm moves; releasing SHIFT mid-jog stops it
    run(p, """
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.2
        RELEASE SHIFT
        WAIT 0.5
        RELEASE +X/J1
        """);
    // 0.2 s of J1, stopped at once by SHIFT (no ramp down)
    double afterShift = control.currentJoints().j1Deg();
    assertThat(afterShift).isBetween(in02[0], in02[1]);
    assertThat(p.lcd().promptLine()).contains("SHIFT released");
    // a SHIFT tap latches nothing: jogging without holding it does not move the arm
    run(p, """
        SHIFT
        HOLD -X/J1
        WAIT 0.2
        RELEASE -X/J1
        """);
    assertThat(control.currentJoints().j1Deg()).isEqualTo(afterShift);
    assertThat(p.shift()).isFalse();
    // letting the DEADMAN go mid-jog with the TP on: SRVO-003, the arm stops
    run(p, """
        HOLD SHIFT
        HOLD -X/J1
        WAIT 0.1
        RELEASE DEADMAN
        WAIT 0.5
        RELEASE -X/J1
        RELEASE SHIFT
        """);
    // 0.1 s back, stopped at once by the DEADMAN
    double afterDeadman = control.currentJoints().j1Deg();
    assertThat(afterDeadman).isBetween(afterShift - in01[1], afterShift - in01[0]);
    assertThat(p.lcd().alarmLine()).contains("SRVO-003");
    // RESET with the DEADMAN held clears it, and jogging works again
    run(p, """
        HOLD DEADMAN
        RESET
        HOLD SHIFT
        HOLD -X/J1
        WAIT 0.1
        RELEASE -X/J1
        """);
    assertThat(p.lcd().alarmLine()).isBlank();
    // another 0.1 s back (the key's ramp down has had no time yet)
    assertThat(control.currentJoints().j1Deg()).isBetween(afterDeadman - in01[1], afterDeadman - in01[0]);
  }

  @Test
  void latchedJogRunsUntilClickedAgainAndKeysCombine() {
    assertT1At100Percent();
    // WORLD jog travel, stopped at once or ramped down (ArmByHand): 250 mm/s ramped, T1 keeping it at 249..250 mm/s
    double[] x02 = ArmByHand.worldJogRange(0.2, false);
    double[] x02ramped = ArmByHand.worldJogRange(0.2, true);
    // X and Y together: each ramps to 250 mm/s, so the TCP asks for √2 × 250 and T1 caps the diagonal
    double[] diag02 = {ArmByHand.heldThenStopped(Math.sqrt(2) * 250, ArmByHand.T1_LEAST_MM_S, 0.2) / Math.sqrt(2),
        ArmByHand.heldThenStopped(Math.sqrt(2) * 250, ArmByHand.T1_MM_S, 0.2) / Math.sqrt(2)};
    double x0 = HOME_FLANGE[0];
    run(p, """
        HOLD DEADMAN
        COORD *2
        HOLD SHIFT
        CLICK +X
        WAIT 0.2
        """);
    // still latched and moving after 0.2 s
    Position.Cartesian a = control.currentPose(0, 0);
    assertThat(a.xMm()).isBetween(x0 + x02[0], x0 + x02[1]);
    run(p, """
        HOLD DEADMAN
        CLICK +X
        WAIT 0.2
        """);
    // clicked off: it ramps down and stands about 250 mm/s × 0.2 s = 50 mm from the start (the ramp's loss given back)
    double xOff = control.currentPose(0, 0).xMm();
    assertThat(xOff).isBetween(x0 + x02ramped[0], x0 + x02ramped[1]);
    // two held keys of different axes move diagonally
    run(p, """
        HOLD +X
        HOLD +Y
        WAIT 0.2
        RELEASE +X
        RELEASE +Y
        RELEASE SHIFT
        """);
    Position.Cartesian b = control.currentPose(0, 0);
    assertThat(b.xMm()).isBetween(xOff + diag02[0], xOff + diag02[1]);
    assertThat(b.yMm()).isBetween(diag02[0], diag02[1]);
    assertThat(b.xMm() - xOff).isCloseTo(b.yMm(), within(1e-6));
    // a latched axis stops when the deadman goes off
    run(p, """
        HOLD DEADMAN
        HOLD SHIFT
        CLICK -X
        WAIT 0.2
        RELEASE SHIFT
        WAIT 0.2
        """);
    assertThat(control.currentPose(0, 0).xMm()).isBetween(b.xMm() - x02[1], b.xMm() - x02[0]);
    assertThat(p.lcd().promptLine()).contains("SHIFT released");
  }

  @Test
  void overrideStepsFineAtTheBottomAndBigWithShift() {
    run(p, "-% *30");
    // VFINE at the bottom: programs run at 1 %, jogging goes in increments
    assertThat(control.overridePct()).isEqualTo(1);
    assertThat(p.lcd().statusLine()).contains("VFINE");
    run(p, "+%");
    assertThat(p.lcd().statusLine()).contains(" FINE");
    run(p, "+%");
    assertThat(p.lcd().statusLine()).contains("  1%");
    run(p, "+%");
    assertThat(control.overridePct()).isEqualTo(5);
    run(p, "+% *2");
    assertThat(control.overridePct()).isEqualTo(15);
    assertThat(p.lcd().statusLine()).contains(" 15%");
    run(p, "SHIFT++%");
    assertThat(control.overridePct()).isEqualTo(50);
    run(p, "SHIFT++%");
    assertThat(control.overridePct()).isEqualTo(100);
    run(p, "SHIFT+-%");
    assertThat(control.overridePct()).isEqualTo(50);
  }

  @Test
  void coordCyclesJointJgfrmWorldToolUser() {
    StringBuilder seen = new StringBuilder();
    for (int i = 0; i < 5; i++) {
      run(p, "COORD");
      seen.append(p.coord()).append(' ');
    }
    assertThat(seen.toString().trim()).isEqualTo("JGFRM WORLD TOOL USER JOINT");
  }

  @Test
  void teachUserFrameByThreePointsShowsTheResult() {
    run(p, """
        HOLD DEADMAN
        MENU
        5
        F1
        2
        F2
        F2
        1
        DOWN
        SHIFT+F5
        COORD *2
        HOLD SHIFT
        HOLD +X
        WAIT 0.4
        RELEASE +X
        RELEASE SHIFT
        SHIFT+F5
        HOLD SHIFT
        HOLD +Y
        WAIT 0.4
        RELEASE +Y
        RELEASE SHIFT
        SHIFT+F5
        """);
    // origin at the first point (HOME's pointer tip), X toward the second, Y toward the third:
    // world-aligned at the tip
    assertThat(body(p)).contains("Taught: X " + oneDecimal(HOME_TCP[0]) + " Y " + oneDecimal(HOME_TCP[1]) + " Z "
        + oneDecimal(HOME_TCP[2]) + " W 0.0 P 0.0 R 0.0");
    assertThat(p.lcd().promptLine()).contains("User Frame 1 taught");
    Position.Cartesian uf1 = control.frame(FrameKind.USER, 1);
    assertThat(uf1.xMm()).isCloseTo(HOME_TCP[0], within(1e-6));
    assertThat(uf1.yMm()).isCloseTo(HOME_TCP[1], within(1e-6));
    assertThat(uf1.zMm()).isCloseTo(HOME_TCP[2], within(1e-6));
    // MOVE_TO back to the origin point
    run(p, """
        UP *2
        SHIFT+F4
        WAIT 5
        """);
    assertThat(control.currentPose(0, 0).xMm()).isCloseTo(HOME_FLANGE[0], within(1e-6));
    assertThat(control.currentPose(0, 0).zMm()).isCloseTo(HOME_FLANGE[2], within(1e-6));
    // SETIND makes it active; POSN then shows the USER position relative to it
    run(p, """
        PREV
        F5
        POSN
        """);
    assertThat(control.activeFrame(FrameKind.USER)).isEqualTo(1);
    assertThat(body(p)).contains("USER  Frame: 1");
  }

  @Test
  void toolFrameByDirectEntryWithComment() {
    run(p, """
        MENU
        5
        DOWN
        F2
        F2
        4
        ENTER
        TYPE GRIPPER
        ENTER
        DOWN *3
        TYPE 150
        ENTER
        DOWN *2
        TYPE -90
        ENTER
        PREV
        """);
    Position.Cartesian ut2 = control.frame(FrameKind.TOOL, 2);
    assertThat(ut2.zMm()).isEqualTo(150.0);
    assertThat(ut2.pDeg()).isCloseTo(-90, within(1e-9));
    assertThat(control.frameComment(FrameKind.TOOL, 2)).isEqualTo("GRIPPER");
    assertThat(body(p)).contains(" 2     0.0     0.0   150.0    0.0  -90.0    0.0 GRIPPER");
  }

  @Test
  void frameTeachingFailureShowsTheReason() {
    run(p, """
        MENU
        5
        F1
        2
        F2
        F2
        1
        DOWN
        SHIFT+F5
        SHIFT+F5
        SHIFT+F5
        """);
    assertThat(body(p)).contains("Not taught: re-teach the X direction point: it is 0.00 mm from");
  }

  @Test
  void toolFrameThreePointFindsTheTcp() {
    // three flange orientations 30 deg apart around the tip of a TCP at (0, 0, 100) in the flange
    Position.Cartesian tcp = new Position.Cartesian(0, 0, 100, 0, 0, 0, org.robotrun.program.Config.DEFAULT);
    control.setFrame(FrameKind.TOOL, 2, tcp);
    control.selectFrame(FrameKind.TOOL, 2);
    run(p, """
        HOLD DEADMAN
        MENU
        5
        F2
        DOWN
        SHIFT+F5
        COORD *3
        HOLD SHIFT
        HOLD +XR/J4
        WAIT 1.0
        RELEASE +XR/J4
        RELEASE SHIFT
        SHIFT+F5
        HOLD SHIFT
        HOLD +YR/J5
        WAIT 1.0
        RELEASE +YR/J5
        RELEASE SHIFT
        SHIFT+F5
        """);
    // rotations in TOOL coordinates pivot about the TCP, so the pivot fit finds it again
    assertThat(body(p)).contains("Taught: X 0.0 Y 0.0 Z 100.0");
  }

  @Test
  void positionRegisterEditedInJointForm() {
    run(p, """
        DATA
        F1
        2
        SHIFT+F3
        F2
        F5
        2
        """);
    // recorded at HOME
    assertThat(body(p)).contains("JOINT").contains("J1 {     0.000} deg")
        .contains(String.format(Locale.ROOT, "J5 %10.3f deg", ArmByHand.HOME[4]));
    run(p, """
        DOWN
        TYPE 30
        ENTER
        DOWN
        DOWN
        TYPE -12.5
        ENTER
        """);
    assertThat(body(p)).contains("J2     30.000 deg").contains("J4 {   -12.500} deg");
    Position pr1 = control.registers().position(1);
    double[] typed = ArmByHand.HOME.clone();
    typed[1] = 30;
    typed[3] = -12.5;
    Position.Joint expected = new Position.Joint(typed[0], typed[1], typed[2], typed[3], typed[4], typed[5]);
    for (int j = 1; j <= 6; j++) {
      assertThat(pr1.element(j)).as("J" + j).isCloseTo(expected.element(j), within(1e-9));
    }
    // bad number: a message, nothing changed
    run(p, """
        TYPE 1.2.3
        ENTER
        """);
    assertThat(p.lcd().promptLine().strip()).isEqualTo("PR[1] J4 1.2.3: not a number, enter -36000 to 36000 deg");
    assertThat(control.registers().position(1)).isEqualTo(pr1);
    // back to Cartesian through the controller's kinematics
    run(p, """
        F5
        1
        """);
    // the pointer's tip (UT 1) in UF 1 (= WORLD) for those joints, composed by hand
    assertThat(control.registers().position(1)).isInstanceOf(Position.Cartesian.class);
    Position.Cartesian c = (Position.Cartesian) control.registers().position(1);
    double[] want = ArmByHand.xyzwpr(ArmByHand.tcp(typed));
    double[] got = {c.xMm(), c.yMm(), c.zMm(), c.wDeg(), c.pDeg(), c.rDeg()};
    for (int i = 0; i < 6; i++) {
      double d = got[i] - want[i];
      if (i >= 3) {
        d = Math.IEEEremainder(d, 360);
      }
      assertThat(d).as("XYZWPR".charAt(i) + " of " + c).isCloseTo(0, within(1e-6));
    }
  }

  @Test
  void numericRegisterValueAndComment() {
    run(p, """
        DATA
        DOWN *2
        TYPE 42
        ENTER
        LEFT
        ENTER
        TYPE COUNT
        ENTER
        """);
    assertThat(control.registers().number(3)).isEqualTo(42.0);
    assertThat(control.registers().isInteger(3)).isTrue();
    assertThat(body(p)).contains("R[  3:{COUNT       }]  = 42");
  }

  @Test
  void ioOutputsToggleAndInputsAreSimulated() {
    run(p, """
        I/O
        DOWN
        F4
        """);
    assertThat(control.registers().bit(IoKind.DO, 2)).isTrue();
    assertThat(body(p)).contains("DO[ 2]  {ON}");
    run(p, """
        F1
        1
        F4
        """);
    assertThat(control.registers().bit(IoKind.DI, 1)).isTrue();
    assertThat(p.lcd().promptLine()).contains("simulated input");
    run(p, "TOOL1");
    assertThat(control.registers().bit(IoKind.RO, 1)).isTrue();
  }

  @Test
  void aGroupPortTakesANumberFromItsFirstKeypadDigitOrFromTypedText() {
    run(p, """
        I/O
        F1
        6
        7
        0
        ENTER
        """);
    assertThat(control.registers().value(IoKind.GO, 1)).isEqualTo(70);
    assertThat(p.lcd().promptLine()).contains("GO[1]=70");
    run(p, """
        F1
        5
        DOWN
        TYPE 65535
        ENTER
        """);
    assertThat(control.registers().value(IoKind.GI, 2)).isEqualTo(65535);
    assertThat(p.lcd().promptLine()).contains("GI[2]=65535 (simulated input)");
    run(p, """
        TYPE 70000
        ENTER
        """);
    assertThat(control.registers().value(IoKind.GI, 2)).isEqualTo(65535);
    assertThat(p.lcd().promptLine().strip()).isEqualTo("GI[2] 70000: out of range, enter 0 to 65535");
  }

  @Test
  void alarmOnTheTopLineOfEveryScreenUntilReset() {
    run(p, """
        HOLD DEADMAN
        SELECT
        F1
        TYPE BADJMP
        ENTER
        F2
        5
        2
        ITEM
        TYPE 1
        ENTER
        HOLD SHIFT
        FWD
        WAIT 0.1
        RELEASE SHIFT
        """);
    String alarm = p.lcd().alarmLine();
    assertThat(alarm).contains("BADJMP, 1").contains("LBL[1]");
    run(p, "DATA");
    assertThat(p.lcd().alarmLine()).isEqualTo(alarm);
    run(p, "STATUS");
    assertThat(body(p)).contains("ACTIVE:").contains("History:");
    // SHIFT+FWD is refused while the alarm stands
    run(p, """
        HOLD DEADMAN
        EDIT
        HOLD SHIFT
        FWD
        RELEASE SHIFT
        """);
    assertThat(p.lcd().promptLine()).contains("RESET");
    run(p, "RESET");
    assertThat(p.lcd().alarmLine()).isBlank();
    run(p, "STATUS");
    assertThat(body(p)).contains("(BADJMP, 1)").contains("INTP-224");
    // F5 HELP: the detail page of the alarm under the cursor, from the alarm table
    run(p, "F5");
    assertThat(body(p)).contains("INTP-224 (BADJMP, 1)").contains("Severity ABORT: the program is aborted")
        .contains("Cause: JMP LBL[n]").contains("Remedy: Add the LBL[n]");
    run(p, "PREV");
    assertThat(body(p)).contains("History:");
    assertThat(p.screen()).isSameAs(p.alarmScreen);
  }

  @Test
  void frameSelectionWithShiftCoord() {
    run(p, """
        SHIFT+COORD
        1
        TYPE 3
        ENTER
        """);
    assertThat(control.activeFrame(FrameKind.TOOL)).isEqualTo(3);
    // the controller shows the active frames on the POSITION screen and in the COORD message
    run(p, "POSN");
    assertThat(body(p)).contains("Tool: 3");
    run(p, "COORD");
    assertThat(p.lcd().promptLine()).contains("Tool 3");
    run(p, """
        SHIFT+COORD
        2
        TYPE 11
        ENTER
        """);
    assertThat(p.lcd().promptLine()).contains("enter 0 to 10");
  }
}
