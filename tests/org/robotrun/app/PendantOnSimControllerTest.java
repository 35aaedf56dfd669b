package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.program.Instruction;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ControllerPort;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.Simulation;

/**
 * The key-sequence scenarios on the real controller (default cell: HOME, UTOOL 1 a
 * 100 mm pointer, UFRAME 1 = WORLD), read back from the LCD text.
 */
class PendantOnSimControllerTest {
  private final Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
  private final Controller controller = sim.controllers().get(0);
  private final ControllerPort control = new ControllerPort(controller);
  private final org.robotrun.sim.CellStepper stepper = new org.robotrun.sim.CellStepper(sim);
  private final Pendant p = new Pendant(control, new LsLineParser());

  private void keys(String script) {
    KeyScript s = switch (KeyScript.parse("test.keys", script.lines().toList())) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new AssertionError(bad.error().display());
    };
    s.run(p, stepper::advance, text -> { });
  }

  private String body() {
    return String.join("\n", p.lcd().body());
  }

  private void createWithThreePoints() {
    keys("""
        HOLD DEADMAN
        SELECT
        F1
        TYPE PICK1
        ENTER
        SHIFT+F1
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.5
        RELEASE +X/J1
        RELEASE SHIFT
        SHIFT+F1
        HOLD SHIFT
        HOLD +Y/J2
        WAIT 0.5
        RELEASE +Y/J2
        RELEASE SHIFT
        SHIFT+F1
        """);
  }

  @Test
  void startingOnTheLastLineSaysSoFromThePanelAndThePendant() {
    keys("""
        HOLD DEADMAN
        SELECT
        F1
        TYPE PICK1
        ENTER
        SHIFT+F1
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.5
        RELEASE +X/J1
        RELEASE SHIFT
        SHIFT+F1
        RELEASE DEADMAN
        RESET
        TP OFF
        MODE AUTO
        CYCLE START
        """);
    assertThat(p.lcd().promptLine()).contains("the last line of PICK1").contains("line 1");
    keys("""
        WAIT 10
        MODE T1
        TP ON
        HOLD DEADMAN
        UP
        HOLD SHIFT
        FWD
        """);
    // from line 1 it is an ordinary start: no notice
    assertThat(p.lcd().promptLine()).doesNotContain("last line");
    keys("""
        WAIT 10
        RELEASE SHIFT
        HOLD SHIFT
        FWD
        """);
    assertThat(p.lcd().promptLine()).contains("the last line of PICK1");
  }

  @Test
  void aWorldJogToTheEdgeOfReachSaysWhyItStopped() {
    keys("""
        HOLD DEADMAN
        COORD *2
        HOLD SHIFT
        HOLD +X/J1
        WAIT 120
        RELEASE +X/J1
        RELEASE SHIFT
        """);
    assertThat(p.lcd().promptLine()).contains("Jog stopped").containsAnyOf("edge of reach", "singularity", "limit");
  }

  @Test
  void aJogThatRunsIntoAJointLimitSaysSoOnThePromptLineWithAxisAndValue() {
    keys("""
        HOLD DEADMAN
        HOLD SHIFT
        HOLD +X/J1
        WAIT 400
        """);
    assertThat(p.lcd().promptLine()).contains("Jog stopped").contains("J1").contains("upper limit").contains("deg");
    keys("""
        RELEASE +X/J1
        HOLD +X/J1
        WAIT 1
        RELEASE +X/J1
        RELEASE SHIFT
        """);
    // pressing into the limit again says it again rather than leaving the line blank
    assertThat(p.lcd().promptLine()).contains("upper limit");
  }

  @Test
  void aBwdNoticeLeavesThePromptLineWithTheNextCommandButAnAlarmStaysUntilReset() {
    keys("""
        HOLD DEADMAN
        SELECT
        F1
        TYPE BACK
        ENTER
        SHIFT+F1
        HOLD SHIFT
        HOLD +X/J1
        WAIT 0.5
        RELEASE +X/J1
        RELEASE SHIFT
        SHIFT+F1
        UP
        HOLD SHIFT
        BWD
        RELEASE SHIFT
        """);
    assertThat(p.lcd().promptLine()).contains("BWD: top of program");
    // the student moves on: SHIFT+FWD runs line 1 and says nothing about BWD
    keys("""
        HOLD DEADMAN
        STEP
        HOLD SHIFT
        FWD
        WAIT 3
        RELEASE SHIFT
        """);
    assertThat(p.lcd().statusLine()).contains("LINE 2");
    assertThat(p.lcd().promptLine()).doesNotContain("BWD");
    keys("HOLD DEADMAN\nSHIFT+BWD");
    assertThat(p.lcd().promptLine()).contains("BWD");
    keys("DOWN");
    assertThat(p.lcd().promptLine()).isBlank();

    // an alarm is not a prompt-line message: it stays on its line through other keys until RESET
    keys("""
        HOLD DEADMAN
        FCTN
        1
        STEP
        F2
        5
        2
        ITEM
        TYPE 1
        ENTER
        HOLD SHIFT
        FWD
        WAIT 0.5
        RELEASE SHIFT
        """);
    String alarm = p.lcd().alarmLine();
    assertThat(alarm).contains("LBL[1]");
    keys("""
        DOWN
        DATA
        EDIT
        """);
    assertThat(p.lcd().alarmLine()).isEqualTo(alarm);
    keys("RESET");
    assertThat(p.lcd().alarmLine()).isBlank();
  }

  @Test
  void createRecordEditInsertRunAndStepBack() {
    createWithThreePoints();
    keys("""
        UP
        RIGHT
        ENTER
        2
        RIGHT *2
        TYPE 200
        ENTER
        RIGHT *2
        TYPE 50
        ENTER
        DOWN *2
        F2
        1
        2
        DOWN
        F2
        3
        1
        TYPE R[1]>5
        ENTER
        """);
    assertThat(body()).contains("L P[2] 200mm/sec CNT50").contains("4:  R[1]=R[1]+1").contains("IF {R[1]>5},JMP LBL[1]");
    Position.Cartesian p3 = (Position.Cartesian) control.program("PICK1").orElseThrow().position(3).orElseThrow().position();
    keys("""
        HOLD DEADMAN
        ITEM
        TYPE 1
        ENTER
        HOLD SHIFT
        FWD
        WAIT 0.2
        """);
    assertThat(p.lcd().statusLine()).contains("RUNNING");
    keys("WAIT 10\nRELEASE SHIFT");
    // after END: the program's last line, ABORTED, as a controller shows it
    assertThat(p.lcd().statusLine()).contains("LINE 5").contains("ABORTED");
    assertThat(p.lcd().alarmLine()).isBlank();
    assertThat(control.registers().number(1)).isEqualTo(1.0);
    Position.Cartesian here = control.currentPose(1, 1);
    assertThat(here.xMm()).isCloseTo(p3.xMm(), within(0.01));
    assertThat(here.yMm()).isCloseTo(p3.yMm(), within(0.01));

    // SHIFT+BWD from line 4 backs out of line 3: the robot returns to P[2]
    Position.Cartesian p2 = (Position.Cartesian) control.program("PICK1").orElseThrow().position(2).orElseThrow().position();
    keys("""
        HOLD DEADMAN
        ITEM
        TYPE 4
        ENTER
        HOLD SHIFT
        BWD
        WAIT 10
        RELEASE SHIFT
        """);
    here = control.currentPose(1, 1);
    assertThat(here.xMm()).isCloseTo(p2.xMm(), within(0.01));
    assertThat(here.yMm()).isCloseTo(p2.yMm(), within(0.01));
    assertThat(p.lcd().cursorRow().orElseThrow()).contains("3:");
  }

  @Test
  void teachUserFrameByThreePoints() {
    keys("""
        HOLD DEADMAN
        MENU
        5
        F1
        2
        DOWN
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
        """);
    Position.Cartesian yPoint = control.currentPose(0, 1);
    keys("SHIFT+F5");
    assertThat(p.lcd().promptLine()).contains("User Frame 2 taught");
    // origin at the first point (the TCP there), X along world X: the frame is world-aligned
    Position.Cartesian uf2 = control.frame(FrameKind.USER, 2);
    assertThat(uf2.wDeg()).isCloseTo(0, within(0.05));
    assertThat(uf2.pDeg()).isCloseTo(0, within(0.05));
    assertThat(uf2.rDeg()).isCloseTo(0, within(0.05));
    assertThat(uf2.zMm()).isCloseTo(yPoint.zMm(), within(0.05));
    assertThat(body()).contains(String.format(Locale.ROOT, "Taught: X %.1f", uf2.xMm())).contains("W 0.0 P 0.0 R 0.0");
  }

  @Test
  void teachToolFrameByThreePointsAroundThePointerTip() {
    // rotations in TOOL coordinates pivot about the active pointer's tip (UTOOL 1, 100 mm):
    // three approaches of that tip teach UTOOL 2 = the same TCP, with the robot's own FrameTeaching
    keys("""
        HOLD DEADMAN
        MENU
        5
        DOWN
        F2
        F2
        1
        DOWN
        SHIFT+F5
        COORD *3
        HOLD SHIFT
        HOLD +XR
        WAIT 1.5
        RELEASE +XR
        RELEASE SHIFT
        SHIFT+F5
        HOLD SHIFT
        HOLD +YR
        WAIT 1.5
        RELEASE +YR
        RELEASE SHIFT
        SHIFT+F5
        """);
    assertThat(p.lcd().promptLine()).contains("Tool Frame 2 taught");
    Position.Cartesian ut2 = control.frame(FrameKind.TOOL, 2);
    assertThat(ut2.xMm()).isCloseTo(0, within(0.05));
    assertThat(ut2.yMm()).isCloseTo(0, within(0.05));
    assertThat(ut2.zMm()).isCloseTo(100, within(0.05));
    assertThat(body()).contains("Taught: X 0.0 Y 0.0 Z 100.0");
    // UTOOL 3 from three approaches in one orientation: the reason is shown, the frame unchanged
    keys("""
        F3
        TYPE 3
        ENTER
        F2
        1
        DOWN
        SHIFT+F5
        SHIFT+F5
        SHIFT+F5
        """);
    assertThat(p.lcd().row(2)).contains("Tool Frame 3");
    assertThat(body()).contains("Not taught:");
    assertThat(p.lcd().promptLine()).startsWith("Frame not taught:");
    assertThat(control.frame(FrameKind.TOOL, 3).zMm()).isEqualTo(0.0);
  }

  @Test
  void positionRegisterInJointForm() {
    keys("""
        DATA
        F1
        2
        SHIFT+F3
        F2
        F5
        2
        DOWN
        TYPE 30
        ENTER
        """);
    Position pr = control.registers().position(1);
    assertThat(pr).isInstanceOf(Position.Joint.class);
    assertThat(pr.element(2)).isEqualTo(30.0);
    assertThat(pr.element(5)).isCloseTo(-90, within(1e-6));
    assertThat(body()).contains("J2 {    30.000} deg").contains("J5    -90.000 deg");
  }

  @Test
  void jogInWorldChangesPosn() {
    keys("""
        POSN
        COORD *2
        """);
    double x0 = control.currentPose(0, 1).xMm();
    double z0 = control.currentPose(0, 1).zMm();
    String before = body();
    keys("""
        HOLD DEADMAN
        HOLD SHIFT
        HOLD +X
        WAIT 0.5
        RELEASE +X
        RELEASE SHIFT
        WAIT 0.5
        """);
    Position.Cartesian after = control.currentPose(0, 1);
    assertThat(after.xMm()).isGreaterThan(x0 + 10);
    assertThat(after.zMm()).isCloseTo(z0, within(0.1));
    assertThat(body()).isNotEqualTo(before).contains(String.format(Locale.ROOT, "X %9.3f mm", after.xMm()));
  }

  @Test
  void alarmOnTopLineClearedByReset() {
    keys("""
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
    assertThat(p.lcd().alarmLine()).contains("(BADJMP, 1)").contains("LBL[1]");
    keys("POSN");
    assertThat(p.lcd().alarmLine()).contains("(BADJMP, 1)");
    keys("RESET");
    assertThat(p.lcd().alarmLine()).isBlank();
  }

  @Test
  void randomKeysOnTheRealControllerNeverThrow() {
    org.robotrun.pendant.Key[] all = org.robotrun.pendant.Key.values();
    java.util.Random rnd = new java.util.Random(7);
    keys("""
        SELECT
        F1
        TYPE FUZZ
        ENTER
        SHIFT+F1
        """);
    org.assertj.core.api.Assertions.assertThatCode(() -> {
      for (int i = 0; i < 1500; i++) {
        int what = rnd.nextInt(16);
        if (what == 0) {
          p.type(List.of("1", "R[2]+1", "abc", "-5", "PR[1]", "200", "FUZZ").get(rnd.nextInt(7)));
        } else if (what == 1) {
          org.robotrun.pendant.KeyScript.advance(p, stepper::advance, rnd.nextDouble() * 0.2);
        } else if (what == 2) {
          p.press(org.robotrun.pendant.Key.SHIFT);
        } else if (what == 3) {
          p.release(org.robotrun.pendant.Key.SHIFT);
        } else {
          org.robotrun.pendant.Key k = all[rnd.nextInt(all.length)];
          p.press(k);
          p.release(k);
        }
        p.lcd();
      }
    }).doesNotThrowAnyException();
  }

  /**
   * Random keys steered so that the arm really moves and a program really runs (issue 31): bursts of
   * SHIFT + a jog key held for a while, SHIFT+F1 to record points, SHIFT+FWD held to run the program
   * from its top, RESET, COORD, STEP, override keys, typed text, and any key at all, with DEADMAN
   * held again soon after a random key lets go of it. Checked on every step: no exception, every joint
   * finite and inside its limits, every alarm one of the alarm table's codes; at the end: the TCP moved
   * at least 100 mm from where it started, the program ran (its state was RUNNING and a motion line
   * of it finished), and both happened more than once.
   */
  @Test
  void steeredRandomKeysMoveTheArmRunAProgramAndKeepEveryInvariant() {
    org.robotrun.pendant.Key[] all = org.robotrun.pendant.Key.values();
    org.robotrun.pendant.Key[] jogs = java.util.Arrays.stream(all).filter(org.robotrun.pendant.Key::isJog)
        .toArray(org.robotrun.pendant.Key[]::new);
    org.robotrun.robot.RobotModel model = controller.model();
    java.util.Random rnd = new java.util.Random(7);
    keys("""
        SELECT
        F1
        TYPE FUZZ
        ENTER
        HOLD DEADMAN
        """);
    org.robotrun.math.Vec3 start = controller.tcpInWorld().position();
    double farthest = 0;
    int runningTicks = 0;
    int runs = 0;
    int records = 0;
    int runsThatMoved = 0;
    java.util.Set<String> codes = new java.util.TreeSet<>();
    for (int i = 0; i < 500; i++) {
      int what = rnd.nextInt(100);
      if (what < 30) { // jog burst
        org.robotrun.pendant.Key k = jogs[rnd.nextInt(jogs.length)];
        p.press(org.robotrun.pendant.Key.SHIFT);
        p.press(k);
        for (int t = rnd.nextInt(6) + 1; t > 0; t--) {
          org.robotrun.pendant.KeyScript.advance(p, stepper::advance, 0.05);
        }
        p.release(k);
        p.release(org.robotrun.pendant.Key.SHIFT);
      } else if (what < 40) { // record a point: SHIFT+F1 in the editor
        p.press(org.robotrun.pendant.Key.EDIT);
        p.release(org.robotrun.pendant.Key.EDIT);
        p.press(org.robotrun.pendant.Key.SHIFT);
        p.press(org.robotrun.pendant.Key.F1);
        p.release(org.robotrun.pendant.Key.F1);
        p.release(org.robotrun.pendant.Key.SHIFT);
        records++;
      } else if (what < 50) { // run from the top: SHIFT held, FWD, time passes
        keys("EDIT\nITEM\nTYPE 1\nENTER");
        p.press(org.robotrun.pendant.Key.SHIFT);
        p.press(org.robotrun.pendant.Key.FWD);
        p.release(org.robotrun.pendant.Key.FWD);
        for (int t = rnd.nextInt(20) + 5; t > 0; t--) {
          org.robotrun.pendant.KeyScript.advance(p, stepper::advance, 0.05);
          if (controller.status().state() == org.robotrun.sim.ExecutionStatus.State.RUNNING) {
            runningTicks++;
          }
        }
        p.release(org.robotrun.pendant.Key.SHIFT);
        runs++;
        if (controller.motionTimings().stream().anyMatch(m -> m.program().equals("FUZZ"))) {
          runsThatMoved++;
        }
      } else if (what < 56) {
        p.press(org.robotrun.pendant.Key.RESET);
        p.release(org.robotrun.pendant.Key.RESET);
      } else if (what < 60) {
        org.robotrun.pendant.Key k = List.of(org.robotrun.pendant.Key.COORD, org.robotrun.pendant.Key.STEP,
            org.robotrun.pendant.Key.OVERRIDE_UP, org.robotrun.pendant.Key.OVERRIDE_DOWN).get(rnd.nextInt(4));
        p.press(k);
        p.release(k);
      } else if (what < 63) {
        p.type(List.of("1", "R[2]+1", "abc", "-5", "PR[1]", "200", "FUZZ").get(rnd.nextInt(7)));
      } else if (what < 66) {
        org.robotrun.pendant.KeyScript.advance(p, stepper::advance, rnd.nextDouble() * 0.2);
      } else { // any key at all
        org.robotrun.pendant.Key k = all[rnd.nextInt(all.length)];
        p.press(k);
        p.release(k);
      }
      if (!p.deadmanHeld() && rnd.nextInt(3) == 0) {
        p.press(org.robotrun.pendant.Key.DEADMAN);
      }
      p.lcd();
      double[] q = controller.jointsRad();
      for (int j = 0; j < q.length; j++) {
        assertThat(Double.isFinite(q[j])).as("J%d finite at step %d", j + 1, i).isTrue();
        assertThat(q[j]).as("J%d inside its limits at step %d", j + 1, i)
            .isBetween(model.joint(j).lowerRad() - 1e-9, model.joint(j).upperRad() + 1e-9);
      }
      for (var a : controller.alarmHistory()) {
        codes.add(a.code());
      }
      farthest = Math.max(farthest, controller.tcpInWorld().position().distanceTo(start));
    }
    assertThat(codes).as("alarm codes raised").allSatisfy(c ->
        assertThat(org.robotrun.program.AlarmCode.of(c)).as("%s is in the alarm table", c).isPresent());
    assertThat(farthest).as("the TCP moved away from where it started (mm)").isGreaterThan(100);
    assertThat(records).isGreaterThan(5);
    assertThat(runs).isGreaterThan(5);
    assertThat(runningTicks).as("steps in which the program was RUNNING").isGreaterThan(20);
    assertThat(runsThatMoved).as("runs in which a motion line of the program finished").isGreaterThan(2);
  }

  @Test
  void uncommentUsesTheLsReaderForLinesFromFiles() {
    controller.saveProgram(org.robotrun.program.Program.of("FROMFILE", List.of(new Instruction.CommentedOut("R[2]=R[2]*3"))));
    keys("""
        SELECT
        ENTER
        NEXT
        F5
        """);
    assertThat(control.program("FROMFILE").orElseThrow().line(1)).isInstanceOf(Instruction.AssignRegister.class);
    assertThat(body()).contains("R[2]=R[2]*3").doesNotContain("//");
  }
}
