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
}
