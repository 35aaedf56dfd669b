package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.robotrun.control.RobotControl.CoordSystem;
import org.robotrun.control.RobotControl.ExecState;
import org.robotrun.control.RobotControl.Mode;
import org.robotrun.control.RobotControl.Result;
import org.robotrun.control.RobotControl.StartFrom;
import org.robotrun.control.RobotControl.TeachMethod;
import org.robotrun.control.RobotControl.TeachResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;

/**
 * The controller port's switch decisions as a truth table (issue 31), each expected answer from
 * the R-30iB's rules as control.RobotControl documents them, never from a run:
 * <ul>
 *   <li>a jog (held key or FINE step) goes only in T1/T2 with TP ENABLE on, no E-stop, DEADMAN
 *       and SHIFT held;</li>
 *   <li>SHIFT+FWD/BWD starts a program under the same five conditions;</li>
 *   <li>CYCLE START on the operator panel starts one only in AUTO with the TP disabled and no
 *       E-stop;</li>
 *   <li>T1 and T2 are hold-to-run: letting SHIFT, the DEADMAN or TP ENABLE go, or turning the mode
 *       switch, pauses a running program; AUTO is not;</li>
 *   <li>the override is 1..100 %.</li>
 * </ul>
 * All 3 × 2⁴ switch settings are tried.
 */
class ControllerPortSwitchTableTest {

  private static final String WAITS = "/PROG  WAITS\n/ATTR\n/MN\n   1:  WAIT   1.00(sec) ;\n   2:  WAIT   1.00(sec) ;\n/POS\n/END\n";

  /** A fresh controller with the WAITS program, its port and its clock. */
  record Rig(ControllerPort port, CellStepper clock) {
    static Rig fresh() {
      Simulation sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
      ControllerPort port = new ControllerPort(sim.controllers().get(0));
      port.saveProgram(LsReader.parse("WAITS.LS", WAITS).program());
      return new Rig(port, new CellStepper(sim));
    }
  }

  record Switches(Mode mode, boolean tp, boolean estop, boolean deadman, boolean shift) {
    boolean teachPendantMayMove() {
      return mode != Mode.AUTO && tp && !estop && deadman && shift;
    }

    boolean cycleStartRuns() {
      return mode == Mode.AUTO && !tp && !estop;
    }

    Rig apply() {
      Rig rig = Rig.fresh();
      ControllerPort c = rig.port();
      c.setMode(mode);
      c.setTpEnabled(tp);
      c.setDeadman(deadman);
      c.setShift(shift);
      if (estop) {
        c.emergencyStop(true);
      }
      return rig;
    }
  }

