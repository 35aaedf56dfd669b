package org.robotrun.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import static org.robotrun.motion.MotionLimitSpecTest.deg;

import java.util.List;

import org.junit.jupiter.api.Test;

/**
 * A joint limit is a closed range: the LR Mate 200iD's data sheet gives J1 −170..+170°,
 * J4 −190..+190°, J5 −125..+125°, J6 −360..+360°, and a joint may stand on either end. The
 * controller moves a joint to its stroke end (docs/motion.md: in JOINT a jog "decelerates to rest
 * exactly at its limit", and a program taught there must run again); only a value beyond it is
 * refused. The values below are the data sheet's (resources/robots/lrmate200id.json), written
 * out here, not read from the code.
 */
class JointLimitBoundarySpecTest {
  @Test
  void aJointMoveOntoTheLimitsRunsAndEndsExactlyThere() {
    double[] atLimits = deg(170, 0, 0, -190, 125, 360);
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, MotionRunnerTest.HOME, rec);
    r.enqueue(new MoveRequest.Joint(atLimits, Speed.percent(100), Termination.fine(), 1, 1));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);

    assertThat(rec.events).as(rec.fault == null ? "" : rec.fault.message()).containsExactly("start 1", "end 1");
    double[] last = trace.get(trace.size() - 1);
    for (int j = 0; j < 6; j++) {
      assertThat(last[j]).as("J%d", j + 1).isCloseTo(atLimits[j], offset(1e-12));
    }

    // and from the other ends of the same ranges
    double[] otherEnds = deg(-170, 0, 0, 190, -125, -360);
    r.enqueue(new MoveRequest.Joint(otherEnds, Speed.percent(100), Termination.fine(), 1, 2));
    trace = MotionRunnerTest.run(r, 20_000);
    assertThat(rec.events).as(rec.fault == null ? "" : rec.fault.message())
        .containsExactly("start 1", "end 1", "start 2", "end 2");
    last = trace.get(trace.size() - 1);
    for (int j = 0; j < 6; j++) {
      assertThat(last[j]).as("J%d", j + 1).isCloseTo(otherEnds[j], offset(1e-12));
    }
  }

  @Test
  void aLinearMoveStartingOnAJointLimitRuns() {
    // J1 on its upper end; an L move of 50 mm straight down keeps J1 where it is (the TCP stays
    // in the arm's plane at J1 = 170°), so J1 stays on its limit for the whole move.
    double[] q0 = deg(170, 10, -10, 0, -80, 0);
    var start = MotionRunnerTest.tcp(q0);
    var end = start.withTranslation(start.x(), start.y(), start.z() - 50);
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, q0, rec);
    r.enqueue(new MoveRequest.Linear(end, MotionRunnerTest.TOOL, Speed.mmPerSec(200), Termination.fine(), 1, 3));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);
    assertThat(rec.events).as(rec.fault == null ? "" : rec.fault.message()).containsExactly("start 3", "end 3");
    double[] last = trace.get(trace.size() - 1);
    assertThat(Math.toDegrees(last[0])).isCloseTo(170, offset(1e-6));
  }

  @Test
  void aHairBeyondTheLimitIsRefusedBeforeTheArmMoves() {
    double[] beyond = deg(0, 0, 0, 0, -125.0001, 0);
    MotionRunnerTest.Recorder rec = new MotionRunnerTest.Recorder();
    MotionRunner r = new MotionRunner(MotionRunnerTest.MODEL, MotionRunnerTest.LIMITS, MotionRunnerTest.HOME, rec);
    r.enqueue(new MoveRequest.Joint(beyond, Speed.percent(100), Termination.fine(), 1, 4));
    List<double[]> trace = MotionRunnerTest.run(r, 20_000);
    assertThat(rec.events).containsExactly("fail 4");
    assertThat(rec.fault.kind()).isEqualTo(MotionFault.Kind.JOINT_LIMIT);
    assertThat(rec.fault.message()).startsWith("target J5 would reach -125.0 deg");
    assertThat(trace.get(trace.size() - 1)).containsExactly(MotionRunnerTest.HOME);
  }
}