  static List<Switches> everySetting() {
    List<Switches> out = new ArrayList<>();
    for (Mode mode : Mode.values()) {
      for (int bits = 0; bits < 16; bits++) {
        out.add(new Switches(mode, (bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0, (bits & 8) != 0));
      }
    }
    return out;
  }

  @TestFactory
  Stream<DynamicTest> aJogMovesTheArmOnlyWithEverySwitchRight() {
    return everySetting().stream().map(s -> DynamicTest.dynamicTest(s + " jog " + s.teachPendantMayMove(), () -> {
      Rig rig = s.apply();
      ControllerPort c = rig.port();
      boolean expected = s.teachPendantMayMove();
      Position.Joint start = c.currentJoints();
      Result step = c.jogIncrement(2, 1, false);
      assertThat(step).as("FINE step").isInstanceOf(expected ? Result.Ok.class : Result.Refused.class);
      assertThat(c.currentJoints().j2Deg() != start.j2Deg()).as("J2 moved by the FINE step").isEqualTo(expected);
      Result held = c.jogKeyDown(1, 1, false);
      assertThat(held).as("held jog key").isInstanceOf(expected ? Result.Ok.class : Result.Refused.class);
      rig.clock().advance(0.2);
      assertThat(c.currentJoints().j1Deg() > start.j1Deg()).as("J1 moved by the held key").isEqualTo(expected);
      assertThat(c.currentJoints().j1Deg()).as("J1 never moves backwards").isGreaterThanOrEqualTo(start.j1Deg());
    }));
  }

  @TestFactory
  Stream<DynamicTest> aProgramStartsFromThePendantOrThePanelOnlyWithTheRightSwitches() {
    return everySetting().stream().map(s -> DynamicTest.dynamicTest(s + " pendant " + s.teachPendantMayMove() + " panel " + s.cycleStartRuns(), () -> {
      Rig rig = s.apply();
      ControllerPort c = rig.port();
      boolean pendant = s.teachPendantMayMove();
      assertThat(c.mayStart(StartFrom.TEACH_PENDANT, true)).as("SHIFT+FWD").isInstanceOf(pendant ? Result.Ok.class : Result.Refused.class);
      assertThat(c.mayStart(StartFrom.TEACH_PENDANT, false)).as("SHIFT+BWD").isInstanceOf(pendant ? Result.Ok.class : Result.Refused.class);
      boolean panel = s.cycleStartRuns();
      assertThat(c.run(StartFrom.OPERATOR_PANEL, "WAITS", 1, true)).as("CYCLE START").isInstanceOf(panel ? Result.Ok.class : Result.Refused.class);
      assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true)).as("SHIFT+FWD run")
          .isInstanceOf(pendant ? Result.Ok.class : Result.Refused.class);
      rig.clock().advance(0.1);
      assertThat(c.status().state()).isEqualTo(pendant || panel ? ExecState.RUNNING : ExecState.IDLE);
      assertThat(c.programStates()).isEqualTo(pendant || panel ? java.util.Map.of("WAITS", "RUNNING") : java.util.Map.of());
      assertThat(c.tasks()).hasSize(pendant || panel ? 1 : 0);
    }));
  }

  /** How an operator lets go in T1/T2. */
  enum LetGo { SHIFT, DEADMAN, TP_ENABLE, MODE_SWITCH }

  @TestFactory
  Stream<DynamicTest> inT1AndT2LettingAnySwitchGoPausesTheProgram() {
    List<DynamicTest> tests = new ArrayList<>();
    for (Mode mode : List.of(Mode.T1, Mode.T2)) {
      for (LetGo letGo : LetGo.values()) {
        tests.add(DynamicTest.dynamicTest(mode + " " + letGo, () -> {
          Rig rig = new Switches(mode, true, false, true, true).apply();
          ControllerPort c = rig.port();
          assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true)).isInstanceOf(Result.Ok.class);
          rig.clock().advance(0.1);
          assertThat(c.status().state()).isEqualTo(ExecState.RUNNING);
          assertThat(c.tasks()).containsExactly(new org.robotrun.control.RobotControl.TaskInfo("WAITS", "RUNNING", 1, true));
          switch (letGo) {
            case SHIFT -> assertThat(c.setShift(false))
                .isEqualTo(new Result.Ok("Program paused: SHIFT released (hold-to-run in " + mode + "; SHIFT+FWD resumes)"));
            case DEADMAN -> {
              assertThat(c.setDeadman(false))
                  .isEqualTo(new Result.Ok("SRVO-003 Deadman switch released: program paused (hold DEADMAN, RESET)"));
              assertThat(c.activeAlarm()).hasValueSatisfying(a -> assertThat(a.code()).isEqualTo("SRVO-003"));
            }
            case TP_ENABLE -> c.setTpEnabled(false);
            case MODE_SWITCH -> c.setMode(mode == Mode.T1 ? Mode.T2 : Mode.T1);
          }
          assertThat(c.status().state()).isEqualTo(ExecState.PAUSED);
          assertThat(c.programStates()).isEqualTo(java.util.Map.of("WAITS", "PAUSED"));
          int line = c.status().line();
          rig.clock().advance(2.5);
          assertThat(c.status().state()).as("stays paused").isEqualTo(ExecState.PAUSED);
          assertThat(c.status().line()).isEqualTo(line);
        }));
      }
    }
    return tests.stream();
  }

  @Test
  void inAutoNothingOnThePendantPausesTheProgram() {
    Rig rig = new Switches(Mode.AUTO, false, false, false, false).apply();
    ControllerPort c = rig.port();
    assertThat(c.run(StartFrom.OPERATOR_PANEL, "WAITS", 1, true)).isInstanceOf(Result.Ok.class);
    rig.clock().advance(0.1);
    assertThat(c.setShift(true)).isEqualTo(Result.ok());
    assertThat(c.setShift(false)).isEqualTo(new Result.Ok(""));
    // with the TP disabled the DEADMAN means nothing: no SRVO-003
    assertThat(c.setDeadman(true)).isEqualTo(Result.ok());
    assertThat(c.setDeadman(false)).isEqualTo(Result.ok());
    assertThat(c.activeAlarm()).isEmpty();
    assertThat(c.status().state()).isEqualTo(ExecState.RUNNING);
    rig.clock().advance(2.5);
    assertThat(c.status().state()).isEqualTo(ExecState.IDLE);
  }

  @Test
  void theDeadmanLetGoWithNothingRunningIsSrvo003WithoutAPause() {
    Rig rig = new Switches(Mode.T1, true, false, true, false).apply();
    ControllerPort c = rig.port();
    assertThat(c.setDeadman(false)).isEqualTo(new Result.Ok("SRVO-003 Deadman switch released (hold DEADMAN, RESET)"));
    assertThat(c.deadmanHeld()).isFalse();
    // letting go twice raises nothing new
    assertThat(c.setDeadman(false)).isEqualTo(Result.ok());
    assertThat(c.alarmHistory()).extracting(a -> a.code()).containsExactly("SRVO-003");
    // while the alarm is active the DEADMAN alone does not let a jog go
    c.setDeadman(true);
    c.setShift(true);
    assertThat(c.jogKeyDown(1, 1, false)).isInstanceOf(Result.Refused.class);
    c.reset();
    assertThat(c.jogKeyDown(1, 1, false)).isInstanceOf(Result.Ok.class);
  }

  @Test
  void theNewestActiveAlarmIsTheOneShown() {
    Rig rig = Rig.fresh();
    ControllerPort c = rig.port();
    c.emergencyStop(true);
    c.emergencyStop(false);
    assertThat(c.activeAlarm()).hasValueSatisfying(a -> assertThat(a.code()).isEqualTo("SRVO-001"));
    assertThat(c.alarmHistory()).extracting(a -> a.code()).containsExactlyInAnyOrder("SRVO-001", "SRVO-002");
    c.clearAlarmHistory();
    assertThat(c.alarmHistory()).isEmpty();
  }

  @Test
  void theOverrideIsKeptBetweenOneAndAHundredPercent() {
    ControllerPort c = Rig.fresh().port();
    int[][] cases = {{0, 1}, {-5, 1}, {1, 1}, {2, 2}, {37, 37}, {99, 99}, {100, 100}, {101, 100}, {250, 100}};
    for (int[] k : cases) {
      c.setOverridePct(k[0]);
      assertThat(c.overridePct()).as("override set to %d", k[0]).isEqualTo(k[1]);
    }
  }

  @Test
  void lettingShiftGoStopsAJogAndSaysSoOnlyWhileOneIsOn() {
    Rig rig = new Switches(Mode.T1, true, false, true, true).apply();
    ControllerPort c = rig.port();
    // no jog on: nothing to say
    assertThat(c.setShift(false)).isEqualTo(new Result.Ok(""));
    c.setShift(true);
    assertThat(c.jogKeyDown(1, 1, false)).isInstanceOf(Result.Ok.class);
    rig.clock().advance(0.1);
    assertThat(c.setShift(false)).isEqualTo(new Result.Ok("Jog stopped: SHIFT released"));
    // a COORD change, the mode switch or an E-stop stops the jog first: SHIFT then has nothing to stop
    for (Runnable stop : List.<Runnable>of(() -> c.setCoordSystem(CoordSystem.WORLD), () -> c.setMode(Mode.T2))) {
      c.setShift(true);
      assertThat(c.jogKeyDown(1, 1, false)).isInstanceOf(Result.Ok.class);
      rig.clock().advance(0.1);
      stop.run();
      rig.clock().advance(0.5);
      double j1 = c.currentJoints().j1Deg();
      rig.clock().advance(0.2);
      assertThat(c.currentJoints().j1Deg()).as("the jog stopped").isEqualTo(j1);
      assertThat(c.setShift(false)).isEqualTo(new Result.Ok(""));
    }
    c.setShift(true);
    assertThat(c.jogKeyDown(1, 1, false)).isInstanceOf(Result.Ok.class);
    c.emergencyStop(true);
    assertThat(c.setShift(false)).isEqualTo(new Result.Ok(""));
    // TP ENABLE off stops a jog too
    Rig other = new Switches(Mode.T1, true, false, true, true).apply();
    ControllerPort d = other.port();
    assertThat(d.jogKeyDown(1, 1, false)).isInstanceOf(Result.Ok.class);
    other.clock().advance(0.1);
    d.setTpEnabled(false);
    other.clock().advance(0.5);
    double j1 = d.currentJoints().j1Deg();
    other.clock().advance(0.2);
    assertThat(d.currentJoints().j1Deg()).isEqualTo(j1);
    assertThat(d.setShift(false)).isEqualTo(new Result.Ok(""));
  }

  @Test
  void aFrameIsTaughtOnlyByAMethodOfItsKindWithAllItsPoints() {
    ControllerPort c = Rig.fresh().port();
    Position.Joint q = c.currentJoints();
    Position.Cartesian before = c.frame(FrameKind.USER, 1);
    assertThat(c.teachFrame(FrameKind.TOOL, 1, TeachMethod.USER_THREE_POINT, List.of(q, q, q)))
        .isEqualTo(new TeachResult.Failed("Three Point teaches USER frames, not TOOL"));
    assertThat(c.teachFrame(FrameKind.USER, 1, TeachMethod.USER_FOUR_POINT, List.of(q, q, q)))
        .isEqualTo(new TeachResult.Failed("Four Point needs 4 points, got 3"));
    assertThat(c.frame(FrameKind.USER, 1)).as("left as it was").isEqualTo(before);
  }

  @Test
  void unknownTasksAreRefusedByName() {
    ControllerPort c = Rig.fresh().port();
    assertThat(c.pauseTask("NOPE", true)).isEqualTo(Result.refused("NOPE is not a running task"));
    assertThat(c.pauseTask("NOPE", false)).isEqualTo(Result.refused("NOPE is not a running task"));
    assertThat(c.abortTask("NOPE")).isEqualTo(Result.refused("NOPE is not a running task"));
  }

  @Test
  void theSwitchesReadBackAsSetAndStepModeToo() {
    ControllerPort c = Rig.fresh().port();
    assertThat(c.deadmanHeld()).isFalse();
    assertThat(c.shiftHeld()).isFalse();
    assertThat(c.stepMode()).isFalse();
    c.setDeadman(true);
    c.setShift(true);
    c.setStepMode(true);
    assertThat(c.deadmanHeld()).isTrue();
    assertThat(c.shiftHeld()).isTrue();
    assertThat(c.stepMode()).isTrue();
    c.setStepMode(false);
    assertThat(c.stepMode()).isFalse();
  }

  @Test
  void holdPausesARunningProgramAndTheTaskCanBePausedByName() {
    Rig rig = new Switches(Mode.T1, true, false, true, true).apply();
    ControllerPort c = rig.port();
    assertThat(c.run(StartFrom.TEACH_PENDANT, "WAITS", 1, true)).isInstanceOf(Result.Ok.class);
    rig.clock().advance(0.1);
    c.hold();
    assertThat(c.status().state()).isEqualTo(ExecState.PAUSED);
    assertThat(c.status().program()).isEqualTo("WAITS");
    c.abort();
    assertThat(c.status().state()).isNotEqualTo(ExecState.PAUSED).isNotEqualTo(ExecState.RUNNING);
  }

  @Test
  void anAbortAlarmEndsTheProgramAndAPauseAlarmKeepsIt() {
    // UALM[1] with the default user alarm severity pauses; a division by zero is an INTP alarm that aborts
    String text = "/PROG  DIV0\n/ATTR\n/MN\n   1:  R[1]=0 ;\n   2:  R[2]=1/R[1] ;\n/POS\n/END\n";
    Rig rig = new Switches(Mode.T1, true, false, true, true).apply();
    ControllerPort c = rig.port();
    c.saveProgram(LsReader.parse("DIV0.LS", text).program());
    assertThat(c.run(StartFrom.TEACH_PENDANT, "DIV0", 1, true)).isInstanceOf(Result.Ok.class);
    rig.clock().advance(0.1);
    assertThat(c.activeAlarm()).isPresent();
    assertThat(c.activeAlarm().get().program()).isEqualTo("DIV0");
    assertThat(c.activeAlarm().get().line()).isEqualTo(2);
    assertThat(c.activeAlarm().get().display()).startsWith(c.activeAlarm().get().code() + " (DIV0, 2) ");
    assertThat(c.status().state()).isIn(ExecState.ABORTED, ExecState.PAUSED);
  }

  @Test
  void bgLogicSlotsAreAddedStartedStoppedAndRemovedByName() {
    String text = "/PROG  BGP\n/ATTR\nDEFAULT_GROUP\t= *,*,*,*,*;\n/MN\n   1:  F[1]=(ON) ;\n/POS\n/END\n";
    Rig rig = Rig.fresh();
    ControllerPort c = rig.port();
    c.saveProgram(LsReader.parse("BGP.LS", text).program());
    assertThat(c.bgSlots()).isEmpty();
    assertThat(c.addBg("BGP")).isInstanceOf(Result.Ok.class);
    assertThat(c.bgSlots()).extracting(org.robotrun.control.RobotControl.BgSlot::program).containsExactly("BGP");
    assertThat(c.runBg("BGP", false)).isInstanceOf(Result.Ok.class);
    assertThat(c.bgSlots()).containsExactly(new org.robotrun.control.RobotControl.BgSlot("BGP", false));
    assertThat(c.programStates()).doesNotContainKey("BGP");
    assertThat(c.runBg("BGP", true)).isInstanceOf(Result.Ok.class);
    rig.clock().advance(0.05);
    assertThat(c.bgSlots()).containsExactly(new org.robotrun.control.RobotControl.BgSlot("BGP", true));
    assertThat(c.programStates()).containsEntry("BGP", "BG");
    assertThat(c.registers().bit(org.robotrun.program.IoKind.F, 1)).isTrue();
    assertThat(c.runBg("BGP", false)).isInstanceOf(Result.Ok.class);
    assertThat(c.programStates()).doesNotContainKey("BGP");
    assertThat(c.removeBg("BGP")).isInstanceOf(Result.Ok.class);
    assertThat(c.bgSlots()).isEmpty();
    assertThat(c.removeBg("BGP")).isInstanceOf(Result.Refused.class);
  }

  @Test
  void jogFramesAreKeptAndSelected() {
    ControllerPort c = Rig.fresh().port();
    Position.Cartesian f = new Position.Cartesian(100, -50, 20, 0, 0, 30, Position.Cartesian.ZERO.config());
    c.setJogFrame(2, f);
    c.selectJogFrame(2);
    Position.Cartesian back = c.jogFrame(2);
    assertThat(new double[] {back.xMm(), back.yMm(), back.zMm(), back.wDeg(), back.pDeg(), back.rDeg()})
        .containsExactly(new double[] {100, -50, 20, 0, 0, 30}, org.assertj.core.data.Offset.offset(1e-9));
    assertThat(c.activeJogFrame()).isEqualTo(2);
  }

  @Test
  void theArmIsDescribedByItsModel() {
    ControllerPort c = Rig.fresh().port();
    var model = c.controller().model();
    assertThat(c.jointNames()).hasSize(6).isEqualTo(model.joints().stream().map(org.robotrun.robot.JointSpec::name).toList());
    assertThat(c.coupledJ3()).isEqualTo(model.coupledJ3());
    assertThat(c.program("WAITS")).isPresent();
    assertThat(c.program("NOPE")).isEmpty();
    assertThat(c.userMessages()).isEmpty();
    assertThat(c.jogStopReason()).isEmpty();
  }

  @Test
  void aPoseConvertsToJointsAndBackAndTheArmMovesThere() {
    Rig rig = Rig.fresh();
    ControllerPort c = rig.port();
    Position.Joint home = c.currentJoints();
    Position.Cartesian pose = c.currentPose(0, 0);
    assertThat(c.toCartesian(home, 0, 0)).isEqualTo(pose);
    Position.Cartesian moved = new Position.Cartesian(pose.xMm() + 30, pose.yMm() - 20, pose.zMm() - 10, pose.wDeg(), pose.pDeg(),
        pose.rDeg(), pose.config());
    var joints = c.toJoints(moved, 0, 0);
    assertThat(joints).isInstanceOf(org.robotrun.control.RobotControl.Conversion.Ok.class);
    Position.Joint q = ((org.robotrun.control.RobotControl.Conversion.Ok<Position.Joint>) joints).value();
    Position.Cartesian back = c.toCartesian(q, 0, 0);
    assertThat(back.xMm()).isCloseTo(moved.xMm(), org.assertj.core.data.Offset.offset(1e-6));
    assertThat(back.yMm()).isCloseTo(moved.yMm(), org.assertj.core.data.Offset.offset(1e-6));
    assertThat(back.zMm()).isCloseTo(moved.zMm(), org.assertj.core.data.Offset.offset(1e-6));
    Position.Cartesian far = new Position.Cartesian(5000, 0, 0, 0, 0, 0, pose.config());
    assertThat(c.toJoints(far, 0, 0)).isInstanceOf(org.robotrun.control.RobotControl.Conversion.Failed.class);
    c.setDeadman(true);
    c.setShift(true);
    assertThat(c.moveTo(q, 0, 0)).isInstanceOf(Result.Ok.class);
    rig.clock().advance(3.0);
    assertThat(c.currentPose(0, 0).xMm()).isCloseTo(moved.xMm(), org.assertj.core.data.Offset.offset(1e-3));
  }

  @Test
  void aThreePointUserFrameHasItsOriginAtTheFirstPointAndItsXAxisThroughTheSecond() {
    ControllerPort c = Rig.fresh().port();
    Position.Joint q0 = c.currentJoints();
    Position.Joint q1 = new Position.Joint(q0.j1Deg() + 10, q0.j2Deg(), q0.j3Deg(), q0.j4Deg(), q0.j5Deg(), q0.j6Deg());
    Position.Joint q2 = new Position.Joint(q0.j1Deg(), q0.j2Deg() + 10, q0.j3Deg(), q0.j4Deg(), q0.j5Deg(), q0.j6Deg());
    var p = java.util.stream.Stream.of(q0, q1, q2).map(q -> c.toCartesian(q, 0, c.activeFrame(FrameKind.TOOL)).toXyzwpr().position()).toList();
    TeachResult r = c.teachFrame(FrameKind.USER, 4, TeachMethod.USER_THREE_POINT, List.of(q0, q1, q2));
    assertThat(r).isInstanceOf(TeachResult.Taught.class);
    Position.Cartesian f = c.frame(FrameKind.USER, 4);
    assertThat(f).isEqualTo(((TeachResult.Taught) r).frame());
    var inFrame = f.toXyzwpr().toTransform().inverse();
    var o = inFrame.apply(p.get(0));
    var x = inFrame.apply(p.get(1));
    var y = inFrame.apply(p.get(2));
    assertThat(o.norm()).isCloseTo(0, org.assertj.core.data.Offset.offset(1e-6));
    assertThat(x.x()).isPositive();
    assertThat(Math.hypot(x.y(), x.z())).isCloseTo(0, org.assertj.core.data.Offset.offset(1e-6));
    assertThat(y.y()).isPositive();
    assertThat(y.z()).isCloseTo(0, org.assertj.core.data.Offset.offset(1e-6));
  }
}
